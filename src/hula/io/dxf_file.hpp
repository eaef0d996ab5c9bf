// SPDX-License-Identifier: MIT
// DXF files of NURBS curves, read and written through dxflib (Debian's
// libdxflib-dev): each curve is one SPLINE entity (AutoCAD 2000 / AC1015
// group codes: 70 flags, 71 degree, 72–74 counts, 40 knots — the full
// Piegl–Tiller vector —, 10/20/30 control points, 41 weights of a rational
// curve). Reals are written as the shortest text that reads back to the same
// double (dxflib's own writer keeps 16 decimals, which rounds small values), so
// a curve comes back bit for bit. Per curve the file carries its layer (group
// 8, with a LAYER table entry), its colour as a true colour (group 420, with
// the nearest of AutoCAD's seven basic colours in group 62) and its name as
// extended data of the application "HULAHOOPS" (1001, then 1000 name and
// 1070 dimension: 2 for a planar curve written with z = 0), which other
// programs keep and ignore. Reading takes every SPLINE with control points;
// other entities are counted, not refused, and a file with no such SPLINE, a
// binary DXF or a file cut short (no EOF marker) is refused naming the file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::io {

/// One SPLINE entity of a DXF file.
struct DxfCurve {
  /// The curve's name (the HULAHOOPS extended data), or empty.
  std::string name{};
  /// The curve: degree, full knot vector, control points and weights as in the file.
  nurbs::NurbsCurve curve;
  /// The entity's layer. Default "0", the layer every DXF file has.
  std::string layer = "0";
  /// The entity's colour "#rrggbb" (group 420, else one of the seven basic colours of group 62),
  /// or empty when the entity follows its layer's colour.
  std::string colour{};
  /// Where it came from when read: "SPLINE 3" (the third SPLINE of the file). Ignored when writing.
  std::string source{};
};

/// What a DXF file held.
struct DxfReadReport {
  std::vector<DxfCurve> curves;  ///< the SPLINE entities with control points, in file order
  std::size_t skipped = 0;       ///< other entities (lines, arcs, text, splines given by fit points only, …)
  /// One line per entity skipped for a reason worth telling ("SPLINE 2: fit points only"), at most 20.
  std::vector<std::string> warnings;
};

/// Writes curves as a DXF file (AC1015), replaced atomically (io::write_file_atomically), or to
/// standard output for `-`.
/// @param path the output file, or `-`
/// @param curves ≥ 1 curves; a curve of dimension 2 is written with z = 0
/// @throws hula::Error(Errc::InvalidArgument) for no curves (field "curves"), a layer name DXF cannot
///   hold (empty, or with one of <>/\":;?*|=` or a control character; field "layer", index) or a
///   colour not "#rrggbb" (field "colour", index)
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
void write_dxf_file(const std::filesystem::path& path, std::span<const DxfCurve> curves);

/// The text of a DXF file of `curves` (as write_dxf_file writes it).
/// @throws as write_dxf_file, except IoError
[[nodiscard]] std::string dxf_text(std::span<const DxfCurve> curves);

/// Reads the SPLINE entities of an ASCII DXF file (any version that has SPLINE, R13 on).
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be read (io::read_text_file)
/// @throws as parse_dxf, with `path` as the name
[[nodiscard]] DxfReadReport read_dxf_file(const std::filesystem::path& path);

/// Reads the SPLINE entities of DXF text.
/// @param text the file's contents
/// @param name the file's name, for messages
/// @throws hula::Error(Errc::ParseError) naming `name` (field "path"): a binary DXF, text that is not
///   DXF, a file cut short (no "EOF" record), or no SPLINE with control points (the entities it does
///   hold are counted in the message)
/// @throws hula::Error from the NurbsCurve constructor (InvalidKnots, InvalidDegree, InvalidWeight,
///   NonFiniteInput) with the message prefixed by `name` and the SPLINE's number
[[nodiscard]] DxfReadReport parse_dxf(std::string_view text, std::string_view name);

}  // namespace hula::io
