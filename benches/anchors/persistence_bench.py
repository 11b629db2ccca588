#!/usr/bin/env python3
"""Persistence of images: gmap against CubicalRipser and GUDHI, whole processes, one sitting.

    cd python && maturin build --release && cd ..
    python3 -m venv --system-site-packages /tmp/gmap-venv && /tmp/gmap-venv/bin/pip install python/target/wheels/gmap-*.whl
    /tmp/gmap-venv/bin/python benches/anchors/persistence_bench.py [--only NAME,…] [--reps 3] [--gudhi-max 4200000]

Each input is a `.npy` array written once into --out (default target/bench-data/persistence):
random floats (seeded) of 1000², 2000², 4000², 128³ and 256³, smooth fields of 128³ and
256³ (seeded normal noise blurred by a Gaussian of 4 voxels, `smooth`), and scikit-image's sample
images at full size. Each tool runs in its own Python process (the interpreter running
this script: a venv with the `gmap` package and, by --system-site-packages, gudhi and
cripser) on the same file and the same construction, one after the other, `reps` times:

* gmap: `gmap.persistence(arr, construction=C)` (the package, Z/2);
* CubicalRipser: `cripser.computePH(arr, n_threads=N)` for V (its default),
  `cripser.computePH_T(arr, n_threads=N)` for T, once per N of --cripser-threads (default 1);
* GUDHI: `CubicalComplex(vertices=arr)` for V, `(top_dimensional_cells=arr)` for T,
  `persistence(homology_coeff_field=2)`, building included.

Per side the minimum over the runs of: the process's wall time, its CPU time (user +
system, the rusage of the process), and the CPU time of the call alone as each process
measures it (`time.process_time()` around the call, the array already loaded); the largest
peak memory (`/usr/bin/time`'s maximum resident set). Ratios are the other side's figure
over gmap's. GUDHI runs once (it takes minutes) and only on inputs of at most --gudhi-max
cells. Prints a Markdown table and the load average before and after.
"""
import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
# each prints `seconds CPU WALL PAIRS` for its one call, the array already loaded
GMAP = (
    "import sys, time, numpy as np, gmap; a = np.load(sys.argv[1]).astype(np.float64);"
    "c, t = time.process_time(), time.perf_counter(); n = len(gmap.persistence(a, construction=sys.argv[2]));"
    "print('seconds', time.process_time() - c, time.perf_counter() - t, n)"
)
CRIPSER = (
    "import sys, time, numpy as np, cripser; a = np.load(sys.argv[1]).astype(np.float64);"
    "c, t = time.process_time(), time.perf_counter();"
    "n = int(sys.argv[3]); r = cripser.computePH(a, n_threads=n) if sys.argv[2] == 'V' else cripser.computePH_T(a, n_threads=n);"
    "print('seconds', time.process_time() - c, time.perf_counter() - t, len(r))"
)
GUDHI = (
    "import sys, time, numpy as np, gudhi; a = np.load(sys.argv[1]).astype(np.float64);"
    "c, t = time.process_time(), time.perf_counter();"
    "x = gudhi.CubicalComplex(**{('vertices' if sys.argv[2] == 'V' else 'top_dimensional_cells'): a});"
    "n = len(x.persistence(homology_coeff_field=2, min_persistence=0));"
    "print('seconds', time.process_time() - c, time.perf_counter() - t, n)"
)


def seconds(text):
    """The in-process CPU time a tool printed (`seconds CPU WALL PAIRS`)."""
    return float(re.search(r"seconds ([0-9.e-]+)", text).group(1))


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


