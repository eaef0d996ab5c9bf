#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Runs the judged benchmarks of issue 27 and writes their table into docs/benchmarks.md.

Each program runs once (one process), so every ratio compares rows measured in the same run on the same
inputs: ours beside the hand-written reference kernels (bench/reference/) and Open CASCADE or pagmo.
Google Benchmark interleaves the rows at random and repeats them; the figure of a row is the median of its
repetitions' CPU time per item. The raw JSON of every program goes to bench/results/<machine>/; the table
replaces the text between the markers

    <!-- bench.py:begin -->  …  <!-- bench.py:end -->

in docs/benchmarks.md, with the command, the CPU model, the load average before and after each program,
the instruction set in use and the commit. scripts/bench.sh builds the programs and calls this script.

usage: bench/report.py BUILD_DIR [--repetitions 5] [--min-time 0.2] [--machine NAME] [--no-docs]
                       [--hula BINARY]   (also runs bench/server/server_load.py --only cost)
"""
import argparse
import datetime
import json
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN, END = "<!-- bench.py:begin -->", "<!-- bench.py:end -->"

# Programs: (key, path under the build directory, filter, extra arguments, min_time scale).
PROGRAMS = [
    ("evaluate", "bench/nurbs/bench_nurbs_evaluate", ".", [], 1.0),
    ("curvature", "bench/diffgeom/bench_diffgeom_curvature", "curvature_torsion|curvature_occt", [], 1.0),
    ("interpolate", "bench/nurbs/bench_nurbs_interpolate",
     "interpolate_natural/10$|reference_interpolate_natural/10$|GeomAPI_Interpolate/10$", [], 1.0),
    ("fitness", "bench/studies/bench_studies_fitness",
     "BM_match_fitness/|BM_reference_fitness/|BM_occt_fitness/|ga_50x50", [], 1.0),
    # NSGA-II and pagmo run a fixed 10 iterations (one per seed); no repetitions needed.
    ("optim", "bench/optim/bench_optim_ga", "nsga2_zdt/[123]/|pagmo_nsga2_zdt/[123]/", ["--benchmark_repetitions=1"], 0),
]


def load_average():
    with open("/proc/loadavg") as f:
        return [float(x) for x in f.read().split()[:3]]


def cpu_model():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return "unknown"


def run(build, key, path, filt, extra, reps, min_time, out_dir, stamp):
    exe = os.path.join(build, path)
    out = os.path.join(out_dir, f"{stamp}-{key}.json")
    cmd = [exe, f"--benchmark_filter={filt}", "--benchmark_format=json", f"--benchmark_out={out}",
           "--benchmark_out_format=json"]
    if not extra:
        cmd += [f"--benchmark_repetitions={reps}", f"--benchmark_min_time={min_time}",
                "--benchmark_enable_random_interleaving=true"]
    cmd += extra
    before = load_average()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    after = load_average()
    with open(out) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            if b.get("error_occurred"):
                sys.exit(f"{b['run_name']}: {b.get('error_message')}")
            continue
        rows.setdefault(b["run_name"], []).append(b)
    command = " ".join(os.path.relpath(c, ROOT) if c == exe else c for c in cmd if not c.startswith("--benchmark_out"))
    return {"rows": rows, "before": before, "after": after, "context": data["context"], "command": command,
            "json": os.path.relpath(out, ROOT)}


def per_item_ns(row):
    """Median CPU nanoseconds per item (points, evaluations) over the repetitions."""
    vals = []
    for b in row:
        if "items_per_second" in b:
            vals.append(1e9 / b["items_per_second"])
        else:
            unit = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
            vals.append(b["cpu_time"] * unit)
    return statistics.median(vals)


def counter(row, name):
    return statistics.median(b[name] for b in row)


def fmt(x, digits=3):
    if x >= 100:
        return f"{x:,.0f}"
    return f"{x:.{digits}g}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--min-time", type=float, default=0.2)
    ap.add_argument("--machine", default="amd-epyc-2c")
    ap.add_argument("--no-docs", action="store_true")
    ap.add_argument("--hula", help="a hula binary: also run server_load.py --only cost")
    a = ap.parse_args()

    stamp = datetime.date.today().isoformat() + "-issue27"
    out_dir = os.path.join(ROOT, "bench", "results", a.machine)
    os.makedirs(out_dir, exist_ok=True)
    res = {}
    for key, path, filt, extra, scale in PROGRAMS:
        print(f"running {path} …", file=sys.stderr)
        res[key] = run(a.build, key, path, filt, extra, a.repetitions, a.min_time * scale, out_dir, stamp)

    def ns(key, name):
        return per_item_ns(res[key]["rows"][name])

    lines = []
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    ctx = res["evaluate"]["context"]
    lines.append(f"Generated by `scripts/bench.sh` on {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC"
                 f" at commit {commit}: {cpu_model()}, {os.cpu_count()} cores, vector instruction set in use "
                 f"**{ctx.get('simd', '?')}** (`HULA_SIMD` caps it), `bench` preset (Release, `-O3`, no `-march`). "
                 "Figures are medians of CPU time over the repetitions; every ratio compares rows of one process "
                 "(same inputs, checked against each other before timing). Load average (1 min) before → after "
                 "each program is given with its table: the machine is shared, so compare ratios, not absolute "
                 "times across runs.")
    lines.append("")

    def load_line(key):
        r = res[key]
        return (f"Command: `{r['command']}`; load average {r['before'][0]:.1f} → {r['after'][0]:.1f}; "
                f"raw results `{r['json']}`.")

    # Evaluation.
    lines.append("#### Evaluation: 65,536 distinct parameters, cubic with 64 control points (ns per point)")
    lines.append("")
    lines.append("| what | ours | ours, scalar path | reference | ours / reference | target | Open CASCADE "
                 "(`GeomAdaptor_Curve`) | ours vs OCCT |")
    lines.append("|---|---|---|---|---|---|---|---|")
    for d, dname in (("d0", "position"), ("d3", "D3")):
        for rational in (0, 1):
            for sorted_ in (1, 0):
                base = f"rational:{rational}/sorted:{sorted_}"
                ours = ns("evaluate", f"BM_nurbs_{d}_ours/{base}/simd:3")
                scalar = ns("evaluate", f"BM_nurbs_{d}_ours/{base}/simd:0")
                ref = ns("evaluate", f"BM_nurbs_{d}_reference/{base}")
                occt = ns("evaluate", f"BM_nurbs_{d}_occt/{base}")
                if sorted_ and not rational:
                    target = "≤ 0.7 (SIMD)"
                elif d == "d3" and rational:
                    target = "≤ 1.2"
                else:
                    target = "≤ 1.1"
                what = f"{dname}, {'sorted' if sorted_ else 'shuffled'}{', rational' if rational else ''}"
                lines.append(f"| {what} | {fmt(ours)} | {fmt(scalar)} | {fmt(ref)} | **{ours / ref:.2f}** | {target} "
                             f"| {fmt(occt)} | {occt / ours:.1f}× faster |")
    lines.append("")
    lines.append(load_line("evaluate"))
    lines.append("")

    # Curvature + torsion.
    lines.append("#### Curvature + torsion: the same curve and parameters (ns per point)")
    lines.append("")
    lines.append("| what | ours | reference | ours / reference | target | Open CASCADE (`GeomLProp_CLProps`, κ only) "
                 "| ours vs OCCT |")
    lines.append("|---|---|---|---|---|---|---|")
    for sorted_ in (1, 0):
        ours = ns("curvature", f"BM_diffgeom_curvature_torsion_ours/sorted:{sorted_}")
        ref = ns("curvature", f"BM_diffgeom_curvature_torsion_reference/sorted:{sorted_}")
        occt = ns("curvature", f"BM_diffgeom_curvature_occt/sorted:{sorted_}")
        lines.append(f"| κ + τ, {'sorted' if sorted_ else 'shuffled'} | {fmt(ours)} | {fmt(ref)} | **{ours / ref:.2f}** "
                     f"| ≤ 1.1 | {fmt(occt)} | {occt / ours:.1f}× faster |")
    lines.append("")
    lines.append(load_line("curvature"))
    lines.append("")

    # Interpolation.
    ours = ns("interpolate", "BM_nurbs_interpolate_natural/10") * 10
    ref = ns("interpolate", "BM_reference_interpolate_natural/10") * 10
    occt = ns("interpolate", "BM_occt_GeomAPI_Interpolate/10") * 10
    lines.append("#### Interpolation: global C2 cubic through 10 points, chord length (ns per curve)")
    lines.append("")
    lines.append("| what | ours | reference | ours / reference | target | Open CASCADE (`GeomAPI_Interpolate`, "
                 "its own ends) | ours vs OCCT |")
    lines.append("|---|---|---|---|---|---|---|")
    lines.append(f"| natural ends, 10 points | {fmt(ours)} | {fmt(ref)} | **{ours / ref:.2f}** | ≤ 1.3 | {fmt(occt)} "
                 f"| {occt / ours:.1f}× faster |")
    lines.append("")
    lines.append(load_line("interpolate"))
    lines.append("")

    # Fitness and the thesis GA.
    lines.append("#### Curvature-matching fitness (thesis eq. 31, 200 samples) and the thesis GA")
    lines.append("")
    lines.append("| what | ours | reference | ours / reference | evaluations / s / core | target | Open CASCADE "
                 "| ours vs OCCT |")
    lines.append("|---|---|---|---|---|---|---|---|")
    for n in (4, 7, 10):
        ours = ns("fitness", f"BM_match_fitness/{n}")
        ref = ns("fitness", f"BM_reference_fitness/{n}")
        occt = ns("fitness", f"BM_occt_fitness/{n}")
        lines.append(f"| fitness, {n} points (ns per evaluation) | {fmt(ours)} | {fmt(ref)} | **{ours / ref:.2f}** "
                     f"| **{1e9 / ours / 1e6:.2f} M** | ≤ 1.2, ≥ 2 M/s | {fmt(occt)} | {occt / ours:.1f}× faster |")
    ga = res["fitness"]["rows"]["BM_match_ga_50x50"]
    ga_ms = per_item_ns(ga) / 1e6
    lines.append(f"| thesis GA, binary, 50 × 50, 4 points (ms per run; mean distance reached "
                 f"{counter(ga, 'mean_distance'):.2g}) | **{ga_ms:.2f}** | | | | ≤ 2 ms | | |")
    lines.append("")
    lines.append(load_line("fitness"))
    lines.append("")

    # NSGA-II.
    lines.append("#### NSGA-II on ZDT1–3: population 100 × 250 generations (25,100 evaluations), 10 seeds")
    lines.append("")
    lines.append("| problem | ours: ms per run | hypervolume median [min, max] | pagmo 2: ms per run | hypervolume median "
                 "[min, max] | target |")
    lines.append("|---|---|---|---|---|---|")
    for z in (1, 2, 3):
        o = res["optim"]["rows"][f"BM_optim_nsga2_zdt/{z}/iterations:10"]
        p = res["optim"]["rows"][f"BM_optim_pagmo_nsga2_zdt/{z}/iterations:10"]
        hv = lambda r: f"{counter(r, 'hv_median'):.5f} [{counter(r, 'hv_min'):.5f}, {counter(r, 'hv_max'):.5f}]"
        lines.append(f"| ZDT{z} | **{per_item_ns(o) / 1e6:.1f}** | {hv(o)} | {per_item_ns(p) / 1e6:.1f} | {hv(p)} "
                     f"| ≤ 10 ms, hypervolume ≥ pagmo's |")
    lines.append("")
    lines.append(load_line("optim"))
    lines.append("")

    if a.hula:
        print("running bench/server/server_load.py --only cost …", file=sys.stderr)
        before = load_average()
        cost = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "server", "server_load.py"), a.hula,
                               "--only", "cost"], capture_output=True, text=True, check=True).stdout
        after = load_average()
        lines.append("#### Server: CPU per analysis request (`bench/server/server_load.py --only cost`)")
        lines.append("")
        lines.append("```")
        lines.extend(cost.strip().splitlines())
        lines.append("```")
        lines.append("")
        lines.append(f"Command: `python3 bench/server/server_load.py {os.path.relpath(a.hula, ROOT)} --only cost`; "
                     f"load average {before[0]:.1f} → {after[0]:.1f}.")
        lines.append("")

    table = "\n".join(lines)
    print(table)
    if a.no_docs:
        return
    doc = os.path.join(ROOT, "docs", "benchmarks.md")
    with open(doc) as f:
        text = f.read()
    if BEGIN not in text or END not in text:
        sys.exit(f"{doc}: markers {BEGIN} / {END} not found")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(doc, "w") as f:
        f.write(head + BEGIN + "\n" + table + "\n" + END + tail)
    print(f"wrote {os.path.relpath(doc, ROOT)}", file=sys.stderr)


if __name__ == "__main__":
    main()
