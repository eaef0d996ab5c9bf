// SPDX-License-Identifier: MIT
// HulaHoops::oli alone: a document file gets a curve and a point drag, is closed and reopened with its
// history, and undoing the drag gives the control point back.
#include <cstdio>
#include <filesystem>

#include "hula/curve/curve.hpp"
#include "hula/oli/document.hpp"

int main(int argc, char** argv) {
  namespace oli = hula::oli;
  const std::filesystem::path dir = argc > 2 ? argv[2] : std::filesystem::temp_directory_path();
  const std::filesystem::path file = dir / "consumer-part.hula";
  std::filesystem::remove(file);
  oli::Label spine;
  {
    oli::Document doc = oli::Document::create(file);
    doc.transact("add spine", [&](oli::Edit& e) {
      spine = e.add_curve(
          hula::curve::Curve::bezier(
              {.control_points = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}}, .weights = {}, .dimension = 3}),
          {.name = "spine"});
    });
    doc.transact("drag", [&](oli::Edit& e) { e.move_point(spine, 1, {1, 2.5, 0}); });
  }
  oli::Document doc = oli::Document::open(file);
  const double dragged = doc.get(spine).curve().nurbs().control_points()[1].y;
  const bool undone = doc.undo().committed;
  const double before = doc.get(spine).curve().nurbs().control_points()[1].y;
  std::printf("oli: revision %llu, point 1 y = %g after the drag, %g after undo\n",
              static_cast<unsigned long long>(doc.revision()), dragged, before);
  return dragged == 2.5 && undone && before == 2.0 && doc.get(spine).attributes().name == "spine" ? 0 : 1;
}
