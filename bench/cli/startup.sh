#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The command line's fixed costs (docs/benchmarks.md, "Command-line start-up and large files"):
# for each `hula` binary given, the wall time of `hula --version` and of a small `hula eval`
# (perf stat: mean and its spread over RUNS=50 runs), the shared libraries it loads and its page
# faults, then `hula interpolate` writing a curve through 1,000,000 points and `hula info` reading it
# back (best of 3). Give the binaries of two commits to compare them in one session:
#   flock /work/wt/.heavy.lock bench/cli/startup.sh /tmp/hula-before build/ci/apps/hula/hula
set -euo pipefail
runs=${RUNS:-50}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
here=$(cd "$(dirname "$0")/../.." && pwd)
# 1,000,000 points on a helix (x, y, z per line), and a small curve for `hula eval`.
python3 - "$work/big.csv" <<'PY'
import math, sys
with open(sys.argv[1], "w") as f:
    for i in range(1_000_000):
        t = i * 1e-4
        f.write(f"{math.cos(t):.9f},{math.sin(t):.9f},{0.01 * t:.9f}\n")
PY
"$1" interpolate --points "$here/examples/cli/pts.csv" -o "$work/small.json"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
for hula in "$@"; do
  echo "== $hula"
  echo "shared libraries loaded by --version: $(LD_DEBUG=files "$hula" --version 2>&1 >/dev/null | grep -c 'calling init')"
  for cmd in "--version" "eval $work/small.json --at 0.25,0.5"; do
    # shellcheck disable=SC2086
    perf stat -r "$runs" -e task-clock,page-faults "$hula" $cmd 2>&1 >/dev/null |
      awk -v c="$cmd" '/task-clock/ {cpu=$1} /page-faults/ {pf=$1} /elapsed/ {printf "  %-28s wall %.2f ms (± %s), cpu %.2f ms, %s page faults\n", c, $1 * 1000, $3, cpu, pf}'
  done
  best_w=1e9 best_r=1e9
  for _ in 1 2 3; do
    s=$(date +%s.%N); "$hula" interpolate --points "$work/big.csv" -o "$work/big.json"; e=$(date +%s.%N)
    best_w=$(python3 -c "print(min($best_w, ($e - $s) * 1000))")
    s=$(date +%s.%N); "$hula" info "$work/big.json" >/dev/null || true; e=$(date +%s.%N)
    best_r=$(python3 -c "print(min($best_r, ($e - $s) * 1000))")
  done
  printf '  interpolate 1e6 points, written: %.0f ms (%s bytes); info reading it back: %.0f ms\n' \
    "$best_w" "$(stat -c %s "$work/big.json")" "$best_r"
  sha256sum "$work/big.json" | cut -c1-16
done
