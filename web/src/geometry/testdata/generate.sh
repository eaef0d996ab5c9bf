#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the kernel's reference values for web/src/geometry/*.test.ts
# from the curve files here: `hula eval` (derivatives to order 3) and
# `hula analyse` (Frenet samples by arc length and by parameter, fins).
# Usage: web/src/geometry/testdata/generate.sh [path/to/hula [OUT_DIR]]
# With OUT_DIR the files are written there instead, unformatted: ctest
# web_testdata_current does so and compares them with the committed ones, so
# the snapshot cannot drift from the kernel.
set -euo pipefail
cd "$(dirname "$0")"
hula=${1:-../../../../build/ci/apps/hula/hula}
out=${2:-.}
fins=curvature,torsion,normal,binormal,bishop-u,bishop-v
for c in space straight; do
  "$hula" eval "$c.json" --at 0,0.1,0.2,0.35,0.5,0.65,0.8,0.93,1 --derivatives 3 >"$out/$c.eval.json"
  "$hula" analyse "$c.json" --samples 9 --by arclength --fins "$fins" --fin-scale 0.5 \
    --fin-density 9 >"$out/$c.arclength.json"
  "$hula" analyse "$c.json" --samples 7 --by parameter >"$out/$c.parameter.json"
done
# The conformance corpus (tests/data/conformance): the kernel's analysis of every curve, as every
# door gives it, with the fins at the samples (--fin-density = --samples) at scale 1 (kept as the CLI
# writes them: .prettierignore lists the folder).
mkdir -p "$out/conformance"
while read -r name; do
  for by in parameter arclength; do
    "$hula" analyse "../../../../tests/data/conformance/$name.json" --samples 33 --by "$by" --features \
      --fins curvature,torsion --fin-density 33 --fin-scale 1 >"$out/conformance/$name.$by.json"
  done
done <../../../../tests/data/conformance/corpus.txt
if [ "$out" = . ]; then (cd ../../.. && npx prettier --write src/geometry/testdata >/dev/null); fi
