// SPDX-License-Identifier: MIT
// Point files: JSON and CSV forms, comments/blank lines, 2-D detection, and
// errors naming the line and column (CSV) or the JSON path.
#include "hula/io/points_file.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"
#include "hula/testing/temp_dir.hpp"

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

// checks: whitespace-separated columns (spaces and tabs, several in a row) read as points.
TEST(PointsFile, WhitespaceColumns) {
  const PointSet s = parse_points("  1.0000  0.0013\n0.95\t\t0.0114\n\n   0  -.0012");
  EXPECT_EQ(s.dimension, 2);
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.points[1], (Vec3{0.95, 0.0114, 0}));
  EXPECT_EQ(s.points[2], (Vec3{0, -0.0012, 0}));
  const PointSet t = parse_points("x y z\n1 2 3\n4 5 6 # a comment after a point\n");
  EXPECT_EQ(t.dimension, 3);
  ASSERT_EQ(t.points.size(), 2u);
  EXPECT_EQ(t.points[1], (Vec3{4, 5, 6}));
}

// checks: semicolon columns, with the decimal comma a semicolon file may use.
TEST(PointsFile, SemicolonColumnsAndDecimalComma) {
  const PointSet s = parse_points("X;Y;Z\r\n1,5;2,25;-3\r\n4.5 ; 0 ; 1e-3\r\n");
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[0], (Vec3{1.5, 2.25, -3}));
  EXPECT_EQ(s.points[1], (Vec3{4.5, 0, 1e-3}));
}

// checks: a Selig airfoil file (a free-text name line, then x y) reads as written, and several
// lines of provenance before the first point are a header too.
TEST(PointsFile, SeligHeaderLines) {
  const PointSet s = parse_points(" NACA 23012  12% \n 1.00003  0.00126  \n 0.5 0.07\n 0.99997 -0.00126  ");
  EXPECT_EQ(s.dimension, 2);
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.points[0], (Vec3{1.00003, 0.00126, 0}));
  EXPECT_EQ(s.points[2], (Vec3{0.99997, -0.00126, 0}));
  const PointSet t =
      parse_points("SC(2)-0714 airfoil\nmodel coordinates\nFrom NASA TP-2890\n1.000  -.0104\n0.5 0.06\n");
  ASSERT_EQ(t.points.size(), 2u);
  EXPECT_EQ(t.points[0], (Vec3{1.0, -0.0104, 0}));
}

// checks: a Lednicer airfoil file (name, counts line, upper then lower surface from the leading
// edge) comes back in Selig order, trailing edge over the upper surface and back, the shared
// leading-edge point once; a count line that does not add up is an ordinary point.
TEST(PointsFile, LednicerBecomesSeligOrder) {
  const PointSet s = parse_points(
      " NACA 0012 AIRFOILS\n       3.       3.\n\n 0.0 0.0\n 0.5 0.06\n 1.0 0.00126\n\n 0.0 0.0\n 0.5 -.06\n 1.0 "
      "-.00126\n");
  ASSERT_EQ(s.points.size(), 5u);
  EXPECT_EQ(s.points[0], (Vec3{1.0, 0.00126, 0}));
  EXPECT_EQ(s.points[1], (Vec3{0.5, 0.06, 0}));
  EXPECT_EQ(s.points[2], (Vec3{0.0, 0.0, 0}));
  EXPECT_EQ(s.points[3], (Vec3{0.5, -0.06, 0}));
  EXPECT_EQ(s.points[4], (Vec3{1.0, -0.00126, 0}));
  const PointSet t = parse_points("name\n 3. 3.\n 0 0\n 1 1\n");
  ASSERT_EQ(t.points.size(), 3u);
  EXPECT_EQ(t.points[0], (Vec3{3, 3, 0}));
}

