// SPDX-License-Identifier: MIT
// `hula convert` run as a process: JSON → STEP / IGES / DXF → JSON round trips
// keep every B-spline (degree, knots, control points, weights within 1e-12,
// here bit for bit) with its name, colour and layer, checked on the way by
// readers that share nothing with HulaHoops — Open CASCADE's XCAF readers
// (occt_read_curves.cpp) for STEP and IGES, dxflib (dxflib_read_splines.cpp)
// for DXF — and on the way back by the hula-document the command writes. SVG
// paths are sampled and compared with the curves. Bad inputs are refused
// naming the file, and no output is left behind. Curves come from two
// independent generators: seeded random B-splines and closed forms / spline
// interpolation of given points.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/curve/curve.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kTol = 1e-12;

struct Item {
  std::string name, colour, layer;
  nurbs::NurbsCurve curve;
};

// Two generators: seeded random B-splines (a 3-D cubic, a rational quintic) and closed forms (a rational
// circle, 2-D) with a cubic spline through given points.
std::vector<Item> items() {
  Rng rng(20261207);
  std::vector<Item> out;
  out.push_back({"random cubic", "#d62728", "splines", testing::random_curve(rng, {.degree = 3})});
  out.push_back({"rational quintic", "#2ca02c", "splines",
                 testing::random_curve(rng, {.degree = 5, .rational = true, .extra_points = 3})});
  out.push_back({"circle", "#1f77b4", "conics", testing::rational_circle(2.5, 0.3)});
  const std::vector<Vec3> points{{0, 0, 0}, {1, 2, 0.5}, {3, 1, 1}, {4, 3, 0.25}, {6, 0, -1}};
  out.push_back({"spline", "#9467bd", "default", nurbs::interpolate_cubic(points)});
  return out;
}

json document_json(const std::vector<Item>& list) {
  json entities = json::array();
  for (const auto& it : list) {
    json e = json::parse(io::curve_to_json(curve::Curve(it.curve)).dump());
    e["attributes"] = {{"name", it.name}, {"colour", it.colour}, {"layer", it.layer}};
    entities.push_back(e);
  }
  return {{"format", "hula-document"}, {"version", 1}, {"entities", entities}};
}

std::string write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

testing::ProcessResult hula(const std::vector<std::string>& args) { return testing::run_process(HULA_CLI_PATH, args); }

// Checks a point read back ([x, y] or [x, y, z]) against the curve's control point.
void expect_point(const json& got, const Vec3& want, const std::string& what) {
  ASSERT_TRUE(got.is_array() && got.size() >= 2) << what;
  for (std::size_t k = 0; k < 3; ++k) {
    const double g = k < got.size() ? got[k].get<double>() : 0.0;
    EXPECT_NEAR(g, want[k], kTol) << what << " component " << k;
  }
}

// Checks degree, knots, control points and weights (null or all 1 when the curve is not rational).
void expect_curve(const json& knots, const json& points, const json& weights, int degree, const nurbs::NurbsCurve& want,
                  const std::string& what) {
  EXPECT_EQ(degree, want.degree()) << what;
  ASSERT_EQ(knots.size(), want.knots().size()) << what;
  for (std::size_t i = 0; i < knots.size(); ++i) EXPECT_NEAR(knots[i].get<double>(), want.knots()[i], kTol) << what;
  ASSERT_EQ(points.size(), want.control_points().size()) << what;
  for (std::size_t i = 0; i < points.size(); ++i)
    expect_point(points[i], want.control_points()[i], what + " control point " + std::to_string(i));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w = weights.is_null() ? 1.0 : weights[i].get<double>();
    EXPECT_NEAR(w, want.is_rational() ? want.weights()[i] : 1.0, kTol) << what << " weight " << i;
  }
}

