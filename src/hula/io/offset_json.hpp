// SPDX-License-Identifier: MIT
// The JSON shape of offset curves (diffgeom/offset.hpp), written by `hula
// offset`, `hula helical-offset`, `hula orthotomic`, `hula polar` and the
// Python binding alike (docs/formats.md "Offset and mapped curves").
#pragma once

#include <string_view>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/mapping.hpp"
#include "hula/diffgeom/offset.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::io {

/// {"distance", "tolerance", "exact", "deviation", "raw": curve file, "cusps": [t, …], "loops": [{"s", "t",
/// "point", "angle"}], "trimmed": [{"spans": [[t0, t1], …], "closed", "curve": curve file}]}; points as [x, y].
[[nodiscard]] Json planar_offset_to_json(const diffgeom::PlanarOffset& offset, double distance,
                                         const diffgeom::OffsetOptions& options);

/// The one answer of `hula offset` and hulahoops.offset: diffgeom::planar_offset encoded by planar_offset_to_json.
/// @throws hula::Error as diffgeom::planar_offset
[[nodiscard]] Json offset_answer(const curve::Curve& curve, double distance,
                                 const diffgeom::OffsetOptions& options = {});

/// {"frame", "distance", "twist", "tolerance", "exact", "deviation", "plane_normal"? ([x, y, z], a plane curve's
/// Bishop frame only), "curve": curve file (a law curve when exact)}.
[[nodiscard]] Json helical_offset_to_json(const diffgeom::HelicalOffset& offset, std::string_view distance,
                                          std::string_view twist, const diffgeom::HelicalOffsetOptions& options);

/// The one answer of `hula helical-offset` and hulahoops.helical_offset: diffgeom::helical_offset encoded by
/// helical_offset_to_json.
/// @throws hula::Error as diffgeom::helical_offset
[[nodiscard]] Json helical_offset_answer(const curve::Curve& curve, std::string_view distance, std::string_view twist,
                                         const diffgeom::HelicalOffsetOptions& options = {});

/// {"mapping": "orthotomic" | "polar", "exact", "deviation", "tolerance", "curve": curve file} plus the mapping's
/// inputs ("pole", "k" or "centre", "radius").
[[nodiscard]] Json mapped_curve_to_json(const diffgeom::MappedCurve& mapped, const Json& inputs,
                                        const diffgeom::MappingOptions& options);

/// The one answer of `hula orthotomic` and hulahoops.orthotomic: diffgeom::orthotomic, encoded.
/// @throws hula::Error as diffgeom::orthotomic
[[nodiscard]] Json orthotomic_answer(const curve::Curve& curve, const Vec3& pole, double k,
                                     const diffgeom::MappingOptions& options = {});

/// The one answer of `hula polar` and hulahoops.polar_map: diffgeom::polar_map, encoded.
/// @throws hula::Error as diffgeom::polar_map
[[nodiscard]] Json polar_answer(const curve::Curve& curve, const Vec3& centre, double radius,
                                const diffgeom::MappingOptions& options = {});

}  // namespace hula::io