// checks: errors name the separator the file uses and the line that set it; a line with another
// separator is not silently split; text after the first point is an error, not a header; a file
// of text lines only has no point.
TEST(PointsFileErrors, NameTheSeparator) {
  HULA_EXPECT_ERROR(parse_points("1 2 3\n4,5,6\n"), Errc::ParseError,
                    "line 2, column 1: the 5-character field is not a number (fields separated by whitespace, as on "
                    "line 1)");
  HULA_EXPECT_ERROR(parse_points("name\n1;2\n3;x\n"), Errc::ParseError,
                    "line 3, column 3: the 1-character field is not a number (fields separated by semicolons, as on "
                    "line 2)");
  HULA_EXPECT_ERROR(parse_points("1 2\nend of data\n"), Errc::ParseError, "line 2, column 1");
  HULA_EXPECT_ERROR(parse_points("root:x:0:0\ndaemon:x:1:1\n"), Errc::ParseError,
                    "no point: none of the 2 non-blank lines");
}

// checks: errors from a file name the file before the line.
TEST(PointsFileErrors, FileErrorsNameTheFile) {
  const testing::TempDir dir;
  const auto path = dir / "wing.dat";
  std::ofstream(path) << "WING\n1 0\n0.5 0.0x6\n";
  HULA_EXPECT_ERROR(read_points_file(path), Errc::ParseError, "wing.dat: line 3, column 5");
}

// checks: every airfoil file of the real corpus (tests/data/real, read as shipped) gives as many
// points as it has lines that begin with a number, counted here by a plain scan of the text; the
// Lednicer file loses its count line and the repeated leading-edge point, and starts and ends at
// its trailing edge (x = 1) like the Selig files.
TEST(PointsFile, RealAirfoilFilesReadAsShipped) {
  const char* root = std::getenv("HULA_TEST_DATA");
  ASSERT_NE(root, nullptr);
  const std::filesystem::path dir = std::filesystem::path(root) / "real";
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".dat") continue;
    ++files;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    std::size_t numeric = 0;
    std::string line;
    while (std::getline(text, line)) {
      const auto b = line.find_first_not_of(" \t");
      if (b != std::string::npos && (std::isdigit(static_cast<unsigned char>(line[b])) != 0 || line[b] == '-' ||
                                     line[b] == '.' || line[b] == '+'))
        ++numeric;
    }
    const PointSet s = read_points_file(entry.path());
    SCOPED_TRACE(entry.path().filename().string());
    EXPECT_EQ(s.dimension, 2);
    const bool lednicer = entry.path().filename().string().find("lednicer") != std::string::npos;
    EXPECT_EQ(s.points.size(), lednicer ? numeric - 2 : numeric);
    EXPECT_NEAR(s.points.front().x, 1.0, 1e-4);
    EXPECT_NEAR(s.points.back().x, 1.0, 1e-4);
  }
  EXPECT_GE(files, 10u);
}

// What a text reader made of a text: the points bit for bit and the dimension, or the error's
// code, message and location.
std::string outcome(PointSet (*read)(std::string_view), std::string_view text) {
  std::string out;
  try {
    const PointSet s = read(text);
    out = "dimension " + std::to_string(s.dimension) + ":";
    for (const Vec3& p : s.points)
      for (const double v : {p.x, p.y, p.z}) out += " " + std::to_string(std::bit_cast<std::uint64_t>(v));
  } catch (const Error& e) {
    const ErrorWhere& w = e.where();
    const auto opt = [](const std::optional<std::size_t>& v) { return v ? std::to_string(*v) : std::string("-"); };
    out = "error " + std::to_string(static_cast<int>(e.code())) + " " + e.message() + " @" + w.field + "/" +
          opt(w.index) + "/" + opt(w.component) + "/" + opt(w.line) + "/" + opt(w.column);
  }
  return out;
}

// A number as a point file may write it: shortest, fixed, exponent, a leading '+' or '.', or a
// field that is not a finite double.
std::string random_field(Rng& rng, bool semicolons) {
  const double v = rng.uniform(-1.0, 1.0) * std::pow(10.0, static_cast<double>(rng.below(9)) - 4.0);
  char buffer[64];
  switch (rng.below(14)) {
    case 0:
      std::snprintf(buffer, sizeof buffer, "%.17g", v);
      break;
    case 1:
      std::snprintf(buffer, sizeof buffer, "%.3e", v);
      break;
    case 2:
      std::snprintf(buffer, sizeof buffer, "+%.4f", std::abs(v));
      break;
    case 3:
      return semicolons ? "1,25" : "-.5";
    case 4: {
      const char* odd[] = {"x", "1.5.2", "nan", "-inf", "1e999", "1e-400", "-", "", "0x1p3", "5.", "1e", "+", "--1"};
      return odd[rng.below(std::size(odd))];
    }
    default:
      std::snprintf(buffer, sizeof buffer, "%.9f", v);
      break;
  }
  return buffer;
}

