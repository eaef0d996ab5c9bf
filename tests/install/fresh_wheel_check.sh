#!/bin/sh
# SPDX-License-Identifier: MIT
# The nearest thing to a fresh machine this project can run offline: a wheel (made by `pip wheel`, e.g.
# by ctest install.pip under build/ci/install-pip/dist) installed into a venv that sees no system site
# packages but Debian's NumPy (linked in alone), with a fresh HOME and TMPDIR, no PYTHONPATH and none of
# the HULA_* variables, from a directory outside the source tree; then every ```python block of
# docs/python.md runs there in order (as python/tests/test_docs.py runs them), and STEP/IGES go
# through the helper the wheel ships.
#
# Not in ctest: it is only honest with the build tree moved away first (the compiled-in fallbacks of
# the exchange helper and the Open CASCADE plugin point into it), which a test of that tree cannot do:
#   mv build/ci build/ci.away && sh tests/install/fresh_wheel_check.sh build/ci.away/install-pip/dist/*.whl . /tmp/fresh
#   mv build/ci.away build/ci
# What it cannot check: a different machine or container (the same Debian libraries are installed
# here), and `pip install .` from source on a machine that never built the project (that is a full
# Release build; ctest install.pip builds the package from the existing build tree instead).
# Usage: fresh_wheel_check.sh WHEEL SOURCE_DIR WORK_DIR
set -eu
wheel=$(realpath "$1")
source=$(realpath "$2")
work=$3
rm -rf "$work"
mkdir -p "$work/home" "$work/tmp" "$work/run"
work=$(realpath "$work")
for v in $(env | sed -n 's/^\(HULA_[A-Z_]*\)=.*/\1/p'); do unset "$v"; done
unset PYTHONPATH PYTHONHOME VIRTUAL_ENV
export HOME="$work/home" TMPDIR="$work/tmp" PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1
/usr/bin/python3 -m venv "$work/v"
site=$("$work/v/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
ln -s /usr/lib/python3/dist-packages/numpy "$site/numpy"
for info in /usr/lib/python3/dist-packages/numpy-*-info; do ln -s "$info" "$site/"; done
"$work/v/bin/pip" install --no-index "$wheel"
cp -r "$source/examples" "$work/run/examples"
cd "$work/run"
"$work/v/bin/python" - "$source/docs/python.md" <<'EOF'
import re, sys
import hulahoops as hh
assert "/usr/lib/python3/dist-packages" not in sys.path, sys.path
print("hulahoops", hh.__version__, "from", hh.__file__, "; exchange helper", hh.exchange_helper())
blocks = re.findall(r"```python\n(.*?)```", open(sys.argv[1], encoding="utf-8").read(), flags=re.S)
namespace = {}
for i, block in enumerate(blocks):
    exec(compile(block, f"docs/python.md block {i}", "exec"), namespace)
print(f"docs/python.md: {len(blocks)} blocks ran")
EOF
