"""gmap against CubicalRipser (and GUDHI beside) on the same binary images, as whole
processes on .npy files, in one sitting; prints a Markdown table (docs/PERFORMANCE.md).

    python3 benches/anchors/compare_cripser.py [--gmap CMD] [--quick] [--gudhi-max N] [--dir DIR]
        [--only NAME,...] [--tools gmap,gen,cripser,gudhi] [--results FILE.jsonl] [--table]

Each row's array is made from its own seed, so rows and tools can run in separate
invocations (`--only`, `--tools`); every measurement is appended to --results (JSON lines)
and `--table` prints the table from that file (the newest measurement of each row and tool).

Each image holds the values 0 and 1 (uint8); the cubical set is the sublevel set at 0.5 (the
cubes of value 0, which make the given density), the T-construction: each value a closed
square or cube. Every tool runs as its own process under /usr/bin/time (wall and CPU
seconds, maximum resident set size):

* gmap: `CMD FILE.npy --level 0.5 --json --timings` (default CMD: `target/release/gmap
  homology`): `--timings` prints the reading stage (header and memory map) and the homology
  apart; the pages of the mapped file are read during the homology;
* gmap with generators: `CMD FILE.npy --level 0.5 --timings --generators`, its text written
  to a file (`gen`; `genjson` the same with `--json`, about four times the bytes): in 1-D and
  2-D the cycles read off two union-finds, in 3-D those and the loops of a sweep over the
  grid (`gmap_homology::cubical::gens`);
* CubicalRipser: `np.load`, `astype(float64)` (the reading stage), then its T-construction,
  `cripser.computePH_T(a, maxdim=d-1, location="no")` (`computePH(a, top_dim=True)` is not
  it: that computes the V-construction's dimension d-1 alone, through Alexander duality);
* GUDHI: `gudhi.CubicalComplex(top_dimensional_cells=a).persistence()`, up to --gudhi-max
  cubes.

The Betti numbers at 0.5 (the classes born at 0 and alive at 0.5) are compared: gmap's with
CubicalRipser's, with GUDHI's wherever GUDHI ran, and with those of gmap's run with
generators.
"""
import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile

import numpy as np

CRIPSER = r"""
import sys, time, json
import numpy as np, cripser
t0 = time.perf_counter()
a = np.load(sys.argv[1]).astype(np.float64)
t1 = time.perf_counter()
r = cripser.computePH_T(a, maxdim=a.ndim - 1, location="no")
t2 = time.perf_counter()
betti = [int(((r[:, 0] == k) & (r[:, 1] <= 0.5) & (r[:, 2] > 0.5)).sum()) for k in range(a.ndim)]
print(json.dumps({"read_s": t1 - t0, "homology_s": t2 - t1, "betti": betti}))
"""

GUDHI = r"""
import sys, time, json
import numpy as np, gudhi
t0 = time.perf_counter()
a = np.load(sys.argv[1])
t1 = time.perf_counter()
c = gudhi.CubicalComplex(top_dimensional_cells=a)
c.persistence()
b = c.persistent_betti_numbers(0.5, 0.5)
t2 = time.perf_counter()
print(json.dumps({"read_s": t1 - t0, "homology_s": t2 - t1, "betti": [int(x) for x in b][: a.ndim]}))
"""


