#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer targets with the `fuzz` preset (clang-14, ASan + UBSan)
# and runs each for a short time on its corpus. New crashers are written to
# fuzz/corpus/<target>/ (-artifact_prefix), where the corpus regression tests
# replay them with the ordinary build; the run fails if a crash is found.
#   scripts/fuzz.sh [seconds per target, default 30]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
cmake --preset fuzz
cmake --build --preset fuzz --target fuzz_law_parser
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# Explore into a scratch corpus seeded from the tracked one, so the repository only gains crashers.
cp fuzz/corpus/law_parser/* "$work/"
./build/fuzz/fuzz/fuzz_law_parser "$work" fuzz/corpus/law_parser -max_total_time="$seconds" -max_len=4096 \
  -timeout=10 -artifact_prefix=fuzz/corpus/law_parser/ -print_final_stats=1
