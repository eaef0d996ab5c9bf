// SPDX-License-Identifier: MIT
// Tests of the "fair-knots" study reader: defaults, the resolved document
// round-trips, every bad member is refused with its name before any run, and
// the energy-map CSV.
#include "hula/io/fair_knots_study_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "hula/testing/expect_error.hpp"

namespace hula::io {
namespace {

using namespace studies;  // NOLINT(google-build-using-namespace)

FairKnotsStudy read(const std::string& members) {
  const std::string text =
      R"({"format": "hula-study", "version": 1, "study": "fair-knots", "points": [[0, 0], [40, 25], [80, -25], [120, 0]])" +
      members + "}";
  return fair_knots_study_from_json(parse_study_json(text, "fair-knots"));
}

// checks: the defaults (natural ends, bending, both methods, real GA 50 x 50) and the header's seed reach the GA
TEST(StudiesFairKnotsStudy, Defaults) {
  const FairKnotsStudy s = read(R"(, "seed": 9)");
  EXPECT_EQ(s.setup.points.size(), 4u);
  EXPECT_EQ(s.setup.dimension, 2);
  EXPECT_EQ(s.setup.start.kind, nurbs::EndCondition::Kind::Natural);
  EXPECT_EQ(s.setup.energy, FairingEnergy::Bending);
  EXPECT_EQ(s.method, FairingMethod::Both);
  EXPECT_EQ(s.ga.algorithm, FairingGa::Real);
  EXPECT_EQ(s.ga.real.population, 50u);
  EXPECT_EQ(s.ga.real.run.stop.generations, 50u);
  EXPECT_EQ(s.ga.real.run.seed, 9u);
  EXPECT_FALSE(s.map.has_value());
  EXPECT_FALSE(s.parameters.has_value());
}

// checks: the resolved document reads back to the same study (a run can be repeated exactly)
TEST(StudiesFairKnotsStudy, ResolvedDocumentRoundTrips) {
  const FairKnotsStudy s = read(
      R"(, "energy": "variation", "method": "ga", "start": "bessel", "ga": {"algorithm": "binary", "population": 20,
         "generations": 7, "boost_end": 8, "max_recentres": 2}, "deterministic": {"x_tolerance": 1e-9},
         "map": {"knots": [1, 2], "grid": 11, "sections": [0.2]}, "parameters": [0, 0.3, 0.7, 1])");
  const Json resolved = fair_knots_study_to_json(s);
  const FairKnotsStudy t = fair_knots_study_from_json(parse_study_json(resolved.dump(), "fair-knots"));
  EXPECT_EQ(fair_knots_study_to_json(t), resolved);
  EXPECT_EQ(t.setup.energy, FairingEnergy::Variation);
  EXPECT_EQ(t.method, FairingMethod::Ga);
  EXPECT_EQ(t.setup.start.kind, nurbs::EndCondition::Kind::Bessel);
  EXPECT_EQ(t.ga.algorithm, FairingGa::Binary);
  EXPECT_EQ(t.ga.binary.population, 20u);
  EXPECT_EQ(t.ga.binary.run.stop.generations, 7u);
  EXPECT_EQ(t.ga.binary.boost_end, 8.0);
  EXPECT_EQ(t.ga.max_recentres, 2u);
  EXPECT_EQ(t.deterministic.x_tolerance, 1e-9);
  ASSERT_TRUE(t.map.has_value());
  EXPECT_EQ(t.map->grid, 11u);
  EXPECT_EQ(t.sections, std::vector<double>{0.2});
  ASSERT_TRUE(t.parameters.has_value());
  EXPECT_EQ((*t.parameters)[2], 0.7);
}

// checks: bad study files are refused before any run, naming the member at fault
TEST(StudiesFairKnotsStudy, BadFilesNameTheMember) {
  HULA_EXPECT_ERROR(read(R"(, "knots": [0, 1])"), Errc::ParseError, "knots");
  HULA_EXPECT_ERROR(read(R"(, "ga": {"populaton": 10})"), Errc::ParseError, "ga.populaton");
  HULA_EXPECT_ERROR(read(R"(, "energy": "strain")"), Errc::ParseError, "energy = \"strain\"");
  HULA_EXPECT_ERROR(read(R"(, "method": "annealing")"), Errc::ParseError, "method = \"annealing\"");
  HULA_EXPECT_ERROR(read(R"(, "ga": {"algorithm": "cmaes"})"), Errc::ParseError, "ga.algorithm");
  HULA_EXPECT_ERROR(read(R"(, "ga": {"population": 7})"), Errc::InvalidOption, "ga:");
  HULA_EXPECT_ERROR(read(R"(, "ga": {"recentre_fraction": 0.7})"), Errc::InvalidOption, "recentre_fraction = 0.7");
  HULA_EXPECT_ERROR(read(R"(, "deterministic": {"initial_step": 0})"), Errc::InvalidOption, "initial_step = 0");
  HULA_EXPECT_ERROR(read(R"(, "map": {"knots": [0, 2]})"), Errc::InvalidOption, "map.knots[0] = 0");
  HULA_EXPECT_ERROR(read(R"(, "map": {"knots": [1, 2, 3]})"), Errc::ParseError, "map.knots");
  HULA_EXPECT_ERROR(read(R"(, "map": {"grid": 1})"), Errc::ParseError, "map.grid");
  HULA_EXPECT_ERROR(read(R"(, "map": {"sections": [0.2, 1.2]})"), Errc::InvalidOption,
                    "map.sections[1]: section k1 = 1.2 is outside");
  HULA_EXPECT_ERROR(read(R"(, "parameters": [0, 0.7, 0.5, 1])"), Errc::InvalidArgument, "parameters[2] = 0.5");
  HULA_EXPECT_ERROR(read(R"(, "parameters": [0, 0.5, 1])"), Errc::InvalidArgument, "3 values for 4 points");
  HULA_EXPECT_ERROR(read(R"(, "start": "free")"), Errc::ParseError, "start");
  const std::string two =
      R"({"format": "hula-study", "version": 1, "study": "fair-knots", "points": [[0, 0], [1, 0]]})";
  HULA_EXPECT_ERROR(fair_knots_study_from_json(parse_study_json(two, "fair-knots")), Errc::TooFewPoints,
                    "at least 3 points");
  const std::string dup =
      R"({"format": "hula-study", "version": 1, "study": "fair-knots", "points": [[0, 0], [1, 0], [1, 0]]})";
  HULA_EXPECT_ERROR(fair_knots_study_from_json(parse_study_json(dup, "fair-knots")), Errc::CoincidentPoints, "");
}

// checks: the CSV has one row per node, k1 fastest, and empty energies where the map is NaN
TEST(StudiesFairKnotsStudy, EnergyMapCsv) {
  EnergyMap m;
  m.k1 = {0.25, 0.5};
  m.k2 = {0.5, 0.75};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.energy = {0.125, nan, 1.5, 2.0};
  EXPECT_EQ(energy_map_csv(m), "k1,k2,energy\n0.25,0.5,0.125\n0.5,0.5,\n0.25,0.75,1.5\n0.5,0.75,2\n");
}

}  // namespace
}  // namespace hula::io
