// SPDX-License-Identifier: MIT
// Property: read(write(curve)) == curve with every double bit-exact, for
// random seeded curves (degrees 1–7, clamped and unclamped knots with
// multiplicities, rational or not, 2-D or 3-D, coordinates over 1e-300..1e300).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/curve_text_scan.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/json_write.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::io {
namespace {

// A double with random sign, mantissa and a decimal exponent in [-emax, emax].
double random_double(Rng& rng, int emax) {
  const double mantissa = rng.uniform(1.0, 10.0);
  const auto e = static_cast<int>(rng.below(static_cast<std::uint64_t>(2 * emax + 1))) - emax;
  const double v = mantissa * std::pow(10.0, e);
  return rng.below(2) == 0 ? v : -v;
}

nurbs::NurbsCurve random_curve(Rng& rng) {
  const int p = 1 + static_cast<int>(rng.below(7));
  const std::size_t n = static_cast<std::size_t>(p) + 1 + rng.below(8);
  const int dimension = rng.below(2) == 0 ? 2 : 3;
  // Coordinates of one scale per curve (kernel limit 1e300), with some exact zeros and integers.
  const int emax = static_cast<int>(rng.below(300));
  std::vector<Vec3> points(n);
  for (auto& P : points) {
    for (std::size_t c = 0; c < static_cast<std::size_t>(dimension); ++c) {
      const auto pick = rng.below(10);
      P[c] = pick == 0 ? 0.0 : (pick == 1 ? static_cast<double>(rng.below(100)) : random_double(rng, emax) / 10.0);
    }
  }
  // Knots: sorted random values with repeats, multiplicity ≤ p inside and ≤ p + 1 at the ends.
  const std::size_t m = n + static_cast<std::size_t>(p) + 1;
  std::vector<double> knots;
  const double a = rng.uniform(-1e3, 1e3), span = std::pow(10.0, rng.uniform(-5, 5));
  const bool clamped = rng.below(2) == 0;
  if (clamped) knots.assign(static_cast<std::size_t>(p) + 1, a);
  while (knots.size() + (clamped ? static_cast<std::size_t>(p) + 1 : 0) < m) {
    const double u = a + span * rng.uniform();
    const std::size_t repeat = 1 + rng.below(static_cast<std::uint64_t>(p));
    for (std::size_t r = 0; r < repeat && knots.size() + (clamped ? static_cast<std::size_t>(p) + 1 : 0) < m; ++r)
      knots.push_back(u);
  }
  if (clamped) knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, a + span);
  std::sort(knots.begin(), knots.end());
  std::vector<double> weights;
  if (rng.below(2) == 0) {
    for (std::size_t i = 0; i < n; ++i) weights.push_back(std::pow(10.0, rng.uniform(-3, 3)));
  }
  return nurbs::NurbsCurve(p, knots, points, weights, dimension);
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// checks: write then read gives back the same curve, every double bit for bit (against the original arrays).
TEST(JsonCurveProperty, RoundTripIsBitExact) {
  int tested = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    Rng rng(seed, 7);
    std::optional<nurbs::NurbsCurve> maybe;
    try {
      maybe = random_curve(rng);
    } catch (const Error&) {
      continue;  // a random knot vector with an empty domain or excess multiplicity: not a curve
    }
    const nurbs::NurbsCurve& curve = *maybe;
    ++tested;
    const std::string text = to_file_text(curve_to_json(curve));
    const curve::Curve back = parse_curve_json(text);
    ASSERT_EQ(back.nurbs(), curve) << "seed " << seed << "\n" << text;
    EXPECT_EQ(back.nurbs().dimension(), curve.dimension()) << "seed " << seed;
    const auto k0 = curve.knots().values(), k1 = back.nurbs().knots().values();
    for (std::size_t i = 0; i < k0.size(); ++i)
      ASSERT_TRUE(same_bits(k0[i], k1[i])) << "seed " << seed << " knot " << i;
    const auto p0 = curve.control_points(), p1 = back.nurbs().control_points();
    for (std::size_t i = 0; i < p0.size(); ++i)
      for (std::size_t c = 0; c < 3; ++c)
        ASSERT_TRUE(same_bits(p0[i][c], p1[i][c])) << "seed " << seed << " point " << i << " component " << c;
    const auto w0 = curve.weights(), w1 = back.nurbs().weights();
    ASSERT_EQ(w0.size(), w1.size());
    for (std::size_t i = 0; i < w0.size(); ++i) ASSERT_TRUE(same_bits(w0[i], w1[i])) << "seed " << seed;
    // Writing again gives the same text (the writer is deterministic).
    EXPECT_EQ(to_file_text(curve_to_json(back.nurbs())), text) << "seed " << seed;
  }
  EXPECT_GE(tested, 200);
}

