#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the current figures of docs/benchmarks.md (issue 27): builds the judged benchmark programs
# with the `bench` preset (Release, Open CASCADE and pagmo linked for the same-run columns), runs each
# once with repetitions, keeps the raw JSON in bench/results/<machine>/ and writes the table between the
# `bench.py` markers of docs/benchmarks.md (bench/report.py). Run it on a machine as quiet as you can
# get; the table records the load average anyway.
#
# usage: scripts/bench.sh [--hula BINARY] [report.py options]
#   --hula build/ci/apps/hula/hula   also measures the server's CPU per analysis request
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset bench >/dev/null
cmake --build build/bench -j 2 --target bench_nurbs_evaluate bench_nurbs_interpolate bench_diffgeom_curvature \
  bench_studies_fitness bench_optim_ga
exec nice -n 0 python3 bench/report.py build/bench "$@"
