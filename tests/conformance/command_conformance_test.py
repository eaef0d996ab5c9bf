#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Command conformance: the one-shot questions that more than one door answers
give the same answer through each (DESIGN.md, "One engine, one answer"; each
door calls the same io entry):

- where two curves meet, where a curve meets itself and how far apart two curves
  are: `hula intersect` / `hula distance`, POST /api/intersect and /api/distance,
  hulahoops.intersect / distance (io::intersection_answer, io::distance_answer);
- a law's values and derivatives: `hula law EXPR --at ... --derivatives N` and
  POST /api/law (io::law_evaluation_json);
- the curves made from a curve: `hula offset`, `hula helical-offset`, `hula orthotomic`,
  `hula polar`, POST /api/offset, /api/helical-offset, /api/orthotomic, /api/polar and
  hulahoops.offset, helical_offset, orthotomic, polar_map (io::offset_answer,
  helical_offset_answer, orthotomic_answer, polar_answer; the commands write the made
  curve to -o, read back here, where the route and the binding answer it as "curve");
- clothoid and biarc splines through points, open and closed: `hula clothoid --points`,
  POST /api/clothoid and hulahoops.clothoid_spline (io::clothoid_answer; the command
  writes the curve to -o, read back here, where the route and the binding answer it
  as "curve");
- a curve from its natural equations: `hula reconstruct` and POST /api/reconstruct
  (io::reconstruction_answer; the CLI prints the points, integration and fit members
  the route answers, the route adds the fitted curve);
- an optimisation problem run with an algorithm named as every door names it:
  `hula optimise --problem-file` and a problem job of `hula serve` (io::solver_options,
  the one reader of solver settings; the best solution and the run report);
- two curves joined: `hula match` and `hula blend`, POST /api/match and /api/blend
  (io::match_answer, io::blend_answer; the commands write the made curve to -o, read
  back here, where the routes answer it as "curve");
- a closed interpolating spline and a degree reduction: `hula interpolate --closed` and
  hulahoops.interpolate(closed=True) (io::closed_cubic_curve), `hula edit reduce-degree`
  and NurbsCurve.reduce_degree (io::edit_curve); the server answers neither. The written
  curve files are compared byte for byte.
- a closed interpolating spline, a degree reduction (rational too), a rebuild and a Frenet
  Hermite curve: `hula interpolate --closed`, POST /api/interpolate-closed and
  hulahoops.interpolate(closed=True) (io::closed_interpolation_answer), `hula edit
  reduce-degree|rebuild`, POST /api/reduce-degree|rebuild and NurbsCurve.reduce_degree|rebuild
  (io::edit_curve), `hula hermite-frenet`, POST /api/hermite-frenet and
  hulahoops.hermite_frenet (io::hermite_frenet_answer). The written curve files are compared
  byte for byte with Python's.

Answers are compared value for value, every double bit for bit; wall-clock members
("seconds") are left out. Each case also checks an independent fact so that a door
answering nothing cannot pass (a circle's radius from κ = 1, a sphere's minimum).

