#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Issue 10, item 2, and issue 24, item 2: commands pipe through `-`.
# 1. A chain of four commands — interpolate (points on stdin, curve on stdout) |
#    eval --format csv | cut | interpolate | analyse (curve on stdin) — must print
#    exactly what the same steps print when run one by one through files.
# 2. Every command that takes `-o -` writes on stdout the very bytes it writes to
#    a file (the curve alone, no JSON summary after it), and a reader of `-`
#    (`hula info -`) prints for the piped curve what it prints for the file.
#    The writers (`hula --help`, `hula edit --help`): interpolate, law
#    --to-nurbs, reconstruct, fin-compound, edit-projection, hermite,
#    hermite-frenet, convert, doc export, every edit subcommand, approximate,
#    fit (and --save-study), offset, helical-offset, orthotomic, polar,
#    clothoid, log-aesthetic, match, blend; `doc export --format step|iges -o -`
#    into `convert - --from step|iges` (the curve read back is the one read
#    from the written file). (`completion bash -o -` writes a shell script, not
#    a curve.)
#   pipe_test.sh HULA_BINARY
set -euo pipefail
hula="$1"
examples="$(cd "$(dirname "$0")/../../examples" && pwd)"
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

# check_writer NAME ARGS...: ARGS with OUT replaced by a file, then by -. The
# bytes on stdout must be the file's, and `hula info -` fed by the pipe must
# print what `hula info FILE` prints.
check_writer() {
  local name="$1"
  shift
  local file_args=() pipe_args=() arg
  for arg in "$@"; do
    file_args+=("${arg//OUT/$work/$name.json}")
    pipe_args+=("${arg//OUT/-}")
  done
  "$hula" "${file_args[@]}" > /dev/null
  "$hula" "${pipe_args[@]}" > "$work/$name.piped"
  if ! cmp -s "$work/$name.json" "$work/$name.piped"; then
    echo "pipe_test: $name -o - differs from the file it writes" >&2
    diff "$work/$name.json" "$work/$name.piped" | head -10 >&2
    exit 1
  fi
  # info names its input ("file"): the rest must agree.
  "$hula" info "$work/$name.json" | grep -v '"file":' > "$work/$name.info-file"
  "$hula" "${pipe_args[@]}" | "$hula" info - | grep -v '"file":' > "$work/$name.info-pipe"
  cmp -s "$work/$name.info-file" "$work/$name.info-pipe" \
    || { echo "pipe_test: hula info - of the piped $name differs from the file's" >&2; exit 1; }
}

c1="$work/c1.json"
check_writer interpolate interpolate --points "$work/points.csv" -o OUT
check_writer insert-knot edit insert-knot "$c1" --at 0.5 --times 2 -o OUT
check_writer refine edit refine "$c1" --knots 0.25,0.5,0.75 -o OUT
check_writer remove-knots edit remove-knots "$work/refine.json" --tolerance 1e-9 -o OUT
check_writer elevate edit elevate "$c1" --times 1 -o OUT
check_writer split-first edit split "$c1" --at 0.4 -o OUT --second "$work/second.json"
check_writer split-second edit split "$c1" --at 0.4 -o "$work/first.json" --second OUT
check_writer reverse edit reverse "$c1" -o OUT
check_writer reparam edit reparam "$c1" --domain 0,10 -o OUT
check_writer approximate approximate --points "$examples/cli/scan.csv" --tolerance 0.05 -o OUT
check_writer fit fit --points "$examples/cli/scan.csv" -o OUT
check_writer law-to-nurbs law 'vec(2*cos(t), 2*sin(t), 0.5*t)' --to-nurbs 0,6.283185307179586 --tolerance 1e-7 -o OUT
check_writer clothoid clothoid --start-point 0,0 --start-angle 0 --end-point 1,1 --end-angle 1.5707963267948966 -o OUT
check_writer clothoid-nurbs clothoid --start-point 0,0 --start-angle 0 --end-point 1,1 --end-angle 1 \
  --to-nurbs 1e-6 -o OUT
check_writer to-nurbs edit to-nurbs "$work/clothoid.json" --tolerance 1e-8 -o OUT
check_writer log-aesthetic log-aesthetic --alpha 1 --rho0 1.5 --lambda 0.4 --length 6 -o OUT
check_writer reconstruct reconstruct --kappa 1 --tau 0 --length 1.5707963267948966 -o OUT
check_writer hermite hermite "$examples/studies/hermite-direction.json" -o OUT
check_writer fin-compound fin-compound "$examples/studies/fin-compound-edit.json" -o OUT
check_writer edit-projection edit-projection "$examples/studies/edit-projection.json" -o OUT
check_writer reduce-degree edit reduce-degree "$work/elevate.json" --tolerance 1e-9 -o OUT
check_writer rebuild edit rebuild "$c1" --control-points 6 -o OUT
check_writer to-law edit to-law "$c1" -o OUT
check_writer clothoid-spline clothoid --points "$work/points.csv" -o OUT
# match and blend join the first curve's end to a second curve beyond it.
printf '8,0,2\n9,1,3\n11,0,2\n12,2,1\n' > "$work/next.csv"
"$hula" interpolate --points "$work/next.csv" -o "$work/next.json" > /dev/null
check_writer match match "$c1" "$work/next.json" --continuity G2 -o OUT
check_writer blend blend "$c1" "$work/next.json" --continuity G2 -o OUT
# The plane-curve writers: offsets and the mappings of thesis 6.3.2.
printf '0,0\n1,2\n3,3\n4,1\n6,0\n' > "$work/plane.csv"
"$hula" interpolate --points "$work/plane.csv" -o "$work/plane.json" > /dev/null
check_writer offset offset "$work/plane.json" --distance 0.25 -o OUT
check_writer helical-offset helical-offset "$work/plane.json" --distance 0.1 --twist 2*t --frame bishop -o OUT
check_writer orthotomic orthotomic "$work/plane.json" --pole 0,20 -o OUT
check_writer polar polar "$work/plane.json" --centre 0,50 --radius 10 -o OUT
cat > "$work/handles.json" <<'JSON'
{"handles": [{"point": [2, 0], "tangent": [0, 6.283], "normal": [-1, 0], "curvature": 0.5},
             {"point": [0, 2], "tangent": [-6.283, 0], "normal": [0, -1], "curvature": 0.5, "torsion": 0}],
 "parameters": [0, 1]}