def smooth(shape, sigma=4.0, seed=20261202):
    """A smooth field: seeded standard normal noise blurred by a Gaussian of `sigma` voxels
    (periodic, through the FFT), float64. Many fewer critical cells than random noise."""
    rng = np.random.default_rng(seed)
    f = np.fft.rfftn(rng.standard_normal(shape))
    k2 = np.zeros(f.shape)
    for axis, n in enumerate(shape):
        k = np.fft.rfftfreq(n) if axis == len(shape) - 1 else np.fft.fftfreq(n)
        view = [1] * len(shape)
        view[axis] = k.size
        k2 = k2 + (k ** 2).reshape(view)
    f *= np.exp(-2.0 * np.pi ** 2 * sigma ** 2 * k2)
    return np.ascontiguousarray(np.fft.irfftn(f, s=shape), dtype=np.float64)


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
    for s in [(128, 128, 128), (256, 256, 256)]:
        name = "smooth_" + "x".join(map(str, s))
        path = os.path.join(out, name + ".npy")
        if not os.path.exists(path):
            np.save(path, smooth(s))
        files.append((name, path, s))
    try:
        import skimage.data as data
    except ImportError:
        print("(scikit-image not installed: its sample images are left out)")
        return files

    for name in ["camera", "coins", "moon", "page", "text", "clock", "brick", "grass", "gravel"]:
        path = os.path.join(out, name + ".npy")
        img = getattr(data, name)()
        if not os.path.exists(path):
            np.save(path, np.ascontiguousarray(img.astype(np.float64)))
        files.append((name, path, img.shape))
    return files


def options():
    """The options both persistence scripts take."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--only", default="", help="comma-separated input names")
    ap.add_argument("--constructions", default="V,T")
    ap.add_argument("--gudhi-max", type=int, default=4_200_000)
    ap.add_argument("--cripser-threads", default="1",
                    help="comma-separated values of CubicalRipser's n_threads, one column each")
    ap.add_argument("--out", default=os.path.join(ROOT, "target", "bench-data", "persistence"))
    return ap


def selected(args):
    """The inputs --only names (all without it), written if missing; prints the load."""
    os.makedirs(args.out, exist_ok=True)
    only = set(filter(None, args.only.split(",")))
    print("load average before:", open("/proc/loadavg").read().split()[:3])
    return [x for x in inputs(args.out) if not only or x[0] in only]


def main():
    ap = options()
    ap.add_argument("--tools", default="gmap,cripser,gudhi", help="which sides to run")
    args = ap.parse_args()
    threads = args.cripser_threads.split(",")
    print("| input | constr. | gmap wall / CPU / in-process CPU s | MB | "
          + "".join(f"CubicalRipser n_threads={t} wall / CPU / in-process CPU s | MB | ratio CPU / in-process | "
                    for t in threads)
          + "GUDHI wall / CPU / in-process CPU s | MB | ratio CPU / in-process |")
    print("| --- | --- | ---: | ---: | " + "---: | ---: | ---: | " * len(threads) + "---: | ---: | ---: |")
    for name, path, shape in selected(args):
        n = int(np.prod(shape))
        for cons in args.constructions.split(","):
            tools = {
                "gmap": ([sys.executable, "-c", GMAP, path, cons], args.reps),
            }
            for t in args.cripser_threads.split(","):
                tools[f"cripser{t}"] = ([sys.executable, "-c", CRIPSER, path, cons, t], args.reps)
            if n <= args.gudhi_max:
                tools["gudhi"] = ([sys.executable, "-c", GUDHI, path, cons], 1)
            # `cripser` names every thread setting's run
            tools = {k: v for k, v in tools.items() if k.rstrip("0123456789") in args.tools.split(",")}
            best, mem = {}, {}
            for rep in range(args.reps):
                for k, (cmd, reps) in tools.items():
                    if rep >= reps:
                        continue
                    w, c, s, m = run(cmd)
                    old = best.get(k, (float("inf"),) * 3)
                    best[k] = (min(old[0], w), min(old[1], c), min(old[2], s))
                    mem[k] = max(mem.get(k, 0.0), m)
            g = best.get("gmap", (float("nan"),) * 3)

            def cell(k):
                if k not in best:
                    return "– | – | –"
                b = best[k]
                return (f"{b[0]:.2f} / {b[1]:.2f} / {b[2]:.3f} | {mem[k]:.0f} | "
                        f"{b[1] / g[1]:.1f}× / {b[2] / g[2]:.1f}×")

            shape_s = "×".join(map(str, shape))
            crs = "".join(cell(f"cripser{t}") + " | " for t in args.cripser_threads.split(","))
            print(f"| {name} {shape_s} | {cons} | {g[0]:.2f} / {g[1]:.2f} / {g[2]:.3f} | {mem.get('gmap', 0):.0f} | "
                  f"{crs}{cell('gudhi')} |", flush=True)
    print("load average after:", open("/proc/loadavg").read().split()[:3])


if __name__ == "__main__":
    main()