// Converts the file back to JSON with hula and checks every curve and its attributes.
void expect_back_to_json(const testing::TempDir& dir, const std::string& from, const std::vector<Item>& list,
                         bool layers) {
  const std::string back = (dir / ("back-" + fs::path(from).filename().string() + ".json")).string();
  const json report = testing::stdout_json(hula({"convert", from, "-o", back}));
  EXPECT_EQ(report.value("curves", 0u), list.size()) << from;
  const json doc = json::parse(read_text(back));
  ASSERT_EQ(doc.value("format", ""), "hula-document") << from;
  ASSERT_EQ(doc["entities"].size(), list.size()) << from;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& e = doc["entities"][i];
    const std::string what = from + " → JSON, " + list[i].name;
    expect_curve(e["knots"], e["control_points"], e["weights"], e["degree"].get<int>(), list[i].curve, what);
    EXPECT_EQ(e["attributes"]["name"], list[i].name) << what;
    EXPECT_EQ(e["attributes"]["colour"], list[i].colour) << what;
    if (layers) {
      EXPECT_EQ(e["attributes"]["layer"], list[i].layer) << what;
    }
  }
}

// checks: JSON → DXF keeps every B-spline bit for bit with its layer and colour, as dxflib itself reads the file,
// and DXF → JSON gives the curves, names, colours and layers back.
TEST(ConvertCli, DxfRoundTripCheckedByDxflib) {
  testing::TempDir dir;
  const auto list = items();
  const std::string in = write_text(dir / "curves.json", document_json(list).dump());
  const std::string dxf = (dir / "curves.dxf").string();
  const json report = testing::stdout_json(hula({"convert", in, "-o", dxf}));
  EXPECT_EQ(report.value("format", ""), "dxf");
  const json read = testing::stdout_json(testing::run_process(HULA_DXFLIB_READ_PATH, {dxf}));
  ASSERT_EQ(read["splines"].size(), list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& s = read["splines"][i];
    const std::string what = "dxflib, " + list[i].name;
    expect_curve(s["knots"], s["points"], s["weights"], s["degree"].get<int>(), list[i].curve, what);
    EXPECT_EQ(s["layer"], list[i].layer) << what;
    EXPECT_EQ(s["colour24"].get<int>(), std::stoi(list[i].colour.substr(1), nullptr, 16)) << what;
    EXPECT_EQ((s["flags"].get<int>() & 4) != 0, list[i].curve.is_rational()) << what;
  }
  expect_back_to_json(dir, dxf, list, true);
}

#ifdef HULA_OCCT_READ_PATH
// checks: JSON → STEP writes each curve as a product named after it (not "Open CASCADE STEP translator"), with
// its colour and layer, and the B-spline exactly, as Open CASCADE's own XCAF reader reads them; STEP → JSON
// gives them back.
TEST(ConvertCli, StepRoundTripCheckedByOpenCascade) {
  testing::TempDir dir;
  const auto list = items();
  const std::string in = write_text(dir / "curves.json", document_json(list).dump());
  const std::string step = (dir / "curves.step").string();
  (void)testing::stdout_json(hula({"convert", in, "-o", step}));
  const json read = testing::stdout_json(testing::run_process(HULA_OCCT_READ_PATH, {step}));
  std::vector<std::string> products = read["products"].get<std::vector<std::string>>();
  for (const auto& it : list)
    EXPECT_NE(std::find(products.begin(), products.end(), it.name), products.end()) << it.name;
  for (const auto& p : products) EXPECT_EQ(p.find("Open CASCADE"), std::string::npos) << p;
  ASSERT_EQ(read["shapes"].size(), list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& s = read["shapes"][i];
    const std::string what = "Open CASCADE STEP, " + list[i].name;
    EXPECT_EQ(s["name"], list[i].name) << what;
    EXPECT_EQ(s["colour"], list[i].colour) << what;
    EXPECT_EQ(s["layer"], list[i].layer) << what;
    ASSERT_EQ(s["edges"].size(), 1u) << what;
    const json& c = s["edges"][0];
    ASSERT_FALSE(c.is_null()) << what;
    expect_curve(c["knots"], c["poles"], c["weights"], c["degree"].get<int>(), list[i].curve, what);
  }
  expect_back_to_json(dir, step, list, true);
}

