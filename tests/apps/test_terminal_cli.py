# SPDX-License-Identifier: MIT
# Terminal conventions of `hula`: --format json|jsonl|csv|text on the commands that print samples or
# tables (the table formats carry the numbers of the JSON document), "did you mean" for misspelt commands
# and options, pipes (process substitution, named FIFOs) as inputs, the bash completion of nested
# commands and enumerated values (sourced in bash, its function called with COMP_WORDS set), the man
# pages generated from the option tables, and the progress line on a pseudo-terminal (absent on a pipe)
# with `optimise --progress` JSON lines carrying every objective.
import json
import math
import os
import pathlib
import pty
import re
import select
import shutil
import subprocess
import threading

import pytest

HULA = os.environ["HULA_BIN"]
SOURCE = pathlib.Path(os.environ["HULA_SOURCE_DIR"])
SPINE = str(SOURCE / "examples" / "curves" / "spine.json")
PTS = str(SOURCE / "examples" / "cli" / "pts.csv")


def run(*args, cwd=None, check=True):
    r = subprocess.run([HULA, *args], capture_output=True, text=True, timeout=300, cwd=cwd)
    if check:
        assert r.returncode == 0, f"hula {' '.join(args)} exited {r.returncode}: {r.stderr}"
    return r


def formats(*args, timed=False):
    """The outputs of `hula ARGS` in every --format, the default included (`timed`: its report's seconds differ)."""
    out = {"default": run(*args).stdout}
    for f in ("json", "jsonl", "csv", "text"):
        out[f] = run(*args, "--format", f).stdout
    if timed:
        strip = lambda text: re.sub(r'"seconds": [0-9.e+-]+', '"seconds": 0', text)  # noqa: E731
        assert strip(out["json"]) == strip(out["default"]), "--format json is the default output"
    else:
        assert out["json"] == out["default"], "--format json is the default output, byte for byte"
    return out


def csv_rows(text):
    lines = text.splitlines()
    assert lines[0].startswith("# "), lines[0]
    header = lines[0][2:].split(" ")
    rows = [line.split(",") for line in lines[1:]]
    for row in rows:
        assert len(row) == len(header), (header, row)
    return header, rows


def number(cell):
    return None if cell == "" else float(cell)


def close(a, b):
    if a is None or b is None:
        return a is None and b is None
    return math.isclose(a, b, rel_tol=0.0, abs_tol=0.0) or a == b


# --format -------------------------------------------------------------------------------------------


def test_analyse_formats_carry_the_json_samples():
    # checks analyse's jsonl/csv/text give one record per sample with the JSON document's numbers
    out = formats("analyse", SPINE, "--samples", "7")
    doc = json.loads(out["json"])
    records = [json.loads(line) for line in out["jsonl"].splitlines()]
    assert len(records) == 7
    for i, r in enumerate(records):
        assert r["t"] == doc["t"][i] and r["s"] == doc["s"][i]
        assert r["point"] == doc["points"][i]
        assert r["T"] == doc["frames"]["T"][i] and r["B"] == doc["frames"]["B"][i]
        assert r["curvature"] == doc["curvature"][i] and r["U"] == doc["bishop"]["U"][i]
    header, rows = csv_rows(out["csv"])
    assert header[:5] == ["t", "s", "x", "y", "z"]
    assert "curvature" in header and "T_x" in header and "V_z" in header
    assert len(rows) == 7
    k = header.index("curvature")
    for i, row in enumerate(rows):
        assert close(number(row[0]), doc["t"][i])
        assert close(number(row[k]), doc["curvature"][i])
        assert [number(c) for c in row[2:5]] == doc["points"][i]
    text = out["text"].splitlines()
    assert len(text) == 7 and text[3].startswith("t = 0.5: s = ") and "curvature = " in text[3]


