#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Design by curvature on a space curve (docs/benchmarks.md, "Design by curvature on a space curve"): the
# κ-graph drag of tests/studies/curvature_edit_test.cpp's space Bézier (0,0,0) (300,400,100) (700,400,300)
# (1000,0,600), |κ| raised by a tenth of κ at 30 % of its length by a cos² bump a sixth of the length wide,
# ends held G1 (tangent) and G2 (curvature), through `hula reconstruct --curve` (the library call of the
# server's curvature-edit route). Prints, per binary and hold, the median over RUNS=7 runs of the edit's own
# "seconds" (studies::edit_curvature's wall time, start-up excluded), the handles and the end errors. Give
# the binaries of two commits to compare them in one session:
#   flock /work/wt/.heavy.lock bench/cli/space_drag.sh /tmp/hula-before build/ci/apps/hula/hula
set -euo pipefail
runs=${RUNS:-7}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/space.json" <<'JSON'
{"kind": "bezier", "control_points": [[0, 0, 0], [300, 400, 100], [700, 400, 300], [1000, 0, 600]], "weights": null}
JSON
# L = 1360.1384281978064 (hula analyse --samples 2), κ(0.3 L) = 0.0016096169150789262 (hula analyse --by arclength).
s0=408.04152845934
w=226.6897380329677
h=0.00016096169150789262
x="((s - $s0)/$w)"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for hula in "$@"; do
  echo "== $hula"
  for hold in tangent curvature; do
    for _ in $(seq "$runs"); do
      "$hula" reconstruct --curve "$work/space.json" --target change --hold "$hold" \
        --kappa "piecewise(abs$x < 1, $h*cos(1.5707963267948966*$x)^2, 0)" >"$work/out.json"
      python3 -c 'import json,sys; e=json.load(open(sys.argv[1]))["edit"]; print(e["seconds"], e["handles_after"], e["end_point_error"], e["end_tangent_error"], e["end_curvature_error"])' "$work/out.json"
    done | sort -n | awk -v hold="$hold" -v n="$runs" 'NR == int((n + 1) / 2) {printf "  %-9s median %.3f s  handles %s  end point %s  end tangent %s  end curvature %s\n", hold, $1, $2, $3, $4, $5}'
  done
done
