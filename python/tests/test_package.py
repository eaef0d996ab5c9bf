# SPDX-License-Identifier: MIT
# The package's identity and help: __version__ is CMake's project(VERSION) (the version pip's metadata
# carries, pyproject.toml through setup.py), and help() on the compiled classes and functions shows
# descriptions, not only signatures: every public class, method, property and function of _core the
# package exports has a docstring beyond pybind11's signature line.
import inspect
import re

import hulahoops as hh
from hulahoops import _core

from conftest import SOURCE


def described(doc):
    """The docstring without pybind11's signature lines ("name(args) -> type")."""
    lines = [line for line in (doc or "").splitlines() if not re.match(r"^\s*(\d+\. )?\w+\(.*\)( -> .*)?$", line)]
    return "\n".join(lines).replace("Overloaded function.", "").strip()


def test_version_is_the_cmake_project_version():
    # checks __version__ against project(hulahoops VERSION x.y.z) in CMakeLists.txt, on the package and the module
    version = re.search(r"project\(\s*hulahoops\s+VERSION\s+([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text()).group(1)
    assert hh.__version__ == version
    assert _core.__version__ == version


def test_compiled_classes_and_functions_have_descriptions():
    # checks each exported _core object, and each public member of its classes, has a description
    missing = []
    for name in hh.__all__:
        obj = getattr(hh, name)
        if getattr(obj, "__module__", "") != "hulahoops._core":
            continue
        if not described(obj.__doc__):
            missing.append(name)
        if inspect.isclass(obj):
            for member, value in vars(obj).items():
                if member.startswith("_") and member not in ("__init__", "__call__"):
                    continue
                doc = value.__doc__
                if not described(doc):
                    missing.append(f"{name}.{member}")
    assert not missing, f"no description: {missing}"


def test_help_of_nurbs_curve_describes_evaluation():
    # checks the text help() prints for NurbsCurve names the domain policies (the description of __call__)
    text = inspect.getdoc(hh.NurbsCurve.__call__)
    assert "OutOfDomainError" in text and "extrapolate" in text
    assert "validated NURBS curve" in hh.NurbsCurve.__doc__
