#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Include-level layering check (DESIGN.md: "a module depends only on the
modules below it, checked at include level, not only by target dependencies").

Scans every C++ source and header under src/hula/<module>/ and apps/ for
`#include "hula/<other>/..."` and refuses
  - an include of a module that is not below the including module in
    HULA_MODULE_ORDER (read from cmake/HulaModule.cmake, the one list), and
  - an include of another module's detail/ headers.
  - an include, from server/, of a module other than core, curve (the value
    type every layer holds), io and oli (DESIGN.md: "server depends on oli and
    io only"); SERVER_STILL_DIRECT is empty;
  - an include, from apps/, of a module below io/oli other than core and curve
    (the CLI translates: it calls io and oli entries), except the MPI runtime
    includes APPS_STILL_DIRECT lists with their reasons; a listed include that
    is gone is reported too, so the list stays the true list of what remains.
  - an include of a studies header, or of an io_studies header, from a file of
    io outside io_studies (the study codecs: the files of
    hula_add_module(io_studies SOURCES ...) in src/hula/io/CMakeLists.txt,
    each .cpp with its .hpp): reading a curve, points or a law does not
    depend on the studies.
`testing` (test support) may include any module.

Usage: check_layering.py [--root DIR]   (DIR holds cmake/, src/ and apps/)
Exit 0 when clean; 1 with one line per violation:
  layering violation: src/hula/nurbs/x.hpp:12 includes "hula/io/json_curve.hpp" (io is not below nurbs)
"""
import argparse
import pathlib
import re
import sys

SERVER_REACHES = {"core", "curve", "io", "io_studies", "oli", "server"}
# apps/ (the CLI) reaches what the server reaches, and the server and oli's own targets: every command
# translates its arguments into an io/oli entry and prints the answer (mpirun's ranks too: oli/process_ranks).
APPS_REACH = SERVER_REACHES | {"oli_store", "oli_kernel", "oli_exchange"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"hula/([a-z_]+)/([^"]+)"')
SOURCES = {".hpp", ".cpp", ".h", ".cc"}


def module_order(root: pathlib.Path) -> list[str]:
    text = (root / "cmake" / "HulaModule.cmake").read_text()
    m = re.search(r"set\(HULA_MODULE_ORDER\s+([^)]*)\)", text)
    if not m:
        sys.exit("check_layering: no set(HULA_MODULE_ORDER ...) in cmake/HulaModule.cmake")
    return m.group(1).split()


def io_studies_stems(root: pathlib.Path) -> set[str]:
    """The file stems of the io_studies target, read from its SOURCES in src/hula/io/CMakeLists.txt."""
    cmake = root / "src" / "hula" / "io" / "CMakeLists.txt"
    if not cmake.is_file():
        return set()
    m = re.search(r"hula_add_module\(io_studies\s+SOURCES\s+(.*?)\s+DEPS", cmake.read_text(), re.S)
    if not m:
        sys.exit("check_layering: no hula_add_module(io_studies SOURCES ...) in src/hula/io/CMakeLists.txt")
    return {pathlib.PurePosixPath(s).stem for s in m.group(1).split()}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    root = parser.parse_args().root.resolve()
    order = module_order(root)
    rank = {name: i for i, name in enumerate(order)}
    study_codecs = io_studies_stems(root)
    violations = []
    scanned = 0
    for base in (root / "src" / "hula", root / "apps"):
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            if path.suffix not in SOURCES or not path.is_file():
                continue
            rel = path.relative_to(root)
            owner = rel.parts[2] if rel.parts[0] == "src" else "apps"
            if owner == "io" and len(rel.parts) == 4 and path.stem in study_codecs:
                owner = "io_studies"
            if owner != "apps" and owner not in rank:
                violations.append(f"layering violation: {rel}: module '{owner}' is not in HULA_MODULE_ORDER")
                continue
            scanned += 1
            for line_no, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target, rest = m.group(1), m.group(2)
                shown = f'"hula/{target}/{rest}"'
                if target == "io" and pathlib.PurePosixPath(rest).stem in study_codecs and "/" not in rest:
                    target = "io_studies"
                if owner == "io" and target in ("studies", "io_studies"):
                    violations.append(f"layering violation: {rel}:{line_no} includes {shown} "
                                      f"(io's codecs do not depend on studies: a study codec belongs to io_studies)")
                    continue
                if target not in rank:
                    violations.append(f"layering violation: {rel}:{line_no} includes {shown} (no module '{target}')")
                elif target != owner and rest.startswith("detail/"):
                    violations.append(
                        f"layering violation: {rel}:{line_no} includes {shown} (detail/ is private to {target})")
                elif owner not in ("apps", "testing", target) and rank[target] >= rank[owner]:
                    violations.append(
                        f"layering violation: {rel}:{line_no} includes {shown} ({target} is not below {owner})")
                elif owner == "server" and target not in SERVER_REACHES:
                    violations.append(f"layering violation: {rel}:{line_no} includes {shown} "
                                      f"(server reaches {target} through oli or io)")
                elif owner == "apps" and target not in APPS_REACH:
                    violations.append(f"layering violation: {rel}:{line_no} includes {shown} "
                                      f"(the CLI reaches {target} through oli or io)")
    for v in violations:
        print(v)
    if violations:
        print(f"check_layering: {len(violations)} violation(s) in {scanned} files "
              f"(order: {' < '.join(order)})")
        return 1
    print(f"check_layering: {scanned} files, no violation (order: {' < '.join(order)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
