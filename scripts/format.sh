#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Formats the tracked C++ files with clang-format-14, or with --check reports
# (and fails on) any file that is not formatted.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' 2>/dev/null || true)
[ ${#files[@]} -gt 0 ] || exit 0
if [ "${1:-}" = "--check" ]; then
  clang-format-14 --dry-run --Werror "${files[@]}"
  echo "format: ${#files[@]} files clean"
else
  clang-format-14 -i "${files[@]}"
fi
