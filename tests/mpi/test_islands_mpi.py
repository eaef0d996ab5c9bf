# SPDX-License-Identifier: MIT
# Islands across processes: `mpirun -np 4 hula optimise ... --islands 4` on
# loopback (the ranks oversubscribe the 2 cores). Checked against the same run
# on threads (the same migration code, bit for bit), run twice for exact
# repetition, with its migration log, and with one rank killed mid-run.
import json
import os
import signal
import subprocess
import time

HULA = os.environ["HULA_BIN"]
MPIRUN = ["mpirun", "--oversubscribe", "--allow-run-as-root", "--mca", "btl_vader_single_copy_mechanism", "none",
          "-np", "4"]
RUN = ["optimise", "--problem", "rastrigin", "--dimension", "10", "--algorithm", "ga-real", "--population", "20",
       "--generations", "40", "--seed", "3", "--islands", "4", "--migration-interval", "5"]


def hula(args, mpi):
    r = subprocess.run((MPIRUN if mpi else []) + [HULA] + args, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def comparable(doc):
    """The output without timings and the transport name."""
    doc = json.loads(json.dumps(doc))
    doc["report"].pop("seconds")
    doc["islands"].pop("transport")
    for island in doc["islands"]["per_island"]:
        island.pop("seconds")
    return doc


def test_mpi_equals_threads_and_repeats():
    # checks two MPI runs and the threaded run with the same seed and K give the same output, bit for bit
    a, b = hula(RUN, True), hula(RUN, True)
    t = hula(RUN, False)
    assert a["islands"]["transport"] == "mpi" and t["islands"]["transport"] == "threads"
    assert comparable(a) == comparable(b) == comparable(t)


def test_mpi_nsga2_front_equals_threads():
    # checks NSGA-II islands over MPI merge the same front (from the same archives, sent to rank 0) as on threads
    args = ["optimise", "--problem", "zdt1", "--dimension", "10", "--algorithm", "nsga2", "--population", "20",
            "--generations", "30", "--seed", "2", "--islands", "4", "--topology", "fully-connected"]
    mpi = hula(args, True)
    assert comparable(mpi) == comparable(hula(args, False))
    assert all(0 < isl["archive"] <= 4 * 20 for isl in mpi["islands"]["per_island"])


def test_migration_is_logged():
    # checks every island received migrants from both ring neighbours every 5 generations and accepted some
    doc = hula(RUN, True)
    accepted = 0
    for isl in doc["islands"]["per_island"]:
        assert [m["generation"] for m in isl["migrations"]][:2] == [5, 5]
        assert {m["from"] for m in isl["migrations"]} == {(isl["island"] + 1) % 4, (isl["island"] + 3) % 4}
        assert isl["received"] == 8 * 2 * 2
        accepted += isl["accepted"]
    assert accepted > 0


def test_wrong_island_count_is_refused():
    # checks --islands different from the number of ranks is refused by name on every rank
    r = subprocess.run(MPIRUN + [HULA] + RUN[:-4] + ["--islands", "3"], capture_output=True, text=True, timeout=120)
    assert r.returncode != 0 and "islands = 3" in r.stderr


def test_mpi_is_loaded_by_the_ranks_only():
    # checks Open MPI comes with the plugin libhula_mpi.so, loaded by the ranks of an islands run, and that the
    # same hula run without a launcher loads neither (issue 27: no MPI in the start-up of every command)
    ranked = subprocess.run(MPIRUN + ["env", "LD_DEBUG=files", HULA] + RUN, capture_output=True, text=True,
                            timeout=300)
    assert ranked.returncode == 0, ranked.stderr[-4000:]
    assert json.loads(ranked.stdout)["islands"]["transport"] == "mpi"
    assert "/libhula_mpi.so" in ranked.stderr and "file=libmpi.so" in ranked.stderr
    alone = subprocess.run([HULA] + RUN, capture_output=True, text=True, timeout=300,
                           env=dict(os.environ, LD_DEBUG="files"))
    assert alone.returncode == 0, alone.stderr[-4000:]
    assert "libhula_mpi.so" not in alone.stderr and "libmpi.so" not in alone.stderr
    assert "file=libtbb" in alone.stderr  # the loader did report the files it opened


def test_killed_rank_fails_the_run():
    # checks a rank killed mid-run makes mpirun end every rank and exit non-zero naming the signal
    long_run = ["optimise", "--problem", "rastrigin", "--dimension", "30", "--algorithm", "ga-real", "--population",
                "50", "--generations", "100000000", "--time", "120", "--islands", "4"]
    proc = subprocess.Popen(MPIRUN + [HULA] + long_run, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    ranks = []
    deadline = time.monotonic() + 60
    while len(ranks) < 4 and time.monotonic() < deadline:
        out = subprocess.run(["pgrep", "-P", str(proc.pid), "-x", "hula"], capture_output=True, text=True).stdout
        ranks = [int(p) for p in out.split()]
        time.sleep(0.2)
    assert len(ranks) == 4, "the 4 ranks did not start"
    time.sleep(1.0)  # let them migrate a few times
    os.kill(ranks[2], signal.SIGKILL)
    try:
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode != 0
    assert "signal 9" in err or "Killed" in err, err


def _campaign(tmp, seeds, generations):
    import shutil
    study = os.path.join(os.environ["HULA_SOURCE_DIR"], "examples", "studies", "fair-knots-7.4-example1.json")
    shutil.copy(study, tmp / "study.json")
    (tmp / "c.json").write_text(json.dumps({
        "format": "hula-campaign", "version": 1,
        "sweep": {"study": "study.json", "seeds": seeds,
                  "settings": [{"method": "ga", "ga": {"population": 20, "generations": generations}}]}}))
    return tmp / "c.json"


def _kill_processes_naming(marker, timeout=60.0):
    """SIGKILLs every process whose command line contains marker, and waits until they are gone."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        alive = []
        for pid in filter(str.isdigit, os.listdir("/proc")):
            try:
                with open(f"/proc/{pid}/cmdline", "rb") as f:
                    if marker.encode() in f.read():
                        alive.append(int(pid))
            except OSError:
                continue
        if not alive:
            return
        for pid in alive:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.1)
    raise AssertionError(f"processes naming {marker} still alive after {timeout} s")


def test_mpi_batch_shares_items_and_resumes_after_kill(tmp_path):
    # checks 2 ranks both run items (dynamic hand-out), and a killed campaign resumes skipping finished items
    c = _campaign(tmp_path, list(range(1, 13)), 150)
    mpirun2 = MPIRUN[:-1] + ["2"]
    proc = subprocess.Popen(mpirun2 + [HULA, "batch", str(c)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    results = tmp_path / "c.results.json"
    deadline = time.monotonic() + 300
    done = 0
    while done < 3 and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.1)
        if results.exists():
            done = len(json.loads(results.read_text())["items"])
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    # Open MPI starts the ranks in their own process groups: killing mpirun's group leaves them
    # running until they notice the lost daemon. Kill them too (they carry the campaign path in
    # their command line), so the results file no longer moves when it is read.
    _kill_processes_naming(str(c))
    before = len(json.loads(results.read_text())["items"])
    assert 3 <= before < 12
    r = subprocess.run(mpirun2 + [HULA, "batch", str(c)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    summary = json.loads(r.stdout)
    assert summary["skipped"] == before and summary["ok"] == 12 and summary["ranks"] == 2
    items = json.loads(results.read_text())["items"].values()
    assert {i["rank"] for i in items} == {0, 1}