// checks: special doubles that stress shortest round-trip printing (subnormals, DBL_MAX-near,
// 0.1-style decimals) survive bit for bit; -0.0 is written as 0.0 (issue 10: no "-0.0" in
// coordinates) and reads back as +0.0, equal in value.
TEST(JsonCurveProperty, SpecialDoublesRoundTrip) {
  const std::vector<double> values = {
      0.1, 1.0 / 3.0, -0.0, 5e-324, 2.2250738585072014e-308, 1e300, -1e300, 9007199254740993.0, 123456789012345678.0,
      1e-7};
  for (double v : values) {
    const nurbs::NurbsCurve curve(1, {0, 0, 1, 1}, {{v, 0, 0}, {1, v, -v}});
    const curve::Curve back = parse_curve_json(to_file_text(curve_to_json(curve)));
    const double x = v == 0.0 ? 0.0 : v;  // both zeros are written as +0.0
    EXPECT_TRUE(same_bits(back.nurbs().control_points()[0].x, x)) << v;
    EXPECT_TRUE(same_bits(back.nurbs().control_points()[1].z, -v == 0.0 ? 0.0 : -v)) << v;
  }
}

Vec3 random_point(Rng& rng, int dimension) {
  return {random_double(rng, 3), random_double(rng, 3), dimension == 2 ? 0.0 : random_double(rng, 3)};
}

std::vector<Vec3> random_points(Rng& rng, std::size_t n, int dimension) {
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < n; ++i) p.push_back(random_point(rng, dimension));
  return p;
}

std::vector<double> random_increasing(Rng& rng, std::size_t n) {
  std::vector<double> t{random_double(rng, 2)};
  for (std::size_t i = 1; i < n; ++i) t.push_back(t.back() + rng.uniform(0.1, 10.0));
  return t;
}

// One random curve of each kind (natural curves every 8th seed: they integrate and fit).
std::vector<curve::Curve> random_curves_of_every_kind(Rng& rng, std::uint64_t seed) {
  std::vector<curve::Curve> out;
  const int dim = rng.below(2) == 0 ? 2 : 3;
  const std::size_t n = 2 + rng.below(6);
  curve::BezierData b{random_points(rng, n, dim), {}, dim};
  if (rng.below(2) == 0)
    for (std::size_t i = 0; i < n; ++i) b.weights.push_back(rng.uniform(0.1, 10.0));
  out.push_back(curve::Curve::bezier(b));
  curve::InterpolatedData in;
  in.points = random_points(rng, n, dim);
  in.dimension = dim;
  in.parameterisation = static_cast<nurbs::Parameterisation>(rng.below(3));
  if (rng.below(2) == 0) in.parameters = random_increasing(rng, n);
  using K = nurbs::EndCondition::Kind;
  for (nurbs::EndCondition* e : {&in.start, &in.end}) {
    e->kind = static_cast<K>(rng.below(5));
    if (e->kind == K::Clamped) e->derivative = random_point(rng, dim);
  }
  out.push_back(curve::Curve::interpolated(in));
  curve::HermiteData h{random_points(rng, n, dim), random_points(rng, n, dim), {}, {}, dim};
  if (rng.below(2) == 0) h.second_derivatives = random_points(rng, n, dim);
  if (rng.below(2) == 0) h.parameters = random_increasing(rng, n);
  out.push_back(curve::Curve::hermite(h));
  const double a = random_double(rng, 2);
  out.push_back(curve::Curve::from_law(dim == 2 ? "vec(t, 0.5*t^2 - t)" : "vec(cos(t), sin(t), 0.25*t)", "t",
                                       {a, a + rng.uniform(0.5, 3.0)}));
  if (seed % 8 == 0) {
    curve::NaturalData d;
    d.curvature = "0.5 + 0.1*s";
    d.torsion = dim == 2 ? "0" : "0.3";
    d.length = rng.uniform(1.0, 5.0);
    d.start_point = random_point(rng, 3);
    d.start_tangent = {1.0, rng.uniform(-1.0, 1.0), 0.0};
    d.start_normal = {0.0, 1.0, rng.uniform(-1.0, 1.0)};
    out.push_back(intrinsic::natural_curve(d, curve::kApproximationTolerance));
  }
  return out;
}

