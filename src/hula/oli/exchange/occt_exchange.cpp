// SPDX-License-Identifier: MIT
// STEP: STEPControl_Writer in GeometricCurveSet mode (one GEOMETRIC_CURVE_SET
// of B-spline curves, no topology), the schema from "write.step.schema", the
// curve names set on the written StepGeom_BSplineCurve entities, the maximum
// deviation in FILE_DESCRIPTION and as the model uncertainty
// ("write.precision.val"). IGES: each curve through GeomToIGES_GeomCurve
// (entity 126), its label and a Name property (406/15), version 11 (5.3) and
// the resolution (global field 19) set to the maximum deviation.
// Reading: the file's header is checked first (so a file that is not STEP or
// IGES at all is refused before OCCT parses it), then every root is
// transferred and each distinct edge's 3-D curve becomes a NURBS; the
// failures OCCT's reader records (presentation entities it cannot read,
// unresolved references) become the report's warnings, never a refusal of the
// geometry it did transfer.
#include "hula/oli/exchange/occt_exchange.hpp"

#include <unistd.h>

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <GeomToIGES_GeomCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Hyperbola.hxx>
#include <Geom_Line.hxx>
#include <Geom_Parabola.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESAppli_LevelFunction.hxx>
#include <IGESBasic_Name.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESData_IGESWriter.hxx>
#include <IGESData_LevelListEntity.hxx>
#include <IGESGraph_Color.hxx>
#include <IGESSelect_WorkLibrary.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_EntityIterator.hxx>
#include <Interface_HArray1OfHAsciiString.hxx>
#include <Interface_Static.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <StepGeom_BSplineCurve.hxx>
#include <StepGeom_TrimmedCurve.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <StepShape_EdgeCurve.hxx>
#include <TColStd_HSequenceOfExtendedString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_LayerTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/oli/kernel/occt_convert.hpp"