JSON
check_writer hermite-frenet hermite-frenet "$work/handles.json" -o OUT
check_writer convert convert "$c1" --format json -o OUT
"$hula" doc new "$work/d.hula" > /dev/null
"$hula" doc add "$work/d.hula" --curve "$c1" --name spine > /dev/null
check_writer doc-export doc export "$work/d.hula" 1 --format json -o OUT

# STEP and IGES on stdout, read back from stdin by convert --from: the same curve as through the files
# (the files themselves carry a time stamp, so the curves read back are compared).
for fmt in step iges; do
  ext=$fmt; [ "$fmt" = iges ] && ext=igs
  "$hula" doc export "$work/d.hula" 1 --format "$fmt" -o "$work/d.$ext" > /dev/null
  "$hula" convert "$work/d.$ext" --format json -o "$work/d-$fmt.json" > /dev/null
  "$hula" doc export "$work/d.hula" 1 --format "$fmt" -o - \
    | "$hula" convert - --from "$fmt" --format json -o - > "$work/d-$fmt.piped"
  cmp -s "$work/d-$fmt.json" "$work/d-$fmt.piped" \
    || { echo "pipe_test: doc export --format $fmt -o - | convert - --from $fmt differs from the files" >&2;
      diff "$work/d-$fmt.json" "$work/d-$fmt.piped" | head -10 >&2; exit 1; }
done

# The probe's chain: interpolate | edit elevate | edit reverse | info, all through `-`.
"$hula" interpolate --points - -o - < "$work/points.csv" \
  | "$hula" edit elevate - -o - \
  | "$hula" edit reverse - -o - \
  | "$hula" info - | grep -v '"file":' > "$work/chain.json"
"$hula" edit elevate "$c1" -o "$work/e.json" > /dev/null
"$hula" edit reverse "$work/e.json" -o "$work/er.json" > /dev/null
"$hula" info "$work/er.json" | grep -v '"file":' | cmp -s - "$work/chain.json" \
  || { echo "pipe_test: interpolate | edit elevate | edit reverse | info differs from files" >&2; exit 1; }
# convert writes DXF on stdout and reads it from stdin: the curve comes back bit for bit, as through files.
"$hula" convert "$c1" --format dxf -o "$work/c1.dxf" > /dev/null
"$hula" convert "$work/c1.dxf" -o "$work/c1-back.json" > /dev/null
"$hula" convert "$c1" --format dxf -o - | cmp -s - "$work/c1.dxf" \
  || { echo "pipe_test: convert --format dxf -o - differs from the file it writes" >&2; exit 1; }
"$hula" convert "$c1" --format dxf -o - | "$hula" convert - --from dxf --format json -o - | cmp -s - "$work/c1-back.json" \
  || { echo "pipe_test: convert - --from dxf -o - differs from the file round trip" >&2; exit 1; }
# fit --save-study - is a "fit" study that `hula fit --study -` reads back.
"$hula" fit --points "$examples/cli/scan.csv" -o "$work/fit-a.json" --save-study "$work/fit-study.json" > /dev/null
"$hula" fit --points "$examples/cli/scan.csv" -o "$work/fit-b.json" --save-study - > "$work/fit-study.piped"
cmp -s "$work/fit-study.json" "$work/fit-study.piped" \
  || { echo "pipe_test: fit --save-study - differs from the file it writes" >&2; exit 1; }
"$hula" fit --points "$examples/cli/scan.csv" -o "$work/fit-b.json" --save-study - \
  | "$hula" fit - -o - | cmp -s - "$work/fit-a.json" \
  || { echo "pipe_test: fit --save-study - | fit - -o - differs from fitting the points" >&2; exit 1; }
# Two outputs of one command cannot share stdout.
if "$hula" edit split "$c1" --at 0.4 -o - --second - > /dev/null 2>&1; then
  echo "pipe_test: edit split -o - --second - was accepted" >&2
  exit 1
fi
[ ! -e ./- ] || { echo "pipe_test: a file named - was created" >&2; exit 1; }
echo "pipe_test: ok"