// checks: JSON → IGES writes each B-spline exactly with its name, colour and layer, as Open CASCADE's XCAF reader
// reads them (a layer is an IGES level, a number: curves on one layer share it, curves on two do not); IGES → JSON
// gives them back, layer names included (the level's Level Function property).
TEST(ConvertCli, IgesRoundTripCheckedByOpenCascade) {
  testing::TempDir dir;
  const auto list = items();
  const std::string in = write_text(dir / "curves.json", document_json(list).dump());
  const std::string iges = (dir / "curves.igs").string();
  (void)testing::stdout_json(hula({"convert", in, "-o", iges}));
  const json read = testing::stdout_json(testing::run_process(HULA_OCCT_READ_PATH, {iges}));
  ASSERT_EQ(read["shapes"].size(), list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& s = read["shapes"][i];
    const std::string what = "Open CASCADE IGES, " + list[i].name;
    EXPECT_EQ(s["name"], list[i].name) << what;
    EXPECT_EQ(s["colour"], list[i].colour) << what;
    ASSERT_TRUE(s["layer"].is_string()) << what;
    for (std::size_t k = 0; k < list.size(); ++k)
      EXPECT_EQ(s["layer"] == read["shapes"][k]["layer"], list[i].layer == list[k].layer) << what << ", " << k;
    ASSERT_EQ(s["edges"].size(), 1u) << what;
    const json& c = s["edges"][0];
    ASSERT_FALSE(c.is_null()) << what;
    expect_curve(c["knots"], c["poles"], c["weights"], c["degree"].get<int>(), list[i].curve, what);
  }
  expect_back_to_json(dir, iges, list, true);
}
#endif

// The Bézier pieces of an SVG path "M x y C x1 y1 x2 y2 x3 y3 …", each as its four points.
std::vector<std::array<Vec3, 4>> path_pieces(const std::string& d) {
  std::istringstream in(d);
  std::string token;
  std::vector<double> numbers;
  while (in >> token)
    if (token != "M" && token != "C") numbers.push_back(std::stod(token));
  std::vector<std::array<Vec3, 4>> out;
  for (std::size_t i = 2; i + 6 <= numbers.size(); i += 6) {
    const Vec3 start = out.empty() ? Vec3{numbers[0], numbers[1], 0} : out.back()[3];
    out.push_back({start, Vec3{numbers[i], numbers[i + 1], 0}, Vec3{numbers[i + 2], numbers[i + 3], 0},
                   Vec3{numbers[i + 4], numbers[i + 5], 0}});
  }
  return out;
}

Vec3 bezier(const std::array<Vec3, 4>& p, double x) {
  const double y = 1 - x;
  return p[0] * (y * y * y) + p[1] * (3 * y * y * x) + p[2] * (3 * y * x * x) + p[3] * (x * x * x);
}

