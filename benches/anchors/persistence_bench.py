#!/usr/bin/env python3
"""Persistence of images: gmap against CubicalRipser and GUDHI, whole processes, one sitting.

    cargo build --release --example persistence_image
    python3 benches/anchors/persistence_bench.py [--only NAME,…] [--reps 3] [--gudhi-max 4200000]

Each input is a `.npy` array written once into --out (default target/bench-data/persistence):
random floats (seeded) of 1000², 2000², 4000², 128³ and 256³, and scikit-image's sample
images at full size. Each tool runs in its own process on the same file and the same
construction, one after the other, `reps` times:

* gmap: `persistence_image FILE V|T` (the library's `CubicalFiltration`, Z/2; reading
  the file included in the process, its own timer around the diagram);
* CubicalRipser: `cripser.computePH(arr)` (its default: V-construction, Z/2);
* GUDHI: `CubicalComplex(vertices=arr)` for V, `(top_dimensional_cells=arr)` for T,
  `persistence(homology_coeff_field=2)`; its timer around both.

Per side the minimum over the runs of: the process's wall time, its CPU time (user +
system, `/usr/bin/time`), and the time of the computation alone as each side times it in
process (the array already in memory); the largest peak memory. Ratios are the other
side's figure over gmap's. GUDHI runs once (it takes minutes) and only on inputs of at most
--gudhi-max cells. Prints a Markdown table and the load average before and after.
"""
import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GMAP = os.path.join(ROOT, "target", "release", "examples", "persistence_image")

CRIPSER = (
    "import sys, time, numpy as np, cripser; a = np.load(sys.argv[1]); t = time.perf_counter();"
    "r = cripser.computePH(a); print('seconds', time.perf_counter() - t, len(r))"
)
GUDHI = (
    "import sys, time, numpy as np, gudhi; a = np.load(sys.argv[1]).astype(np.float64); t = time.perf_counter();"
    "c = gudhi.CubicalComplex(**{('vertices' if sys.argv[2] == 'V' else 'top_dimensional_cells'): a});"
    "n = len(c.persistence(homology_coeff_field=2, min_persistence=0)); print('seconds', time.perf_counter() - t, n)"
)


def seconds(text):
    """The in-process time a tool printed: `seconds X` or the example's `diagram 1.2s`."""
    m = re.search(r"seconds ([0-9.e-]+)", text)
    if m:
        return float(m.group(1))
    m = re.search(r"values ([0-9.]+)(ms|µs|s), diagram ([0-9.]+)(ms|µs|s)", text)
    unit = {"s": 1.0, "ms": 1e-3, "µs": 1e-6}
    return float(m.group(1)) * unit[m.group(2)] + float(m.group(3)) * unit[m.group(4)]


def run(cmd):
    """Wall, CPU (user + system, the rusage of the process tree, microseconds), in-process
    seconds, peak MB (`/usr/bin/time`'s: a fork of this big Python process would report
    this process's size)."""
    t = time.perf_counter()
    p = subprocess.Popen(["/usr/bin/time", "-f", "MAXRSS %M"] + cmd, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t
    if status != 0:
        raise RuntimeError(f"{cmd}: {out[-500:]}")
    kb = int(re.search(r"MAXRSS (\d+)", out).group(1))
    return wall, ru.ru_utime + ru.ru_stime, seconds(out), kb / 1024.0


def inputs(out):
    rng = np.random.default_rng(20261125)
    files = []
    for s in [(1000, 1000), (2000, 2000), (4000, 4000), (128, 128, 128), (256, 256, 256)]:
        name = "random_" + "x".join(map(str, s))
        path = os.path.join(out, name + ".npy")
        arr = rng.random(s)
        if not os.path.exists(path):
            np.save(path, arr)
        files.append((name, path, s))
    import skimage.data as data

    for name in ["camera", "coins", "moon", "page", "text", "clock", "brick", "grass", "gravel"]:
        path = os.path.join(out, name + ".npy")
        img = getattr(data, name)()
        if not os.path.exists(path):
            np.save(path, np.ascontiguousarray(img.astype(np.float64)))
        files.append((name, path, img.shape))
    return files


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--only", default="", help="comma-separated input names")
    ap.add_argument("--constructions", default="V,T")
    ap.add_argument("--gudhi-max", type=int, default=4_200_000)
    ap.add_argument("--out", default=os.path.join(ROOT, "target", "bench-data", "persistence"))
    ap.add_argument("--gmap", default=GMAP)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    only = set(filter(None, args.only.split(",")))
    print("load average before:", open("/proc/loadavg").read().split()[:3])
    print("| input | constr. | gmap wall / CPU / in-process s | MB | CubicalRipser wall / CPU / in-process s | MB "
          "| ratio CPU / in-process | GUDHI wall / CPU / in-process s | MB | ratio CPU / in-process |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for name, path, shape in inputs(args.out):
        if only and name not in only:
            continue
        n = int(np.prod(shape))
        for cons in args.constructions.split(","):
            tools = {"gmap": ([args.gmap, path, cons], args.reps)}
            if cons == "V":
                tools["cripser"] = ([sys.executable, "-c", CRIPSER, path], args.reps)
            if n <= args.gudhi_max:
                tools["gudhi"] = ([sys.executable, "-c", GUDHI, path, cons], 1)
            best, mem = {}, {}
            for rep in range(args.reps):
                for k, (cmd, reps) in tools.items():
                    if rep >= reps:
                        continue
                    w, c, s, m = run(cmd)
                    old = best.get(k, (float("inf"),) * 3)
                    best[k] = (min(old[0], w), min(old[1], c), min(old[2], s))
                    mem[k] = max(mem.get(k, 0.0), m)
            g = best["gmap"]

            def cell(k):
                if k not in best:
                    return "– | – | –"
                b = best[k]
                return (f"{b[0]:.2f} / {b[1]:.2f} / {b[2]:.3f} | {mem[k]:.0f} | "
                        f"{b[1] / g[1]:.1f}× / {b[2] / g[2]:.1f}×")

            shape_s = "×".join(map(str, shape))
            print(f"| {name} {shape_s} | {cons} | {g[0]:.2f} / {g[1]:.2f} / {g[2]:.3f} | {mem['gmap']:.0f} | "
                  f"{cell('cripser')} | {cell('gudhi')} |", flush=True)
    print("load average after:", open("/proc/loadavg").read().split()[:3])


if __name__ == "__main__":
    main()