namespace hula::oli::detail {
namespace {

namespace fs = std::filesystem;

// The deviation rounded up to 3 significant digits: what a header field printed with few digits
// keeps, still a bound (never below the true maximum deviation).
double rounded_up(double deviation) {
  if (!(deviation > 0.0)) return deviation;
  const double unit = std::pow(10.0, std::floor(std::log10(deviation)) - 2.0);
  const double up = std::ceil(deviation / unit) * unit;
  return up >= deviation ? up : std::nextafter(up, HUGE_VAL);
}

// Every failure OCCT recorded while reading or transferring the file, one line each ("entity #5:
// Parameter n0.2 (curve_font) not an Entity"): at most kMaxWarnings of them, then how many more.
// IGES entities are named by their directory-entry line.
constexpr std::size_t kMaxWarnings = 20;
std::vector<std::string> failures(const Handle(XSControl_WorkSession) & session, bool iges) {
  std::vector<std::string> out;
  std::size_t more = 0;
  const Interface_CheckIterator checks = session->ModelCheckList(Standard_True);
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    if (!check->HasFailed()) continue;
    if (out.size() == kMaxWarnings) {
      ++more;
      continue;
    }
    const int n = checks.Number();
    const std::string where = n <= 0 ? std::string("the file")
                              : iges ? "DE " + std::to_string(2 * n - 1)
                                     : "entity #" + std::to_string(n);
    out.push_back(where + ": " + check->CFail(1, Standard_True));
  }
  if (more > 0) out.push_back("and " + std::to_string(more) + " more entities with failures");
  return out;
}

std::string deviation_note(double max_deviation) {
  return "HulaHoops: maximum deviation of NURBS approximations from their law or natural-equation curves: " +
         format_number(max_deviation) + " model units";
}

[[noreturn]] void write_failed(const fs::path& path, const std::string& why) {
  throw Error(Errc::IoError, "cannot write '" + path.string() + "': " + why, {.field = "path"});
}

// Reals with 17 significant digits and always an exponent (so always a decimal point, as STEP requires).
constexpr const char* kRealFormat = "%.16E";

// Prints a file through an OCCT writer's Print(ostream&) into `out` (io::OutputFile: the output-path
// policy, a temporary file renamed over the target on commit, checked writes).
template <class Print>
void print_file(io::OutputFile& out, const fs::path& path, Print&& print) {
  if (!print(out.stream())) write_failed(path, "the Open CASCADE writer failed");
}

// "#rrggbb" as an sRGB colour, or nullopt for an empty or malformed text.
std::optional<Quantity_Color> occt_colour(const std::string& colour) {
  if (colour.size() != 7 || colour[0] != '#') return std::nullopt;
  unsigned rgb = 0;
  if (std::sscanf(colour.c_str() + 1, "%6x", &rgb) != 1) return std::nullopt;
  return Quantity_Color(((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0, (rgb & 0xff) / 255.0,
                        Quantity_TOC_sRGB);
}

// The "#rrggbb" of an sRGB colour (each channel rounded to 8 bits).
std::string colour_text(const Quantity_Color& colour) {
  double r = 0.0, g = 0.0, b = 0.0;
  colour.Values(r, g, b, Quantity_TOC_sRGB);
  auto byte = [](double v) { return static_cast<unsigned>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(r), byte(g), byte(b));
  return text;
}

TCollection_ExtendedString utf8(const std::string& text) { return TCollection_ExtendedString(text.c_str(), true); }

std::string utf8(const TCollection_ExtendedString& text) {
  std::string out(static_cast<std::size_t>(text.LengthOfCString()), '\0');
  char* data = out.data();
  out.resize(static_cast<std::size_t>(text.ToUTF8CString(data)));
  return out;
}

// The curves as an XCAF document: one free edge shape per curve, named (its STEP product name), with
// its colour and layer.
Handle(TDocStd_Document) xcaf_document(const ExportRequest& r) {
  Handle(TDocStd_Document) doc = new TDocStd_Document("MDTV-XCAF");
  XCAFApp_Application::GetApplication()->InitDocument(doc);
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  const Handle(XCAFDoc_LayerTool) layers = XCAFDoc_DocumentTool::LayerTool(doc->Main());
  for (const auto& c : r.curves) {
    const TDF_Label label = shapes->AddShape(BRepBuilderAPI_MakeEdge(to_occt(c.curve)).Edge(), Standard_False);
    TDataStd_Name::Set(label, utf8(c.name));
    if (const auto colour = occt_colour(c.colour)) colours->SetColor(label, *colour, XCAFDoc_ColorCurv);
    if (!c.layer.empty()) layers->SetLayer(label, utf8(c.layer));
  }
  return doc;
}

void write_step(const ExportRequest& r, io::OutputFile& file, double max_deviation) {
  STEPControl_Controller::Init();
  Interface_Static::SetCVal("write.step.schema", r.format == ExchangeFormat::StepAp242 ? "AP242DIS" : "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "MM");
  if (max_deviation > 0.0) {
    // The model uncertainty (UNCERTAINTY_MEASURE_WITH_UNIT): mode 2 = the value given here.
    Interface_Static::SetIVal("write.precision.mode", 2);
    Interface_Static::SetRVal("write.precision.val", rounded_up(max_deviation));
  }
  // Through XCAF, so each curve is a product named after it, with its colour (a styled item) and its
  // layer (a presentation layer assignment).
  STEPCAFControl_Writer caf;
  caf.SetNameMode(Standard_True);
  caf.SetColorMode(Standard_True);
  caf.SetLayerMode(Standard_True);
  if (!caf.Transfer(xcaf_document(r), STEPControl_GeometricCurveSet))
    write_failed(r.path, "the STEP translator refused the curves");
  STEPControl_Writer& writer = caf.ChangeWriter();
  // Name the written curves: the writer adds, per edge and in order, one B-spline entity and, in
  // the GEOMETRIC_CURVE_SET, one TRIMMED_CURVE of it (both are named, as other systems read either).
  const Handle(StepData_StepModel) model = writer.Model();
  std::size_t next_bspline = 0, next_trimmed = 0;
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient) entity = model->Value(i);
    std::size_t* next = nullptr;
    if (entity->IsKind(STANDARD_TYPE(StepGeom_BSplineCurve))) next = &next_bspline;
    if (entity->IsKind(STANDARD_TYPE(StepGeom_TrimmedCurve))) next = &next_trimmed;
    if (next == nullptr || *next >= r.curves.size()) continue;
    Handle(StepRepr_RepresentationItem)::DownCast(entity)->SetName(
        new TCollection_HAsciiString(r.curves[(*next)++].name.c_str()));
  }
  if (next_bspline != r.curves.size())
    throw InternalError("STEP export: " + std::to_string(next_bspline) + " B-spline entities for " +
                        std::to_string(r.curves.size()) + " curves");
  APIHeaderSection_MakeHeader header(model);
  Handle(Interface_HArray1OfHAsciiString) description = new Interface_HArray1OfHAsciiString(1, 2);
  description->SetValue(1, new TCollection_HAsciiString("HulaHoops curves"));
  description->SetValue(2, new TCollection_HAsciiString(deviation_note(max_deviation).c_str()));
  header.SetDescription(description);
  header.SetOriginatingSystem(new TCollection_HAsciiString("HulaHoops"));
  // Written by hand rather than by writer.Write, whose reals carry 12 significant digits: 17
  // digits ("%.16E") make every double read back bit-exactly.
  StepData_StepWriter out(model);
  out.FloatWriter().SetFormat(kRealFormat);
  out.SendModel(Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol()));
  print_file(file, r.path, [&](std::ostream& stream) { return out.Print(stream); });
}

void write_iges(const ExportRequest& r, io::OutputFile& file, double max_deviation) {
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);
  const Handle(IGESData_IGESModel) model = writer.Model();
  IGESData_GlobalSection global = model->GlobalSection();
  global.SetIGESVersion(11);  // IGES 5.3
  if (max_deviation > 0.0) global.SetResolution(rounded_up(max_deviation));
  global.SetSystemId(new TCollection_HAsciiString("HulaHoops"));
  model->SetGlobalSection(global);
  model->AddStartLine("HulaHoops curves");
  model->AddStartLine(deviation_note(max_deviation).c_str());
  GeomToIGES_GeomCurve translator;
  translator.SetModel(model);
  std::map<std::string, int> levels;
  for (const auto& c : r.curves) {
    const auto occt = to_occt(c.curve);
    const Handle(IGESData_IGESEntity) entity =
        translator.TransferCurve(occt, occt->FirstParameter(), occt->LastParameter());
    if (entity.IsNull()) write_failed(r.path, "the IGES translator refused curve '" + c.name + "'");
    if (!c.name.empty()) {
      // The directory-entry label holds 8 characters; the Name property holds the whole name.
      entity->SetLabel(new TCollection_HAsciiString(c.name.substr(0, 8).c_str()));
      Handle(IGESBasic_Name) name = new IGESBasic_Name;
      name->Init(1, new TCollection_HAsciiString(c.name.c_str()));
      entity->AddProperty(name);
    }
    if (const auto colour = occt_colour(c.colour)) {
      // A colour definition (entity 314) in percent of full intensity, as IGES 5.3 has it.
      double red = 0.0, green = 0.0, blue = 0.0;
      colour->Values(red, green, blue, Quantity_TOC_sRGB);
      Handle(IGESGraph_Color) definition = new IGESGraph_Color;
      definition->Init(red * 100.0, green * 100.0, blue * 100.0, new TCollection_HAsciiString(c.colour.c_str()));
      entity->InitColor(definition);
    }
    if (!c.layer.empty()) {
      // IGES levels are numbers: each distinct layer is a level (1, 2, ... in order of first use), which
      // other systems show as the layer, and its name a Level Function property (406 form 3) of the entity.
      const int level = levels.try_emplace(c.layer, static_cast<int>(levels.size()) + 1).first->second;
      entity->InitLevel(Handle(IGESData_LevelListEntity)(), level);
      Handle(IGESAppli_LevelFunction) function = new IGESAppli_LevelFunction;
      function->Init(2, 0, new TCollection_HAsciiString(c.layer.c_str()));
      entity->AddProperty(function);
    }
    writer.AddEntity(entity);
  }
  writer.ComputeModel();
  // As for STEP, 17 significant digits instead of the writer's default 9.
  IGESData_IGESWriter out(model);
  out.FloatWriter().SetFormat(kRealFormat);
  out.SendModel(IGESSelect_WorkLibrary::DefineProtocol());
  print_file(file, r.path, [&](std::ostream& stream) { return out.Print(stream); });
}

