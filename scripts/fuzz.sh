#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer targets with the `fuzz` preset (clang-14, ASan + UBSan)
# and runs each for a bounded time on its corpus: the law parser and every
# reader (curve, points, problem, study, profile). New crashers are written to
# fuzz/corpus/<target>/ (-artifact_prefix), where the corpus regression tests
# replay them with the ordinary build; the run fails if a crash is found.
#   scripts/fuzz.sh [seconds per target, default 20]
# Six targets at 20 s, two at a time, keep the fuzz runs near one minute of CI time; the preset builds at
# -O1 -gline-tables-only (the usual libFuzzer flags), which compiles the Eigen- and
# Ceres-heavy studies sources about three times faster than -O2 -g under ASan + UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
targets=(law_parser curve_reader points_reader problem_reader study_reader profile_reader)
cmake --preset fuzz
cmake --build --preset fuzz --target "${targets[@]/#/fuzz_}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# libFuzzer runs one thread: HULA_FUZZ_JOBS targets (default 2, one per core of the CI machine) run at
# once, each for its full time on its own core, and their output is shown when each group ends.
jobs="${HULA_FUZZ_JOBS:-2}"
fuzz_one() {
  local t="$1"
  # Explore into a scratch corpus seeded from the tracked one, so the repository only gains crashers.
  mkdir -p "$work/$t"
  cp fuzz/corpus/"$t"/* "$work/$t/"
  # -rss_limit_mb: an input must never need more than 2 GB (sizes are capped by the readers).
  if ! ./build/fuzz/fuzz/fuzz_"$t" "$work/$t" -max_total_time="$seconds" -max_len=65536 -timeout=10 \
      -rss_limit_mb=2048 -artifact_prefix=fuzz/corpus/"$t"/ -print_final_stats=1 >"$work/$t.log" 2>&1; then
    echo "fuzz: $t found a failing input (saved under fuzz/corpus/$t/)" >>"$work/$t.log"
    return 1
  fi
}
status=0
running=()
finish_group() {
  local i
  for i in "${!running[@]}"; do
    wait "${pids[$i]}" || status=1
    echo "fuzz: ${running[$i]}:" >&2
    cat "$work/${running[$i]}.log" >&2
  done
  running=()
  pids=()
}
pids=()
for t in "${targets[@]}"; do
  fuzz_one "$t" &
  pids+=($!)
  running+=("$t")
  if [ "${#running[@]}" -ge "$jobs" ]; then finish_group; fi
done
finish_group
exit "$status"
