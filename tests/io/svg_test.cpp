// SPDX-License-Identifier: MIT
#include "hula/io/svg.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(Svg, PolylineBreaksAtNaNAndMapsTheDataIntoTheFrame) {
  hula::io::SvgFigure fig(400, 300);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> x = {0, 1, nan, 2, 3}, y = {0, 1, 0, 1, 0};
  fig.add_polyline(x, y);
  const std::string svg = fig.render();
  EXPECT_EQ(count(svg, "<polyline"), 2u);
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
  // Without axes the frame has a 20 px margin: x = 0 maps to 20, x = 3 to 380.
  EXPECT_NE(svg.find("20.00,280.00"), std::string::npos);
  EXPECT_NE(svg.find("380.00,280.00"), std::string::npos);
  EXPECT_NE(svg.find("260.00,20.00"), std::string::npos) << svg;  // (2, 1)
}

TEST(Svg, EqualAspectKeepsCirclesRound) {
  hula::io::SvgFigure fig(600, 300);
  fig.set_equal_aspect(true);
  const std::vector<double> x = {0, 2, 2, 0}, y = {0, 0, 1, 1};
  fig.add_polyline(x, y);
  const std::string svg = fig.render();
  // Plot area 560 x 260: scale min(280, 260) = 260 px per unit, centred horizontally.
  EXPECT_NE(svg.find("40.00,280.00 560.00,280.00 560.00,20.00 40.00,20.00"), std::string::npos) << svg;
}

TEST(Svg, HeatmapDrawsFiniteCellsAndAColourBar) {
  hula::io::SvgFigure fig;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> xs = {0, 1, 2}, ys = {0, 1}, v = {1, 2, 3, nan, 5, 6};
  fig.add_heatmap(xs, ys, v, "energy");
  fig.set_axes("knot 1", "knot 2");
  const std::string svg = fig.render();
  EXPECT_EQ(count(svg, "<rect") - 2 /* background, frame */ - 50 /* colour bar */, 5u);
  EXPECT_NE(svg.find(">6<"), std::string::npos);
  EXPECT_NE(svg.find(">1<"), std::string::npos);
}

TEST(Svg, LogAxisSkipsNonPositiveValuesAndEscapesText) {
  hula::io::SvgFigure fig;
  fig.set_log_y(true);
  fig.set_title("a < b & c");
  fig.set_axes("generation", "distance");
  const std::vector<double> x = {0, 1, 2, 3}, y = {1, 0.1, 0, 0.001};
  fig.add_polyline(x, y, {}, "best");
  const std::string svg = fig.render();
  EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 2u);  // the zero breaks the line
  EXPECT_NE(svg.find(">1e-3<"), std::string::npos);
  EXPECT_NE(svg.find(">1e0<"), std::string::npos);
}

TEST(Svg, MismatchedSizesAreRefused) {
  hula::io::SvgFigure fig;
  const std::vector<double> a = {0, 1}, b = {0};
  HULA_EXPECT_ERROR(fig.add_polyline(a, b), hula::Errc::InvalidArgument, "differ in size");
  HULA_EXPECT_ERROR(fig.add_heatmap(a, a, b), hula::Errc::InvalidArgument, "expected 4");
}

}  // namespace

namespace {

// checks the legend's mark matches the plotted one: a circle for a point series, a stroke for a line
TEST(Svg, LegendMarkMatchesThePlottedMark) {
  hula::io::SvgFigure fig(400, 300);
  const std::vector<double> x = {0, 1}, y = {0, 1};
  fig.add_points(x, y, hula::io::SvgStyle{.stroke = "#ff0000"}, 4.0, "data");
  fig.add_polyline(x, y, hula::io::SvgStyle{.stroke = "#0000ff"}, "fit");
  const std::string svg = fig.render();
  EXPECT_EQ(count(svg, "<circle"), 3u);  // two data points and the legend's marker
  EXPECT_EQ(count(svg, "<line"), 1u);    // the polyline's legend stroke only
  EXPECT_NE(svg.find("r=\"4.00\" fill=\"#ff0000\"/>\n<text"), std::string::npos) << svg;
}

}  // namespace
