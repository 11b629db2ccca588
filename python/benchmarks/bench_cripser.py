#!/usr/bin/env python3
"""gmap in process against CubicalRipser (and GUDHI) in process, on the same arrays.

    python python/benchmarks/bench_cripser.py [--only NAME,...] [--tools gmap,gen,cripser,gudhi]
        [--gudhi-max N] [--results FILE.jsonl] [--table]

The rows and arrays of ``benches/anchors/compare_cripser.py`` (random 0/1 uint8 images, each
from its own seed, and scikit-image's ``camera`` thresholded at its median); the cubical set
is the sublevel set at 0.5, the T-construction (each value a closed square or cube). In one
Python process, each tool in turn on the same array, CPU (``time.process_time``: every
thread) and wall seconds, the reading stage apart; a tool's call is repeated while its calls
so far took under 2 s, at most 5 times, and the call of median CPU is kept (for ``gen``,
the median of the times to read the arrays apart):

* gmap: reading ``a == 0`` (the set, a bool array read in place), then
  ``gmap.homology(mask)``; ``gen``: ``gmap.homology(mask, generators=True)``, then, timed
  apart, reading every generator's ``cells``, ``extents`` and ``coefficients`` (a
  generator's arrays are made when first read);
* CubicalRipser: reading ``a.astype(float64)``, then its T-construction,
  ``cripser.computePH_T(f, maxdim=d - 1, location="no")`` (``computePH(f, top_dim=True)``
  is the V-construction's dimension d - 1 alone);
* GUDHI: reading nothing (it takes the uint8 array), then
  ``CubicalComplex(top_dimensional_cells=a).persistence()``, up to --gudhi-max cubes.

Every measurement is appended to --results (JSON lines); ``--table`` prints the Markdown table
of the newest measurement of each row and tool.
"""

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benches" / "anchors"))
from compare_cripser import cases, groups, make, ok, results, short  # noqa: E402


# each tool's call is repeated while the calls so far took under BUDGET seconds of wall, at
# most REPS times, and the call of median CPU is kept: one call of a few milliseconds is at
# the mercy of the clock's resolution and the scheduler
REPS = 5
BUDGET = 2.0


def timed_once(read, compute):
    """(read, compute) CPU and wall seconds, and compute's result (or the error's text)."""
    c0, t0 = time.process_time(), time.perf_counter()
    x = read()
    c1, t1 = time.process_time(), time.perf_counter()
    try:
        out = compute(x)
    except Exception as e:  # a refusal (memory, generator limit) is a result of the row
        out = e
    c2, t2 = time.process_time(), time.perf_counter()
    return {"read_cpu": c1 - c0, "read_wall": t1 - t0, "cpu": c2 - c1, "wall": t2 - t1}, out


