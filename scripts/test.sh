#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, part 2: install what is missing, build the `ci` configuration
# (RelWithDebInfo, -Werror, _GLIBCXX_ASSERTIONS, Open CASCADE required) and
# check that the tracked C++ sources are clang-format clean, fuzz the law
# parser and every reader for 20 s each (about two minutes) when clang-14 is
# installed, and run every test label
# (unit, property, oracle, golden) last, so ctest's summary closes the output.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
cmake --preset ci
cmake --build --preset ci
scripts/format.sh --check
# The fuzzers, briefly (STYLE.md CI step 7; seconds per target); HULA_CI_FUZZ_SECONDS=0 skips them.
if [ "${HULA_CI_FUZZ_SECONDS:-20}" != "0" ] && command -v clang++-14 >/dev/null 2>&1; then
  scripts/fuzz.sh "${HULA_CI_FUZZ_SECONDS:-20}"
fi
ctest --preset ci
