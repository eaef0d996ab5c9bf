# SPDX-License-Identifier: MIT
"""The setuptools side of pyproject.toml: the version from CMakeLists.txt's project(VERSION), and a
build_ext step that builds the compiled module hulahoops._core with the project's CMake build and
copies it into the package, with the plugins (libhula_pagmo.so, libhula_ceres.so, libhula_sqlite.so,
libhula_occt.so) and, in builds with Open CASCADE, the STEP/IGES helper hula-exchange beside it.

The CMake build directory is build/pip-cmake (configured Release with HULA_PYTHON=ON for the running
interpreter, no tests, no MPI), kept between installs so a second install only rebuilds what changed.
Environment:
  HULA_CMAKE_BUILD_DIR  an already configured build directory with HULA_PYTHON=ON (e.g. build/ci):
                        its hulahoops_core is built there and packaged, with that build's configuration
  HULA_CMAKE_ARGS       extra arguments for the configure step (e.g. "-DHULA_WITH_OCCT=OFF")
  HULA_PIP_BUILD_BASE   where setuptools puts its own build files and metadata (default build/pip)
  CMAKE_BUILD_PARALLEL_LEVEL, CMAKE_CXX_COMPILER_LAUNCHER  read by CMake itself
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version() -> str:
    text = (ROOT / "CMakeLists.txt").read_text()
    m = re.search(r"project\(\s*hulahoops\s+VERSION\s+([0-9][0-9.]*)", text)
    if not m:
        sys.exit("setup.py: no project(hulahoops VERSION x.y.z) in CMakeLists.txt")
    return m.group(1)


class CMakeBuild(build_ext):
    """Builds hulahoops._core with CMake (target hulahoops_core) instead of setuptools' compiler."""

    def build_extension(self, ext: Extension) -> None:
        given = os.environ.get("HULA_CMAKE_BUILD_DIR")
        build_dir = pathlib.Path(given).resolve() if given else ROOT / "build" / "pip-cmake"
        if not given:
            configure = [
                "cmake", "-S", str(ROOT), "-B", str(build_dir),
                "-DCMAKE_BUILD_TYPE=Release", "-DHULA_BUILD_TESTS=OFF", "-DHULA_PYTHON=ON", "-DHULA_MPI=OFF",
                f"-DPython3_EXECUTABLE={sys.executable}",
            ]
            if shutil.which("ninja"):
                configure += ["-G", "Ninja"]
            if (build_dir / "CMakeCache.txt").exists():
                configure = [a for a in configure if a not in ("-G", "Ninja")]
            configure += shlex.split(os.environ.get("HULA_CMAKE_ARGS", ""))
            self.announce("hulahoops: " + " ".join(configure), level=2)
            subprocess.run(configure, check=True)
        # With Open CASCADE the STEP/IGES helper is built too and shipped in the package, beside the
        # module, where oli::default_exchange_helper finds it (hulahoops.exchange_helper()).
        occt = re.search(r"^HULA_WITH_OCCT:BOOL=(ON|TRUE|1)$", (build_dir / "CMakeCache.txt").read_text(), re.M)
        targets = ["hulahoops_core"] + (["hula_exchange_helper"] if occt else [])
        subprocess.run(["cmake", "--build", str(build_dir), "--target", *targets], check=True)
        built = sorted((build_dir / "python" / "hulahoops").glob("_core*.so"))
        if len(built) != 1:
            raise RuntimeError(f"hulahoops: expected one _core*.so in {build_dir / 'python' / 'hulahoops'}, "
                               f"found {[str(b) for b in built]}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)
        # The plugins (pagmo, Ceres, SQLite, Open CASCADE) beside the module too, where hula::plugin_symbol looks for them.
        for plugin in sorted((build_dir / "lib" / "hulahoops").glob("libhula_*.so")):
            shutil.copyfile(plugin, target.parent / plugin.name)
        if occt:
            helper = target.parent / "hula-exchange"
            shutil.copyfile(build_dir / "apps" / "hula" / "hula-exchange", helper)
            helper.chmod(0o755)


build_base = pathlib.Path(os.environ.get("HULA_PIP_BUILD_BASE", ROOT / "build" / "pip"))
build_base.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    ext_modules=[Extension("hulahoops._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(build_base)}, "egg_info": {"egg_base": str(build_base)}},
)