def timed(read, compute, after=None):
    """timed_once repeated (REPS, BUDGET): the CPU and wall of the call of median CPU, the
    number of calls, and the last call's result. `after(result)`, when given, runs after each
    call, timed apart: the median of its CPU is `after_cpu`."""
    runs, afters, spent = [], [], 0.0
    while len(runs) < REPS and spent < BUDGET:
        r, out = timed_once(read, compute)
        runs.append(r)
        spent += r["read_wall"] + r["wall"]
        if isinstance(out, Exception):
            break
        if after is not None:
            c0, t0 = time.process_time(), time.perf_counter()
            after(out)
            afters.append(time.process_time() - c0)
            spent += time.perf_counter() - t0
    runs.sort(key=lambda x: x["read_cpu"] + x["cpu"])
    r = {**runs[(len(runs) - 1) // 2], "calls": len(runs)}
    if afters:
        r["after_cpu"] = sorted(afters)[(len(afters) - 1) // 2]
    return r, out


def run(tool, a):
    d = a.ndim
    if tool in ("gmap", "gen"):
        import gmap

        def arrays(h):
            # a generator's arrays are made when first read: every one read, timed apart
            for g in h.generators:
                g.cells, g.extents, g.coefficients

        r, h = timed(lambda: a == 0, lambda m: gmap.homology(m, generators=(tool == "gen")),
                     arrays if tool == "gen" else None)
        if isinstance(h, Exception):
            return {**r, "failed": str(h)[:300]}
        if "after_cpu" in r:
            r["arrays_cpu"] = r.pop("after_cpu")
        return {**r, "betti": [int(x) for x in h.betti][:d]}
    if tool == "cripser":
        import cripser

        r, p = timed(lambda: a.astype(np.float64),
                     lambda f: cripser.computePH_T(f, maxdim=d - 1, location="no"))
        if isinstance(p, Exception):
            return {**r, "failed": str(p)[:300]}
        return {**r, "betti": [int(((p[:, 0] == k) & (p[:, 1] <= 0.5) & (p[:, 2] > 0.5)).sum()) for k in range(d)]}
    import gudhi

    def compute(x):
        c = gudhi.CubicalComplex(top_dimensional_cells=x)
        c.persistence()
        return [int(v) for v in c.persistent_betti_numbers(0.5, 0.5)][:d]

    r, b = timed(lambda: a, compute)
    if isinstance(b, Exception):
        return {**r, "failed": str(b)[:300]}
    return {**r, "betti": b}


def table(path):
    rows, order = results(path)
    print("| image | cubes | gmap read + homology CPU (s) | gmap wall (s) | cripser read + PH CPU (s) "
          "| cripser wall (s) | CPU ratio cripser / gmap (homology; with reading) "
          "| gmap with generators CPU (s): call; every generator's arrays read "
          "| CPU ratio cripser / gmap with generators (call; arrays read too) "
          "| GUDHI CPU (s) | GUDHI wall (s) | groups |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")

    for name in order:
        t = rows[name]
        g, c, e, u = (t.get(k) for k in ("gmap", "cripser", "gen", "gudhi"))
        cubes = next(x["cubes"] for x in t.values())

        def cell(x, f):
            if x is None:
                return "—"
            return short(x["failed"]) if "failed" in x else f(x)

        ratio = "—"
        if ok(g) and ok(c):
            ratio = (f"{c['cpu'] / max(g['cpu'], 1e-3):.1f}× ; "
                     f"{(c['cpu'] + c['read_cpu']) / max(g['cpu'] + g['read_cpu'], 1e-3):.1f}×")
        eratio = "—"
        if ok(e) and ok(c):
            eratio = f"{c['cpu'] / max(e['cpu'], 1e-3):.1f}×"
            if "arrays_cpu" in e:
                eratio += f" ; {c['cpu'] / max(e['cpu'] + e['arrays_cpu'], 1e-3):.1f}×"
        check = groups(g, e, c, u)
        def stages(x):
            return "%.3f + %.3f" % (x["read_cpu"], x["cpu"])

        def cpu(x):
            return "%.3f" % x["cpu"] + ("; +%.3f" % x["arrays_cpu"] if "arrays_cpu" in x else "")

        def wall(x):
            return "%.3f" % x["wall"]

        print(f"| {name} | {cubes:,} | {cell(g, stages)} | {cell(g, wall)} | {cell(c, stages)} | {cell(c, wall)} "
              f"| {ratio} | {cell(e, cpu)} | {eratio} | {cell(u, cpu)} | {cell(u, wall)} | {check} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", default=None, help="comma-separated row names (substrings)")
    ap.add_argument("--tools", default="gmap,gen,cripser,gudhi")
    ap.add_argument("--gudhi-max", type=int, default=1 << 22)
    ap.add_argument("--results", default="bench_cripser.jsonl")
    ap.add_argument("--table", action="store_true")
    args = ap.parse_args()
    if args.table:
        table(args.results)
        return
    for name, shape, dens in cases(False):
        if args.only and not any(o in name for o in args.only.split(",")):
            continue
        a = make(name, shape, dens)
        for tool in args.tools.split(","):
            if tool == "gudhi" and a.size > args.gudhi_max:
                continue
            r = run(tool, a)
            r.update(image=name, tool=tool, cubes=int(a.size))
            with open(args.results, "a") as fh:
                fh.write(json.dumps(r) + "\n")
            print(json.dumps(r), flush=True)
    table(args.results)


if __name__ == "__main__":
    main()