def test_closest_formats():
    # checks closest's table: px,py,pz (empty z for a 2-D point), t, x, y, z, distance per given point
    out = formats("closest", SPINE, "--point", "1,1", "--point", "2,2,0")
    doc = json.loads(out["json"])
    assert [json.loads(line) for line in out["jsonl"].splitlines()] == doc["results"]
    header, rows = csv_rows(out["csv"])
    assert header == ["px", "py", "pz", "t", "x", "y", "z", "distance"]
    assert rows[0][2] == "" and rows[1][2] == "0.0"
    for row, r in zip(rows, doc["results"]):
        assert close(number(row[3]), r["t"]) and close(number(row[7]), r["distance"])
        assert [number(c) for c in row[4:7]] == r["closest"]
    assert out["text"].splitlines()[1] == "point = [2.0,2.0,0.0]: t = 0.5, closest = [2.0,1.5,0.0], distance = 0.5"


def test_deviation_formats_one_record(tmp_path):
    # checks deviation's summary is one record: the same figures in jsonl, csv and text
    other = tmp_path / "other.json"
    run("edit", "elevate", SPINE, "--times", "1", "-o", str(other))
    out = formats("deviation", SPINE, str(other), "--samples", "11", "--mode", "closest")
    doc = json.loads(out["json"])
    assert json.loads(out["jsonl"]) == doc
    header, rows = csv_rows(out["csv"])
    assert header[:4] == ["a", "b", "mode", "samples"] and "max_axis_z" in header
    assert len(rows) == 1 and rows[0][2] == "closest" and close(number(rows[0][header.index("rms")]), doc["rms"])
    assert out["text"].startswith('a = "' + SPINE + '": b = ')


def test_law_at_formats_are_evals():
    # checks law --at prints eval's table (csv t,x,y,z,dx,dy,dz) and refuses a table format without --at
    out = formats("law", "vec(cos(t), sin(t), t)", "--at", "0,1", "--derivatives", "1")
    doc = json.loads(out["json"])
    header, rows = csv_rows(out["csv"])
    assert header == ["t", "x", "y", "z", "dx", "dy", "dz"]
    assert [number(c) for c in rows[1]] == [1.0, math.cos(1.0), math.sin(1.0), 1.0, -math.sin(1.0), math.cos(1.0), 1.0]
    assert [json.loads(line) for line in out["jsonl"].splitlines()] == doc["results"]
    assert out["text"].splitlines()[0] == "t = 0.0: [1.0,0.0,0.0] [0.0,1.0,1.0]"
    r = run("law", "sin(t)", "--roots", "1,4", "--format", "csv", check=False)
    assert r.returncode == 3 and "give --at" in r.stderr


def test_eval_formats_unchanged():
    # checks eval's csv/text keep their documented shapes through the shared table writer
    csv = run("eval", SPINE, "--at", "0,0.5", "--derivatives", "1", "--format", "csv").stdout
    assert csv.splitlines()[0] == "# t x y z dx dy dz"
    assert csv.splitlines()[2] == "0.5,2.0,1.5,0.0,4.5,0.0,0.0"
    text = run("eval", SPINE, "--at", "0.5", "--format", "text").stdout
    assert text == "t = 0.5: [2.0,1.5,0.0]\n"


def test_optimise_front_formats():
    # checks the NSGA-II front as a table: f0, f1, x0..x29 per member, the JSON front's numbers
    args = ("optimise", "--problem", "zdt1", "--algorithm", "nsga2", "--generations", "5", "--population", "16")
    out = formats(*args, timed=True)
    doc = json.loads(out["json"])
    header, rows = csv_rows(out["csv"])
    assert header[:3] == ["f0", "f1", "x0"] and header[-1] == "x29"
    assert len(rows) == len(doc["front"])
    for row, member in zip(rows, doc["front"]):
        assert [number(c) for c in row[:2]] == member["objectives"]
        assert [number(c) for c in row[2:]] == member["variables"]
    assert [json.loads(line) for line in out["jsonl"].splitlines()] == doc["front"]
    # one objective: the best solution is the table's one row
    best = run("optimise", "--problem", "sphere", "--algorithm", "ga-real", "--generations", "3", "--format", "csv")
    header, rows = csv_rows(best.stdout)
    assert header[0] == "f0" and len(rows) == 1


