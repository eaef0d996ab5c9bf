#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, part 1: install what is missing, build the release
# configuration and run the main job (`hula demo`: the thesis's example
# curves, interpolated and analysed). Extra arguments are passed to `hula`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
cmake --preset release >/dev/null
cmake --build --preset release
if [ $# -eq 0 ]; then set -- demo; fi
exec build/release/apps/hula/hula "$@"
