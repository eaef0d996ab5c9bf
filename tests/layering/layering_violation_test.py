#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks scripts/check_layering.py against deliberate violations: a copy of the
real tree passes; the same copy with an upward include (nurbs including io), a
header-only upward include (a curve header including diffgeom), a foreign
detail/ include, a server route including studies (below it, but reached
through oli), a CLI command including diffgeom (reached through io/oli), and
io's curve codec including a studies header or a study codec (io_studies)
fails, naming each file, line and included header."""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

root = pathlib.Path(sys.argv[1]).resolve()
checker = root / "scripts" / "check_layering.py"


def run(tree: pathlib.Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(checker), "--root", str(tree)], capture_output=True, text=True,
                          timeout=120)


def append(path: pathlib.Path, line: str) -> int:
    text = path.read_text()
    path.write_text(text + line + "\n")
    return text.count("\n") + 1


with tempfile.TemporaryDirectory() as tmp:
    tree = pathlib.Path(tmp)
    shutil.copytree(root / "cmake", tree / "cmake")
    shutil.copytree(root / "src", tree / "src")
    shutil.copytree(root / "apps", tree / "apps")
    clean = run(tree)
    assert clean.returncode == 0, "the real tree must pass:\n" + clean.stdout + clean.stderr

    l1 = append(tree / "src/hula/nurbs/knot_vector.cpp", '#include "hula/io/json_curve.hpp"')
    l2 = append(tree / "src/hula/curve/curve.hpp", '#include "hula/diffgeom/frenet.hpp"')
    l3 = append(tree / "src/hula/studies/knot_fairing.cpp", '#include "hula/nurbs/detail/homogeneous.hpp"')
    l4 = append(tree / "src/hula/server/routes/entities.cpp", '#include "hula/studies/fairing_assistant.hpp"')
    l5 = append(tree / "apps/hula/commands/analyse.cpp", '#include "hula/diffgeom/frenet.hpp"')
    l6 = append(tree / "src/hula/io/json_curve.cpp", '#include "hula/studies/profile.hpp"')
    l7 = append(tree / "src/hula/io/points_file.hpp", '#include "hula/io/study_file.hpp"')
    # The MPI runtime is reached through oli (hula/oli/process_ranks.hpp) like every other entry: no exemption.
    l8 = append(tree / "apps/hula/commands/batch.cpp", '#include "hula/optim/islands_mpi.hpp"')
    # A study codec may include studies: not a violation.
    append(tree / "src/hula/io/study_file.cpp", '#include "hula/studies/profile.hpp"')
    bad = run(tree)
    assert bad.returncode == 1, "violations must fail the check:\n" + bad.stdout
    expected = [
        f'src/hula/nurbs/knot_vector.cpp:{l1} includes "hula/io/json_curve.hpp" (io is not below nurbs)',
        f'src/hula/curve/curve.hpp:{l2} includes "hula/diffgeom/frenet.hpp" (diffgeom is not below curve)',
        f'src/hula/studies/knot_fairing.cpp:{l3} includes "hula/nurbs/detail/homogeneous.hpp" (detail/ is private to nurbs)',
        f'src/hula/server/routes/entities.cpp:{l4} includes "hula/studies/fairing_assistant.hpp" '
        '(server reaches studies through oli or io)',
        f'apps/hula/commands/analyse.cpp:{l5} includes "hula/diffgeom/frenet.hpp" '
        '(the CLI reaches diffgeom through oli or io)',
        f'src/hula/io/json_curve.cpp:{l6} includes "hula/studies/profile.hpp" '
        "(io's codecs do not depend on studies: a study codec belongs to io_studies)",
        f'src/hula/io/points_file.hpp:{l7} includes "hula/io/study_file.hpp" '
        "(io's codecs do not depend on studies: a study codec belongs to io_studies)",
        f'apps/hula/commands/batch.cpp:{l8} includes "hula/optim/islands_mpi.hpp" '
        '(the CLI reaches optim through oli or io)',
    ]
    for e in expected:
        assert ("layering violation: " + e) in bad.stdout, f"missing: {e}\n--- output:\n{bad.stdout}"
    assert bad.stdout.count("layering violation:") == 8, bad.stdout
# The check keeps no list of exemptions (the criterion): no (file, module) pair is let through.
script = (root / "scripts" / "check_layering.py").read_text()
assert not re.search(r"^\w*(STILL_DIRECT|EXEMPT|ALLOW)\w*\s*[:=]", script, re.M | re.I), \
    "check_layering.py must not carry a list of exemptions"
print("layering check: clean tree passes, 8 deliberate violations reported, no exemption list")
