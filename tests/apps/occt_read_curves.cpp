// SPDX-License-Identifier: MIT
// occt-read-curves FILE: the independent reader of the `hula convert` round-trip
// test (convert_cli_test.cpp). Open CASCADE's XCAF readers used as its
// documentation shows them, and nothing of HulaHoops: STEPCAFControl_Reader or
// IGESCAFControl_Reader (names, colours, layers on) into an XCAF document, then
// for every free shape its name, colour and layers, and for every edge of it
// the B-spline it carries (degree, flat knot sequence, poles, weights). For
// STEP it also lists the names of the file's PRODUCT entities. One JSON object
// on standard output.
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <StepBasic_Product.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_HSequenceOfExtendedString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_LayerTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

std::string utf8(const TCollection_ExtendedString& text) {
  std::string out(static_cast<std::size_t>(text.LengthOfCString()), '\0');
  char* data = out.data();
  out.resize(static_cast<std::size_t>(text.ToUTF8CString(data)));
  return out;
}

// A JSON string (the names tested are plain ASCII; quotes and backslashes escaped).
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string colour_json(const Handle(XCAFDoc_ColorTool) & tool, const TDF_Label& label, const TopoDS_Shape& shape) {
  Quantity_Color c;
  if (!tool->GetColor(label, XCAFDoc_ColorCurv, c) && !tool->GetColor(label, XCAFDoc_ColorGen, c) &&
      !tool->GetColor(shape, XCAFDoc_ColorCurv, c) && !tool->GetColor(shape, XCAFDoc_ColorGen, c))
    return "null";
  double r = 0, g = 0, b = 0;
  c.Values(r, g, b, Quantity_TOC_sRGB);
  char text[16];
  std::snprintf(text, sizeof text, "\"#%02x%02x%02x\"", static_cast<unsigned>(std::lround(r * 255)),
                static_cast<unsigned>(std::lround(g * 255)), static_cast<unsigned>(std::lround(b * 255)));
  return text;
}

void print_curve(const TopoDS_Edge& edge) {
  double first = 0, last = 0;
  Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
  while (!curve.IsNull() && curve->IsKind(STANDARD_TYPE(Geom_TrimmedCurve)))
    curve = Handle(Geom_TrimmedCurve)::DownCast(curve)->BasisCurve();
  auto b = Handle(Geom_BSplineCurve)::DownCast(curve);
  if (b.IsNull()) {
    std::printf("null");
    return;
  }
  if (b->IsPeriodic()) {
    // The STEP reader makes a closed B-spline periodic: its clamped form on the edge's bounds.
    b = Handle(Geom_BSplineCurve)::DownCast(b->Copy());
    b->SetNotPeriodic();
    b->Segment(first, last);
  }
  std::printf("{\"first\": %.17g, \"last\": %.17g, \"degree\": %d, \"knots\": [", first, last, b->Degree());
  const TColStd_Array1OfReal& knots = b->KnotSequence();
  for (int i = knots.Lower(); i <= knots.Upper(); ++i) std::printf("%s%.17g", i > knots.Lower() ? ", " : "", knots(i));
  std::printf("], \"poles\": [");
  for (int i = 1; i <= b->NbPoles(); ++i) {
    const gp_Pnt p = b->Pole(i);
    std::printf("%s[%.17g, %.17g, %.17g]", i > 1 ? ", " : "", p.X(), p.Y(), p.Z());
  }
  std::printf("], \"weights\": ");
  if (!b->IsRational()) {
    std::printf("null}");
    return;
  }
  std::printf("[");
  for (int i = 1; i <= b->NbPoles(); ++i) std::printf("%s%.17g", i > 1 ? ", " : "", b->Weight(i));
  std::printf("]}");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: occt-read-curves FILE.step|FILE.igs\n");
    return 2;
  }
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  const std::string path = argv[1];
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  const bool iges = ext == "igs" || ext == "iges";
  Handle(TDocStd_Document) doc = new TDocStd_Document("MDTV-XCAF");
  XCAFApp_Application::GetApplication()->InitDocument(doc);
  std::string products = "[]";
  if (iges) {
    IGESCAFControl_Reader reader;
    // Set after the reader's controller is initialised: B-splines whole, not split at C0 knots.
    Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    reader.SetLayerMode(true);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || !reader.Transfer(doc)) return 3;
  } else {
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    reader.SetColorMode(true);
    reader.SetLayerMode(true);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || !reader.Transfer(doc)) return 3;
    const Handle(StepData_StepModel) model = reader.ChangeReader().StepModel();
    products = "[";
    for (int i = 1; i <= model->NbEntities(); ++i) {
      const auto product = Handle(StepBasic_Product)::DownCast(model->Value(i));
      if (product.IsNull()) continue;
      products += (products.size() > 1 ? ", " : "") + quoted(product->Name()->ToCString());
    }
    products += "]";
  }
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const Handle(XCAFDoc_ColorTool) colours = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  const Handle(XCAFDoc_LayerTool) layers = XCAFDoc_DocumentTool::LayerTool(doc->Main());
  TDF_LabelSequence free;
  shapes->GetFreeShapes(free);
  std::printf("{\"products\": %s, \"shapes\": [", products.c_str());
  for (int i = 1; i <= free.Length(); ++i) {
    const TDF_Label label = free.Value(i);
    const TopoDS_Shape shape = shapes->GetShape(label);
    Handle(TDataStd_Name) name;
    std::string layer = "null";
    Handle(TColStd_HSequenceOfExtendedString) names;
    if (layers->GetLayers(label, names) && !names.IsNull() && names->Length() > 0)
      layer = quoted(utf8(names->Value(1)));
    std::printf("%s{\"name\": %s, \"colour\": %s, \"layer\": %s, \"edges\": [", i > 1 ? ", " : "",
                label.FindAttribute(TDataStd_Name::GetID(), name) ? quoted(utf8(name->Get())).c_str() : "null",
                colour_json(colours, label, shape).c_str(), layer.c_str());
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    for (int e = 1; e <= edges.Extent(); ++e) {
      std::printf("%s", e > 1 ? ", " : "");
      print_curve(TopoDS::Edge(edges(e)));
    }
    std::printf("]}");
  }
  std::printf("]}\n");
  return 0;
}