def timed(cmd, timeout=None, stdout_path=None):
    """Runs cmd under /usr/bin/time: its last stdout line as JSON (None when it failed), its
    stderr, and the resources. With stdout_path the output goes to that file instead, and
    the first value is {}."""
    # a process group of its own, so that a run stopped at the timeout stops whole
    sink = open(stdout_path, "w") if stdout_path else subprocess.PIPE
    p = subprocess.Popen(["/usr/bin/time", "-f", "TIME %e %U %S %M"] + cmd, stdout=sink,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        stdout, stderr = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        return None, f"stopped after {timeout:.0f} s", None
    lines = [l for l in stderr.splitlines() if l.startswith("TIME ")]
    res = None
    if lines:
        t = lines[-1].split()
        res = {"wall": float(t[1]), "cpu": float(t[2]) + float(t[3]), "rss_mb": int(t[4]) / 1024}
    if p.returncode != 0:
        err = [l for l in stderr.splitlines() if not l.startswith("TIME ") and "exited" not in l]
        return None, (err[-1] if err else f"exit {p.returncode}")[-300:], res
    if stdout_path:
        sink.close()
        return {}, stderr, res
    return json.loads(stdout.strip().splitlines()[-1]), stderr, res


def betti_of_text(path, d):
    """The Betti numbers from the `H_k = ...` lines of gmap's text output (free groups: `0`,
    `Z`, `Z^n`)."""
    b = [0] * d
    with open(path) as fh:
        for line in fh:
            if line.startswith("generator"):
                break
            if line.startswith("H_"):
                k, g = line[2:].split(" = ")
                g = g.strip()
                if int(k) < d:
                    b[int(k)] = 0 if g == "0" else 1 if g == "Z" else int(g.split("^")[1])
    return b


def gmap_timings(stderr):
    """`timings: read X s, homology Y s` from gmap's stderr."""
    for l in stderr.splitlines():
        if l.startswith("timings:"):
            w = l.replace(",", " ").split()
            return float(w[2]), float(w[5])
    return None, None


def betti_of(j, d):
    """gmap's JSON (the CLI's `betti`, or the example's) as d numbers."""
    b = j.get("betti")
    if b is None and "homology" in j:
        b = j["homology"]["betti"]
    return [int(x) for x in b][:d]


def cases(quick):
    sizes2 = [1000] if quick else [1000, 2000, 4000]
    sizes3 = [128] if quick else [128, 256, 512]
    for n in sizes2:
        for dens in (0.3, 0.5, 0.7):
            yield f"2-D {n}² random {dens}", (n, n), dens
    for n in sizes3:
        for dens in (0.3, 0.5, 0.7):
            yield f"3-D {n}³ random {dens}", (n, n, n), dens
    yield "camera 512² at its median", None, None


def make(name, shape, dens):
    """The row's array: value 0 (in the set) with probability dens, from the row's own seed."""
    if shape is None:
        from skimage import data

        cam = data.camera()
        return (cam > np.median(cam)).astype(np.uint8)
    rng = np.random.default_rng(int.from_bytes(name.encode(), "little") % (1 << 63))
    a = np.empty(shape, dtype=np.uint8)
    step = max(1, (1 << 24) // int(np.prod(shape[1:])))
    for i in range(0, shape[0], step):
        a[i : i + step] = rng.random((min(step, shape[0] - i),) + shape[1:], dtype=np.float32) >= dens
    return a


def measure(tool, f, a, gmap, timeout):
    """One tool on the file: a dict for the results file."""
    if tool == "gmap":
        out, err, res = timed(gmap + [f, "--level", "0.5", "--json", "--timings"], timeout)
        if out is None:
            return {"failed": err, **(res or {})}
        read, hom = gmap_timings(err)
        return {"read_s": read, "homology_s": hom, "betti": betti_of(out, a.ndim), **res}
    if tool in ("gen", "genjson"):
        # the cycles written to a file, as a user keeps them: the text of `gmap homology
        # --generators`, or its --json
        path = f + (".gen.json" if tool == "genjson" else ".gen.txt")
        cmd = gmap + [f, "--level", "0.5", "--timings", "--generators"] + (["--json"] if tool == "genjson" else [])
        out, err, res = timed(cmd, timeout, stdout_path=path)
        if out is None:
            return {"failed": err, **(res or {})}
        read, hom = gmap_timings(err)
        if tool == "genjson":
            with open(path) as fh:
                betti = json.loads(fh.read(4096).split(',"coefficients"')[0] + "}")["betti"][: a.ndim]
        else:
            betti = betti_of_text(path, a.ndim)
        size = os.path.getsize(path) / 2**20
        os.remove(path)
        return {"read_s": read, "homology_s": hom, "betti": betti, "output_mb": size, **res}
    script = CRIPSER if tool == "cripser" else GUDHI
    out, err, res = timed([sys.executable, "-c", script, f], timeout)
    if out is None:
        return {"failed": err, **(res or {})}
    return {**out, **res}


def short(msg):
    """A refusal in a few words: the generators' limit, a timeout, or the message's start."""
    import re

    m = re.search(r"dimension (\d+) keeps (\d+)", msg)
    if m:
        return f"refused: the reduced complex keeps {int(m.group(2)):,} cells of dimension {m.group(1)} (limit 2,000)"
    return msg[:120]


def ok(x):
    """A measurement that did not fail."""
    return x is not None and "failed" not in x


def groups(g, e, c, u):
    """The groups column: gmap's, checked against CubicalRipser's, GUDHI's and gmap's with
    generators (each named once it agrees, shown where it differs)."""
    check = f"gmap {g['betti']}" if ok(g) else ""
    if ok(g):
        for who, x in (("CubicalRipser", c), ("GUDHI", u)):
            if ok(x):
                check += f" = {who}" if x["betti"] == g["betti"] else f" ≠ {who} {x['betti']}"
    if ok(e) and ok(g) and e["betti"] != g["betti"]:
        check += f" ≠ with generators {e['betti']}"
    if ok(c) and not ok(g):
        check += f"cripser {c['betti']}"
    return check


def results(path):
    """The rows of a results file: {image: {tool: record}}, and the images in table order
    (the known cases first, in their order, then any other in the file's order)."""
    rows, seen = {}, []
    with open(path) as fh:
        for line in fh:
            r = json.loads(line)
            if r["image"] not in rows:
                rows[r["image"]] = {}
                seen.append(r["image"])
            rows[r["image"]][r["tool"]] = r
    known = [n for n, _, _ in cases(False)]
    return rows, [n for n in known if n in rows] + [n for n in seen if n not in known]


def cpu_ratio(c, x):
    """CubicalRipser's CPU over x's. Where CubicalRipser did not finish, a lower bound: the
    CPU it spent before it failed (out of memory), or, stopped at a timeout, the timeout
    over x's wall."""
    if not ok(x) or c is None:
        return "—"
    if ok(c):
        return f"{c['cpu'] / max(x['cpu'], 1e-2):.1f}×"
    if "cpu" in c:
        return f"> {c['cpu'] / max(x['cpu'], 1e-2):.0f}×"
    if c["failed"].startswith("stopped after "):
        return f"> {float(c['failed'].split()[2]) / max(x['wall'], 1e-2):.0f}× (wall)"
    return "—"


def table(path):
    rows, order = results(path)
    print("| image | cubes | gmap read + homology (s) | gmap wall / CPU (s) | gmap max RSS (MB) "
          "| cripser read + PH (s) | cripser wall / CPU (s) | cripser max RSS (MB) | CPU ratio cripser / gmap "
          "| gmap --generators wall / CPU (s) | CPU ratio cripser / gmap --generators "
          "| GUDHI wall / CPU (s) | GUDHI max RSS (MB) | groups |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for name in order:
        t = rows[name]
        g, c, e, u = (t.get(k) for k in ("gmap", "cripser", "gen", "gudhi"))
        cubes = next((x["cubes"] for x in t.values() if "cubes" in x), 0)

        def cell(x, f):
            if x is None:
                return "—"
            if "failed" in x:
                if f is rss:
                    return "—"
                if f is times and "cpu" in x:
                    return times(x) + ", unfinished"
                spent = f" (after {x['wall']:.0f} s, {x['rss_mb']:.0f} MB resident)" if "wall" in x else ""
                return short(x["failed"]) + spent
            return f(x)

        def rss(x):
            return f"{x['rss_mb']:.0f}"

        def times(x):
            return f"{x['wall']:.2f} / {x['cpu']:.2f}"

        gcol = cell(g, lambda x: f"{x['read_s']:.3f} + {x['homology_s']:.3f}")
        gwall = cell(g, times)
        grss = cell(g, rss)
        ccol = cell(c, lambda x: f"{x['read_s']:.3f} + {x['homology_s']:.3f}")
        cwall = cell(c, times)
        crss = cell(c, rss)
        ratio = cpu_ratio(c, g)
        ewall = cell(e, times)
        eratio = cpu_ratio(c, e)
        uwall = cell(u, times)
        urss = cell(u, rss)
        check = groups(g, e, c, u)
        print(f"| {name} | {cubes:,} | {gcol} | {gwall} | {grss} | {ccol} | {cwall} | {crss} | {ratio} "
              f"| {ewall} | {eratio} | {uwall} | {urss} | {check} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gmap", default="target/release/gmap homology")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--gudhi-max", type=int, default=1 << 24)
    ap.add_argument("--dir", default=None)
    ap.add_argument("--only", default=None, help="comma-separated row names (substrings)")
    ap.add_argument("--tools", default="gmap,gen,cripser,gudhi")
    ap.add_argument("--results", default=None, help="JSON lines file the measurements are appended to")
    ap.add_argument("--timeout", type=float, default=None, help="seconds before a tool's run is stopped")
    ap.add_argument("--table", action="store_true", help="print the table of --results and stop")
    args = ap.parse_args()
    results = args.results or os.path.join(tempfile.mkdtemp(prefix="cripser_"), "results.jsonl")
    if args.table:
        table(results)
        return
    gmap = args.gmap.split()
    d = args.dir or tempfile.mkdtemp(prefix="cripser_")
    tools = args.tools.split(",")
    for name, shape, dens in cases(args.quick):
        if args.only and not any(o in name for o in args.only.split(",")):
            continue
        a = make(name, shape, dens)
        f = os.path.join(d, "img.npy")
        np.save(f, a)
        for tool in tools:
            if tool == "gudhi" and a.size > args.gudhi_max:
                continue
            r = measure(tool, f, a, gmap, args.timeout)
            r.update(image=name, tool=tool, cubes=int(a.size))
            with open(results, "a") as fh:
                fh.write(json.dumps(r) + "\n")
            print(json.dumps(r), flush=True)
        os.remove(f)
    table(results)


if __name__ == "__main__":
    main()