Usage: command_conformance_test.py HULA_BINARY   (PYTHONPATH must reach hulahoops)
"""
import json
import math
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "tests" / "server"))
from hula_server import Server, open_events, read_events  # noqa: E402

import hulahoops as hh  # noqa: E402
from conformance_test import first_difference, plain  # noqa: E402

CORPUS = ROOT / "tests" / "data" / "conformance"
# NURBS curves of the corpus that cross or come close (planar and space, rational ones included).
PAIRS = [("planar_bezier_s", "random_planar_nurbs_0"), ("random_planar_nurbs_0", "random_planar_nurbs_1"),
         ("random_space_nurbs_0", "random_space_nurbs_1"), ("rational_circle", "random_rational_0")]
SELF = ["random_planar_nurbs_1", "random_space_nurbs_0", "space_bezier_issue22"]
LAWS = [("sin(t)*t", "0,0.5,1,2", 3), ("vec(cos(t), sin(t), 0.5*t)", "0,1,2.5", 2), ("abs(t - 0.5)", "0.25,0.5", 1)]
# Natural equations (κ, τ, L): a circle of radius 1 (planar), a helix, a curve whose torsion varies.
RECONSTRUCTIONS = [("1", "0", 2 * math.pi, None), ("0.5", "0.25", 10.0, [0, 2.5, 10]),
                   ("1 + 0.5*sin(s)", "0.3*cos(2*s)", 5.0, None)]
# Offsets (curve, distance: NURBS with loops and cusps, a law curve exact), helical offsets (curve, distance, twist,
# frame) and mappings (curve, kind, point, k or radius).
OFFSETS = [("random_planar_nurbs_0", -0.4), ("planar_bezier_s", 0.3), ("rational_circle", 0.25)]
HELICAL = [("law_helix", "0.3", "4*t", "frenet"), ("random_space_nurbs_0", "0.1 + 0.05*t", "2*t", "frenet"),
           ("law_helix", "0.3", "0", "bishop"), ("planar_bezier_s", "0.2", "3*t", "bishop")]
MAPPINGS = [("planar_bezier_s", "orthotomic", [0.5, -1.0], 2.0), ("rational_circle", "polar", [0.1, 0.2], 1.5)]
# Match (A, B, continuity, options) and Blend (A, B, continuity, A's end, B's end): planar and space NURBS, a Bézier,
# an interpolated curve, to B's start, end and a parameter; blends from and to either end.
MATCHES = [("random_planar_nurbs_0", "random_planar_nurbs_1", "G3", []),
           ("random_space_nurbs_0", "random_space_nurbs_1", "G2", ["--end", "start", "--to-end", "end"]),
           ("planar_bezier_s", "random_planar_nurbs_0", "G1", ["--at", "0.3"]),
           ("random_interpolated", "planar_bezier_s", "G0", ["--tangent-scale", "1.5"])]
BLENDS = [("random_planar_nurbs_0", "random_planar_nurbs_1", "G2", "end", "start"),
          ("random_space_nurbs_0", "random_space_nurbs_1", "G3", "start", "end"),
          ("planar_bezier_s", "random_interpolated", "G1", "end", "end")]
# A constrained two-objective problem file's single-objective cousin and a plain one.
PROBLEMS = [
    ({"name": "shifted-sphere", "variables": [{"name": "x", "lower": -2, "upper": 2},
                                              {"name": "y", "lower": -2, "upper": 2}],
      "objectives": ["(x - 0.5)^2 + (y + 0.25)^2"]}, "ga-real", 3),
    ({"name": "constrained", "variables": [{"name": "x", "lower": 0, "upper": 3}, {"name": "y", "lower": 0, "upper": 3}],
      "objectives": ["(x - 2)^2 + (y - 1)^2"],
      "constraints": [{"expression": "x + y - 2", "type": "inequality"}]}, "ga-real", 5),
]


def run(hula, *args):
    r = subprocess.run([hula, *args], capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise AssertionError(f"hula {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return json.loads(r.stdout)


def post(server, path, body):
    status, _, text = server.request("POST", path, body)
    assert status == 200, (path, status, text)
    return json.loads(text)


def without_seconds(value):
    if isinstance(value, dict):
        return {k: without_seconds(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [without_seconds(v) for v in value]
    return value


def compare(failures, name, answers):
    """answers: [(door, value)]; the first is the reference."""
    (door0, ref), *rest = answers
    for door, value in rest:
        d = first_difference(without_seconds(ref), without_seconds(value))
        if d:
            failures.append(f"{name}: {door0} and {door} differ at {d}")


def curve_file(name):
    return CORPUS / f"{name}.json"


def curve_json(name):
    return json.loads(curve_file(name).read_text())


def intersections(hula, server, failures):
    checked = 0
    for a, b in PAIRS:
        cli = run(hula, "intersect", str(curve_file(a)), str(curve_file(b)))
        del cli["a"], cli["b"]
        http = post(server, "/api/intersect", {"a": curve_json(a), "b": curve_json(b)})
        py = plain(hh.intersect(hh.NurbsCurve.from_json(curve_json(a)), hh.NurbsCurve.from_json(curve_json(b))))
        compare(failures, f"intersect {a} {b}", [("CLI", cli), ("HTTP", http), ("Python", py)])
        # Every reported point lies on both curves, within the tolerance.
        for p in cli["points"]:
            if not p["distance"] <= cli["tolerance"]:
                failures.append(f"intersect {a} {b}: a point {p} is {p['distance']} apart")
        cli = run(hula, "distance", str(curve_file(a)), str(curve_file(b)))
        del cli["a"], cli["b"]
        http = post(server, "/api/distance", {"a": curve_json(a), "b": curve_json(b)})
        py = plain(hh.distance(hh.NurbsCurve.from_json(curve_json(a)), hh.NurbsCurve.from_json(curve_json(b))))
        compare(failures, f"distance {a} {b}", [("CLI", cli), ("HTTP", http), ("Python", py)])
        gap = math.dist(cli["point_a"], cli["point_b"])
        if not abs(gap - cli["distance"]) <= 1e-9 * max(1.0, gap):
            failures.append(f"distance {a} {b}: |point_a - point_b| = {gap} but distance = {cli['distance']}")
        checked += 2
    for a in SELF:
        cli = run(hula, "intersect", str(curve_file(a)), "--self")
        del cli["a"], cli["self"]
        http = post(server, "/api/intersect", {"a": curve_json(a)})
        py = plain(hh.intersect(hh.NurbsCurve.from_json(curve_json(a))))
        compare(failures, f"intersect {a} --self", [("CLI", cli), ("HTTP", http), ("Python", py)])
        checked += 1
    return checked


def laws(hula, server, failures):
    for expression, at, order in LAWS:
        cli = run(hula, "law", expression, "--at", at, "--derivatives", str(order))
        http = post(server, "/api/law", {"expression": expression, "at": [float(t) for t in at.split(",")],
                                         "derivatives": order})
        compare(failures, f"law {expression}", [("CLI", cli), ("HTTP", http)])
        if expression == "sin(t)*t":
            # d/dt (t sin t) = sin t + t cos t at t = 1.
            d1 = cli["results"][2]["derivatives"][1][0]
            if abs(d1 - (math.sin(1) + math.cos(1))) > 1e-12:
                failures.append(f"law {expression}: derivative at 1 is {d1}")
    return len(LAWS)


def reconstructions(hula, server, failures):
    for kappa, tau, length, at in RECONSTRUCTIONS:
        args = ["reconstruct", "--kappa", kappa, "--tau", tau, "--length", repr(length)]
        body = {"kappa": kappa, "tau": tau, "length": length}
        if at is not None:
            args += ["--at", ",".join(repr(float(s)) for s in at)]
            body["at"] = at
        cli = run(hula, *args)
        http = post(server, "/api/reconstruct", body)
        compare(failures, f"reconstruct {kappa} {tau}",
                [("CLI", cli), ("HTTP", {k: http[k] for k in ("points", "integration", "fit")})])
        if kappa == "1" and tau == "0":
            # A full turn of the unit circle ends where it starts.
            end = cli["points"][-1]["position"]
            if math.dist(end, [0, 0, 0]) > 1e-8:
                failures.append(f"reconstruct circle: ends at {end}")
    return len(RECONSTRUCTIONS)


def constructions(hula, server, failures, folder):
    out = str(pathlib.Path(folder) / "made.json")
    for name, d in OFFSETS:
        cli = run(hula, "offset", str(curve_file(name)), "--distance", repr(d))
        del cli["curve"]
        http = post(server, "/api/offset", {"curve": curve_json(name), "distance": d})
        py = plain(hh.offset(curve_json(name), d))
        compare(failures, f"offset {name} {d}", [("CLI", cli), ("HTTP", http), ("Python", py)])
        if name == "rational_circle" and not (len(cli["trimmed"]) == 1 and cli["trimmed"][0]["closed"]):
            failures.append(f"offset {name}: a circle's offset is not one closed piece: {cli['trimmed']}")
    for name, d, twist, frame in HELICAL:
        cli = run(hula, "helical-offset", str(curve_file(name)), "--distance", d, "--twist", twist, "--frame", frame,
                  "-o", out)
        del cli["input"], cli["output"]
        cli["curve"] = json.loads(pathlib.Path(out).read_text())
        http = post(server, "/api/helical-offset", {"curve": curve_json(name), "distance": d, "twist": twist,
                                                    "frame": frame})
        py = plain(hh.helical_offset(curve_json(name), d, twist=twist, frame=frame))
        compare(failures, f"helical-offset {name}", [("CLI", cli), ("HTTP", http), ("Python", py)])
    for name, kind, point, value in MAPPINGS:
        text = ",".join(repr(float(x)) for x in point)
        if kind == "orthotomic":
            cli = run(hula, "orthotomic", str(curve_file(name)), "--pole", text, "--k", repr(value), "-o", out)
            http = post(server, "/api/orthotomic", {"curve": curve_json(name), "pole": point, "k": value})
            py = plain(hh.orthotomic(curve_json(name), point, k=value))
        else:
            cli = run(hula, "polar", str(curve_file(name)), "--centre", text, "--radius", repr(value), "-o", out)
            http = post(server, "/api/polar", {"curve": curve_json(name), "centre": point, "radius": value})
            py = plain(hh.polar_map(curve_json(name), point, radius=value))
        del cli["input"], cli["output"]
        cli["curve"] = json.loads(pathlib.Path(out).read_text())
        compare(failures, f"{kind} {name}", [("CLI", cli), ("HTTP", http), ("Python", py)])
    return len(OFFSETS) + len(HELICAL) + len(MAPPINGS)


def joins(hula, server, failures, folder):
    out = str(pathlib.Path(folder) / "joined.json")
    for a, b, k, options in MATCHES:
        cli = run(hula, "match", str(curve_file(a)), str(curve_file(b)), "--continuity", k, *options, "-o", out)
        del cli["a"], cli["b"], cli["output"]
        cli["curve"] = json.loads(pathlib.Path(out).read_text())
        body = {"a": curve_json(a), "b": curve_json(b), "continuity": k}
        for flag, value in zip(options[::2], options[1::2]):
            body[flag[2:].replace("-", "_")] = float(value) if flag in ("--at", "--tangent-scale") else value
        http = post(server, "/api/match", body)
        compare(failures, f"match {a} {b} {k} {options}", [("CLI", cli), ("HTTP", http)])
        if cli["geometric"] is None or int(cli["geometric"][1]) < int(k[1]):
            failures.append(f"match {a} {b}: asked {k}, reached {cli['geometric']}")
    for a, b, k, end, to_end in BLENDS:
        cli = run(hula, "blend", str(curve_file(a)), str(curve_file(b)), "--continuity", k, "--end", end,
                  "--to-end", to_end, "-o", out)
        del cli["a"], cli["b"], cli["output"]
        cli["curve"] = json.loads(pathlib.Path(out).read_text())
        http = post(server, "/api/blend", {"a": curve_json(a), "b": curve_json(b), "continuity": k, "end": end,
                                           "to_end": to_end})
        compare(failures, f"blend {a} {b} {k} {end} {to_end}", [("CLI", cli), ("HTTP", http)])
        # Independent fact: the blend is a Hermite curve of degree 2k + 1 reaching at least Gk at both ends.
        reached = [cli[side]["geometric"] for side in ("start", "end")]
        if cli["curve"]["degree"] != 2 * int(k[1]) + 1 or any(g is None or g[1] < k[1] for g in reached):
            failures.append(f"blend {a} {b}: degree {cli['curve']['degree']}, ends {cli['start']} {cli['end']}")
    return len(MATCHES) + len(BLENDS)
# Clothoid splines: an open walk (G2, G1) and a seeded loop (closed G2, closed biarcs).
WALK = [[0, 0], [1.2, 0.4], [2.0, 1.5], [3.1, 1.7], [3.9, 0.8], [5.2, 0.6]]


def clothoids(hula, server, failures, folder):
    out = str(pathlib.Path(folder) / "clothoid.json")
    loop = seeded_points(26, 7, 2)
    # The ends of an open spline: (start angle, end angle, start curvature, end curvature), None = free.
    free = (None, None, None, None)
    cases = [("walk", WALK, False, "g2", free), ("walk", WALK, False, "g1", free), ("loop", loop, True, "g2", free),
             ("loop", loop, True, "biarc", free), ("walk", WALK, False, "g2", (None, None, 0.0, -0.4)),
             ("walk", WALK, False, "g2", (0.3, None, None, 0.5))]
    for name, points, closed, fit, (a0, a1, k0, k1) in cases:
        source = pathlib.Path(folder) / f"{name}.clothoid-points.json"
        source.write_text(json.dumps(points))
        ends = {"start_angle": a0, "end_angle": a1, "start_curvature": k0, "end_curvature": k1}
        ends = {key: value for key, value in ends.items() if value is not None}
        flags = [f"--{key.replace('_', '-')}={value!r}" for key, value in ends.items()]
        cli = run(hula, "clothoid", "--points", str(source), f"--{fit}", *(["--closed"] if closed else []), *flags,
                  "-o", out)
        del cli["output"]
        cli["curve"] = json.loads(pathlib.Path(out).read_text())
        http = post(server, "/api/clothoid", {"points": points, "closed": closed, "fit": fit, **ends})
        py = plain(hh.clothoid_spline(points, closed=closed, biarc=fit == "biarc",
                                      continuity=1 if fit == "g1" else 2, **ends))
        compare(failures, f"clothoid {name} {fit}", [("CLI", cli), ("HTTP", http), ("Python", py)])
        # Independent fact: every segment ends on its data point.
        per = 2 if fit == "biarc" else 1
        for i, seg in enumerate(http["segments"][per - 1::per]):
            if math.dist(seg["end"], points[(i + 1) % len(points)]) > 1e-9:
                failures.append(f"clothoid {name} {fit}: segment {i} ends at {seg['end']}, not on its point")
        # Independent fact: the given end curvatures are the spline's (the segments' own end values).
        if k0 is not None and abs(http["segments"][0]["kappa0"] - k0) > 1e-9:
            failures.append(f"clothoid {name}: start curvature {http['segments'][0]['kappa0']}, not {k0}")
        if k1 is not None and abs(http["segments"][-1]["kappa1"] - k1) > 1e-9:
            failures.append(f"clothoid {name}: end curvature {http['segments'][-1]['kappa1']}, not {k1}")
    # The Hermite problems: hulahoops.clothoid_g1 / clothoid_g2 / biarc answer as `hula clothoid` prints and
    # POST /api/clothoid answers (the route adds the curve file, "curve").
    hermite = [("g1", [0.0, 0.0], 0.3, None, [3.0, 1.0], -0.5, None),
               ("biarc", [0.0, 0.0], 0.3, None, [3.0, 1.0], -0.5, None),
               ("g2", [-2.0, 3.0], math.pi / 3, -0.2, [3.0, 2.0], -math.pi / 4, 0.5)]
    for kind, p0, a0, k0, p1, a1, k1 in hermite:
        body = {"start_point": p0, "start_angle": a0, "end_point": p1, "end_angle": a1}
        if k0 is not None:
            body.update(start_curvature=k0, end_curvature=k1)
        flags = [f"--{key.replace('_', '-')}={','.join(map(repr, v)) if isinstance(v, list) else repr(v)}"
                 for key, v in body.items()]
        cli = run(hula, "clothoid", *flags, *(["--biarc"] if kind == "biarc" else []))
        http = post(server, "/api/clothoid", {**body, **({"fit": "biarc"} if kind == "biarc" else {})})
        del http["curve"]
        if kind == "g1":
            py = plain(hh.clothoid_g1(p0, a0, p1, a1))
        elif kind == "biarc":
            py = plain(hh.biarc(p0, a0, p1, a1))
        else:
            py = plain(hh.clothoid_g2(p0, a0, k0, p1, a1, k1))
        compare(failures, f"clothoid hermite {kind}", [("CLI", cli), ("HTTP", http), ("Python", py)])
        if cli.get("kind") != kind:
            failures.append(f"clothoid hermite {kind}: kind {cli.get('kind')}")
    return len(cases) + len(hermite)


def job(server, body):
    status, _, text = server.request("POST", "/api/jobs", body)
    assert status == 202, text
    conn, response = open_events(server, f"/api/jobs/{json.loads(text)['job']}/events")
    events = list(read_events(response))
    conn.close()
    event, data = events[-1]
    assert event == "done" and data["state"] == "done", events[-1]
    return data


def optimisations(hula, server, failures, folder):
    for problem, algorithm, seed in PROBLEMS:
        path = pathlib.Path(folder) / f"{problem['name']}.json"
        path.write_text(json.dumps(problem))
        cli = run(hula, "optimise", "--problem-file", str(path), "--algorithm", algorithm, "--population", "16",
                  "--generations", "20", "--seed", str(seed))
        done = job(server, {"problem": problem, "algorithm": algorithm, "population": 16, "generations": 20,
                            "seed": seed})
        best = {k: done["result"]["best"][k] for k in cli["best"]}  # the job always writes "violation"
        compare(failures, f"optimise {problem['name']}",
                [("CLI", {"best": cli["best"], "report": {k: v for k, v in cli["report"].items() if k != "threads"}}),
                 ("HTTP", {"best": best, "report": done["report"]})])
        if problem["name"] == "shifted-sphere" and not cli["best"]["objectives"][0] < 0.05:
            failures.append(f"optimise shifted-sphere: best {cli['best']} is not near (0.5, -0.25)")
    return len(PROBLEMS)


# Closed interpolation: points about an ellipse with seeded noise (rounded to 6 decimals so the file is exact).
def seeded_points(seed, count, dimension):
    rng = random_generator(seed)
    return [[round(10 * math.cos(2 * math.pi * i / count) + rng.uniform(-2, 2), 6),
             round(6 * math.sin(2 * math.pi * i / count) + rng.uniform(-2, 2), 6)]
            + ([round(rng.uniform(-3, 3), 6)] if dimension == 3 else []) for i in range(count)]


def random_generator(seed):
    import random
    return random.Random(seed)


# A square whose closed spline is known in closed form, a seeded planar and a seeded space set.
CLOSED = [("square", [[1, 0], [0, 1], [-1, 0], [0, -1]], "uniform"),
          ("planar", seeded_points(5, 9, 2), "chord"), ("space", seeded_points(6, 7, 3), "centripetal")]
# Degree reduction: corpus curves (planar, space, a Bézier, rational ones) elevated once, so exactly reducible with
# tolerance 0.
REDUCTIONS = ["random_planar_nurbs_0", "random_space_nurbs_0", "planar_bezier_s", "rational_circle", "random_rational_0"]
# Rebuild (curve, degree, control points): a circle (its deviation has a closed form), a space curve, a rational one,
# and a Bézier of degree 3 rebuilt as a quintic (reproduced).
REBUILDS = [("rational_circle", 3, 12), ("random_space_nurbs_0", 3, 9), ("random_rational_1", 4, 10),
            ("planar_bezier_s", 5, 8)]
# Frenet handles: a quarter of the circle of radius 2 (κ = 1/2) and a space pair with torsion.
FRENET = [{"handles": [{"point": [2, 0], "tangent": [0, 3.14159], "normal": [-1, 0], "curvature": 0.5},
                       {"point": [0, 2], "tangent": [-3.14159, 0], "normal": [0, -1], "curvature": 0.5}],
           "parameters": [0, 1]},
          {"handles": [{"point": [0, 0, 0], "tangent": [1, 0, 0.2], "normal": [0, 1, 0], "curvature": 0.8,
                        "torsion": 0.3},
                       {"point": [1, 1, 0.5], "tangent": [0, 1, 0.3], "normal": [-1, 0, 0], "curvature": 0.4},
                       {"point": [0, 2, 1], "tangent": [-1, 0, 0.1]}]}]


def edits(hula, server, failures, folder):
    folder = pathlib.Path(folder)
    checked = 0
    for name, points, rule in CLOSED:
        source = folder / f"{name}.points.json"
        source.write_text(json.dumps(points))
        out = folder / f"{name}.closed.json"
        cli = run(hula, "interpolate", "--points", str(source), "--closed", "--parameterisation", rule, "-o", str(out))
        del cli["output"]
        cli["curve"] = json.loads(out.read_text())
        http = post(server, "/api/interpolate-closed", {"points": points, "parameterisation": rule})
        ring = hh.interpolate(points, closed=True, parameterisation=rule)
        compare(failures, f"interpolate --closed {name}", [("CLI", cli), ("HTTP", http)])
        compare(failures, f"interpolate --closed {name}", [("CLI", cli["curve"]), ("Python", plain(ring))])
        ring.save(str(folder / f"{name}.closed.py.json"))
        if out.read_bytes() != (folder / f"{name}.closed.py.json").read_bytes():
            failures.append(f"interpolate --closed {name}: the CLI's and Python's curve files differ")
        # Independent facts: the curve passes through every point and ends where it starts; the square's
        # uniform closed spline has C(1/8) = (11/16, 11/16) (its closed form).
        if math.dist(ring(0.0), ring(1.0)) > 1e-12:
            failures.append(f"interpolate --closed {name}: C(0) = {list(ring(0.0))} but C(1) = {list(ring(1.0))}")
        if name == "square" and math.dist(ring(0.125), [0.6875, 0.6875]) > 1e-15:
            failures.append(f"interpolate --closed square: C(1/8) = {list(ring(0.125))}, not (11/16, 11/16)")
        checked += 1
    for name in REDUCTIONS:
        elevated = hh.NurbsCurve.from_json(curve_json(name)).elevate(1)
        source = folder / f"{name}.elevated.json"
        elevated.save(str(source))
        out = folder / f"{name}.reduced.json"
        cli = run(hula, "edit", "reduce-degree", str(source), "--tolerance", "0", "-o", str(out))
        cli["curve"] = json.loads(out.read_text())
        http = post(server, "/api/reduce-degree", {"curve": json.loads(source.read_text()), "tolerance": 0})
        py = elevated.reduce_degree(0.0)
        compare(failures, f"edit reduce-degree {name}", [("CLI", cli), ("HTTP", http)])
        compare(failures, f"edit reduce-degree {name}",
                [("CLI", {k: cli[k] for k in py}), ("Python", plain(py))])
        py["curve"].save(str(folder / f"{name}.reduced.py.json"))
        if out.read_bytes() != (folder / f"{name}.reduced.py.json").read_bytes():
            failures.append(f"edit reduce-degree {name}: the CLI's and Python's curve files differ")
        # Independent fact: an elevated curve comes back to its own degree, its shape unchanged.
        original = hh.NurbsCurve.from_json(curve_json(name))
        if py["curve"].degree != original.degree or not py["error_bound"] < 1e-9:
            failures.append(f"edit reduce-degree {name}: degree {py['curve'].degree}, bound {py['error_bound']}")
        lo, hi = original.domain
        gap = max(math.dist(original(lo + (hi - lo) * i / 200), py["curve"](lo + (hi - lo) * i / 200))
                  for i in range(201))
        if not gap < 1e-9:
            failures.append(f"edit reduce-degree {name}: the reduced curve is {gap} away from the original")
        checked += 1
    for name, degree, count in REBUILDS:
        out = folder / f"{name}.rebuilt.json"
        cli = run(hula, "edit", "rebuild", str(curve_file(name)), "--degree", str(degree), "--control-points",
                  str(count), "-o", str(out))
        cli["curve"] = json.loads(out.read_text())
        http = post(server, "/api/rebuild", {"curve": curve_json(name), "degree": degree, "control_points": count})
        py = hh.NurbsCurve.from_json(curve_json(name)).rebuild(count, degree=degree)
        compare(failures, f"edit rebuild {name}", [("CLI", cli), ("HTTP", http)])
        compare(failures, f"edit rebuild {name}", [("CLI", {k: cli[k] for k in py}), ("Python", plain(py))])
        py["curve"].save(str(folder / f"{name}.rebuilt.py.json"))
        if out.read_bytes() != (folder / f"{name}.rebuilt.py.json").read_bytes():
            failures.append(f"edit rebuild {name}: the CLI's and Python's curve files differ")
        # Independent facts: the circle's deviation is ||C(s)| - R| at the same samples (closed form); a cubic
        # Bézier rebuilt as a quintic is itself.
        if name == "rational_circle":
            lo, hi = py["curve"].domain
            radius = math.hypot(*hh.NurbsCurve.from_json(curve_json(name))(lo))
            worst = max(abs(math.hypot(*py["curve"](lo + (hi - lo) * i / 1000)) - radius) for i in range(1001))
            if abs(worst - py["max_deviation"]) > 1e-9 * radius:
                failures.append(f"edit rebuild {name}: max_deviation {py['max_deviation']}, closed form {worst}")
        if name == "planar_bezier_s" and not py["max_deviation"] < 1e-9:
            failures.append(f"edit rebuild {name}: a cubic rebuilt as a quintic moved by {py['max_deviation']}")
        checked += 1
    for k, handles in enumerate(FRENET):
        source = folder / f"handles{k}.json"
        source.write_text(json.dumps(handles))
        out = folder / f"frenet{k}.json"
        cli = run(hula, "hermite-frenet", str(source), "-o", str(out))
        del cli["input"], cli["output"]
        cli["curve"] = json.loads(out.read_text())
        http = post(server, "/api/hermite-frenet", handles)
        py = hh.hermite_frenet(handles)
        compare(failures, f"hermite-frenet {k}", [("CLI", cli), ("HTTP", http)])
        compare(failures, f"hermite-frenet {k}", [("CLI", cli["curve"]), ("Python", plain(py))])
        # Independent fact: the curve runs through every handle's point.
        lo, hi = py.domain
        if math.dist(py(lo), handles["handles"][0]["point"]) > 1e-12 or \
                math.dist(py(hi), handles["handles"][-1]["point"]) > 1e-12:
            failures.append(f"hermite-frenet {k}: the curve misses its end handles")
        checked += 1
    return checked


def main():
    hula = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as folder, Server(hula) as server:
        checked = intersections(hula, server, failures)
        checked += laws(hula, server, failures)
        checked += reconstructions(hula, server, failures)
        checked += constructions(hula, server, failures, folder)
        checked += joins(hula, server, failures, folder)
        checked += clothoids(hula, server, failures, folder)
        checked += optimisations(hula, server, failures, folder)
        checked += edits(hula, server, failures, folder)
    for f in failures:
        print("FAIL:", f)
    print(f"command conformance: {checked} questions through CLI, HTTP (and Python where it answers), "
          f"{len(failures)} difference(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
