#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The Python package as its users install it (pyproject.toml, setup.py), offline:

1. `python3 -m venv --system-site-packages V1` and `V1/bin/pip install --no-index --no-build-isolation SOURCE`
   (Debian's setuptools, wheel and NumPy through the system site packages, nothing fetched);
2. `pip wheel --no-index --no-build-isolation --no-deps SOURCE` makes a wheel, installed with
   `--no-index` into a second venv V2;
3. in each venv, from a directory outside the source tree, `import hulahoops` loads the venv's copy,
   `hulahoops.__version__` is CMake's project version and the installed distribution's version, the
   compiled module carries docstrings, a quadratic Bézier evaluates to its closed-form point, and (in
   builds with Open CASCADE) the hula-exchange helper the package ships beside its module writes STEP
   and IGES that read back to the same control points and knots (hh.write, hh.read, Document.export).

The backend builds the compiled module in the existing build directory given as BUILD_DIR
(HULA_CMAKE_BUILD_DIR), so the test packages the tree ctest runs in instead of compiling a second one.
Usage: pip_install_test.py SOURCE_DIR BUILD_DIR WORK_DIR
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import zipfile

source, build, work = (pathlib.Path(a).resolve() for a in sys.argv[1:4])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
version = re.search(r"project\(\s*hulahoops\s+VERSION\s+([0-9.]+)", (source / "CMakeLists.txt").read_text()).group(1)
env = dict(os.environ, HULA_CMAKE_BUILD_DIR=str(build), HULA_PIP_BUILD_BASE=str(work / "setuptools"),
           PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_CACHE_DIR="1", PYTHONDONTWRITEBYTECODE="1")
env.pop("PYTHONPATH", None)
env.pop("HULA_EXCHANGE_HELPER", None)

CHECK = r"""
import importlib.metadata, pathlib, sys
import numpy as np
import hulahoops as hh
venv = pathlib.Path(sys.argv[1]).resolve()
where = pathlib.Path(hh.__file__).resolve()
assert venv in where.parents, f"hulahoops imported from {where}, not from the venv {venv}"
assert hh.__version__ == sys.argv[2], (hh.__version__, sys.argv[2])
assert importlib.metadata.version("hulahoops") == hh.__version__
assert hh._core.__doc__, "the compiled module has no docstring"
# B(1/4) of the quadratic Bezier (0,0), (2,4), (4,0) is (9 P0 + 6 P1 + P2) / 16 = (1.0, 1.5).
c = hh.NurbsCurve(2, [0, 0, 0, 1, 1, 1], np.array([[0.0, 0.0], [2.0, 4.0], [4.0, 0.0]]))
p = c(0.25)
assert np.allclose(p, [1.0, 1.5], rtol=0, atol=1e-15), p
print(f"hulahoops {hh.__version__} from {where.parent}: B(1/4) = {p.tolist()}")
# STEP and IGES through the hula-exchange helper the package ships beside the module (no
# HULA_EXCHANGE_HELPER): written by hh.write and Document.export, read back exactly by hh.read.
helper = hh.exchange_helper()
if helper is not None:
    helper = pathlib.Path(helper)
    assert helper.parent == where.parent and helper.name == "hula-exchange", (helper, where)
    cubic = hh.NurbsCurve(3, [0, 0, 0, 0, 0.4, 1, 1, 1, 1],
                          np.array([[0.0, 0, 0], [1, 2, 0.5], [3, 2.5, 1], [4, 0, 2], [6, 1, 0]]))
    for ext in ("step", "iges"):
        hh.write(cubic, f"c.{ext}", names=["spine"])
        back = hh.read(f"c.{ext}")
        assert len(back) == 1 and back[0].degree == 3, back
        assert np.array_equal(back[0].control_points, cubic.control_points), back[0].control_points
        assert np.array_equal(back[0].knots, cubic.knots), back[0].knots
    with hh.Document.create("d.hula", force=True) as doc:
        doc.add(cubic, name="spine")
        assert doc.export(1, "d.step")["curves"] == 1
        assert doc.import_("d.step")["labels"] == [2]
        assert np.array_equal(np.asarray(doc.show(2)["control_points"]), cubic.control_points)
    print(f"STEP and IGES written and read through {helper}")
"""


def run(*cmd, cwd=work):
    print("+", " ".join(str(c) for c in cmd), flush=True)
    done = subprocess.run([str(c) for c in cmd], cwd=cwd, env=env, text=True, capture_output=True, timeout=1800)
    print(done.stdout[-4000:], done.stderr[-4000:], sep="\n", flush=True)
    if done.returncode != 0:
        sys.exit(f"failed ({done.returncode}): {' '.join(str(c) for c in cmd)}")
    return done


def venv(name):
    path = work / name
    run(sys.executable, "-m", "venv", "--system-site-packages", path)
    return path


v1 = venv("v1")
run(v1 / "bin" / "pip", "install", "--no-index", "--no-build-isolation", source)
run(v1 / "bin" / "python", "-c", CHECK, v1, version)

run(v1 / "bin" / "pip", "wheel", "--no-index", "--no-build-isolation", "--no-deps", "-w", work / "dist", source)
wheels = sorted((work / "dist").glob("hulahoops-*.whl"))
assert len(wheels) == 1, wheels
assert re.match(rf"hulahoops-{re.escape(version)}-cp3\d+-cp3\d+-linux_\w+\.whl$", wheels[0].name), wheels[0].name
# The plugins (pagmo, Ceres, SQLite; Open CASCADE) and the STEP/IGES helper travel in the wheel, beside the module.
shipped = set(zipfile.ZipFile(wheels[0]).namelist())
expected = {"hulahoops/libhula_pagmo.so", "hulahoops/libhula_ceres.so", "hulahoops/libhula_sqlite.so"}
if (build / "apps" / "hula" / "hula-exchange").exists():
    expected |= {"hulahoops/libhula_occt.so", "hulahoops/hula-exchange"}
assert expected <= shipped, expected - shipped
v2 = venv("v2")
run(v2 / "bin" / "pip", "install", "--no-index", wheels[0])
run(v2 / "bin" / "python", "-c", CHECK, v2, version)
print(f"pip install and pip wheel: {wheels[0].name} installs and imports in two venvs")
