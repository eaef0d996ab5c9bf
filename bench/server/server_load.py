#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Load figures of `hula serve`, recorded in docs/benchmarks.md.

Bounded loops on loopback that stop by themselves:
  interrogation  two GA jobs running, RATE requests/s for SECONDS s of the
                 interrogation request (the analysis of a 50-point curve with
                 100 samples and curvature fins when the server has documents,
                 else POST /api/law with 100 points); p50/p99/max latency, errors
  sse            SUBSCRIBERS concurrent SSE clients of one job: every event
                 received, in order, by every subscriber
  drag           PATCH continue moves at 120/s (documents only); p99 round trip
  drag-rate      one client dragging as fast as it can for SECONDS s: each move is a
                 PATCH continue of one point of the 50-point curve followed by
                 its analysis re-read (100 samples, curvature fins), as the
                 workbench does; moves/s and per-move p50/p99, no jobs running
  cost           the server's CPU time per analysis request (from /proc/PID/stat,
                 1000 sequential requests each) for the full request and with
                 parts left out, to see where an analysis request's time goes
The output starts with the machine's cores and load average (1, 5, 15 min) at
the start and the end: other programs' load is part of every figure.

usage: server_load.py HULA_BINARY [--rate 500] [--seconds 20] [--subscribers 200] [--background-jobs 2]
                      [--only NAME]