// The curve types imported, by the basis of a trimmed curve; empty for any other geometry.
std::string curve_type(const Handle(Geom_Curve) & curve) {
  Handle(Geom_Curve) c = curve;
  while (const auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(c)) c = trimmed->BasisCurve();
  if (c->IsKind(STANDARD_TYPE(Geom_BSplineCurve))) return "b-spline";
  if (c->IsKind(STANDARD_TYPE(Geom_BezierCurve))) return "bezier";
  if (c->IsKind(STANDARD_TYPE(Geom_Line))) return "line";
  if (c->IsKind(STANDARD_TYPE(Geom_Circle))) return "circle";
  if (c->IsKind(STANDARD_TYPE(Geom_Ellipse))) return "ellipse";
  if (c->IsKind(STANDARD_TYPE(Geom_Parabola))) return "parabola";
  if (c->IsKind(STANDARD_TYPE(Geom_Hyperbola))) return "hyperbola";
  return {};
}

// The name a STEP file gives the entity an edge came from (itself, or the curve of an edge or
// the basis of a trimmed curve when those are unnamed).
std::string step_name(const Handle(Standard_Transient) & entity) {
  auto name_of = [](const Handle(Standard_Transient) & e) -> std::string {
    const auto item = Handle(StepRepr_RepresentationItem)::DownCast(e);
    return item.IsNull() || item->Name().IsNull() ? std::string() : std::string(item->Name()->ToCString());
  };
  std::string name = name_of(entity);
  if (!name.empty()) return name;
  if (const auto edge = Handle(StepShape_EdgeCurve)::DownCast(entity)) return step_name(edge->EdgeGeometry());
  if (const auto trimmed = Handle(StepGeom_TrimmedCurve)::DownCast(entity)) return name_of(trimmed->BasisCurve());
  return {};
}

