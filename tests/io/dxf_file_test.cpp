// SPDX-License-Identifier: MIT
// io/dxf_file: write → parse gives every curve back bit for bit (doubles chosen to need 17 digits) with name,
// layer, colour and dimension; DXF text written by hand in the group-code layout of the DXF reference reads as
// the spline it spells; bad inputs are refused naming the file.
#include "hula/io/dxf_file.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::io {
namespace {

void expect_same(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b) {
  EXPECT_EQ(a.degree(), b.degree());
  EXPECT_EQ(a.dimension(), b.dimension());
  ASSERT_EQ(a.knots().size(), b.knots().size());
  for (std::size_t i = 0; i < a.knots().size(); ++i) EXPECT_EQ(a.knots()[i], b.knots()[i]);
  ASSERT_EQ(a.control_points().size(), b.control_points().size());
  for (std::size_t i = 0; i < a.control_points().size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(a.control_points()[i][k], b.control_points()[i][k]);
  ASSERT_EQ(a.weights().size(), b.weights().size());
  for (std::size_t i = 0; i < a.weights().size(); ++i) EXPECT_EQ(a.weights()[i], b.weights()[i]);
}

// checks: random curves (rational or not, unclamped, tiny coordinates) and a 2-D circle come back bit for bit
TEST(DxfFile, WriteThenParseIsBitExact) {
  Rng rng(4242);
  std::vector<DxfCurve> curves;
  curves.push_back({"cubic", testing::random_curve(rng, {.degree = 3, .clamped = false}), "A", "#123456", {}});
  curves.push_back({"quartic", testing::random_curve(rng, {.degree = 4, .rational = true}), "B", "", {}});
  curves.push_back({"circle", testing::rational_circle(1.2345678901234567e-5), "0", "#ff0000", {}});
  const DxfReadReport read = parse_dxf(dxf_text(curves), "mem.dxf");
  ASSERT_EQ(read.curves.size(), curves.size());
  EXPECT_EQ(read.skipped, 0u);
  for (std::size_t i = 0; i < curves.size(); ++i) {
    expect_same(read.curves[i].curve, curves[i].curve);
    EXPECT_EQ(read.curves[i].name, curves[i].name);
    EXPECT_EQ(read.curves[i].layer, curves[i].layer);
    EXPECT_EQ(read.curves[i].colour, curves[i].colour);
    EXPECT_EQ(read.curves[i].source, "SPLINE " + std::to_string(i + 1));
  }
}

// checks: a SPLINE spelt by hand (DXF reference group codes, no HulaHoops data) reads as its degree, knots and
// points, 3-D, with its layer and basic colour 1 (red); a LINE beside it is counted as skipped
TEST(DxfFile, ReadsAHandWrittenSpline) {
  const std::string text =
      "  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\n0\n 10\n0\n 20\n0\n 11\n1\n 21\n1\n"
      "  0\nSPLINE\n  8\nCUT\n 62\n1\n 70\n8\n 71\n2\n 72\n6\n 73\n3\n 74\n0\n"
      " 40\n0\n 40\n0\n 40\n0\n 40\n2\n 40\n2\n 40\n2\n"
      " 10\n0\n 20\n0\n 30\n0\n 10\n1\n 20\n2\n 30\n0\n 10\n2\n 20\n0\n 30\n0\n"
      "  0\nENDSEC\n  0\nEOF\n";
  const DxfReadReport read = parse_dxf(text, "hand.dxf");
  ASSERT_EQ(read.curves.size(), 1u);
  EXPECT_EQ(read.skipped, 1u);
  const nurbs::NurbsCurve& c = read.curves[0].curve;
  EXPECT_EQ(c.degree(), 2);
  EXPECT_EQ(c.dimension(), 3);
  EXPECT_FALSE(c.is_rational());
  const Vec3 mid = c.evaluate(1.0);  // (P0 + 2 P1 + P2) / 4 for a quadratic Bezier at its middle
  EXPECT_DOUBLE_EQ(mid.x, 1.0);
  EXPECT_DOUBLE_EQ(mid.y, 1.0);
  EXPECT_EQ(read.curves[0].layer, "CUT");
  EXPECT_EQ(read.curves[0].colour, "#ff0000");
}

// checks: not DXF, binary DXF, a file cut short, no SPLINE, a fit-point-only SPLINE and bad knots are refused
// naming the file (and, for the spline, which one)
TEST(DxfFile, BadInputsNameTheFile) {
  HULA_EXPECT_ERROR(parse_dxf("hello\n", "a.dxf"), Errc::ParseError, "'a.dxf': not a DXF file");
  HULA_EXPECT_ERROR(parse_dxf("AutoCAD Binary DXF\r\n\x1a", "b.dxf"), Errc::ParseError, "'b.dxf': a binary DXF");
  const std::string whole = dxf_text(std::vector<DxfCurve>{{"c", testing::rational_circle(1.0), "0", "", {}}});
  HULA_EXPECT_ERROR(parse_dxf(whole.substr(0, whole.size() - 8), "c.dxf"), Errc::ParseError,
                    "'c.dxf': the file is cut short");
  HULA_EXPECT_ERROR(parse_dxf("  0\nSECTION\n  2\nENTITIES\n  0\nENDSEC\n  0\nEOF\n", "d.dxf"), Errc::ParseError,
                    "'d.dxf': it holds no SPLINE");
  const std::string fit =
      "  0\nSECTION\n  2\nENTITIES\n  0\nSPLINE\n 71\n3\n 72\n0\n 73\n0\n 74\n2\n"
      " 11\n0\n 21\n0\n 31\n0\n 11\n1\n 21\n1\n 31\n0\n  0\nENDSEC\n  0\nEOF\n";
  HULA_EXPECT_ERROR(parse_dxf(fit, "e.dxf"), Errc::ParseError, "SPLINE 1: given by fit points only");
  const std::string bad =
      "  0\nSECTION\n  2\nENTITIES\n  0\nSPLINE\n 71\n1\n 72\n4\n 73\n2\n 74\n0\n"
      " 40\n1\n 40\n0\n 40\n1\n 40\n1\n 10\n0\n 20\n0\n 30\n0\n 10\n1\n 20\n1\n 30\n0\n"
      "  0\nENDSEC\n  0\nEOF\n";
  HULA_EXPECT_ERROR(parse_dxf(bad, "f.dxf"), Errc::InvalidKnots, "f.dxf: SPLINE 1");
  HULA_EXPECT_ERROR(dxf_text(std::vector<DxfCurve>{{"c", testing::rational_circle(1.0), "a/b", "", {}}}),
                    Errc::InvalidArgument, "layer");
}

}  // namespace
}  // namespace hula::io