"""
import argparse
import json
import math
import os
import resource
import sys
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "server"))
from hula_server import Server, open_events, read_events  # noqa: E402

LONG_GA = {
    "problem": {
        "name": "long-rastrigin",
        "variables": [{"name": f"x{i}", "lower": -5, "upper": 5} for i in range(20)],
        "objectives": [" + ".join(f"(x{i}^2 - 10*cos(2*pi*x{i}) + 10)" for i in range(20))],
    },
    "algorithm": "ga-real", "population": 2000, "generations": 100000,
}


def percentile(values, p):
    s = sorted(values)
    return s[min(len(s) - 1, int(math.ceil(p / 100 * len(s))) - 1)] if s else float("nan")


def paced(server, rate, seconds, make_request, threads=8):
    """Sends `rate` requests/s for `seconds` s from `threads` keep-alive clients, each on a fixed
    schedule (a late request goes at once, the schedule does not slip). Returns latencies (s), errors."""
    latencies, errors, lock = [], [], threading.Lock()
    start = time.monotonic() + 0.2
    per_thread = rate / threads

    def worker(k):
        conn = server.connection(timeout=10)
        n = int(seconds * per_thread)
        for i in range(n):
            due = start + (i + k / threads) / per_thread
            delay = due - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            method, path, body = make_request(k, i)
            t = time.monotonic()
            try:
                status, _, data = server.request(method, path, body=body, conn=conn)
                dt = time.monotonic() - t
                with lock:
                    latencies.append(dt)
                    if status >= 400:
                        errors.append((status, data[:200]))
            except Exception as e:  # a dropped connection is an error of the run, reported
                with lock:
                    errors.append(("exception", repr(e)))
                conn.close()
                conn = server.connection(timeout=10)
        conn.close()

    ts = [threading.Thread(target=worker, args=(k,)) for k in range(threads)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    return latencies, errors


def has_documents(server):
    status, _, _ = server.request("GET", "/api/documents")
    return status == 200


def make_document(server):
    """A document with one 50-point interpolated curve; returns (name, label)."""
    name = "bench.hula"
    server.request("POST", "/api/documents", body={"name": name})
    points = [[i, math.sin(i / 5.0) * 3, math.cos(i / 7.0)] for i in range(50)]
    curve = {"format": "hula-curve", "version": 1, "kind": "interpolated", "points": points}
    status, _, data = server.request("POST", f"/api/documents/{name}/entities", body={"curve": curve, "name": "c"})
    if status >= 300:
        raise RuntimeError(data)
    return name, json.loads(data)["label"]


def interrogation(hula, rate, seconds, background_jobs=2):
    with Server(hula, args=["--jobs", "2"]) as server:
        for _ in range(background_jobs):
            server.request("POST", "/api/jobs", body=LONG_GA)
        if has_documents(server):
            name, label = make_document(server)
            what = "analysis of a 50-point curve, 100 samples, curvature fins"
            req = lambda k, i: ("POST", f"/api/documents/{name}/entities/{label}/analysis",
                                {"samples": 100, "fins": ["curvature"], "scale": 1.0})
        else:
            what = "POST /api/law, 100 points with 2 derivatives (no document routes in this build)"
            at = [i / 99 for i in range(100)]
            req = lambda k, i: ("POST", "/api/law", {"expression": "vec(cos(3*t), sin(2*t), t^2)", "at": at, "derivatives": 2})
        lat, errors = paced(server, rate, seconds, req)
        running = [json.loads(server.request("GET", f"/api/jobs/{j + 1}")[2])["state"] for j in range(background_jobs)]
    return {"what": what, "rate": rate, "seconds": seconds, "requests": len(lat), "errors": len(errors),
            "first_errors": errors[:3], "jobs": running,
            "p50_ms": 1000 * percentile(lat, 50), "p99_ms": 1000 * percentile(lat, 99), "max_ms": 1000 * max(lat)}


def sse(hula, subscribers):
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    resource.setrlimit(resource.RLIMIT_NOFILE, (hard, hard))
    with Server(hula, args=["--jobs", "1"]) as server:
        job = {"problem": LONG_GA["problem"], "algorithm": "ga-real", "population": 50, "generations": 300}
        # Hold the job until every subscriber is connected: a first job keeps the only worker busy.
        blocker = json.loads(server.request("POST", "/api/jobs", body=LONG_GA)[2])["job"]
        jid = json.loads(server.request("POST", "/api/jobs", body=job)[2])["job"]
        results = [None] * subscribers
        streams = [open_events(server, f"/api/jobs/{jid}/events") for _ in range(subscribers)]

        def consume(k):
            conn, response = streams[k]
            results[k] = list(read_events(response))
            conn.close()

        ts = [threading.Thread(target=consume, args=(k,)) for k in range(subscribers)]
        for t in ts:
            t.start()
        t0 = time.monotonic()
        server.request("DELETE", f"/api/jobs/{blocker}")
        for t in ts:
            t.join()
        elapsed = time.monotonic() - t0
    expected = [("generation", g) for g in range(301)]
    complete = sum(1 for r in results
                   if [(e, d.get("generation")) for e, d in r[:-1]] == expected and r[-1][0] == "done")
    return {"subscribers": subscribers, "events_per_subscriber": 302, "complete_in_order": complete,
            "seconds": elapsed}


def drag(hula, seconds):
    with Server(hula, args=["--jobs", "2"]) as server:
        if not has_documents(server):
            return {"skipped": "no document routes in this build"}
        name, label = make_document(server)
        path = f"/api/documents/{name}/entities/{label}"
        req = lambda k, i: ("PATCH", path, {"move": [{"index": 10, "to": [10, 3 + math.sin(i / 10), 0]}], "continue": True})
        lat, errors = paced(server, 120, seconds, req, threads=1)
    return {"rate": 120, "seconds": seconds, "requests": len(lat), "errors": len(errors),
            "p50_ms": 1000 * percentile(lat, 50), "p99_ms": 1000 * percentile(lat, 99), "max_ms": 1000 * max(lat)}


def drag_rate(hula, seconds):
    with Server(hula, args=["--jobs", "1"]) as server:
        name, label = make_document(server)
        path = f"/api/documents/{name}/entities/{label}"
        conn = server.connection(timeout=10)
        moves, errors, lat = 0, 0, []
        t0 = time.monotonic()
        while time.monotonic() - t0 < seconds:
            t = time.monotonic()
            move = {"move": [{"index": 10, "to": [10, 3 + math.sin(moves / 10), 0]}], "continue": moves > 0}
            s1, _, _ = server.request("PATCH", path, body=move, conn=conn)
            s2, _, data = server.request("POST", path + "/analysis", body={"samples": 100, "fins": ["curvature"]},
                                         conn=conn)
            lat.append(time.monotonic() - t)
            errors += (s1 != 200) + (s2 != 200)
            moves += 1
        elapsed = time.monotonic() - t0
        conn.close()
        history = json.loads(server.request("GET", f"/api/documents/{name}/history")[2])["history"]
    return {"moves": moves, "seconds": elapsed, "moves_per_s": moves / elapsed, "errors": errors,
            "undo_steps": len(history), "p50_ms": 1000 * percentile(lat, 50), "p99_ms": 1000 * percentile(lat, 99)}


def server_cpu_seconds(pid):
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def cost(hula, requests=1000):
    bodies = {
        "full: 100 samples, curvature fins, features": {"samples": 100, "fins": ["curvature"], "scale": 1.0},
        "without features": {"samples": 100, "fins": ["curvature"], "scale": 1.0, "features": False},
        "without features and fins": {"samples": 100, "features": False},
        "2 samples, no fins, no features (fixed cost)": {"samples": 2, "features": False},
    }
    out = {}
    with Server(hula, args=["--jobs", "1"]) as server:
        name, label = make_document(server)
        path = f"/api/documents/{name}/entities/{label}/analysis"
        conn = server.connection(timeout=10)
        for what, body in bodies.items():
            for _ in range(50):  # warm up
                server.request("POST", path, body=body, conn=conn)
            c0, t0 = server_cpu_seconds(server.process.pid), time.monotonic()
            for _ in range(requests):
                status, _, data = server.request("POST", path, body=body, conn=conn)
                if status != 200:
                    raise RuntimeError(data)
            c1, t1 = server_cpu_seconds(server.process.pid), time.monotonic()
            out[what] = {"server_cpu_ms": 1000 * (c1 - c0) / requests, "round_trip_ms": 1000 * (t1 - t0) / requests,
                         "response_bytes": len(data)}
        conn.close()
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("hula")
    ap.add_argument("--rate", type=int, default=500)
    ap.add_argument("--seconds", type=float, default=20)
    ap.add_argument("--subscribers", type=int, default=200)
    ap.add_argument("--background-jobs", type=int, default=2, choices=range(0, 3),
                    help="GA jobs running during the interrogation load (the issue's figure: 2)")
    ap.add_argument("--only", choices=["interrogation", "sse", "drag", "drag-rate", "cost"])
    a = ap.parse_args()
    # Other programs share the machine: its load average is part of every figure.
    out = {"machine": {"cores": os.cpu_count(), "load_average_at_start": os.getloadavg()}}
    if a.only in (None, "interrogation"):
        out["interrogation"] = interrogation(a.hula, a.rate, a.seconds, a.background_jobs)
    if a.only in (None, "sse"):
        out["sse"] = sse(a.hula, a.subscribers)
    if a.only in (None, "drag"):
        out["drag"] = drag(a.hula, a.seconds)
    if a.only in (None, "drag-rate"):
        out["drag_rate"] = drag_rate(a.hula, a.seconds)
    if a.only in (None, "cost"):
        out["cost"] = cost(a.hula)
    out["machine"]["load_average_at_end"] = os.getloadavg()
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
