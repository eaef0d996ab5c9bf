// SPDX-License-Identifier: MIT
// occt-count-edges FILE: the independent reference of the real-file import
// test (exchange_real_test.cpp). Open CASCADE's own reader, used as its
// documentation shows it and nothing of HulaHoops: STEPControl_Reader or
// IGESControl_Reader (B-splines kept whole, "read.iges.bspline.continuity" 0),
// TransferRoots, then every distinct edge of the transferred shapes, printed
// as one JSON object {"roots", "edges": [{"start": [x, y, z], "end": [...]}]}
// (the edge's 3-D curve at its bounds; null without one).
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <cstdio>
#include <string>

namespace {

void print_point(const gp_Pnt& p) { std::printf("[%.17g, %.17g, %.17g]", p.X(), p.Y(), p.Z()); }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: occt-count-edges FILE.step|FILE.igs\n");
    return 2;
  }
  // OCCT's readers report progress on standard output; the answer is this program's only output.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  const std::string path = argv[1];
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  const bool iges = ext == "igs" || ext == "iges" || ext == "IGS" || ext == "IGES";
  TopTools_IndexedMapOfShape edges;
  int roots = 0;
  if (iges) {
    Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return 3;
    roots = reader.NbRootsForTransfer();
    reader.TransferRoots();
    for (int i = 1; i <= reader.NbShapes(); ++i) TopExp::MapShapes(reader.Shape(i), TopAbs_EDGE, edges);
  } else {
    STEPControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return 3;
    roots = reader.NbRootsForTransfer();
    reader.TransferRoots();
    for (int i = 1; i <= reader.NbShapes(); ++i) TopExp::MapShapes(reader.Shape(i), TopAbs_EDGE, edges);
  }
  std::printf("{\"roots\": %d, \"edges\": [", roots);
  for (int i = 1; i <= edges.Extent(); ++i) {
    double first = 0.0, last = 0.0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(edges(i)), first, last);
    std::printf("%s", i > 1 ? ", " : "");
    if (curve.IsNull()) {
      std::printf("null");
      continue;
    }
    std::printf("{\"start\": ");
    print_point(curve->Value(first));
    std::printf(", \"end\": ");
    print_point(curve->Value(last));
    std::printf("}");
  }
  std::printf("]}\n");
  return 0;
}