// checks: the SVG paths of non-rational cubics are the curves (each piece equals the curve on its knot span, the
// curve projected on XY) and those of the rational curves stay within the tolerance of the curve (closest-point
// distance of 50 samples per piece).
TEST(ConvertCli, SvgPathsFollowTheCurves) {
  testing::TempDir dir;
  const auto list = items();
  const std::string in = write_text(dir / "curves.json", document_json(list).dump());
  const std::string svg = (dir / "curves.svg").string();
  const double tolerance = 1e-7;
  (void)testing::stdout_json(hula({"convert", in, "-o", svg, "--tolerance", "1e-7"}));
  const std::string text = read_text(svg);
  const std::regex path_re("<path id=\"curve-(\\d+)\"[^>]*data-exact=\"(true|false)\"[^>]*d=\"([^\"]*)\"");
  std::size_t seen = 0;
  for (std::sregex_iterator m(text.begin(), text.end(), path_re), end; m != end; ++m, ++seen) {
    const Item& it = list[std::stoul((*m)[1]) - 1];
    // The SVG is the curve's projection on XY: the curve with its control points' z dropped (a parallel
    // projection is affine, so it maps the rational curve to the one of the projected control points).
    std::vector<Vec3> flat(it.curve.control_points().begin(), it.curve.control_points().end());
    for (Vec3& p : flat) p.z = 0;
    const nurbs::NurbsCurve projected(it.curve.knots(), flat, {it.curve.weights().begin(), it.curve.weights().end()});
    const auto pieces = path_pieces((*m)[3]);
    const bool exact = (*m)[2] == "true";
    EXPECT_EQ(exact, !it.curve.is_rational() && it.curve.degree() <= 3) << it.name;
    ASSERT_FALSE(pieces.empty()) << it.name;
    std::vector<double> breaks;
    for (double k : it.curve.knots().values())
      if (it.curve.domain().contains(k) && (breaks.empty() || k > breaks.back())) breaks.push_back(k);
    if (exact) {
      ASSERT_EQ(pieces.size() + 1, breaks.size()) << it.name;
    }
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      for (int s = 0; s <= 50; ++s) {
        const double x = s / 50.0;
        const Vec3 p = bezier(pieces[k], x);
        if (exact) {
          Vec3 c = it.curve.evaluate(breaks[k] + x * (breaks[k + 1] - breaks[k]));
          c.z = 0;
          EXPECT_LT(distance(p, c), 1e-11) << it.name << " piece " << k << " x " << x;
        } else {
          EXPECT_LE(nurbs::closest_point(projected, p).distance, tolerance) << it.name << " piece " << k;
        }
      }
    }
  }
  EXPECT_EQ(seen, list.size());
}

// checks: a DXF with no SPLINE, a DXF cut short, a STEP file cut short and an unknown extension are refused with
// a message naming the file, and neither a new output nor a change to an existing one is left behind.
TEST(ConvertCli, BadInputsAreRefusedNamingTheFileAndWriteNothing) {
  testing::TempDir dir;
  const std::string lines =
      write_text(dir / "lines.dxf",
                 "  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\n0\n 10\n0\n 20\n0\n 30\n0\n 11\n1\n"
                 " 21\n1\n 31\n0\n  0\nENDSEC\n  0\nEOF\n");
  const std::string out = (dir / "out.json").string();
  auto refused = [&](const std::string& input, const std::string& output, const std::string& says) {
    const auto r = hula({"convert", input, "-o", output});
    EXPECT_NE(r.exit_code, 0) << input;
    const json error = testing::stderr_error(r);
    const std::string message = error.value("message", "");
    EXPECT_NE(message.find(input), std::string::npos) << message;
    EXPECT_NE(message.find(says), std::string::npos) << message;
  };
  refused(lines, out, "no SPLINE");
  EXPECT_FALSE(fs::exists(out));

  const auto list = items();
  const std::string in = write_text(dir / "curves.json", document_json(list).dump());
  const std::string dxf = (dir / "curves.dxf").string();
  (void)testing::stdout_json(hula({"convert", in, "-o", dxf}));
  const std::string whole = read_text(dxf);
  const std::string cut = write_text(dir / "cut.dxf", whole.substr(0, whole.size() / 2));
  write_text(out, "previous contents\n");
  refused(cut, out, "cut short");
  EXPECT_EQ(read_text(out), "previous contents\n");

  const std::string svg = (dir / "never.svg").string();
  refused(write_text(dir / "curves.txt", "0 0\n1 1\n"), svg, "extension");
  EXPECT_FALSE(fs::exists(svg));
#ifdef HULA_OCCT_READ_PATH
  const std::string step = (dir / "curves.step").string();
  (void)testing::stdout_json(hula({"convert", in, "-o", step}));
  const std::string text = read_text(step);
  const std::string cut_step = write_text(dir / "cut.step", text.substr(0, text.size() / 3));
  refused(cut_step, out, "cut.step");
  EXPECT_EQ(read_text(out), "previous contents\n");
#endif
  // No temporary file is left beside the outputs.
  for (const auto& name : dir.names()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;
}

}  // namespace
}  // namespace hula