// The first bytes of the file, to recognise its format before OCCT parses it.
std::string file_head(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(Errc::IoError, "cannot open '" + path.string() + "'", {.field = "path"});
  std::string head(160, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

[[noreturn]] void not_readable(const fs::path& path, const std::string& why) {
  throw Error(Errc::ParseError, "cannot import '" + path.string() + "': " + why, {.field = "path"});
}

ImportedCurve edge_curve(const TopoDS_Edge& edge, std::string name, std::string source, const std::string& type) {
  double first = 0.0, last = 0.0;
  const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
  // Conics exactly as rational quadratics; B-splines keep their parameterisation on [first, last].
  Handle(Geom_BSplineCurve) bspline = Handle(Geom_BSplineCurve)::DownCast(curve);
  if (bspline.IsNull() || first != bspline->FirstParameter() || last != bspline->LastParameter())
    bspline = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, first, last));
  if (bspline->IsPeriodic()) {
    // OCCT's STEP reader turns a closed B-spline (closed_curve .T., first pole = last pole) into a
    // periodic one; back to the clamped form on the edge's bounds (end knots of multiplicity p + 1),
    // the one the file wrote, poles equal up to the rounding of the end knot insertions.
    bspline = Handle(Geom_BSplineCurve)::DownCast(bspline->Copy());
    bspline->SetNotPeriodic();
    bspline->Segment(first, last);
  }
  return {std::move(name), std::move(source), type, from_occt(bspline, 3)};
}

// The colour and layer XCAF gives `shape` (or, failing that, `root`, the shape it belongs to).
struct Presentation {
  std::string colour;
  std::string layer;
};
Presentation presentation(const Handle(TDocStd_Document) & doc, const TopoDS_Shape& shape, const TopoDS_Shape& root) {
  const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  const Handle(XCAFDoc_LayerTool) layers = XCAFDoc_DocumentTool::LayerTool(doc->Main());
  Presentation out;
  for (const TopoDS_Shape* s : {&shape, &root}) {
    Quantity_Color colour;
    if (out.colour.empty() &&
        (colours->GetColor(*s, XCAFDoc_ColorCurv, colour) || colours->GetColor(*s, XCAFDoc_ColorGen, colour)))
      out.colour = colour_text(colour);
    Handle(TColStd_HSequenceOfExtendedString) names;
    if (out.layer.empty() && layers->GetLayers(*s, names) && !names.IsNull() && names->Length() > 0)
      out.layer = utf8(names->Value(1));
  }
  return out;
}

