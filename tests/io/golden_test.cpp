// SPDX-License-Identifier: MIT
// Golden tests (tests/data/io/README.md gives provenance and tolerances):
// the rational unit circle evaluated through the library and through
// `hula eval` against the closed form; the thesis's cumulative chord lengths
// through the CSV reader and through `hula demo`; the format samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::io {
namespace {

using nlohmann::json;

std::string data(const std::string& name) {
  const char* root = std::getenv("HULA_TEST_DATA");
  return (std::filesystem::path(root ? root : "tests/data") / "io" / name).string();
}

json load(const std::string& name) { return json::parse(read_text_file(data(name))); }

// checks: circle_rational.json evaluated by the library matches the closed form of the unit circle.
TEST(IoGolden, RationalCircleMatchesClosedForm) {
  const curve::Curve f = read_curve_file(data("circle_rational.json"));
  const json expected = load("circle_eval_expected.json");
  const double tol = expected["tolerance"], dtol = expected["derivative_tolerance"];
  EXPECT_EQ(f.nurbs().dimension(), 2);
  for (const auto& c : expected["cases"]) {
    const double t = c["t"];
    const auto d = f.nurbs().derivatives(t, 1);
    EXPECT_NEAR(d[0].x, c["position"][0].get<double>(), tol) << "t = " << t;
    EXPECT_NEAR(d[0].y, c["position"][1].get<double>(), tol) << "t = " << t;
    if (c.contains("first_derivative")) {
      const double dx = c["first_derivative"][0], dy = c["first_derivative"][1];
      EXPECT_NEAR(d[1].x, dx, dtol * std::hypot(dx, dy)) << "t = " << t;
      EXPECT_NEAR(d[1].y, dy, dtol * std::hypot(dx, dy)) << "t = " << t;
    }
  }
  const double L = expected["length"];
  EXPECT_NEAR(nurbs::arc_length(f.nurbs()), L, expected["length_tolerance"].get<double>() * L);
}

// checks: `hula eval` on circle_rational.json prints the closed-form circle points as [x, y].
TEST(IoGolden, CliEvalOfRationalCircle) {
  const json expected = load("circle_eval_expected.json");
  std::string at;
  for (const auto& c : expected["cases"]) at += (at.empty() ? "" : ",") + c["t"].dump();
  const auto r =
      testing::run_process(HULA_CLI_PATH, {"eval", data("circle_rational.json"), "--at", at, "--derivatives", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json out = json::parse(r.out);
  const double tol = expected["tolerance"];
  ASSERT_EQ(out["results"].size(), expected["cases"].size());
  for (std::size_t i = 0; i < expected["cases"].size(); ++i) {
    const json& c = expected["cases"][i];
    const json& got = out["results"][i];
    EXPECT_EQ(got["t"], c["t"]);
    ASSERT_EQ(got["derivatives"][0].size(), 2u);
    for (std::size_t k = 0; k < 2; ++k)
      EXPECT_NEAR(got["derivatives"][0][k].get<double>(), c["position"][k].get<double>(), tol) << "t = " << c["t"];
  }
}

// checks: the thesis's cumulative chord lengths 47.17, 111.20, 158.37 from thesis_points.csv and from `hula demo`.
TEST(IoGolden, ThesisChordLengths) {
  const json expected = load("thesis_chord_lengths.json");
  const double tol = expected["tolerance"];
  const PointSet pts = read_points_file(data(expected["points"]));
  const std::vector<double> L = nurbs::cumulative_chord_lengths(pts.points);
  ASSERT_EQ(L.size(), expected["cumulative_chord_lengths"].size());
  for (std::size_t i = 0; i < L.size(); ++i)
    EXPECT_NEAR(L[i], expected["cumulative_chord_lengths"][i].get<double>(), tol) << i;

  const auto r = testing::run_process(HULA_CLI_PATH, {"demo"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json demo = json::parse(r.out);
  const json& chords = demo["examples"][0]["cumulative_chord_lengths"];
  ASSERT_EQ(chords.size(), L.size());
  for (std::size_t i = 0; i < L.size(); ++i)
    EXPECT_NEAR(chords[i].get<double>(), expected["cumulative_chord_lengths"][i].get<double>(), tol) << i;
}

// checks: the format samples load with their documented values (bezier midpoint (1,1) by de Casteljau;
// the interpolated sample passes through its end points with the clamped end derivative).
TEST(IoGolden, FormatSamples) {
  const curve::Curve b = read_curve_file(data("bezier_2d.json"));
  EXPECT_EQ(b.kind(), curve::Kind::Bezier);
  EXPECT_NEAR(b.nurbs().evaluate(0.5).x, 1.0, 1e-15);
  EXPECT_NEAR(b.nurbs().evaluate(0.5).y, 1.0, 1e-15);
  // The parabola (2t, 4t(1 - t)) has length ∫₀² √(1 + u²) du = √5 + asinh(2) / 2.
  const double parabola = std::sqrt(5.0) + std::asinh(2.0) / 2.0;
  EXPECT_NEAR(nurbs::arc_length(b.nurbs()), parabola, 1e-12 * parabola);

  const curve::Curve s = read_curve_file(data("interpolated_thesis.json"));
  EXPECT_EQ(s.kind(), curve::Kind::Interpolated);
  EXPECT_NEAR(distance(s.nurbs().evaluate(0.0), Vec3{0, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(s.nurbs().evaluate(1.0), Vec3{120, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(s.nurbs().derivatives(1.0, 1)[1], Vec3{100, 0, 0}), 0.0, 1e-9 * 100);
}

// FNV-1a (64 bits) of a text: a fingerprint of the bytes, to compare with the files of an earlier build.
std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

// checks: the curve file `hula interpolate` writes through 10,000 points, and the `hula info` answer that
// reads it back, are byte for byte those of the build before the large-file work (huge-page hints, the span
// cache without zero fill, numbers laid out in one buffer): the fingerprints below were taken with main at
// 479c32d on the same CSV (x = i, y = 7919 i mod 1009, z = i² mod 101: integers, so the input text is exact),
// 846,633 and 847,188 bytes (info without the file name it echoes).
TEST(IoGolden, LargeCurveFileAndInfoBytesUnchanged) {
  testing::TempDir dir;
  std::string csv;
  for (long i = 0; i < 10000; ++i)
    csv += std::to_string(i) + "," + std::to_string(i * 7919 % 1009) + "," + std::to_string(i * i % 101) + "\n";
  write_file_atomically(dir.path() / "g.csv", csv);
  const std::string curve_path = (dir.path() / "g.json").string();
  const auto written = testing::run_process(
      HULA_CLI_PATH, {"interpolate", "--points", (dir.path() / "g.csv").string(), "-o", curve_path});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const std::string file = read_text_file(curve_path);
  EXPECT_EQ(file.size(), 846633U);
  EXPECT_EQ(fnv1a(file), 0x5121c32d08578983ULL);
  const auto info = testing::run_process(HULA_CLI_PATH, {"info", curve_path});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  std::string answer = info.out;
  const std::size_t at = answer.find(curve_path);
  ASSERT_NE(at, std::string::npos);
  answer.erase(at, curve_path.size());
  EXPECT_EQ(answer.size(), 847188U);
  EXPECT_EQ(fnv1a(answer), 0xa4ab322fc3ae24ebULL);
}

}  // namespace
}  // namespace hula::io
