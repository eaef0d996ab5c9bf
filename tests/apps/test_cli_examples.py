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
import math
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


# --- Values: each check runs after its docs/cli.md command and asserts what the page (or a closed form) says
# the command gives, computed here independently of hula (closed forms, the input files, or hula's own other
# commands only where the claim is that two commands agree: a split, a reversal, a conversion).


def close(a, b, tol, what):
    """Vectors (or numbers) a and b agree within tol (absolute, per component)."""
    a = a if isinstance(a, list) else [a]
    b = b if isinstance(b, list) else [b]
    assert len(a) == len(b) and all(abs(x - y) <= tol for x, y in zip(a, b)), f"{what}: {a} != {b} (tol {tol})"


def hula_json(workdir, *args):
    r = subprocess.run([HULA, *args], cwd=workdir, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, f"hula {' '.join(args)}: {r.stderr[-500:]}"
    return json.loads(r.stdout)


def point_at(workdir, curve, t, order=0):
    return hula_json(workdir, "eval", curve, "--at", repr(t), "--derivatives", str(order))["results"][0]["derivatives"]


def csv_points(path):
    return [[float(x) for x in line.split(",")] for line in path.read_text().splitlines() if line.strip()]


def check_eval(out, workdir):
    # the curve interpolates examples/cli/pts.csv: C(0) and C(1) are its first and last points, and C'(1) points
    # along +x (--end direction:1,0,0)
    pts = csv_points(workdir / "examples" / "cli" / "pts.csv")
    first, middle, last = out["results"]
    close(first["derivatives"][0], pts[0][: len(first["derivatives"][0])], 1e-9, "C(0)")
    close(last["derivatives"][0], pts[-1][: len(last["derivatives"][0])], 1e-9, "C(1)")
    d = last["derivatives"][1]
    speed = math.hypot(*d)
    close([x / speed for x in d], [1.0, 0.0, 0.0][: len(d)], 1e-12, "C'(1) direction")
    assert middle["t"] == 0.5


def check_info(out, workdir):
    # a C2 cubic through the 8 points of pts.csv: degree 3, 8 + 2 control points, on [0, 1], planar in z = 0
    pts = csv_points(workdir / "examples" / "cli" / "pts.csv")
    assert out["degree"] == 3 and len(out["control_points"]) == len(pts) + 2, out
    close(out["domain"], [0.0, 1.0], 0.0, "domain")
    # the arc length is at least the polygon's (a chord never exceeds its arc)
    polygon = sum(math.dist(p, q) for p, q in zip(pts, pts[1:]))
    assert polygon <= out["length"] <= 1.5 * polygon, (polygon, out["length"])


def check_abs_kink(out, workdir):
    # |t| at 0: the value 0 is kept, the first derivative is null with the kink named
    r = out["results"][0]
    assert r["derivatives"][0] == [0.0] and r["derivatives"][1] == [None], r
    assert r["undefined"]["kind"] == "AbsKink" and r["undefined"]["order"] == 1, r


def integral(expected, tol):
    def check(out, workdir):
        value = out["integral"]["value"]
        assert out["integral"]["converged"] and abs(value - expected) <= tol, (value, expected)
    return check


def check_singularities(out, workdir):
    # abs(t + 0.5) + 1/(t - 1) on [-3, 3]: a kink at -0.5 and a pole at 1, nothing else
    points = {(round(p["t"], 12), p["kind"]) for p in out["singularities"]["points"]}
    assert points == {(-0.5, "Kink"), (1.0, "Pole")} or {t for t, _ in points} == {-0.5, 1.0}, points


def check_helix(out, workdir):
    # the NURBS helix.json is within 1e-7 of (2 cos t, 2 sin t, t / 2) (measured here at 13 parameters)
    assert out["nurbs"]["max_deviation"] <= 1e-7, out["nurbs"]
    for i in range(13):
        t = 2 * math.pi * i / 12
        close(point_at(workdir, "helix.json", t)[0], [2 * math.cos(t), 2 * math.sin(t), 0.5 * t], 1e-7, f"helix({t})")


def check_degree_undone(out, workdir):
    # reduce-degree of the elevated curve gives back curve.json: degree 3 and the same control points
    a = json.loads((workdir / "cubic.json").read_text())
    b = json.loads((workdir / "curve.json").read_text())
    assert a["degree"] == b["degree"] == 3
    assert len(a["control_points"]) == len(b["control_points"])
    for p, q in zip(a["control_points"], b["control_points"]):
        close(p, q, 1e-9, "control point")


def check_split(out, workdir):
    # first.json ends and second.json starts at C(0.4) of curve.json
    at = point_at(workdir, "curve.json", 0.4)[0]
    end = hula_json(workdir, "info", "first.json")["domain"][1]
    close(point_at(workdir, "first.json", end)[0], at, 1e-9, "first's end")
    start = hula_json(workdir, "info", "second.json")["domain"][0]
    close(point_at(workdir, "second.json", start)[0], at, 1e-9, "second's start")


def check_reverse(out, workdir):
    # R(t) = C(1 - t) on [0, 1]
    for t in (0.0, 0.25, 0.6, 1.0):
        close(point_at(workdir, "reversed.json", t)[0], point_at(workdir, "curve.json", 1 - t)[0], 1e-9, f"R({t})")


def check_reparam(out, workdir):
    # the same point set on [0, 10]: L(10 t) = C(t)
    for t in (0.0, 0.3, 1.0):
        close(point_at(workdir, "long.json", 10 * t)[0], point_at(workdir, "curve.json", t)[0], 1e-9, f"L({10 * t})")


def check_to_law(out, workdir):
    # "the same curve, held by its law": points and first derivatives agree
    for t in (0.1, 0.5, 0.9):
        a, b = point_at(workdir, "curve_law.json", t, 1), point_at(workdir, "curve.json", t, 1)
        close(a[0], b[0], 1e-6, f"law C({t})")
        close(a[1], b[1], 1e-4 * math.hypot(*b[1]), f"law C'({t})")


def check_crosses_at_origin(out, workdir):
    # "the wave and the S-curve cross at the origin"
    assert any(math.hypot(*p["point"]) <= 1e-6 for p in out["points"]), out["points"]


def check_quarter_circle(out, workdir):
    # κ = 1, τ = 0 for s in [0, π/2] from the origin along +x turning to +y: (sin s, 1 - cos s, 0)
    for p in out["points"]:
        s = p["s"]
        close(p["position"], [math.sin(s), 1 - math.cos(s), 0.0], 1e-8, f"position at s = {s}")
        close(p["T"], [math.cos(s), math.sin(s), 0.0], 1e-8, f"T at s = {s}")


def check_clothoid_quarter(out, workdir):
    # the docs' output: one segment of the unit circle, κ = 1 throughout, length π/2
    assert out["kind"] == "g1" and len(out["segments"]) == 1, out
    seg = out["segments"][0]
    close([seg["kappa0"], seg["kappa1"], seg["dkappa"]], [1.0, 1.0, 0.0], 1e-9, "curvatures")
    close([seg["length"], out["length"]], [math.pi / 2, math.pi / 2], 1e-9, "length")
    close(seg["end"], [1.0, 1.0], 1e-9, "end point")


def check_rosenbrock(out, workdir):
    # Rosenbrock's minimum is 0 at (1, 1, 1, 1)
    best = out["best"]
    assert best["objectives"][0] <= 1e-6, best
    close(best["variables"], [1.0] * 4, 1e-2, "minimiser")


def check_onemax(out, workdir):
    # onemax of 64 bits, minimised as the count of unset bits: the optimum sets all 64, objective 0
    best = out["best"]
    assert len(best["variables"]) == 64 and all(v == 1 for v in best["variables"]), best
    assert best["objectives"] == [64 - sum(best["variables"])] == [0], best


def check_step_round_trip(out, workdir):
    # the cubic Bézier spine.json through STEP and back: the same curve, a clamped cubic B-spline on one span
    # with the Bézier's control points, and nothing lost (max_deviation 0)
    assert out["curves"] == 1 and out["skipped"] == 0 and out["max_deviation"] == 0.0, out
    a = json.loads((workdir / "examples" / "curves" / "spine.json").read_text())
    b = json.loads((workdir / "spine-from-step.json").read_text())
    assert a["kind"] == "bezier" and b["degree"] == len(a["control_points"]) - 1 == 3, b
    assert b["knots"] == [0.0] * 4 + [1.0] * 4, b["knots"]
    for p, q in zip(a["control_points"], b["control_points"], strict=True):
        close(q, p, 1e-12, "control point")


# docs/cli.md command line -> its value check (every line here must be on the page).
VALUE_CHECKS = {
    "hula eval curve.json --at 0,0.5,1 --derivatives 1": check_eval,
    "hula info curve.json": check_info,
    "hula law 'abs(t)' --at 0 --derivatives 1": check_abs_kink,
    "hula law 'log(t)' --integrate 0,1": integral(-1.0, 1e-12),
    "hula law 't*exp(t)' --integrate 0,1": integral(1.0, 1e-12),
    "hula law 'exp(-t^2)' --integrate -inf,inf": integral(math.sqrt(math.pi), 1e-9),
    "hula law 'abs(t + 0.5) + 1/(t - 1)' --singularities -3,3": check_singularities,
    "hula law 'vec(2*cos(t), 2*sin(t), 0.5*t)' --to-nurbs 0,6.283185307179586 --tolerance 1e-7 -o helix.json":
        check_helix,
    "hula edit reduce-degree quartic.json --tolerance 0 -o cubic.json": check_degree_undone,
    "hula edit split curve.json --at 0.4 -o first.json --second second.json": check_split,
    "hula edit reverse curve.json -o reversed.json": check_reverse,
    "hula edit reparam curve.json --domain 0,10 -o long.json": check_reparam,
    "hula edit to-law curve.json -o curve_law.json": check_to_law,
    "hula intersect curve.json examples/cli/reference.json": check_crosses_at_origin,
    "hula reconstruct --kappa 1 --tau 0 --length 1.5707963267948966": check_quarter_circle,
    "hula clothoid --start-point 0,0 --start-angle 0 --end-point 1,1 --end-angle 1.5707963267948966":
        check_clothoid_quarter,
    "hula optimise --problem rosenbrock --dimension 4 --algorithm nelder-mead --evaluations 5000": check_rosenbrock,
    "hula optimise --problem onemax --dimension 64 --algorithm ga-binary --boost 1,8 --log run.csv": check_onemax,
    "hula convert spine.step -o spine-from-step.json": check_step_round_trip,
}


def value_check(line):
    """The value check of a page line (its comment dropped), or None."""
    return VALUE_CHECKS.get(line.split("#")[0].strip())


def test_every_sh_example_runs(workdir):
    # checks each docs/cli.md ```sh command exits with its documented code and prints JSON or nothing (or the
    # table its --format asks for), and the commands of VALUE_CHECKS give the values the page states (closed
    # forms: integrals, the quarter circle, Rosenbrock's minimum; the inputs interpolated; edits that keep the
    # point set)
    ran, checked = 0, set()
    for heading, line in commands():
        expected = re.search(r"#\s*exit (\d+)", line)
        r = subprocess.run(argv(line), cwd=workdir, capture_output=True, text=True, timeout=600)
        want = int(expected.group(1)) if expected else 0
        assert r.returncode == want, f"{heading}: `{line}` exited {r.returncode}, not {want}: {r.stderr[-2000:]}"
        check_output(line, r.stdout)
        check = value_check(line)
        if check is not None:
            check(json.loads(r.stdout) if r.stdout.strip() else None, workdir)
            checked.add(line.split("#")[0].strip())
        ran += 1
    assert ran >= 30
    assert checked == set(VALUE_CHECKS), f"value checks whose command is no longer on the page: {set(VALUE_CHECKS) - checked}"


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
