#!/usr/bin/env python3
"""Persistence of images: gmap against GUDHI and CubicalRipser, whole processes, one sitting.

    cargo build --release --example persistence_image
    python3 benches/anchors/persistence_bench.py [--sizes small|all] [--reps 3] [--out DIR]

Each input is a `.npy` array written once into DIR (default target/bench-data/persistence):
random floats of 1000², 2000², 4000² (and 128³, 256³ with --sizes all; 64³ and 128³ by
default), and scikit-image's sample images at full size. Each tool runs in its own
process on the same file and the same construction, alternating, `reps` times:

* gmap: `persistence_image FILE V` (the library's CubicalFiltration, V-construction, Z/2);
  the same binary with `T` against GUDHI's T-construction;
* CubicalRipser: `cripser.computePH(arr)` (its default: V-construction, Z/2, one thread);
* GUDHI: `CubicalComplex(vertices=arr)` / `(top_dimensional_cells=arr)`, `persistence()`
  over Z/2 (GUDHI's own timing includes the complex's construction).

Wall-clock medians (the whole process, from launch to exit, reading the file included)
and the largest peak memory (`/usr/bin/time -f %M`), then the ratios other/gmap. Prints a
Markdown table. GUDHI is skipped past 2000² and 128³ (it takes minutes there).
"""
import argparse
import os
import statistics
import subprocess
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GMAP = os.path.join(ROOT, "target", "release", "examples", "persistence_image")

CRIPSER = "import sys, numpy as np, cripser; a = np.load(sys.argv[1]); r = cripser.computePH(a); print(len(r))"
GUDHI = (
    "import sys, numpy as np, gudhi; a = np.load(sys.argv[1]).astype(np.float64);"
    "c = gudhi.CubicalComplex(**{('vertices' if sys.argv[2] == 'V' else 'top_dimensional_cells'): a});"
    "print(len(c.persistence(homology_coeff_field=2, min_persistence=0)))"
)


def run(cmd):
    r = subprocess.run(["/usr/bin/time", "-f", "%e %M"] + cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{cmd}: {r.stderr[-500:]}")
    wall, kb = r.stderr.strip().splitlines()[-1].split()
    return float(wall), int(kb) / 1024.0


def inputs(out, sizes):
    rng = np.random.default_rng(20261125)
    shapes = [(1000, 1000), (2000, 2000), (4000, 4000), (64, 64, 64), (128, 128, 128)]
    if sizes == "all":
        shapes.append((256, 256, 256))
    files = []
    for s in shapes:
        name = "random_" + "x".join(map(str, s)) + ".npy"
        path = os.path.join(out, name)
        if not os.path.exists(path):
            np.save(path, rng.random(s))
        files.append((name[:-4], path, s))
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
    ap.add_argument("--sizes", default="small", choices=["small", "all"])
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(ROOT, "target", "bench-data", "persistence"))
    ap.add_argument("--gmap", default=GMAP)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    print("| input | construction | gmap s | gmap MB | CubicalRipser s | MB | ratio | GUDHI s | MB | ratio |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for name, path, shape in inputs(args.out, args.sizes):
        n = int(np.prod(shape))
        for cons in ("V", "T"):
            tools = {"gmap": [args.gmap, path, cons]}
            if cons == "V":
                tools["cripser"] = [sys.executable, "-c", CRIPSER, path]
            if n <= 4_200_000 and (len(shape) == 2 or n <= 128**3):
                tools["gudhi"] = [sys.executable, "-c", GUDHI, path, cons]
            times = {k: [] for k in tools}
            mem = {k: 0.0 for k in tools}
            for _ in range(args.reps):
                for k, cmd in tools.items():
                    t, m = run(cmd)
                    times[k].append(t)
                    mem[k] = max(mem[k], m)
            med = {k: statistics.median(v) for k, v in times.items()}
            g = med["gmap"]

            def cell(k):
                if k not in med:
                    return "– | – | –"
                return f"{med[k]:.2f} | {mem[k]:.0f} | {med[k] / g:.1f}x"

            print(f"| {name} {'x'.join(map(str, shape))} | {cons} | {g:.2f} | {mem['gmap']:.0f} | {cell('cripser')} | {cell('gudhi')} |",
                  flush=True)


if __name__ == "__main__":
    main()
