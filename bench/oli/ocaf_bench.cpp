// SPDX-License-Identifier: MIT
// The yardstick of the document benchmarks:
// Open CASCADE OCAF doing the same edit as BM_oli_move_in_memory — move one
// control point of a 100-point curve inside a named command — with a
// TDocStd_Document whose curve label holds the control points as a
// TDataStd_RealArray (3n doubles), knots as a second array and the degree as a
// TDataStd_Integer: OpenCommand, three SetValue calls, CommitCommand; and the
// same followed by Undo. In memory (OCAF's transactions have no disk side;
// saving is a whole-document write, measured separately for 100 curves).
// Results beside the Oli figures in docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <TDF_Label.hxx>
#include <TDataStd_Integer.hxx>
#include <TDataStd_RealArray.hxx>
#include <TDocStd_Document.hxx>
#include <vector>

namespace {

// The undo limit keeps memory bounded over millions of iterations, as in document_bench.cpp.
constexpr int kUndoLimit = 100;

struct OcafCurve {
  Handle(TDocStd_Document) document;
  Handle(TDataStd_RealArray) points;
};

// A document with one curve of n control points (a clamped uniform cubic's data).
OcafCurve make_document(int n) {
  OcafCurve out;
  out.document = new TDocStd_Document("BinOcaf");
  out.document->SetUndoLimit(kUndoLimit);
  out.document->OpenCommand();
  const TDF_Label curve = out.document->Main().NewChild();
  TDataStd_Integer::Set(curve, 3);
  out.points = TDataStd_RealArray::Set(curve.NewChild(), 0, 3 * n - 1);
  for (int i = 0; i < n; ++i) {
    out.points->SetValue(3 * i, i);
    out.points->SetValue(3 * i + 1, i % 3);
    out.points->SetValue(3 * i + 2, 0.5 * i);
  }
  const Handle(TDataStd_RealArray) knots = TDataStd_RealArray::Set(curve.NewChild(), 0, n + 3);
  for (int i = 0; i <= n + 3; ++i) knots->SetValue(i, i < 4 ? 0.0 : i > n - 1 ? 1.0 : (i - 3.0) / (n - 3.0));
  out.document->CommitCommand();
  return out;
}

// Moves control point 50 to (x, 1, 2) inside one OCAF command.
void move_point(OcafCurve& c, double x) {
  c.document->OpenCommand();
  c.points->SetValue(150, x);  // the first SetValue backs the whole array up (TDF_Attribute::Backup)
  c.points->SetValue(151, 1.0);
  c.points->SetValue(152, 2.0);
  c.document->CommitCommand();
}

void BM_oli_ocaf_move_commit(benchmark::State& state) {
  OcafCurve c = make_document(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) move_point(c, static_cast<double>(i++ % 17));
  benchmark::DoNotOptimize(c.points->Value(150));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_oli_ocaf_move_commit)->Arg(100)->Unit(benchmark::kMicrosecond);

// One iteration = a move committed and then undone (the document returns to its state).
void BM_oli_ocaf_move_commit_undo(benchmark::State& state) {
  OcafCurve c = make_document(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    move_point(c, static_cast<double>(i++ % 17));
    c.document->Undo();
  }
  benchmark::DoNotOptimize(c.points->Value(150));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_oli_ocaf_move_commit_undo)->Arg(100)->Unit(benchmark::kMicrosecond);

// One iteration = an undo or a redo (alternating) of one committed move.
void BM_oli_ocaf_undo_redo(benchmark::State& state) {
  OcafCurve c = make_document(static_cast<int>(state.range(0)));
  move_point(c, 7.0);
  bool undo = true;
  for (auto _ : state) {
    const bool done = undo ? c.document->Undo() : c.document->Redo();
    if (!done) state.SkipWithError("OCAF refused the undo or redo");
    undo = !undo;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_oli_ocaf_undo_redo)->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