// checks: for every kind, read(write(curve)) == curve with its construction data and NURBS bit for bit,
// and writing again gives the same text.
TEST(JsonCurveProperty, EveryKindRoundTripsBitExact) {
  int tested[6] = {};
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed, 11);
    std::vector<curve::Curve> curves;
    try {
      curves = random_curves_of_every_kind(rng, seed);
    } catch (const Error&) {
      continue;  // e.g. random Hermite points that coincide: not a curve
    }
    for (const curve::Curve& c : curves) {
      const std::string text = to_file_text(curve_to_json(c));
      const curve::Curve back = parse_curve_json(text);
      ASSERT_EQ(back, c) << "seed " << seed << "\n" << text;
      EXPECT_EQ(to_file_text(curve_to_json(back)), text) << "seed " << seed;
      ++tested[static_cast<int>(c.kind())];
    }
  }
  for (int k = 1; k < 6; ++k) EXPECT_GE(tested[k], 4) << curve::kind_name(static_cast<curve::Kind>(k));
}

// checks: every file written carries "format": "hula-curve", "version": 1 first; a file without them reads
// as version 1; another format or a later version is refused naming the member.
TEST(JsonCurveFormat, TagWrittenAndChecked) {
  const curve::Curve c = curve::Curve::bezier({{{0, 0, 0}, {1, 2, 0}}, {}, 2});
  const Json j = curve_to_json(c);
  EXPECT_EQ(j.begin().key(), "format");
  EXPECT_EQ(j["format"], "hula-curve");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 2]]})"), c);
  HULA_EXPECT_ERROR(
      parse_curve_json(R"({"format": "hula-points", "kind": "bezier", "control_points": [[0, 0], [1, 2]]})"),
      Errc::ParseError, "format");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"version": 2, "kind": "bezier", "control_points": [[0, 0], [1, 2]]})"),
                    Errc::ParseError, "version = 2");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"version": 1.5, "kind": "bezier", "control_points": [[0, 0], [1, 2]]})"),
                    Errc::ParseError, "version");
}

// The general reader alone (through the JSON value), or nullopt when it refuses the text.
std::optional<curve::Curve> general_read(const std::string& text) {
  try {
    return curve_from_json(json::parse_json_text(text, "curve file"));
  } catch (const Error&) {
    return std::nullopt;
  }
}

bool same_curve_bits(const curve::Curve& a, const curve::Curve& b) {
  if (a.kind() != b.kind() || a.dimension() != b.dimension()) return false;
  const nurbs::NurbsCurve &x = a.nurbs(), &y = b.nurbs();
  if (x.degree() != y.degree()) return false;
  const auto same = [](auto u, auto v) {
    if (u.size() != v.size()) return false;
    for (std::size_t i = 0; i < u.size(); ++i)
      if (!same_bits(u[i], v[i])) return false;
    return true;
  };
  if (!same(x.knots().values(), y.knots().values()) || !same(x.weights(), y.weights())) return false;
  const auto p = x.control_points(), q = y.control_points();
  if (p.size() != q.size()) return false;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      if (!same_bits(p[i][c], q[i][c])) return false;
  return true;
}

