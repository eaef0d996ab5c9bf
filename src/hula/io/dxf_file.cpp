// SPDX-License-Identifier: MIT
#include "hula/io/dxf_file.hpp"

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <dl_writer_ascii.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"

namespace hula::io {
namespace {

// The extended-data application that carries a curve's name and dimension.
constexpr const char* kApp = "HULAHOOPS";

// AutoCAD's seven basic colours (ACI 1–7); 7 draws black on a white page.
constexpr std::array<std::pair<int, int>, 8> kBasicColours{{{1, 0xff0000},
                                                            {2, 0xffff00},
                                                            {3, 0x00ff00},
                                                            {4, 0x00ffff},
                                                            {5, 0x0000ff},
                                                            {6, 0xff00ff},
                                                            {7, 0x000000},
                                                            {7, 0xffffff}}};

// "#rrggbb" → 0xrrggbb, or nullopt.
std::optional<int> parse_colour(const std::string& colour) {
  if (colour.size() != 7 || colour[0] != '#') return std::nullopt;
  int value = 0;
  const auto [end, ec] = std::from_chars(colour.data() + 1, colour.data() + 7, value, 16);
  if (ec != std::errc() || end != colour.data() + 7) return std::nullopt;
  return value;
}

std::string colour_text(int rgb) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%06x", rgb & 0xffffff);
  return buffer;
}

// The basic colour nearest to `rgb` (squared RGB distance): what a reader without true colour shows.
int nearest_basic_colour(int rgb) {
  auto distance = [rgb](int other) {
    int d = 0;
    for (int shift : {0, 8, 16}) {
      const int a = (rgb >> shift) & 0xff, b = (other >> shift) & 0xff;
      d += (a - b) * (a - b);
    }
    return d;
  };
  int best = 7, best_distance = distance(0x000000);
  for (const auto& [aci, value] : kBasicColours) {
    if (distance(value) < best_distance) {
      best = aci;
      best_distance = distance(value);
    }
  }
  return best;
}

// A layer name AutoCAD accepts: non-empty, no control character and none of <>/\":;?*|=`.
bool valid_layer(const std::string& layer) {
  if (layer.empty()) return false;
  return std::none_of(layer.begin(), layer.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20 || std::string_view("<>/\\\":;?*|=`").find(c) != std::string_view::npos;
  });
}

// dxflib's DL_WriterA, writing into memory (the file is then replaced atomically by the io policy)
// and printing reals as the shortest text that reads back to the same double: dxflib's own
// "%.16lf" keeps 16 decimals, so 1.2345678901234567e-5 would lose five significant digits.
class MemoryWriter : public DL_WriterA {
 public:
  MemoryWriter() : DL_WriterA("/dev/null", DL_Codes::AC1015) {}
  void dxfReal(int gc, double value) const override {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, ec == std::errc() ? end : buffer);
    // DXF readers expect a decimal point or an exponent in a real.
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    dxfString(gc, text);
  }
  void dxfInt(int gc, int value) const override { dxfString(gc, std::to_string(value)); }
  void dxfHex(int gc, int value) const override {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%X", static_cast<unsigned>(value));
    dxfString(gc, buffer);
  }
  void dxfString(int gc, const char* value) const override { dxfString(gc, std::string(value)); }
  void dxfString(int gc, const std::string& value) const override {
    char code[8];
    std::snprintf(code, sizeof code, "%3d", gc);
    out_ << code << '\n' << value << '\n';
  }
  [[nodiscard]] std::string text() const { return out_.str(); }

 private:
  mutable std::ostringstream out_;
};

void validate(std::span<const DxfCurve> curves) {
  if (curves.empty()) throw Error(Errc::InvalidArgument, "no curves to write as DXF", {.field = "curves"});
  for (std::size_t i = 0; i < curves.size(); ++i) {
    if (!valid_layer(curves[i].layer))
      throw Error(Errc::InvalidArgument,
                  "curves[" + std::to_string(i) + "].layer = \"" + curves[i].layer +
                      "\" is not a DXF layer name (empty, or a control character or one of <>/\\\":;?*|=`)",
                  {.field = "layer", .index = i});
    if (!curves[i].colour.empty() && !parse_colour(curves[i].colour))
      throw Error(Errc::InvalidArgument,
                  "curves[" + std::to_string(i) + "].colour = \"" + curves[i].colour + "\" is not \"#rrggbb\"",
                  {.field = "colour", .index = i});
  }
}