ImportReport read_step(const fs::path& path) {
  STEPControl_Controller::Init();
  // Through XCAF for the colours and layers; the geometry and the names come from the same transfer.
  STEPCAFControl_Reader caf;
  caf.SetNameMode(Standard_True);
  caf.SetColorMode(Standard_True);
  caf.SetLayerMode(Standard_True);
  if (caf.ReadFile(path.c_str()) != IFSelect_RetDone) not_readable(path, "the STEP reader refuses the file");
  Handle(TDocStd_Document) doc = new TDocStd_Document("MDTV-XCAF");
  XCAFApp_Application::GetApplication()->InitDocument(doc);
  (void)caf.Transfer(doc);
  STEPControl_Reader& reader = caf.ChangeReader();
  // OCCT records presentation and schema problems (a curve font or colour it cannot read, an
  // unresolved reference, an entity of the wrong type) as failures and carries on with what it
  // could read: every edge it transferred is imported, and the failures become warnings.
  const Handle(XSControl_TransferReader) transfer = reader.WS()->TransferReader();
  const Handle(StepData_StepModel) model = reader.StepModel();
  ImportReport report;
  report.warnings = failures(reader.WS(), false);
  TopTools_IndexedMapOfShape edges;
  std::vector<TopoDS_Shape> roots;  // the root shape of each edge
  for (int i = 1; i <= reader.NbShapes(); ++i) {
    TopExp::MapShapes(reader.Shape(i), TopAbs_EDGE, edges);
    roots.resize(static_cast<std::size_t>(edges.Extent()), reader.Shape(i));
  }
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    const std::string type = curve.IsNull() ? std::string() : curve_type(curve);
    if (type.empty()) {
      ++report.skipped;
      continue;
    }
    // Mode -1: search the whole transfer process (the edges of a GEOMETRIC_CURVE_SET are not bound
    // to their curve entity directly).
    const Handle(Standard_Transient) entity = transfer->EntityFromShapeResult(edge, -1);
    const int number = entity.IsNull() ? 0 : model->Number(entity);
    report.curves.push_back(edge_curve(edge, entity.IsNull() ? std::string() : step_name(entity),
                                       number > 0 ? "#" + std::to_string(number) : "", type));
    const Presentation p = presentation(doc, edge, roots[static_cast<std::size_t>(i - 1)]);
    report.curves.back().colour = p.colour;
    report.curves.back().layer = p.layer;
  }
  return report;
}

// The IGES entity an edge was transferred from (mode -1: the whole transfer process), or null.
Handle(IGESData_IGESEntity) iges_entity(const Handle(XSControl_TransferReader) & transfer, const TopoDS_Edge& edge) {
  return Handle(IGESData_IGESEntity)::DownCast(transfer->EntityFromShapeResult(edge, -1));
}

// The colour of an IGES entity: its colour definition (314, in percent) or its colour number (1–8), or empty.
std::string iges_colour(const Handle(IGESData_IGESEntity) & entity) {
  if (entity->DefColor() == IGESData_DefReference) {
    const auto definition = Handle(IGESGraph_Color)::DownCast(entity->Color());
    if (definition.IsNull()) return {};
    double red = 0.0, green = 0.0, blue = 0.0;
    definition->RGBIntensity(red, green, blue);
    return colour_text(Quantity_Color(red / 100.0, green / 100.0, blue / 100.0, Quantity_TOC_sRGB));
  }
  // Colour numbers of IGES 5.3 table 3: 1 black, 2 red, 3 green, 4 blue, 5 yellow, 6 magenta, 7 cyan, 8 white.
  static constexpr const char* kNumbered[] = {"#000000", "#ff0000", "#00ff00", "#0000ff",
                                              "#ffff00", "#ff00ff", "#00ffff", "#ffffff"};
  const int rank = entity->RankColor();
  return entity->DefColor() == IGESData_DefValue && rank >= 1 && rank <= 8 ? kNumbered[rank - 1] : std::string();
}

// The layer of an IGES entity: the name its Level Function property (406 form 3) gives, else its level
// number as text (as Open CASCADE's XCAF reader names IGES layers), or empty on no level.
std::string iges_layer(const Handle(IGESData_IGESEntity) & entity) {
  for (Interface_EntityIterator it = entity->Properties(); it.More(); it.Next()) {
    const auto function = Handle(IGESAppli_LevelFunction)::DownCast(it.Value());
    if (!function.IsNull() && !function->FuncDescription().IsNull() && function->FuncDescription()->Length() > 0)
      return function->FuncDescription()->ToCString();
  }
  return entity->DefLevel() == IGESData_DefOne && entity->Level() > 0 ? std::to_string(entity->Level()) : std::string();
}

