#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages HulaHoops needs to build, test and benchmark.
# Idempotent: packages already present are skipped, and apt is not touched when
# nothing is missing. Runs as root, or through sudo when it is available.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git python3
  clang-format-14 clang-14 libclang-rt-14-dev
  libeigen3-dev libboost-dev libboost-math-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev librapidcheck-dev libbenchmark-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev
  libpagmo-dev libboost-serialization-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  libopenmpi-dev openmpi-bin
  libsqlite3-dev sqlite3
  doxygen
  python3 python3-jsonschema curl
  chromium
  help2man util-linux
  libceres-dev
  libdxflib-dev
)
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
  echo "setup-debian: all ${#packages[@]} packages present"
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