// A text point file: a separator, perhaps header lines, rows of 2 or 3 fields with blanks around
// them, comments, blank lines, CRLF, and now and then a row of another width.
std::string random_points_text(Rng& rng) {
  const char* seps[] = {" ", "\t", ",", ";", " , ", " ;"};
  const std::string sep = seps[rng.below(std::size(seps))];
  const bool semicolons = sep.find(';') != std::string::npos;
  const std::size_t width = 2 + rng.below(2);
  std::string text;
  for (std::uint64_t h = rng.below(3); h > 0; --h) text += rng.below(2) == 0 ? "x y z\n" : "NACA 0012 # name\n";
  const std::size_t rows = 1 + rng.below(25);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::uint64_t kind = rng.below(20);
    if (kind == 0) {
      text += rng.below(2) == 0 ? "\n" : "  # comment, 1 2 3\n";
      continue;
    }
    std::size_t n = width;
    if (kind == 1) n = 1 + rng.below(4);
    if (rng.below(8) == 0) text += " \t";
    for (std::size_t c = 0; c < n; ++c) {
      if (c > 0) text += sep;
      if (rng.below(12) == 0) {
        text += random_field(rng, semicolons);
      } else {
        char b[32];
        std::snprintf(b, sizeof b, "%.9f", rng.uniform(-10.0, 10.0));
        text += b;
      }
    }
    if (rng.below(10) == 0) text += rng.below(2) == 0 ? sep : std::string(" # after");
    text += rng.below(6) == 0 ? "\r\n" : "\n";
  }
  if (rng.below(4) == 0 && !text.empty()) text.pop_back();  // no final newline
  return text;
}

// checks: the reader's fast path for plain data lines gives what the general path gives (points bit
// for bit, or the same error, message and location) on random point texts and on the real airfoil
// files with random edits.
TEST(PointsFileProperty, FastPathAgreesWithGeneralPath) {
  const testing::FpeGuard overflow_is_expected;  // 1e999 overflows inside from_chars
  std::size_t read = 0, refused = 0;
  for (std::uint64_t seed = 1; seed <= 1500; ++seed) {
    Rng rng(seed, 21);
    const std::string text = random_points_text(rng);
    const std::string general = outcome(parse_points_csv_general, text);
    ASSERT_EQ(outcome(parse_points_csv, text), general) << "seed " << seed << ":\n" << text;
    (general.starts_with("error") ? refused : read) += 1;
  }
  EXPECT_GE(read, 300u);
  EXPECT_GE(refused, 300u);

  const char* root = std::getenv("HULA_TEST_DATA");
  ASSERT_NE(root, nullptr);
  const std::string alphabet = "0123456789.,; \t\r\n#+-eEx";
  std::uint64_t seed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(root) / "real")) {
    if (entry.path().extension() != ".dat") continue;
    std::ifstream in(entry.path());
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string original = buffer.str();
    ASSERT_EQ(outcome(parse_points_csv, original), outcome(parse_points_csv_general, original));
    for (int k = 0; k < 20; ++k) {
      Rng rng(++seed, 22);
      std::string text = original;
      for (std::uint64_t e = 1 + rng.below(3); e > 0; --e) {
        const std::size_t at = rng.below(text.size());
        if (rng.below(2) == 0)
          text.erase(at, 1);
        else
          text.insert(at, 1, alphabet[rng.below(alphabet.size())]);
      }
      ASSERT_EQ(outcome(parse_points_csv, text), outcome(parse_points_csv_general, text))
          << entry.path().filename() << " edit seed " << seed;
    }
  }
  EXPECT_GE(seed, 200u);
}

}  // namespace
}  // namespace hula::io
