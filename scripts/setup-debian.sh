#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages HulaHoops needs: by default only what a run
# needs (scripts/run.sh: build the release configuration with the Python
# package and MPI islands, the web workbench, `pip install .` in a venv);
# with --test also the test and development toolchain (scripts/test.sh, CI:
# clang-14 and clang-format-14, the fuzzers' runtime, GoogleTest, RapidCheck,
# Google Benchmark, pytest, chromium for the e2e tests, doxygen, ...).
# Idempotent: packages already present are skipped, and apt is not touched when
# nothing is missing. Runs as root, or through sudo when it is available.
#   scripts/setup-debian.sh [--test]
set -euo pipefail

want_test=0
for arg in "$@"; do
  case "$arg" in
    --test) want_test=1 ;;
    -h | --help)
      sed -n '3,10p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *)
      echo "setup-debian: unknown argument '$arg' (expected --test)" >&2
      exit 2
      ;;
  esac
done

# What a run needs: the compiler and build tools, the libraries the release build links, the
# Python package's build (pybind11, NumPy) and its venv/pip install, Open MPI for islands across
# processes, help2man for the installed man page.
packages=(
  build-essential cmake ninja-build pkg-config python3
  libeigen3-dev libboost-dev libboost-math-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev
  libpagmo-dev libboost-serialization-dev
  libsqlite3-dev
  libceres-dev
  libdxflib-dev
  pybind11-dev python3-dev python3-numpy
  python3-venv python3-pip python3-setuptools python3-wheel
  libopenmpi-dev openmpi-bin
  help2man
)
# The test and development toolchain (--test): scripts/test.sh and CI.
if [ "$want_test" -eq 1 ]; then
  packages+=(
    git
    clang-format-14 clang-14 libclang-rt-14-dev
    libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
    python3-pytest python3-jsonschema
    sqlite3 curl util-linux doxygen
    chromium
  )
fi
# The web workbench (web/) needs Node.js >= 20 and npm; Debian's nodejs/npm
# are installed only when no node is on the PATH (a newer one is kept).
if ! command -v node >/dev/null 2>&1; then packages+=(nodejs); fi
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-debian: all ${#packages[@]} packages present$([ "$want_test" -eq 1 ] && echo " (with the test toolchain)")"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "setup-debian: missing packages (${missing[*]}) and not root; run as root or install sudo" >&2
    exit 1
  fi
fi

echo "setup-debian: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