# did you mean ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "args, suggestion",
    [
        (["interpolte", "--points", PTS], "did you mean `hula interpolate`?"),
        (["doc", "exprt", "x.hula"], "did you mean `hula doc export`?"),
        (["analyse", SPINE, "--sampels", "3"], "did you mean --samples?"),
        (["optimise", "--problem", "zdt1", "--algoritm", "nsga2"], "did you mean --algorithm?"),
    ],
)
def test_did_you_mean(args, suggestion):
    # checks a misspelt command, subcommand or option is a usage error that names the nearest one
    r = run(*args, "--error-format", "json", check=False)
    assert r.returncode == 2, r.stderr
    assert suggestion in json.loads(r.stderr)["error"]["message"]


def test_did_you_mean_after_the_error_format_option():
    # checks a misspelt command after --error-format and its value still gets the nearest command
    r = run("--error-format", "json", "anlyse", SPINE, check=False)
    assert r.returncode == 2, r.stderr
    assert "did you mean `hula analyse`?" in json.loads(r.stderr)["error"]["message"]


def test_no_suggestion_for_a_far_word():
    # checks an unknown word far from every command gets no made-up suggestion
    r = run("zzzzzzzz", "--error-format", "json", check=False)
    assert r.returncode == 2 and "did you mean" not in r.stderr


# pipes as inputs ------------------------------------------------------------------------------------


