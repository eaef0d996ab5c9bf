// SPDX-License-Identifier: MIT
// Point files: JSON and CSV forms, comments/blank lines, 2-D detection, and
// errors naming the line and column (CSV) or the JSON path.
#include "hula/io/points_file.hpp"

#include <gtest/gtest.h>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"

namespace hula::io {
namespace {

Error error_of(std::string_view text) {
  try {
    (void)parse_points(text);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no hula::Error for " << text;
  return Error(Errc::InvalidArgument, "none");
}

// checks: a JSON array of 3-D points reads as written.
TEST(PointsFile, JsonThreeD) {
  const PointSet s = parse_points("  [[0, 0, 0], [40, 25, 0], [80, -25, 1.5]]");
  EXPECT_EQ(s.dimension, 3);
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.points[2], (Vec3{80, -25, 1.5}));
}

// checks: [x, y] points give a 2-D set with z = 0.
TEST(PointsFile, JsonTwoD) {
  const PointSet s = parse_points("[[0, 0], [40, 25]]");
  EXPECT_EQ(s.dimension, 2);
  EXPECT_EQ(s.points[1], (Vec3{40, 25, 0}));
}

// checks: CSV with comments, blank lines, spaces and CRLF line ends.
TEST(PointsFile, CsvWithCommentsAndBlanks) {
  const PointSet s = parse_points("# thesis 7.1.2\n\n0,0,0\r\n 40 , 25, 0\n  # again\n80,-25,0\n120,0,0");
  EXPECT_EQ(s.dimension, 3);
  ASSERT_EQ(s.points.size(), 4u);
  EXPECT_EQ(s.points[1], (Vec3{40, 25, 0}));
  EXPECT_EQ(s.points[3], (Vec3{120, 0, 0}));
  const PointSet t = parse_points("0,0\n1.5e1,+2\n");
  EXPECT_EQ(t.dimension, 2);
  EXPECT_EQ(t.points[1], (Vec3{15, 2, 0}));
}

// checks: a CSV field that is not a number names line and column (1-based).
TEST(PointsFileErrors, CsvBadNumberNamesLineAndColumn) {
  const std::string text = "# header\n0,0,0\n1, 2x,3\n";
  HULA_EXPECT_ERROR(parse_points(text), Errc::ParseError, "line 3, column 4: the 2-character field is not a number");
  const Error e = error_of(text);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 4u);
  EXPECT_EQ(e.where().index, 1u);
  EXPECT_EQ(e.where().component, 1u);
  HULA_EXPECT_ERROR(parse_points("1,,3\n"), Errc::ParseError, "line 1, column 3: empty field");
  HULA_EXPECT_ERROR(parse_points("1,nan,3\n"), Errc::NonFiniteInput, "line 1, column 3");
  const testing::FpeGuard overflow_is_expected;  // from_chars may raise FE_OVERFLOW for 1e999
  HULA_EXPECT_ERROR(parse_points("1,2,1e999\n"), Errc::NonFiniteInput, "line 1, column 5");
}

// checks: wrong field counts are named by line.
TEST(PointsFileErrors, CsvFieldCounts) {
  HULA_EXPECT_ERROR(parse_points("1,2,3\n4\n"), Errc::ParseError, "line 2: 1 number");
  HULA_EXPECT_ERROR(parse_points("1,2,3,4\n"), Errc::ParseError, "line 1, column 7: more than 3 numbers");
  HULA_EXPECT_ERROR(parse_points("1,2,3\n4,5\n"), Errc::ParseError, "line 2: 2 numbers but the first point has 3");
}

// checks: JSON point errors name the path and value.
TEST(PointsFileErrors, JsonErrorsNamePath) {
  HULA_EXPECT_ERROR(parse_points("[[0, 0], [1, \"a\"]]"), Errc::ParseError, "points[1][1] = \"a\" must be a number");
  HULA_EXPECT_ERROR(parse_points("[[0, 0], [1, 1, 1]]"), Errc::ParseError, "points[1] has 3 components");
  HULA_EXPECT_ERROR(parse_points("[[0, 0], 5]"), Errc::ParseError, "points[1] = 5 must be an array of 2 or 3");
  HULA_EXPECT_ERROR(parse_points("[[0, 0],"), Errc::ParseError, "not valid JSON at line 1");
  const testing::FpeGuard overflow_is_expected;  // 1e999 overflows inside strtod (FE_OVERFLOW)
  HULA_EXPECT_ERROR(parse_points("[[0, 1e999]]"), Errc::NonFiniteInput, "1e999");
}

}  // namespace
}  // namespace hula::io
