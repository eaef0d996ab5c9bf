#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, part 2: install what is missing, build the `ci` configuration
# (RelWithDebInfo, -Werror, _GLIBCXX_ASSERTIONS, Open CASCADE required) and
# run every test label (unit, property, oracle, golden), then check that the
# tracked C++ sources are clang-format clean.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
cmake --preset ci
cmake --build --preset ci
scripts/format.sh --check
ctest --preset ci
