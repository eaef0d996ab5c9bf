# SPDX-License-Identifier: MIT
# docs/cli.md executed as a user would type it (issue 10: doc examples are
# executed, not just shown). Every command of the page's ```sh blocks runs, in
# page order, from a scratch copy of the repository's examples/ (the files the
# examples name are shipped there: examples/cli/, examples/studies/, ...), so a
# command may read what an earlier one wrote (curve.json, first.json, fit.json);
# each must exit 0, or with the code its comment states ("# exit 4: ..."), and
# print JSON (or nothing) on stdout. `mpirun` lines run under Open MPI on
# loopback (oversubscribed) when hula is built with HULA_MPI, and as the plain
# command (islands on threads, one batch slot) otherwise. The ```console blocks
# are the `hula doc` and `hula fit` transcripts, run with their outputs by
# tests/oli/doc_cli_test.cpp and tests/studies/fit_cli_test.cpp.
import json
import os
import pathlib
import re
import shlex
import shutil
import subprocess

import pytest

HULA = os.environ["HULA_BIN"]
SOURCE = pathlib.Path(os.environ["HULA_SOURCE_DIR"])
MPI = os.environ.get("HULA_MPI") == "ON"
MPIRUN = ["mpirun", "--oversubscribe", "--allow-run-as-root", "--mca", "btl_vader_single_copy_mechanism", "none"]
PAGE = SOURCE / "docs" / "cli.md"


def blocks(page, language):
    """(heading, lines) of every ```language block, lines with their backslash continuations joined."""
    out, heading, inside, lines = [], None, False, []
    for line in page.splitlines():
        if not inside and line.startswith("## "):
            heading = line
        if not inside and line.strip() == "```" + language:
            inside, lines = True, []
        elif inside and line.strip() == "```":
            inside = False
            joined = []
            for text in lines:
                if joined and joined[-1].endswith("\\"):
                    joined[-1] = joined[-1][:-1] + " " + text.strip()
                else:
                    joined.append(text)
            out.append((heading, [text for text in joined if text.strip()]))
        elif inside:
            lines.append(line)
    return out


def commands():
    """Every command of the page's ```sh blocks, in order: (heading, line)."""
    return [(heading, line) for heading, lines in blocks(PAGE.read_text(), "sh") for line in lines]


def argv(line):
    """The command line to run: hula by its path, mpirun with the loopback options (or dropped without MPI)."""
    words = shlex.split(line, comments=True)
    launcher = []
    if words[0] == "mpirun":
        start = words.index("hula")
        launcher = MPIRUN + words[1:start] if MPI else []
        words = words[start:]
    assert words[0] == "hula", f"a docs/cli.md example runs something other than hula: {line}"
    return launcher + [HULA] + words[1:]


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    """A scratch copy of examples/ and tests/data/real/ (the airfoils of docs/howto/airfoil.md), the directory
    every example runs from (as from the repository root)."""
    root = tmp_path_factory.mktemp("cli-examples")
    shutil.copytree(SOURCE / "examples", root / "examples")
    shutil.copytree(SOURCE / "tests" / "data" / "real", root / "tests" / "data" / "real")
    return root


def check_output(line, stdout):
    """The output of an example: JSON or nothing, or with --format csv|jsonl|text that table (jsonl lines of JSON,
    a csv "# " header and rows, some text)."""
    table = re.search(r"--format (csv|jsonl|text)", line)
    if table and table.group(1) == "jsonl":
        for record in stdout.splitlines():
            json.loads(record)
    elif table and table.group(1) == "csv":
        assert stdout.startswith("# ") and len(stdout.splitlines()) >= 2, f"`{line}`: {stdout[:200]}"
    elif table:
        assert stdout.strip(), f"`{line}` printed nothing"
    elif stdout.strip():
        json.loads(stdout)


def test_every_sh_example_runs(workdir):
    # checks each docs/cli.md ```sh command exits with its documented code and prints JSON or nothing (or the
    # table its --format asks for)
    ran = 0
    for heading, line in commands():
        expected = re.search(r"#\s*exit (\d+)", line)
        r = subprocess.run(argv(line), cwd=workdir, capture_output=True, text=True, timeout=600)
        want = int(expected.group(1)) if expected else 0
        assert r.returncode == want, f"{heading}: `{line}` exited {r.returncode}, not {want}: {r.stderr[-2000:]}"
        check_output(line, r.stdout)
        ran += 1
    assert ran >= 30


def test_console_blocks_are_the_tested_transcripts():
    # checks every ```console block sits in a section whose transcript another test runs with its output
    headings = {heading for heading, _ in blocks(PAGE.read_text(), "console")}
    assert headings <= {"## `hula doc`", "## `hula fit`"}, headings


def test_shipped_reference_is_the_documented_curve(tmp_path):
    # checks examples/cli/reference.json is what examples/cli/README.md says: `hula law --to-nurbs` of the
    # S-curve the scan was taken from, written again here byte for byte
    readme = (SOURCE / "examples" / "cli" / "README.md").read_text()
    command = re.search(r"`(hula law [^`]*--to-nurbs[^`]*)`", readme).group(1)
    words = shlex.split(command)
    words[words.index("-o") + 1] = str(tmp_path / "reference.json")
    subprocess.run([HULA] + words[1:], check=True, capture_output=True, timeout=120)
    assert (tmp_path / "reference.json").read_bytes() == (SOURCE / "examples" / "cli" / "reference.json").read_bytes()


def test_every_howto_example_runs(workdir):
    # checks each ```sh command of the how-to pages (docs/howto/*.md) exits 0 and prints JSON or nothing (or the
    # table its --format asks for)
    ran = 0
    for page in sorted((SOURCE / "docs" / "howto").glob("*.md")):
        for heading, lines in blocks(page.read_text(), "sh"):
            for line in lines:
                r = subprocess.run(argv(line), cwd=workdir, capture_output=True, text=True, timeout=600)
                assert r.returncode == 0, f"{page.name} {heading}: `{line}` exited {r.returncode}: {r.stderr[-2000:]}"
                check_output(line, r.stdout)
                ran += 1
    assert ran >= 20
