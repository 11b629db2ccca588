"""gmap against CubicalRipser (and GUDHI beside) on the same binary images, as whole
processes on .npy files, in one sitting; prints a Markdown table (docs/PERFORMANCE.md).

    python3 benches/anchors/compare_cripser.py [--gmap CMD] [--quick] [--gudhi-max N] [--dir DIR]

Each image holds the values 0 and 1 (uint8); the cubical set is the sublevel set at 0.5 (the
cubes of value 0, which make the given density), the T-construction: each value a closed
square or cube. Every tool runs as its own process under /usr/bin/time (wall and CPU
seconds, maximum resident set size):

* gmap: `CMD FILE.npy --level 0.5 --json` (default CMD: `target/release/gmap homology`),
  its JSON giving the reading and the homology stages apart;
* CubicalRipser: `np.load`, `astype(float64)` (the reading stage), then
  `cripser.computePH(a, maxdim=d-1, top_dim=True, location="no")`;
* GUDHI: `gudhi.CubicalComplex(top_dimensional_cells=a).persistence()`, up to --gudhi-max
  cubes.

The Betti numbers at 0.5 are compared: gmap's with GUDHI's wherever GUDHI ran (CubicalRipser's
T-construction reports no pairs of dimension 0, so its counts are shown, not compared).
"""
import argparse
import json
import os
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
r = cripser.computePH(a, maxdim=a.ndim - 1, top_dim=True, location="no")
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


def timed(cmd):
    """Runs cmd under /usr/bin/time; its last stdout line as JSON, and the resources."""
    p = subprocess.run(["/usr/bin/time", "-f", "TIME %e %U %S %M"] + cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{cmd} failed: {p.stderr[-2000:]}")
    line = [l for l in p.stderr.splitlines() if l.startswith("TIME ")][-1].split()
    wall, user, sys_, rss = float(line[1]), float(line[2]), float(line[3]), int(line[4])
    out = json.loads(p.stdout.strip().splitlines()[-1])
    return out, {"wall": wall, "cpu": user + sys_, "rss_mb": rss / 1024}


def betti_of(j, d):
    """gmap's JSON (the CLI's `betti`, or the example's) as d numbers."""
    b = j.get("betti")
    if b is None and "homology" in j:
        b = j["homology"]["betti"]
    return [int(x) for x in b][:d]


def cases(quick):
    rng = np.random.default_rng(2026)
    sizes2 = [1000] if quick else [1000, 2000, 4000]
    sizes3 = [128] if quick else [128, 256, 512]
    for n in sizes2:
        for dens in (0.3, 0.5, 0.7):
            yield f"2-D {n}² random {dens}", (n, n), dens, rng
    for n in sizes3:
        for dens in (0.3, 0.5, 0.7):
            yield f"3-D {n}³ random {dens}", (n, n, n), dens, rng
    yield "camera 512² at its median", None, None, None


def make(shape, dens, rng):
    if shape is None:
        from skimage import data

        cam = data.camera()
        return (cam > np.median(cam)).astype(np.uint8)
    # value 0 (in the set) with probability dens
    a = np.empty(shape, dtype=np.uint8)
    step = max(1, (1 << 24) // int(np.prod(shape[1:])))
    for i in range(0, shape[0], step):
        a[i : i + step] = rng.random((min(step, shape[0] - i),) + shape[1:], dtype=np.float32) >= dens
    return a


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--gmap", default="target/release/gmap homology")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--gudhi-max", type=int, default=1 << 24)
    ap.add_argument("--dir", default=None)
    args = ap.parse_args()
    gmap = args.gmap.split()
    d = args.dir or tempfile.mkdtemp(prefix="cripser_")
    print("| image | cubes | gmap read + homology (s) | gmap wall / CPU (s) | gmap max RSS (MB) "
          "| cripser read + PH (s) | cripser wall / CPU (s) | cripser max RSS (MB) "
          "| ratio wall / CPU | GUDHI wall (s) | groups |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for name, shape, dens, rng in cases(args.quick):
        a = make(shape, dens, rng)
        f = os.path.join(d, "img.npy")
        np.save(f, a)
        n = a.size
        g, gt = timed(gmap + [f, "--level", "0.5", "--json"])
        c, ct = timed([sys.executable, "-c", CRIPSER, f])
        gb = betti_of(g, a.ndim)
        check = f"gmap {gb}"
        gudhi_wall = "—"
        if n <= args.gudhi_max:
            u, ut = timed([sys.executable, "-c", GUDHI, f])
            gudhi_wall = f"{ut['wall']:.2f}"
            check += " = GUDHI" if u["betti"] == gb else f" ≠ GUDHI {u['betti']}"
        check += f"; cripser {c['betti']}"
        print(
            f"| {name} | {n:,} | {g.get('read_s', 0):.3f} + {g.get('homology_s', 0):.3f} "
            f"| {gt['wall']:.2f} / {gt['cpu']:.2f} | {gt['rss_mb']:.0f} "
            f"| {c['read_s']:.3f} + {c['homology_s']:.3f} | {ct['wall']:.2f} / {ct['cpu']:.2f} | {ct['rss_mb']:.0f} "
            f"| {ct['wall'] / gt['wall']:.1f}× / {ct['cpu'] / max(gt['cpu'], 1e-3):.1f}× | {gudhi_wall} | {check} |",
            flush=True,
        )
        os.remove(f)


if __name__ == "__main__":
    main()
