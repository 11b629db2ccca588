#!/usr/bin/env python3
# usage: gudhi_cubical_file.py FILE.cub [--periodic]
# Anchor for benches/cubical.rs: GUDHI's CubicalComplex (bitmap + persistence over Z/2) on
# the cubes of a .cub file: the top-dimensional cells of the bounding box, 0 for a cube of
# the set and 1 for the others, so the sublevel set at 0 is the closed union. The file is
# parsed first (not timed); the build of the complex and the persistence are timed in-process.
# Prints `seconds betti...` on one line (betti numbers of the set, at filtration value 0).
# compare_gudhi.py imports `read_bitmap` and `timed` from here.
import sys, time
import numpy as np
import gudhi


def read_bitmap(path):
    """The bounding box of the cubes of a .cub file as top cells: 0 in the set, 1 outside."""
    cubes = []
    for line in open(path):
        line = line.split(";", 1)[0].strip()
        if not line or line.startswith("dimension"):
            continue
        cubes.append([int(t) for t in line.strip("()").replace(",", " ").split()])
    a = np.array(cubes, dtype=np.int64)
    lo = a.min(axis=0)
    shape = tuple(a.max(axis=0) - lo + 1)
    top = np.ones(shape, dtype=np.float64)
    top[tuple((a - lo).T)] = 0.0
    return top


def timed(top, periodic=False):
    """Seconds of the build plus Z/2 persistence, and the Betti numbers at filtration 0."""
    t0 = time.perf_counter()
    if periodic:
        cc = gudhi.PeriodicCubicalComplex(top_dimensional_cells=top, periodic_dimensions=[True] * top.ndim)
    else:
        cc = gudhi.CubicalComplex(top_dimensional_cells=top)
    cc.compute_persistence(homology_coeff_field=2)
    betti = cc.persistent_betti_numbers(0.0, 0.0)
    return time.perf_counter() - t0, betti


if __name__ == "__main__":
    seconds, betti = timed(read_bitmap(sys.argv[1]), "--periodic" in sys.argv[2:])
    print(f"{seconds:.6f}", *betti)