ImportReport read_iges(const fs::path& path) {
  IGESControl_Controller::Init();
  // Keep each B-spline whole: by default the reader splits curves at C0 knots into several edges.
  Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
  IGESControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) not_readable(path, "the IGES reader refuses the file");
  // The roots as OCCT's reader transfers them (the independent curves and surfaces; members of a
  // composite curve and boundaries belong to their root), one curve per distinct edge, as for STEP.
  reader.TransferRoots();
  const Handle(IGESData_IGESModel) model = reader.IGESModel();
  const Handle(XSControl_TransferReader) transfer = reader.WS()->TransferReader();
  ImportReport report;
  report.warnings = failures(reader.WS(), true);
  TopTools_IndexedMapOfShape edges;
  for (int i = 1; i <= reader.NbShapes(); ++i) TopExp::MapShapes(reader.Shape(i), TopAbs_EDGE, edges);
  for (int e = 1; e <= edges.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges(e));
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) c = BRep_Tool::Curve(edge, first, last);
    const std::string kind = c.IsNull() ? std::string() : curve_type(c);
    if (kind.empty()) {
      ++report.skipped;
      continue;
    }
    const Handle(IGESData_IGESEntity) entity = iges_entity(transfer, edge);
    const std::string name =
        !entity.IsNull() && entity->HasName() ? std::string(entity->NameValue()->ToCString()) : std::string();
    const int number = entity.IsNull() ? 0 : model->Number(entity);
    report.curves.push_back(edge_curve(edge, name, number > 0 ? "DE " + std::to_string(2 * number - 1) : "", kind));
    if (!entity.IsNull()) {
      report.curves.back().colour = iges_colour(entity);
      report.curves.back().layer = iges_layer(entity);
    }
  }
  return report;
}

}  // namespace

ExportReport write_exchange_file(const ExportRequest& request) {
  if (request.curves.empty())
    throw Error(Errc::InvalidArgument, "nothing to export to '" + request.path.string() + "': no curves",
                {.field = "curves"});
  double max_deviation = 0.0;
  for (const auto& c : request.curves) max_deviation = std::max(max_deviation, c.deviation);
  // The same policy as every writer: a regular file or nothing at the target (never a link, FIFO,
  // device or directory), replaced atomically; an uncommitted file is removed by its destructor.
  io::OutputFile file(request.path, "path");
  try {
    if (request.format == ExchangeFormat::Iges)
      write_iges(request, file, max_deviation);
    else
      write_step(request, file, max_deviation);
  } catch (const Standard_Failure& f) {
    write_failed(request.path,
                 std::string("Open CASCADE raised ") + f.DynamicType()->Name() + ": " + f.GetMessageString());
  }
  file.commit();
  return {request.path, request.format, request.curves.size(), max_deviation};
}

ImportReport read_exchange_file(const fs::path& path) {
  const ExchangeFormat format = exchange_format_for_path(path);
  const std::string head = file_head(path);
  ImportReport report;
  try {
    if (format == ExchangeFormat::Iges) {
      // An IGES file is 80-column records; the first is a Start ('S') or, in compressed form, 'C' line.
      if (head.size() < 80 || (head[72] != 'S' && head[72] != 'C'))
        not_readable(path, "not an IGES file (the first record has no 'S' in column 73)");
      report = read_iges(path);
    } else {
      if (head.rfind("ISO-10303-21;", 0) != 0)
        not_readable(path, "not a STEP file (it does not start with \"ISO-10303-21;\")");
      report = read_step(path);
    }
  } catch (const Standard_Failure& f) {
    not_readable(path, std::string("Open CASCADE raised ") + f.DynamicType()->Name() + ": " + f.GetMessageString());
  }
  if (report.curves.empty())
    not_readable(path, "it holds no B-spline, line, circle or conic curve" +
                           (report.skipped > 0 ? " (" + std::to_string(report.skipped) + " curves of other kinds)"
                                               : std::string()) +
                           (report.warnings.empty() ? std::string() : "; " + report.warnings.front()));
  return report;
}

}  // namespace hula::oli::detail