void write_spline(DL_Dxf& dxf, MemoryWriter& w, const DxfCurve& c) {
  const nurbs::NurbsCurve& curve = c.curve;
  const auto points = curve.control_points();
  const auto weights = curve.weights();
  const auto knots = curve.knots().values();
  const bool planar =
      curve.dimension() == 2 || std::all_of(points.begin(), points.end(), [](const Vec3& p) { return p[2] == 0.0; });
  const std::optional<int> rgb = c.colour.empty() ? std::nullopt : parse_colour(c.colour);
  // Colour 256 = BYLAYER; with a true colour (420), the nearest basic colour for older readers.
  // value_or, not *rgb: GCC 12 at -O2 takes the optional's value for "maybe uninitialized" once this file
  // shares a unity batch (HULA_UNITY_BUILD).
  const int true_colour = rgb.value_or(-1);
  const DL_Attributes attributes(c.layer, rgb ? nearest_basic_colour(true_colour) : 256, true_colour, -1, "BYLAYER");
  const int flags = (planar ? 8 : 0) | (curve.is_rational() ? 4 : 0);
  DL_SplineData data(curve.degree(), static_cast<int>(knots.size()), static_cast<int>(points.size()), 0, flags);
  dxf.writeSpline(w, data, attributes);
  for (double k : knots) dxf.writeKnot(w, DL_KnotData(k));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double weight = curve.is_rational() ? weights[i] : 1.0;
    dxf.writeControlPoint(w, DL_ControlPointData(points[i][0], points[i][1], points[i][2], weight));
    if (curve.is_rational()) w.dxfReal(41, weight);
  }
  w.dxfString(1001, kApp);
  w.dxfString(1000, c.name);
  w.dxfInt(1070, curve.dimension());
}

// The reader: collects SPLINE entities with their knots, control points, weights, attributes and
// HULAHOOPS extended data; counts every other entity.
class Reader : public DL_CreationAdapter {
 public:
  explicit Reader(std::string name) : name_(std::move(name)) {}

  void addSpline(const DL_SplineData& data) override {
    finish();
    ++splines_;
    spline_ = Pending{data.degree, data.nControl, data.nFit, getAttributes(), std::move(xdata_), {}, {}, {}};
    xdata_ = {};
  }
  void addControlPoint(const DL_ControlPointData& p) override {
    if (spline_) {
      spline_->points.push_back({p.x, p.y, p.z});
      spline_->weights.push_back(p.w);
    }
  }
  void addKnot(const DL_KnotData& k) override {
    if (spline_) spline_->knots.push_back(k.k);
  }
  void addXDataApp(const std::string& app) override {
    xdata_ = {};
    xdata_.ours = app == kApp;
  }
  void addXDataString(int code, const std::string& value) override {
    if (xdata_.ours && code == 1000 && !xdata_.name) xdata_.name = value;
  }
  void addXDataInt(int code, int value) override {
    if (xdata_.ours && code == 1070 && !xdata_.dimension) xdata_.dimension = value;
  }
  // Every other entity (its extended data, if any, is not a curve's).
  void addPoint(const DL_PointData&) override { other("POINT"); }
  void addLine(const DL_LineData&) override { other("LINE"); }
  void addXLine(const DL_XLineData&) override { other("XLINE"); }
  void addRay(const DL_RayData&) override { other("RAY"); }
  void addArc(const DL_ArcData&) override { other("ARC"); }
  void addCircle(const DL_CircleData&) override { other("CIRCLE"); }
  void addEllipse(const DL_EllipseData&) override { other("ELLIPSE"); }
  void addPolyline(const DL_PolylineData&) override { other("POLYLINE"); }
  void addInsert(const DL_InsertData&) override { other("INSERT"); }
  void addTrace(const DL_TraceData&) override { other("TRACE"); }
  void add3dFace(const DL_3dFaceData&) override { other("3DFACE"); }
  void addSolid(const DL_SolidData&) override { other("SOLID"); }
  void addMText(const DL_MTextData&) override { other("MTEXT"); }
  void addText(const DL_TextData&) override { other("TEXT"); }
  void addLeader(const DL_LeaderData&) override { other("LEADER"); }
  void addHatch(const DL_HatchData&) override { other("HATCH"); }
  void addImage(const DL_ImageData&) override { other("IMAGE"); }
  void addLayer(const DL_LayerData&) override { xdata_ = {}; }

  DxfReadReport finish_all() {
    finish();
    return std::move(report_);
  }
  [[nodiscard]] const std::map<std::string, std::size_t>& others() const { return others_; }

 private:
  struct XData {
    bool ours = false;
    std::optional<std::string> name;
    std::optional<int> dimension;
  };
  struct Pending {
    unsigned degree, controls, fits;
    DL_Attributes attributes;
    XData xdata;
    std::vector<Vec3> points;
    std::vector<double> weights;
    std::vector<double> knots;
  };