def test_process_substitution_and_named_fifo_are_inputs(tmp_path):
    # checks --points <(cat pts.csv) and a named FIFO give the curve the file itself gives
    by_file = run("interpolate", "--points", PTS, "-o", "-").stdout
    bash = shutil.which("bash")
    r = subprocess.run([bash, "-c", f'"{HULA}" interpolate --points <(cat "{PTS}") -o -'], capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout == by_file
    fifo = tmp_path / "pts.fifo"
    os.mkfifo(fifo)
    writer = threading.Thread(target=lambda: fifo.write_bytes(pathlib.Path(PTS).read_bytes()))
    writer.start()
    r = run("interpolate", "--points", str(fifo), "-o", "-")
    writer.join(timeout=10)
    assert r.stdout == by_file
    # a device is still refused
    r = run("info", "/dev/zero", check=False)
    assert r.returncode == 3 and "character device" in r.stderr


# completion -----------------------------------------------------------------------------------------


def complete(script, *words):
    """COMPREPLY of the generated _hula for the command line `words` (the last one being completed)."""
    program = (f"source {script}\nCOMP_WORDS=({' '.join(repr(w) for w in words)})\n"
               f"COMP_CWORD={len(words) - 1}\n_hula\nprintf '%s\\n' \"${{COMPREPLY[@]}}\"\n")
    r = subprocess.run(["bash", "--norc", "--noprofile"], input=program, capture_output=True, text=True, timeout=30)
    assert r.returncode == 0, r.stderr
    return sorted(line for line in r.stdout.splitlines() if line)


def test_completion_nested_commands_and_enum_values(tmp_path):
    # checks the sourced script completes subcommands, their options and enumerated option values
    script = tmp_path / "hula"
    run("completion", "bash", "-o", str(script))
    assert complete(script, "hula", "interp") == ["interpolate"]
    assert complete(script, "hula", "doc", "ex") == ["export"]
    assert complete(script, "hula", "edit", "re") == ["rebuild", "reduce-degree", "refine", "remove-knots", "reparam",
                                                    "reverse"]
    assert complete(script, "hula", "optimise", "--algorithm", "n") == ["nelder-mead", "nsga2"]
    assert complete(script, "hula", "optimise", "--algorithm", "pagmo-n") == ["pagmo-nsga2"]
    assert complete(script, "hula", "eval", "c.json", "--format", "j") == ["json", "jsonl"]
    assert complete(script, "hula", "doc", "export", "d.hula", "--format", "st") == ["step", "step-ap214", "step-ap242"]
    assert complete(script, "hula", "doc", "export", "--o") == ["--output"]
    assert "--samples" in complete(script, "hula", "analyse", "--sa")
    assert complete(script, "hula", "--error-format", "t") == ["text"]


# man pages ------------------------------------------------------------------------------------------


def test_man_pages_from_the_option_tables(tmp_path):
    # checks one page per command path, each with every option --help lists and an example of docs/cli.md
    out = json.loads(run("completion", "man", "--output-dir", str(tmp_path), "--examples",
                         str(SOURCE / "docs" / "cli.md"), "--examples", str(SOURCE / "docs" / "server.md")).stdout)
    pages = sorted(p.name for p in tmp_path.glob("hula-*.1"))
    assert out["pages"] == len(pages)
    for name in ("hula-doc.1", "hula-doc-export.1", "hula-optimise.1", "hula-analyse.1", "hula-edit-split.1"):
        assert name in pages
    for page in pages:
        text = (tmp_path / page).read_text()
        assert ".SH EXAMPLE" in text and "\nhula " in text, page
    export = (tmp_path / "hula-doc-export.1").read_text()
    help_text = run("doc", "export", "--help").stdout
    for option in re.findall(r"^\s+(?:-\w,)?(--[a-z-]+)", help_text, re.M):
        assert "\\fB" + option.replace("-", "\\-") in export or option.replace("-", "\\-") in export, option
    if shutil.which("groff"):
        r = subprocess.run(["groff", "-man", "-Tutf8", "-ww", "-z", str(tmp_path / "hula-optimise.1")],
                           capture_output=True, text=True, timeout=30)
        assert r.returncode == 0 and r.stderr == "", r.stderr


def test_install_puts_completion_and_man_pages_in_place(tmp_path):
    # checks `cmake --install` of the hula directory installs the completion under share/bash-completion and the
    # pages under share/man/man1, and that the installed script completes
    build = pathlib.Path(os.environ["HULA_APPS_BUILD_DIR"])
    r = subprocess.run(["cmake", "--install", str(build), "--prefix", str(tmp_path)], capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    script = tmp_path / "share" / "bash-completion" / "completions" / "hula"
    assert complete(script, "hula", "doc", "ex") == ["export"]
    pages = {p.name for p in (tmp_path / "share" / "man" / "man1").glob("hula-*.1")}
    assert {"hula-doc.1", "hula-doc-export.1", "hula-serve.1", "hula-completion.1"} <= pages


def test_help_matches_behaviour():
    # checks the help does not call demo the default command (plain `hula` prints the help)
    top = run().stdout
    assert "default command" not in top
    assert top.startswith("hula: HulaHoops NURBS curve workbench")


# each command built alone ---------------------------------------------------------------------------

# The 37 commands of docs/cli.md, in the order `hula --help` lists them.
COMMANDS = ["interpolate", "eval", "info", "demo", "law", "analyse", "reconstruct", "optimise", "fair-knots",
            "fin-compound", "edit-projection", "hermite", "match-curvature", "match-curvature-torsion", "doc",
            "convert", "edit", "approximate", "fit", "closest", "intersect", "distance", "offset", "helical-offset",
            "orthotomic", "polar", "hermite-frenet", "clothoid", "log-aesthetic", "deviation", "continuity", "energy",
            "match", "blend", "serve", "batch", "completion"]


def man_options(page):
    """The long options a man page of `hula completion man` lists (its .TP items), with their dashes."""
    text = page.read_text().replace("\\-", "-")
    return set(re.findall(r"^\\fB(?:-\w,)?(--[a-z-]+)", text, re.M))


def test_each_command_alone_is_the_command_of_the_whole_tree(tmp_path):
    # checks `hula --help` lists the 37 commands, and that each command's own --help (main.cpp builds only the
    # command named) has the description `hula --help` gives it, and the options of its man page, which
    # `hula completion man` writes from the whole tree; --error-format before the command changes nothing
    top = run("--help").stdout
    listed = re.findall(r"^  (\S+) +(.+)$", top.split("Subcommands:\n")[1].split("\n\n")[0], re.M)
    assert [name for name, _ in listed] == COMMANDS
    run("completion", "man", "--output-dir", str(tmp_path), "--examples", str(SOURCE / "docs" / "cli.md"),
        "--examples", str(SOURCE / "docs" / "server.md"))
    for name, description in listed:
        own = run(name, "--help").stdout
        assert own.splitlines()[0] == description, name
        assert own.splitlines()[1].startswith(f"Usage: hula {name} "), name
        options = set(re.findall(r"^\s+(?:-\w,)?(--[a-z-]+)", own, re.M))
        assert options == man_options(tmp_path / f"hula-{name}.1") - {"--error-format"}, name
        assert run("--error-format", "text", name, "--help").stdout == own, name


def test_version_alone_is_what_the_version_flag_prints():
    # checks `hula --version` (answered before any command is built) prints what CLI11's flag prints when other
    # words come with it
    alone = run("--version")
    assert re.fullmatch(r"hula \d+\.\d+\.\d+\n", alone.stdout) and alone.stderr == ""
    assert run("--error-format", "json", "--version").stdout == alone.stdout


# progress -------------------------------------------------------------------------------------------


def on_pty(args):
    """(stdout, stderr seen on a pseudo-terminal, exit code) of hula ARGS with stderr on a pty."""
    master, slave = pty.openpty()
    p = subprocess.Popen([HULA, *args], stdout=subprocess.PIPE, stderr=slave, stdin=subprocess.DEVNULL)
    os.close(slave)
    seen = b""
    while True:
        ready, _, _ = select.select([master], [], [], 60)
        if not ready:
            break
        try:
            chunk = os.read(master, 65536)
        except OSError:  # EIO: the child closed the pty
            break
        if not chunk:
            break
        seen += chunk
    out = p.stdout.read().decode()
    code = p.wait(timeout=60)
    os.close(master)
    return out, seen.decode(errors="replace"), code


def test_progress_line_on_a_terminal_not_on_a_pipe():
    # checks a multi-objective run shows generation, best of each objective, front size and hypervolume on a
    # pty, ending with the last generation, and writes nothing on stderr when it is a pipe
    args = ["optimise", "--problem", "zdt1", "--algorithm", "nsga2", "--generations", "40", "--population", "24"]
    out, seen, code = on_pty(args)
    assert code == 0
    doc = json.loads(out)
    last = seen.replace("\x1b[K", "").replace("\r\n", "\n").split("\r")[-1]
    m = re.search(r"generation 40  evaluations (\d+)  best (\S+), (\S+)  front (\d+)  hypervolume (\S+)", last)
    assert m, seen[-500:]
    assert int(m.group(1)) == doc["report"]["evaluations"]
    assert float(m.group(5)) == pytest.approx(doc["hypervolume"], rel=1e-12)
    piped = run(*args)
    assert piped.stderr == ""
    # a single-objective study on a terminal too
    _, seen, code = on_pty(["match-curvature", str(SOURCE / "examples" / "studies" / "match-curvature-example1.json")])
    assert code == 0 and re.search(r"generation \d+  evaluations \d+  best \S+", seen), seen[-300:]


def test_progress_json_lines_carry_every_objective():
    # checks --progress lines: best (objective 0, as before), objectives (the best of each), front_size and
    # hypervolume, the last line agreeing with the final front's minima and hypervolume
    r = run("optimise", "--problem", "zdt1", "--algorithm", "nsga2", "--generations", "20", "--population", "24",
            "--progress")
    doc = json.loads(r.stdout)
    lines = [json.loads(line) for line in r.stderr.splitlines()]
    assert [line["generation"] for line in lines] == list(range(21))
    last = lines[-1]
    assert set(last) == {"generation", "evaluations", "best", "objectives", "front_size", "hypervolume"}
    assert last["best"] == last["objectives"][0]
    for k in range(2):
        assert last["objectives"][k] == min(member["objectives"][k] for member in doc["front"])
    assert last["hypervolume"] == pytest.approx(doc["hypervolume"], rel=1e-12)
    single = run("optimise", "--problem", "sphere", "--algorithm", "ga-real", "--generations", "2", "--progress")
    first = json.loads(single.stderr.splitlines()[0])
    assert set(first) == {"generation", "evaluations", "best", "objectives"} and first["objectives"] == [first["best"]]


def without_seconds(text):
    """A run's output with its wall time zeroed (the only member that differs between two runs)."""
    return re.sub(r'"seconds": [0-9.e+-]+', '"seconds": 0', text)


def progress_lines(stderr):
    lines = [json.loads(line) for line in stderr.splitlines()]
    generations = [line["generation"] for line in lines]
    evaluations = [line["evaluations"] for line in lines]
    assert generations == list(range(len(lines))), generations
    assert evaluations == sorted(evaluations) and evaluations[-1] > evaluations[0], evaluations
    return lines


def test_progress_of_nelder_mead_and_pagmo():
    # checks --progress on nelder-mead (a generation per simplex iteration, then the final simplex) and on
    # pagmo's algorithms (a generation per population of evaluations, then the final population): counts
    # increase, the last line carries the result, and the result is the same with and without the lines
    cases = [
        (["--problem", "rosenbrock", "--dimension", "3", "--algorithm", "nelder-mead", "--evaluations", "1500"], None),
        (["--problem", "sphere", "--dimension", "4", "--algorithm", "pagmo-de", "--population", "20",
          "--generations", "15", "--seed", "3"], 20),
        (["--problem", "zdt1", "--algorithm", "pagmo-nsga2", "--population", "24", "--generations", "10"], 24),
    ]
    for args, population in cases:
        quiet = run("optimise", *args)
        assert quiet.stderr == ""
        loud = run("optimise", *args, "--progress")
        assert without_seconds(loud.stdout) == without_seconds(quiet.stdout), args
        doc = json.loads(loud.stdout)
        lines = progress_lines(loud.stderr)
        last = lines[-1]
        assert last["generation"] == doc["report"]["generations"]
        assert last["evaluations"] == doc["report"]["evaluations"]
        if population:
            assert [line["evaluations"] for line in lines] == [population * (g + 1) for g in range(len(lines))]
        if "front" in doc:
            assert last["front_size"] == len(doc["front"])
            assert last["hypervolume"] == pytest.approx(doc["hypervolume"], rel=1e-12)
        else:
            assert last["best"] == doc["best"]["objectives"][0]


def last_drawn(seen):
    """The progress line left on the terminal (the last redraw)."""
    return seen.replace("\x1b[K", "").replace("\r\n", "\n").split("\r")[-1].strip()


def drawn_lines(seen):
    return [part.strip() for part in seen.replace("\x1b[K", "").replace("\r\n", "\r").split("\r") if part.strip()]


def test_progress_line_of_nelder_mead_fit_and_batch_on_a_terminal(tmp_path):
    # checks the terminal's progress line of `optimise --algorithm nelder-mead`, `fit` (a generation per
    # candidate curve, then the result's largest deviation and least-squares solves), a deterministic
    # `fair-knots` study (its simplex iterations, best in energy units) and `batch` (items
    # finished, ok, failed, running), ending with the run's figures; the output is the same as on a pipe,
    # where nothing is drawn
    args = ["optimise", "--problem", "rosenbrock", "--dimension", "3", "--algorithm", "nelder-mead"]
    out, seen, code = on_pty(args)
    assert code == 0
    doc = json.loads(out)
    m = re.fullmatch(r"generation (\d+)  evaluations (\d+)  best (\S+)", last_drawn(seen))
    assert m, seen[-300:]
    assert int(m.group(1)) == doc["report"]["generations"] and int(m.group(2)) == doc["report"]["evaluations"]
    assert float(m.group(3)) == pytest.approx(doc["best"]["objectives"][0], rel=1e-12, abs=1e-300)

    fit = ["fit", "--points", str(SOURCE / "examples" / "cli" / "scan.csv"), "-o", str(tmp_path / "fit.json")]
    out, seen, code = on_pty(fit)
    assert code == 0
    piped = run(*fit)
    assert piped.stderr == "" and out == piped.stdout
    doc = json.loads(out)
    drawn = [re.fullmatch(r"generation (\d+)  evaluations (\d+)  best (\S+)", line) for line in drawn_lines(seen)]
    assert drawn and all(drawn), seen[-300:]
    generations = [int(d.group(1)) for d in drawn]
    assert generations == sorted(generations) and len(set(generations)) == len(generations) and generations[-1] > 0
    assert int(drawn[-1].group(2)) == doc["fits"]
    assert float(drawn[-1].group(3)) == pytest.approx(doc["after"]["max_deviation"], rel=1e-12)

    # a deterministic fair-knots study: its Nelder-Mead iterations, in energy units, end at the result's energy
    study = json.loads((SOURCE / "examples" / "studies" / "fair-knots-7.3-example2.json").read_text())
    study["method"] = "deterministic"
    study.pop("map", None)
    (tmp_path / "nm.json").write_text(json.dumps(study))
    out, seen, code = on_pty(["fair-knots", str(tmp_path / "nm.json")])
    assert code == 0
    doc = json.loads(out)
    drawn = [re.fullmatch(r"generation (\d+)  evaluations (\d+)  best (\S+)", line) for line in drawn_lines(seen)]
    assert drawn and all(drawn), seen[-300:]
    generations = [int(d.group(1)) for d in drawn]
    assert generations == sorted(generations) and len(set(generations)) == len(generations) and generations[-1] > 10
    assert int(drawn[-1].group(2)) + 1 == doc["deterministic"]["evaluations"]  # and the start's energy
    assert float(drawn[-1].group(3)) == pytest.approx(doc["deterministic"]["energy"], rel=1e-12)
    assert "generation" not in run("fair-knots", str(tmp_path / "nm.json")).stderr

    shutil.copy(SOURCE / "examples" / "studies" / "fair-knots-7.4-example1.json", tmp_path / "study.json")
    (tmp_path / "c.json").write_text(json.dumps(
        {"format": "hula-campaign", "version": 1,
         "sweep": {"study": "study.json", "seeds": [1, 2],
                   "settings": [{"method": "ga", "ga": {"population": 20, "generations": 5}}]}}))
    out, seen, code = on_pty(["batch", str(tmp_path / "c.json")])
    assert code == 0 and json.loads(out)["ok"] == 2
    assert seen.count('"finished"') == 2  # the JSON lines, as on a pipe, above the progress line
    assert re.fullmatch(r"finished 2 of 2  ok 2  failed 0  running 0  seconds [0-9.]+", last_drawn(seen)), seen[-300:]
    (tmp_path / "c.results.json").unlink()
    piped = subprocess.run([HULA, "batch", str(tmp_path / "c.json")], capture_output=True, text=True, timeout=300)
    assert piped.returncode == 0 and "finished 2 of 2" not in piped.stderr
    assert [json.loads(line)["finished"] for line in piped.stderr.splitlines()] == [1, 2]
