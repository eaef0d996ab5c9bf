#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Issue 10, item 2: commands pipe through `-`. A chain of four commands —
# interpolate (points on stdin, curve on stdout) | eval --format csv | cut |
# interpolate | analyse (curve on stdin) — must print exactly what the same
# steps print when run one by one through files.
#   pipe_test.sh HULA_BINARY
set -euo pipefail
hula="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
printf '0,0,0\n1,2,0\n3,3,1\n4,1,2\n6,0,2\n' > "$work/points.csv"
at="0,0.125,0.25,0.375,0.5,0.625,0.75,0.875,1"

# With files.
"$hula" interpolate --points "$work/points.csv" -o "$work/c1.json" > /dev/null
"$hula" eval "$work/c1.json" --at "$at" --format csv > "$work/samples.csv"
cut -d, -f2- "$work/samples.csv" > "$work/points2.csv"
"$hula" interpolate --points "$work/points2.csv" -o "$work/c2.json" > /dev/null
"$hula" analyse "$work/c2.json" --samples 20 > "$work/files.json"

# With pipes.
"$hula" interpolate --points - -o - < "$work/points.csv" \
  | "$hula" eval - --at "$at" --format csv \
  | cut -d, -f2- \
  | "$hula" interpolate --points - -o - \
  | "$hula" analyse - --samples 20 > "$work/piped.json"

if ! cmp -s "$work/files.json" "$work/piped.json"; then
  echo "pipe_test: the piped chain differs from the same steps through files" >&2
  diff "$work/files.json" "$work/piped.json" | head -20 >&2
  exit 1
fi
# The piped curve is the file's curve, byte for byte.
"$hula" interpolate --points - -o - < "$work/points.csv" | cmp -s - "$work/c1.json" \
  || { echo "pipe_test: interpolate -o - differs from the file it writes" >&2; exit 1; }
[ ! -e ./- ] || { echo "pipe_test: a file named - was created" >&2; exit 1; }
echo "pipe_test: ok"