  void other(const char* type) {
    finish();
    xdata_ = {};
    ++report_.skipped;
    ++others_[type];
  }

  void warn(std::string text) {
    if (report_.warnings.size() < 20) report_.warnings.push_back(std::move(text));
  }

  void finish() {
    if (!spline_) return;
    Pending s = std::move(*spline_);
    spline_.reset();
    const std::string where = "SPLINE " + std::to_string(splines_);
    if (s.points.empty()) {
      ++report_.skipped;
      warn(where + (s.fits > 0 ? ": given by fit points only (no control points), not read" : ": no control points"));
      return;
    }
    const bool rational = std::any_of(s.weights.begin(), s.weights.end(), [](double w) { return w != 1.0; });
    const int dimension = s.xdata.dimension == 2 && std::all_of(s.points.begin(), s.points.end(),
                                                                [](const Vec3& p) { return p[2] == 0.0; })
                              ? 2
                              : 3;
    DxfCurve c{s.xdata.name.value_or(""),
               [&] {
                 try {
                   return nurbs::NurbsCurve(static_cast<int>(s.degree), s.knots, s.points,
                                            rational ? s.weights : std::vector<double>{}, dimension);
                 } catch (const Error& e) {
                   throw Error(e.code(), name_ + ": " + where + ": " + e.message(), e.where());
                 }
               }(),
               s.attributes.getLayer().empty() ? std::string("0") : s.attributes.getLayer(),
               {},
               where};
    const int aci = s.attributes.getColor();
    if (s.attributes.getColor24() >= 0) {
      c.colour = colour_text(s.attributes.getColor24());
    } else if (aci >= 1 && aci <= 7) {
      c.colour = colour_text(kBasicColours[static_cast<std::size_t>(aci - 1)].second);
    }
    report_.curves.push_back(std::move(c));
  }

  std::string name_;
  std::size_t splines_ = 0;
  std::optional<Pending> spline_;
  XData xdata_;
  DxfReadReport report_;
  std::map<std::string, std::size_t> others_;
};

[[noreturn]] void refuse(std::string_view name, const std::string& why) {
  throw Error(Errc::ParseError, "cannot read DXF '" + std::string(name) + "': " + why, {.field = "path"});
}

// The non-blank lines of the text, trimmed (DXF values are one per line; CR LF is common).
std::vector<std::string_view> last_lines(std::string_view text, std::size_t count) {
  std::vector<std::string_view> out;
  std::size_t end = text.size();
  while (out.size() < count && end > 0) {
    const std::size_t start = text.rfind('\n', end - 1);
    const std::size_t from = start == std::string_view::npos ? 0 : start + 1;
    std::string_view line = text.substr(from, end - from);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (!line.empty()) out.push_back(line);
    if (start == std::string_view::npos) break;
    end = start;
  }
  return out;
}

}  // namespace

