// SPDX-License-Identifier: MIT
// Readers of the editing study kinds: defaults and values as documented in
// docs/formats.md, and every refusal naming its member before any work.
#include "hula/io/editing_study_file.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "hula/testing/expect_error.hpp"

namespace hula::io {
namespace {

const std::string kCurve = R"({"kind": "interpolated", "points": [[0, 0, 0], [1, 1, 1], [2, 0, 2], [3, 1, 0]]})";
const std::string kFlat = R"({"kind": "interpolated", "points": [[0, 0, 0], [1, 1, 0], [2, 0, 0], [3, 1, 0]]})";

StudyDocument doc(const std::string& kind, const std::string& members) {
  return parse_study_json(R"({"format": "hula-study", "version": 1, "study": ")" + kind + "\", " + members + "}", kind);
}

// checks the projection members and their defaults are read as documented.
TEST(EditingStudy, FinCompoundProjectionMembers) {
  const FinCompoundStudy s = read_fin_compound_study(
      doc("fin-compound", R"("method": "projection", "plane": "yz", "scale": 0.25, "curve": )" + kCurve));
  EXPECT_EQ(s.method, FinCompoundMethod::Projection);
  EXPECT_EQ(s.projection.plane, diffgeom::Plane::YZ);
  EXPECT_EQ(s.projection.scale, 0.25);
  EXPECT_EQ(s.projection.samples, 1001);
  EXPECT_EQ(s.projection.fit.tolerance, 1e-9);
  EXPECT_TRUE(s.curve.has_value());
  EXPECT_FALSE(s.compound.has_value());
  const FinCompoundStudy c = read_fin_compound_study(
      doc("fin-compound", R"("method": "combescure", "c": 0.3, "samples": 11, "compound": )" + kCurve));
  EXPECT_EQ(c.combescure.c, 0.3);
  EXPECT_EQ(c.combescure.samples, 11);
  EXPECT_TRUE(c.compound.has_value());
}

// checks the fin-compound refusals name the member.
TEST(EditingStudy, FinCompoundRefusals) {
  HULA_EXPECT_ERROR(read_fin_compound_study(doc("fin-compound", R"("method": "offset", "curve": )" + kCurve)),
                    Errc::ParseError, "method = \"offset\"");
  HULA_EXPECT_ERROR(read_fin_compound_study(
                        doc("fin-compound", R"("method": "projection", "plane": "xy", "c": 1, "curve": )" + kCurve)),
                    Errc::ParseError, "c: not a member of a \"projection\"");
  HULA_EXPECT_ERROR(
      read_fin_compound_study(doc("fin-compound", R"("method": "combescure", "plane": "xy", "curve": )" + kCurve)),
      Errc::ParseError, "plane: not a member of a \"combescure\"");
  HULA_EXPECT_ERROR(read_fin_compound_study(doc(
                        "fin-compound", R"("method": "projection", "plane": "xy", "samples": 1, "curve": )" + kCurve)),
                    Errc::ParseError, "samples");
  HULA_EXPECT_ERROR(
      read_fin_compound_study(
          doc("fin-compound", R"("method": "projection", "plane": "xy", "min_stretch": 2, "curve": )" + kCurve)),
      Errc::InvalidOption, "min_stretch");
  HULA_EXPECT_ERROR(read_fin_compound_study(doc("fin-compound", R"("method": "projection", "curve": )" + kCurve)),
                    Errc::ParseError, "plane");
  HULA_EXPECT_ERROR(read_fin_compound_study(
                        doc("fin-compound", R"("method": "projection", "plane": "xy", "curve": {"kind": "nurbs"})")),
                    Errc::ParseError, "curve: ");
}

// checks the edit-projection reader accepts a planar edit and refuses a non-planar one by control point.
TEST(EditingStudy, EditProjection) {
  const EditProjectionStudy s = read_edit_projection_study(
      doc("edit-projection", R"("plane": "xy", "curve": )" + kCurve + R"(, "edited": )" + kFlat));
  EXPECT_EQ(s.plane, diffgeom::Plane::XY);
  HULA_EXPECT_ERROR(read_edit_projection_study(
                        doc("edit-projection", R"("plane": "zx", "curve": )" + kCurve + R"(, "edited": )" + kFlat)),
                    Errc::InvalidArgument, "edited is not planar in zx: control_points[");
}

// checks the hermite reader: degrees become radians, defaults, and the refusals name the edit member.
TEST(EditingStudy, Hermite) {
  const std::string spline = R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]]})";
  const HermiteStudy s = read_hermite_study(
      doc("hermite", R"("spline": )" + spline + R"(, "edits": [{"knot": 1, "tangent_angle": 90, "normal_scale": 2}])"));
  ASSERT_EQ(s.edits.size(), 1u);
  EXPECT_DOUBLE_EQ(s.edits[0].tangent_angle, std::numbers::pi / 2.0);
  EXPECT_EQ(s.edits[0].normal_scale, 2.0);
  EXPECT_EQ(s.edits[0].tangent_scale, 1.0);
  EXPECT_EQ(s.options.rebuild, studies::HermiteRebuild::Quintic);
  EXPECT_EQ(s.options.interpolation.dimension, 2);
  HULA_EXPECT_ERROR(
      read_hermite_study(doc("hermite", R"("spline": {"kind": "bezier", "control_points": [[0, 0], [1, 1]]})")),
      Errc::ParseError, "must be an \"interpolated\" curve document");
  HULA_EXPECT_ERROR(read_hermite_study(doc("hermite", R"("spline": )" + spline + R"(, "rebuild": "septic")")),
                    Errc::ParseError, "rebuild = \"septic\"");
  HULA_EXPECT_ERROR(read_hermite_study(doc("hermite", R"("spline": )" + spline + R"(, "edits": [{"knot": 3}])")),
                    Errc::InvalidArgument, "edits[0].knot = 3");
  HULA_EXPECT_ERROR(
      read_hermite_study(doc("hermite", R"("spline": )" + spline + R"(, "edits": [{"tangent_scale": 2}])")),
      Errc::ParseError, "knot");
}

}  // namespace
}  // namespace hula::io