// checks: the streamed file text is format_json of the curve's JSON value byte for byte, for every kind
// and for numbers at the edges of nlohmann's fixed/scientific layout.
TEST(CurveFileText, IsFormatJsonOfTheValue) {
  int tested = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed, 11);
    std::vector<curve::Curve> curves;
    try {
      curves = random_curves_of_every_kind(rng, seed);
      curves.emplace_back(random_curve(rng));
    } catch (const Error&) {
      continue;
    }
    for (const curve::Curve& c : curves) {
      ASSERT_EQ(curve_file_text(c), format_json(curve_to_json(c))) << "seed " << seed;
      ++tested;
    }
  }
  EXPECT_GE(tested, 150);
  for (double v : {1234567890123456.0, 123456789012345.0, 1e15, 1e16, 0.0001, 0.00012345, 1.5e-5, 5e-324, 1e300}) {
    const curve::Curve c = nurbs::NurbsCurve(1, {0, 0, 1, 1}, {{v, -v, 0}, {1, 2, 3}});
    EXPECT_EQ(curve_file_text(c), format_json(curve_to_json(c))) << v;
  }
}

// checks: the fast path reads what hula writes to the same bits as the general reader, for random
// NURBS (rational, 2-D and 3-D, 1e-300..1e300) and Bézier curves.
TEST(CurveTextScan, ReadsWrittenFilesAsTheGeneralReaderDoes) {
  int scanned = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    Rng rng(seed, 7);
    std::optional<curve::Curve> c;
    try {
      c = seed % 3 == 0 ? random_curves_of_every_kind(rng, 1).front() : curve::Curve(random_curve(rng));
    } catch (const Error&) {
      continue;
    }
    const std::string text = curve_file_text(*c);
    const std::optional<curve::Curve> fast = scan_plain_curve_text(text), general = general_read(text);
    ASSERT_TRUE(fast.has_value()) << "seed " << seed << "\n" << text;
    ASSERT_TRUE(general.has_value()) << "seed " << seed;
    ASSERT_TRUE(same_curve_bits(*fast, *general)) << "seed " << seed << "\n" << text;
    ++scanned;
  }
  EXPECT_GE(scanned, 150);
}

