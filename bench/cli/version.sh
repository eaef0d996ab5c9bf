#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `hula --version` against the floor of this machine (docs/benchmarks.md, "Command-line start-up"): the
# median wall time (and mean CPU time) of 20 runs (hyperfine -N --warmup 5 --runs 20) of a C hello world, a C++ hello world
# that writes with std::cout, and `hula --version` of each binary given, then, for each binary, the shared
# objects the loader initialises and its relocation statistics (LD_DEBUG=statistics). Give the binaries of
# two commits to compare them in one session:
#   flock /work/wt/.heavy.lock bench/cli/version.sh /tmp/hula-before build/ci/apps/hula/hula
set -euo pipefail
runs=${RUNS:-20}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '#include <stdio.h>\nint main(void) { puts("hello"); return 0; }\n' >"$work/hello.c"
printf '#include <iostream>\nint main() { std::cout << "hello\\n"; }\n' >"$work/hello.cpp"
cc -O2 "$work/hello.c" -o "$work/hello-c"
c++ -O2 "$work/hello.cpp" -o "$work/hello-cpp"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
commands=("$work/hello-c" "$work/hello-cpp")
for hula in "$@"; do commands+=("$hula --version"); done
hyperfine -N --warmup 5 --runs "$runs" --export-json "$work/times.json" "${commands[@]}" >/dev/null 2>&1
python3 - "$work/times.json" <<'PY'
import json, sys
for r in json.load(open(sys.argv[1]))["results"]:
    name = r["command"].split("/")[-1] if "hello" in r["command"] else r["command"]
    print(f"  {name:40s} median {r['median'] * 1e3:6.2f} ms  (mean {r['mean'] * 1e3:.2f} ± {r['stddev'] * 1e3:.2f}, "
          f"min {r['min'] * 1e3:.2f}; CPU user + sys, mean {(r['user'] + r['system']) * 1e3:.2f} ms)")
PY
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
for hula in "$@"; do
  echo "== $hula"
  echo "  shared objects initialised by --version: $(LD_DEBUG=files "$hula" --version 2>&1 >/dev/null | grep -c 'calling init')"
  LD_DEBUG=statistics "$hula" --version 2>&1 >/dev/null | grep -E 'total startup time|time needed for relocation|number of relocations:|relocation dependencies|objects loaded' | sed 's/^ *[0-9]*: */  /'
done
