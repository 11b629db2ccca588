#!/usr/bin/env python3
"""Persistence of images in one Python process: gmap's package against GUDHI and CubicalRipser.

    /tmp/gmap-venv/bin/python benches/anchors/persistence_inprocess.py [--only NAME,…] [--reps 3] [--gudhi-max 4200000] [--cripser-threads 1,2]

Needs the `gmap` package (`cd python && maturin build --release`, then pip install the wheel
into a venv made with --system-site-packages, where gudhi and cripser are), and the `.npy`
inputs that `persistence_bench.py` writes (the same seeded arrays and sample images; this
script writes them too if missing, by the same function).

For each input and construction, one process loads the array once and calls, in turn,
`reps` rounds of:

* gmap: `gmap.persistence(arr, construction=C)` (Z/2);
* CubicalRipser: `cripser.computePH(arr, n_threads=N)` for V (its default),
  `cripser.computePH_T(arr, n_threads=N)` for T (`computePH(top_dim=True)` computes
  something else: only the top dimension), once per N of --cripser-threads (default 1;
  `1,2`: a column each);
* GUDHI: `gudhi.CubicalComplex(vertices=arr)` or `(top_dimensional_cells=arr)` then
  `.persistence(homology_coeff_field=2, min_persistence=0)`, building the complex included;
  once, and only on inputs of at most --gudhi-max cells.

Each call is timed by `time.process_time()` (CPU of the process, all threads) and
`time.perf_counter()` (wall); the minimum over the rounds is kept. The number of pairs of
positive persistence is printed per side (GUDHI's and gmap's must agree: the tests compare
the diagrams themselves). Prints a Markdown table and the load average before and after.
"""
import gc
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from persistence_bench import options, selected  # noqa: E402


def timed(f):
    gc.collect()
    c, w = time.process_time(), time.perf_counter()
    n = f()
    return time.process_time() - c, time.perf_counter() - w, n


def main():
    import cripser
    import gmap
    import gudhi

    args = options().parse_args()
    threads = [int(t) for t in args.cripser_threads.split(",")]
    print("| input | constr. | gmap CPU / wall s | "
          + "".join(f"CubicalRipser n_threads={t} CPU / wall s | ratio CPU / wall | " for t in threads)
          + "GUDHI CPU / wall s | ratio CPU / wall | pairs gmap / CR / GUDHI |")
    print("| --- | --- | ---: | " + "---: | ---: | " * len(threads) + "---: | ---: | ---: |")
    for name, path, shape in selected(args):
        arr = np.ascontiguousarray(np.load(path), dtype=np.float64)
        for cons in args.constructions.split(","):
            tools = {"gmap": (lambda: len(gmap.persistence(arr, construction=cons)), args.reps)}
            for t in threads:
                tools[f"cripser{t}"] = ((lambda t=t: finite(cripser.computePH(arr, n_threads=t))) if cons == "V"
                                        else (lambda t=t: finite(cripser.computePH_T(arr, n_threads=t))), args.reps)
            if arr.size <= args.gudhi_max:
                key = "vertices" if cons == "V" else "top_dimensional_cells"
                tools["gudhi"] = (lambda: len(gudhi.CubicalComplex(**{key: arr}).persistence(
                    homology_coeff_field=2, min_persistence=0)), 1)
            best, count = {}, {}
            for rep in range(args.reps):
                for k, (f, reps) in tools.items():
                    if rep >= reps:
                        continue
                    c, w, n = timed(f)
                    old = best.get(k, (float("inf"), float("inf")))
                    best[k] = (min(old[0], c), min(old[1], w))
                    count[k] = n
            g = best["gmap"]

            def cell(k):
                if k not in best:
                    return "– | –"
                b = best[k]
                return f"{b[0]:.3f} / {b[1]:.3f} | {b[0] / g[0]:.1f}× / {b[1] / g[1]:.1f}×"

            cr = "/".join(str(count.get(f"cripser{t}", "–")) for t in threads)
            counts = " / ".join([str(count["gmap"]), cr, str(count.get("gudhi", "–"))])
            shape_s = "×".join(map(str, shape))
            print(f"| {name} {shape_s} | {cons} | {g[0]:.3f} / {g[1]:.3f} | "
                  + "".join(cell(f"cripser{t}") + " | " for t in threads)
                  + f"{cell('gudhi')} | {counts} |", flush=True)
    print("load average after:", open("/proc/loadavg").read().split()[:3])


def finite(r):
    """CubicalRipser's pairs of positive persistence (it also lists birth == death)."""
    r = np.asarray(r)
    return int(np.count_nonzero(r[:, 1] != r[:, 2]))


if __name__ == "__main__":
    main()
