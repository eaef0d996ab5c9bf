#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, part 2: install what is missing, the test toolchain included
# (scripts/setup-debian.sh --test), build the `ci` configuration
# (RelWithDebInfo at -O2 -g1, -Werror, _GLIBCXX_ASSERTIONS, Open CASCADE required) and
# check that the tracked C++ sources are clang-format clean, fuzz the law
# parser and every reader for 20 s each, two at a time (about one minute) when clang-14 is
# installed, and run every test label (unit, property, oracle, golden), then
# the web workbench's checks, unit tests, build and end-to-end tests
# (scripts/web.sh --e2e), and last ctest, so ctest's summary closes the output.
set -euo pipefail
cd "$(dirname "$0")/.."
# The elapsed time at each step, so a slow CI run shows where its time went.
step() { echo "test.sh: [$((SECONDS / 60)) min $((SECONDS % 60)) s] $*" >&2; }
step "setup"
scripts/setup-debian.sh --test
step "configure and build (ci preset)"
cmake --preset ci
cmake --build --preset ci
step "format check"
scripts/format.sh --check
# The fuzzers, briefly (STYLE.md CI step 7; seconds per target); HULA_CI_FUZZ_SECONDS=0 skips them.
if [ "${HULA_CI_FUZZ_SECONDS:-20}" != "0" ] && command -v clang++-14 >/dev/null 2>&1; then
  step "fuzz"
  scripts/fuzz.sh "${HULA_CI_FUZZ_SECONDS:-20}"
fi
# The web workbench: lint, format, types, unit tests, build, and the e2e
# tests in chromium against this build's `hula serve` (a build without the
# server command says so loudly and runs the rest).
step "web"
if build/ci/apps/hula/hula serve --help >/dev/null 2>&1; then
  HULA_BIN="$PWD/build/ci/apps/hula/hula" scripts/web.sh --e2e
else
  echo "test.sh: WEB E2E NOT RUN: this build has no 'hula serve'; web unit tests and build only" >&2
  scripts/web.sh
fi
step "ctest"
ctest --preset ci
step "done"
