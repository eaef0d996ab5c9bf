// SPDX-License-Identifier: MIT
// Issue 24, item 14: a file `hula` writes, `hula` could not read. Interpolating
// 1,000,000 points wrote a ~70 MB curve file that every reader refused ("larger
// than the 67108864-byte limit"). Curve and point files are now read up to
// io::kMaxGeometryInputBytes, and a writer refuses a curve file above it.
#include <cmath>
#include <string>

#include "cli.hpp"
#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"

namespace hula::regress {
namespace {

// checks: `hula interpolate` of 1,000,000 points on a helix writes a file above 64 MiB that `hula eval`
// reads back: with a uniform parameterisation the curve passes through the first point at t = 0 and the
// last at t = 1 (the interpolation conditions), to 1e-9.
TEST(Issue24WrittenFilesReadBack, MillionPointInterpolationReadsBack) {
  TempDir dir;
  constexpr int kPoints = 1'000'000;
  std::string csv;
  csv.reserve(std::size_t{kPoints} * 40);
  auto point = [](int i) { return Vec3{std::cos(1e-3 * i), std::sin(1e-3 * i), 1e-4 * i}; };
  for (int i = 0; i < kPoints; ++i) {
    const Vec3 p = point(i);
    csv += format_number(p.x) + ',' + format_number(p.y) + ',' + format_number(p.z) + '\n';
  }
  write(dir / "points.csv", csv);
  const fs::path curve = dir / "big.json";
  const ProcessResult w = hula({"interpolate", "--points", (dir / "points.csv").string(), "--parameterisation",
                                "uniform", "-o", curve.string()});
  ASSERT_EQ(w.exit_code, 0) << w.err.substr(0, 400);
  EXPECT_GT(fs::file_size(curve), std::uintmax_t{64} << 20);
  const ProcessResult r = hula({"eval", curve.string(), "--at", "0,1"});
  ASSERT_EQ(r.exit_code, 0) << r.err.substr(0, 400);
  const json out = json::parse(r.out);
  const json& results = out.is_array() ? out : out["results"];
  ASSERT_EQ(results.size(), 2U) << r.out;
  const Vec3 ends[2] = {point(0), point(kPoints - 1)};
  for (std::size_t k = 0; k < 2; ++k) {
    const json& p = results[k]["derivatives"][0];
    EXPECT_NEAR(p[0].get<double>(), ends[k].x, 1e-9) << r.out;
    EXPECT_NEAR(p[1].get<double>(), ends[k].y, 1e-9) << r.out;
    EXPECT_NEAR(p[2].get<double>(), ends[k].z, 1e-9) << r.out;
  }
}

// checks: the writers' check refuses, by path, size and limit, a text one byte over the readers' limit and
// accepts one at the limit.
TEST(Issue24WrittenFilesReadBack, WriterRefusesAFileReadersCouldNotRead) {
  EXPECT_NO_THROW(io::check_readable_size(io::kMaxGeometryInputBytes, "c.json", "--output"));
  try {
    io::check_readable_size(io::kMaxGeometryInputBytes + 1, "c.json", "--output");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::InvalidArgument);
    EXPECT_EQ(e.where().field, "--output");
    const std::string m = e.message();
    EXPECT_NE(m.find("'c.json'"), std::string::npos) << m;
    EXPECT_NE(m.find(std::to_string(io::kMaxGeometryInputBytes + 1) + " bytes"), std::string::npos) << m;
    EXPECT_NE(m.find(std::to_string(io::kMaxGeometryInputBytes) + "-byte limit"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace hula::regress
