# SPDX-License-Identifier: MIT
# `hula batch`: a campaign of study runs with --jobs child processes (and, in
# tests/mpi, one slot per MPI rank): every item's result equals the study
# command's own output, a failed item is reported while the rest finish, and
# a campaign killed mid-run resumes from its atomically written results file.
import json
import os
import pathlib
import shutil
import signal
import subprocess
import time

HULA = os.environ["HULA_BIN"]
SOURCE = pathlib.Path(os.environ["HULA_SOURCE_DIR"])
STUDY = SOURCE / "examples" / "studies" / "fair-knots-7.4-example1.json"


def campaign(tmp, seeds, generations=5, bad=False):
    shutil.copy(STUDY, tmp / "study.json")
    doc = {"format": "hula-campaign", "version": 1,
           "sweep": {"study": "study.json", "seeds": seeds,
                     "settings": [{"method": "ga", "ga": {"population": 20, "generations": generations}}]}}
    if bad:
        (tmp / "bad.json").write_text(json.dumps({"format": "hula-study", "version": 1, "study": "fair-knots",
                                                  "points": [[0, 0]]}))
        doc["items"] = [{"id": "bad", "study": "bad.json"}]
    (tmp / "c.json").write_text(json.dumps(doc))
    return tmp / "c.json"


def run(args, **kw):
    return subprocess.run([HULA, "batch", *map(str, args)], capture_output=True, text=True, timeout=600, **kw)


def test_items_equal_the_study_command_and_failures_are_reported(tmp_path):
    # checks each item's result is the `hula fair-knots --seed` output and a bad item fails alone (exit 3)
    c = campaign(tmp_path, [1, 2, 3], bad=True)
    r = run([c, "--jobs", "2"])
    assert r.returncode == 3, r.stderr
    summary = json.loads(r.stdout)
    assert summary["items"] == 4 and summary["ok"] == 3 and summary["failed"] == 1
    results = json.loads((tmp_path / "c.results.json").read_text())["items"]
    assert results["bad"]["status"] == "failed" and results["bad"]["error"]["error"]["code"] == "TooFewPoints"
    for seed in (1, 2, 3):
        study = json.loads((tmp_path / "study.json").read_text())
        study.update({"method": "ga", "ga": {"population": 20, "generations": 5}, "seed": seed})
        (tmp_path / "direct.json").write_text(json.dumps(study))
        direct = json.loads(subprocess.run([HULA, "fair-knots", tmp_path / "direct.json"], capture_output=True,
                                           text=True, check=True).stdout)
        got = results[f"study/seed{seed}"]["result"]
        assert got["ga"]["parameters"] == direct["ga"]["parameters"] and got["ga"]["energy"] == direct["ga"]["energy"]
    # progress lines on stderr, one per finished item
    assert sum(1 for line in r.stderr.splitlines() if '"finished"' in line) == 4
    assert not list(tmp_path.glob(".hula-batch-*"))  # the study copies are removed


def test_resume_after_kill(tmp_path):
    # checks a campaign killed mid-run skips its finished items when run again, and completes all of them
    c = campaign(tmp_path, list(range(1, 9)), generations=150)
    results = tmp_path / "c.results.json"
    proc = subprocess.Popen([HULA, "batch", c], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)
    deadline = time.monotonic() + 300
    done = 0
    while done < 2 and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.1)
        if results.exists():
            done = len(json.loads(results.read_text())["items"])  # written atomically: always whole
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert 2 <= done < 8
    finished_before = len(json.loads(results.read_text())["items"])
    r = run([c])
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["skipped"] == finished_before and summary["ran"] == 8 - finished_before and summary["ok"] == 8


def live_processes_mentioning(text):
    # pids of live (not zombie) processes whose command line holds `text`
    found = []
    for entry in pathlib.Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            if text in (entry / "cmdline").read_bytes().decode(errors="replace"):
                found.append(int(entry.name))
        except OSError:
            pass
    return found