std::string dxf_text(std::span<const DxfCurve> curves) {
  validate(curves);
  DL_Dxf dxf;
  MemoryWriter writer;
  // The sections and tables AutoCAD expects of an AC1015 file, in dxflib's documented order.
  dxf.writeHeader(writer);
  writer.sectionEnd();
  writer.sectionTables();
  dxf.writeVPort(writer);
  writer.tableLinetypes(3);
  dxf.writeLinetype(writer, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(writer, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(writer, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  writer.tableEnd();
  std::set<std::string> layers{"0"};
  for (const auto& c : curves) layers.insert(c.layer);
  writer.tableLayers(static_cast<int>(layers.size()));
  for (const auto& layer : layers)
    dxf.writeLayer(writer, DL_LayerData(layer, 0), DL_Attributes("", 7, 0x000000, -1, "CONTINUOUS"));
  writer.tableEnd();
  writer.tableStyle(1);
  dxf.writeStyle(writer, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  writer.tableEnd();
  dxf.writeView(writer);
  dxf.writeUcs(writer);
  writer.tableAppid(2);
  dxf.writeAppid(writer, "ACAD");
  dxf.writeAppid(writer, kApp);
  writer.tableEnd();
  dxf.writeDimStyle(writer, 1.0, 1.0, 1.0, 1.0, 1.0);
  dxf.writeBlockRecord(writer);
  writer.tableEnd();
  writer.sectionEnd();
  writer.sectionBlocks();
  for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(writer, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(writer, block);
  }
  writer.sectionEnd();
  writer.sectionEntities();
  for (const auto& c : curves) write_spline(dxf, writer, c);
  writer.sectionEnd();
  dxf.writeObjects(writer);
  dxf.writeObjectsEnd(writer);
  writer.dxfEOF();
  return writer.text();
}

void write_dxf_file(const std::filesystem::path& path, std::span<const DxfCurve> curves) {
  check_output_path(path, "path");
  write_file_atomically(path, dxf_text(curves));
}

// dxflib allocates (and zeroes) an array for the count an entity states before reading its elements: a SPLINE's
// knots (group code 72), control points with their weights (73) and fit points (74), a LWPOLYLINE's vertices
// (90), a LEADER's vertices (76). A count above the elements that follow in the entity is refused here, before
// dxflib sees it: a few hostile bytes must not make it allocate gigabytes.
void check_counts(std::string_view text, std::string_view name) {
  struct Count {
    const char* entity;
    int count_code;
    int element_code;
    const char* what;
  };
  static constexpr Count kCounts[] = {{"SPLINE", 72, 40, "knots"},
                                      {"SPLINE", 73, 10, "control points"},
                                      {"SPLINE", 74, 11, "fit points"},
                                      {"LWPOLYLINE", 90, 10, "vertices"},
                                      {"LEADER", 76, 10, "vertices"}};
  struct Claim {
    const Count* count;
    long long value;
    std::size_t line;
  };
  std::string entity;
  std::vector<Claim> claims;
  std::map<int, long long> elements;
  const auto settle = [&] {
    for (const Claim& c : claims)
      if (c.value > elements[c.count->element_code])
        refuse(name, "line " + std::to_string(c.line) + ": the " + std::string(c.count->entity) + " states " +
                         std::to_string(c.value) + " " + c.count->what + " (group code " +
                         std::to_string(c.count->count_code) + ") but holds " +
                         std::to_string(elements[c.count->element_code]));
    claims.clear();
    elements.clear();
  };
  const auto trimmed = [](std::string_view line) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    return line;
  };
  std::size_t at = 0, line = 0;
  const auto next_line = [&]() -> std::optional<std::string_view> {
    if (at >= text.size()) return std::nullopt;
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view l = text.substr(at, end - at);
    at = end + 1;
    ++line;
    return l;
  };
  while (const auto code_line = next_line()) {
    const auto value_line = next_line();
    if (!value_line) break;
    const std::string code_text(trimmed(*code_line));
    char* end = nullptr;
    const long code = std::strtol(code_text.c_str(), &end, 10);
    if (end == code_text.c_str()) continue;  // not a group code: dxflib's to judge
    if (code == 0) {
      settle();
      entity = std::string(trimmed(*value_line));
      continue;
    }
    for (const Count& c : kCounts) {
      if (entity != c.entity) continue;
      if (code == c.element_code) ++elements[code];
      if (code == c.count_code) {
        const std::string value(trimmed(*value_line));
        claims.push_back({&c, std::strtoll(value.c_str(), nullptr, 10), line});
      }
    }
  }
  settle();
}

DxfReadReport parse_dxf(std::string_view text, std::string_view name) {
  if (text.rfind("AutoCAD Binary DXF", 0) == 0) refuse(name, "a binary DXF file (only ASCII DXF is read)");
  const auto first = last_lines(text.substr(0, std::min<std::size_t>(text.size(), 4096)), SIZE_MAX);
  // The first record of a DXF file is a group code: 0 (SECTION) or 999 (a comment).
  if (first.empty() || (first.back() != "0" && first.back() != "999"))
    refuse(name, "not a DXF file (it does not start with a group code 0 SECTION or 999)");
  const auto tail = last_lines(text, 2);
  if (tail.size() < 2 || tail[0] != "EOF" || tail[1] != "0")
    refuse(name, "the file is cut short (it does not end with the record 0 EOF)");
  check_counts(text, name);
  Reader reader{std::string(name)};
  DL_Dxf dxf;
  std::istringstream stream{std::string(text)};
  if (!dxf.in(stream, &reader)) refuse(name, "dxflib could not read it");
  DxfReadReport report = reader.finish_all();
  if (report.curves.empty()) {
    std::string held;
    for (const auto& [type, n] : reader.others()) held += (held.empty() ? "" : ", ") + std::to_string(n) + " " + type;
    refuse(name, "it holds no SPLINE entity with control points" +
                     (held.empty() ? std::string(" (no entities at all)") : " (it holds " + held + ")") +
                     (report.warnings.empty() ? std::string() : "; " + report.warnings.front()));
  }
  return report;
}

DxfReadReport read_dxf_file(const std::filesystem::path& path) {
  return parse_dxf(read_text_file(path), path.string());
}

}  // namespace hula::io