// checks: hand-written texts at the edges of JSON's grammar: the fast path either declines or gives
// the general reader's curve bit for bit; the cases the general reader reads differently or refuses
// are declined.
TEST(CurveTextScan, DeclinesWhatIsNotPlain) {
  const std::string head = R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1], "control_points": )";
  const auto nurbs = [&](const std::string& points, const std::string& rest = "") {
    return head + points + rest + "}";
  };
  // Read by the fast path, equal to the general reader ("-0" is the integer 0, as nlohmann reads it).
  for (const std::string& text :
       {nurbs("[[-0, 1], [2, 3]]"), nurbs("[[0.1, 1e2], [2E-3, -3.5e+1]]"),
        nurbs("[[1,2,3],[4,5,6]]", ", \"weights\": null"), nurbs("[[1, 2], [3, 4]]", ", \"weights\": [1, 2]"),
        nurbs("[[9007199254740993, 1], [18446744073709551615, 1]]"),
        nurbs("[[184467440737095516160, 1], [-9223372036854775809, 1]]"),
        nurbs("[[1, 2], [3, 4]]", ", \"format\": \"hula-curve\", \"version\": 1"),
        std::string(R"({"kind":"bezier","control_points":[[0,0],[1,2],[3,1]],"weights":[1,0.5,1]})")}) {
    const std::optional<curve::Curve> fast = scan_plain_curve_text(text), general = general_read(text);
    ASSERT_TRUE(fast.has_value()) << text;
    ASSERT_TRUE(general.has_value()) << text;
    EXPECT_TRUE(same_curve_bits(*fast, *general)) << text;
  }
  // Declined: the general reader reads these (unknown members, escapes, a repeated member keeping its
  // last value, subnormal underflow, huge integers) or refuses them with a message.
  for (const std::string& text :
       {nurbs("[[1, 2], [3, 4]]", ", \"name\": \"a\""),
        nurbs("[[1, 2], [3, 4]]", ", \"degree\": 1"),
        nurbs("[[1e-400, 2], [3, 4]]"),
        nurbs("[[1e999, 2], [3, 4]]"),
        nurbs("[[01, 2], [3, 4]]"),
        nurbs("[[1., 2], [3, 4]]"),
        nurbs("[[.5, 2], [3, 4]]"),
        nurbs("[[+1, 2], [3, 4]]"),
        nurbs("[[NaN, 2], [3, 4]]"),
        nurbs("[[1, 2], [3, 4, 5]]"),
        nurbs("[[1], [3, 4]]"),
        nurbs("[]"),
        nurbs("[[1, 2], [3, 4]]", ", \"weights\": []"),
        nurbs("[[1, 2], [3, 4]]", ", \"version\": 2"),
        nurbs("[[1, 2], [3, 4]]") + " x",
        nurbs("[[1, 2], [3, 4],]"),
        nurbs("[[1, 2], [3, 4]]", ", \"kind\": \"bezier\""),
        nurbs("[[1, 2], [3, 4]]", ", \"format\": \"hula\\u002dcurve\""),
        nurbs("[[1, 2], [3, 4]]", ", \"weights\": [1, -1]"),
        nurbs("[[1, 2], [3, 4]]", ", \"weights\": [1]"),
        nurbs("[[1, 2], [3, 4]]", ", \"version\": 1.0"),
        std::string(R"({"kind": "interpolated", "points": [[0, 0], [1, 1]]})"),
        std::string(R"({"kind": "bezier", "degree": 1, "control_points": [[0, 0], [1, 1]]})")})
    EXPECT_FALSE(scan_plain_curve_text(text).has_value()) << text;
}

// checks (property): for 3,000 seeded mutations of written files (a byte replaced, inserted or
// deleted among JSON's significant characters), whenever the fast path reads a curve the general
// reader reads the same curve bit for bit: the fast path never accepts what the general reader
// refuses or reads differently.
TEST(CurveTextScan, NeverDisagreesWithTheGeneralReaderOnMutatedFiles) {
  static constexpr std::string_view kBytes = "0123456789-+.eE,:[]{}\" nul\\";
  Rng rng(2026, 12);
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const bool bezier = trial % 4 == 0;
    const curve::Curve c = bezier
                               ? curve::Curve::bezier({{{0, 0, 0}, {1, 2, 0}, {3.5, -1, 0}}, {1, 0.5, 2}, 2})
                               : curve::Curve(nurbs::NurbsCurve(2, {0, 0, 0, 0.5, 1, 1, 1},
                                                                {{0, 0, 1}, {1, 2, -0.25}, {3, 1, 1e-7}, {4, 0, 2}}));
    std::string text = curve_file_text(c);
    for (int edits = 1 + static_cast<int>(rng.below(3)); edits > 0; --edits) {
      const std::size_t at = rng.below(text.size());
      const char byte = kBytes[rng.below(kBytes.size())];
      switch (rng.below(3)) {
        case 0:
          text[at] = byte;
          break;
        case 1:
          text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), byte);
          break;
        default:
          text.erase(at, 1);
      }
    }
    const std::optional<curve::Curve> fast = scan_plain_curve_text(text);
    if (!fast) continue;
    ++accepted;
    const std::optional<curve::Curve> general = general_read(text);
    ASSERT_TRUE(general.has_value()) << "trial " << trial << ": the general reader refuses\n" << text;
    ASSERT_TRUE(same_curve_bits(*fast, *general)) << "trial " << trial << "\n" << text;
  }
  EXPECT_GE(accepted, 150);  // many mutations only change a digit: both readers read them
}

}  // namespace
}  // namespace hula::io