def test_finished_line_means_recorded_and_kills_leave_nothing(tmp_path):
    # checks a campaign SIGKILLed right after it prints an item's "finished" line has that item's record in the
    # results file (the line came before the write), that its items die with it (only the campaign's own
    # process is killed, not its group), and that the next run removes the study copies and scratch folder
    # the killed ones left: three kills, then a run to the end
    tmpdir = tmp_path / "tmp"
    tmpdir.mkdir()
    env = dict(os.environ, TMPDIR=str(tmpdir))
    c = campaign(tmp_path, list(range(1, 7)), generations=60)
    results = tmp_path / "c.results.json"
    recorded = set()
    for kill in range(3):
        proc = subprocess.Popen([HULA, "batch", c, "--jobs", "2"], stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, env=env)
        finished = None
        for line in proc.stderr:
            if b'"finished"' in line:
                proc.kill()
                finished = json.loads(line)["id"]
                break
        proc.wait()
        proc.stderr.close()
        assert finished is not None, f"kill {kill}: the campaign ended without a finished line"
        items = json.loads(results.read_text())["items"]
        assert finished in items, f"kill {kill}: {finished} was announced finished but is not in the results"
        recorded.add(finished)
        # the study processes die with the campaign: within 5 s none runs on a study copy of this campaign
        copy = f".hula-batch-{proc.pid}-"
        deadline = time.monotonic() + 5
        while live_processes_mentioning(copy) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not live_processes_mentioning(copy), f"kill {kill}: an item of the killed campaign still runs"
    r = run([c, "--jobs", "2"], env=env)
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["ok"] == 6 and summary["skipped"] >= len(recorded)
    assert not list(tmp_path.glob(".hula-batch-*")), list(tmp_path.glob(".hula-batch-*"))
    assert not list(tmpdir.iterdir()), list(tmpdir.iterdir())


def fault_kills(default):
    # kills per fault test: HULA_FAULT_KILLS (the nightly mode, docs/testing.md) or the quick default of ctest
    return max(default, int(os.environ.get("HULA_FAULT_KILLS", default)))


def test_kills_at_random_moments_lose_no_record(tmp_path):
    # checks SIGKILL of a campaign at seeded random moments of its run (10 in ctest, HULA_FAULT_KILLS nightly):
    # after each, the results file is absent or whole JSON holding every record an earlier run had written
    # (no acknowledged record is lost), no item of the killed campaign runs on 5 s later, and the run to the end
    # completes every item and leaves no study copy and no scratch folder
    import random
    tmpdir = tmp_path / "tmp"
    tmpdir.mkdir()
    env = dict(os.environ, TMPDIR=str(tmpdir))
    c = campaign(tmp_path, list(range(1, 7)), generations=10)
    results = tmp_path / "c.results.json"
    t0 = time.monotonic()
    r = run([c, "--jobs", "2", "--results", tmp_path / "full.json"], env=env)
    span = time.monotonic() - t0
    assert r.returncode == 0, r.stderr
    rng = random.Random(20261207)
    recorded = set()
    for kill in range(fault_kills(10)):
        proc = subprocess.Popen([HULA, "batch", c, "--jobs", "2"], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, env=env)
        time.sleep(rng.uniform(0, span * 1.1))
        proc.kill()
        proc.wait()
        if results.exists():
            items = json.loads(results.read_text())["items"]  # whole JSON, or this raises
            assert recorded <= set(items), f"kill {kill}: lost {recorded - set(items)}"
            recorded = set(items)
        copy = f".hula-batch-{proc.pid}-"
        deadline = time.monotonic() + 5
        while live_processes_mentioning(copy) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not live_processes_mentioning(copy), f"kill {kill}: an item of the killed campaign still runs"
        if len(recorded) == 6:  # finished: start again from nothing, so later kills land mid-run too
            results.unlink()
            recorded = set()
    r = run([c, "--jobs", "2"], env=env)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["ok"] == 6
    assert not list(tmp_path.glob(".hula-batch-*")), list(tmp_path.glob(".hula-batch-*"))
    assert not list(tmpdir.iterdir()), list(tmpdir.iterdir())
