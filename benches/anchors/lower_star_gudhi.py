#!/usr/bin/env python3
"""Lower-star persistence of a triangulated grid in one Python process: gmap against GUDHI.

    /tmp/gmap-venv/bin/python benches/anchors/lower_star_gudhi.py [N …] [--reps 2]

For each N (default 100 300 600): the disk made of the N × N grid of vertices (vertex
(i, j) labelled i·N + j), each square cut into two triangles, with uniform random vertex
values (seed 0). Each round times, by `time.process_time()`, building and computing on
each side, over Z/2:

* gmap: `gmap.persistence(gmap.SimplicialComplex(triangles), vertex_values=values)`;
* GUDHI, as its documentation does it: every triangle inserted, then
  `assign_filtration(s, max of its vertices)` for every simplex,
  `make_filtration_non_decreasing()`, `persistence(homology_coeff_field=2,
  min_persistence=0, persistence_dim_max=True)`;
* GUDHI, the fastest way we know: `insert_batch` of the vertices, then of the edges, then
  of the triangles, each with its lower-star value computed in numpy (in increasing
  dimension, so that no face is lowered), then `persistence(…)` as above. (Inserting the
  triangles with their values and assigning the vertices' is faster still but gives an
  edge the least value of its triangles, not of its vertices: not the lower star.)

Prints the minimum over the rounds and whether the diagrams agree (pairs of positive
persistence, as multisets).
"""
import argparse
import time
from collections import Counter

import numpy as np

import gmap
import gudhi


def grid(n):
    tris = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, i * n + j + 1, (i + 1) * n + j, (i + 1) * n + j + 1
            tris += [[a, b, d], [a, c, d]]
    return tris


def ours(tris, vals):
    return gmap.persistence(gmap.SimplicialComplex(tris), vertex_values=vals)


def gudhi_documented(tris, vals):
    st = gudhi.SimplexTree()
    for f in tris:
        st.insert(f)
    for s, _ in list(st.get_simplices()):
        st.assign_filtration(s, max(vals[v] for v in s))
    st.make_filtration_non_decreasing()
    return st.persistence(homology_coeff_field=2, min_persistence=0, persistence_dim_max=True)


def gudhi_batch(tris, vals):
    t = np.asarray(tris, dtype=np.int64)
    e = np.unique(np.sort(np.concatenate([t[:, [0, 1]], t[:, [0, 2]], t[:, [1, 2]]]), axis=1), axis=0)
    st = gudhi.SimplexTree()
    st.insert_batch(np.arange(len(vals))[None, :], vals)
    st.insert_batch(e.T, vals[e].max(axis=1))
    st.insert_batch(t.T, vals[t].max(axis=1))
    return st.persistence(homology_coeff_field=2, min_persistence=0, persistence_dim_max=True)


def timed(f, *args):
    t = time.process_time()
    r = f(*args)
    return time.process_time() - t, r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("n", nargs="*", type=int, default=[100, 300, 600])
    ap.add_argument("--reps", type=int, default=2)
    a = ap.parse_args()
    print("| grid | triangles | gmap s | GUDHI documented s | ratio | GUDHI insert_batch s | ratio | equal |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    for n in a.n:
        tris = grid(n)
        vals = np.random.default_rng(0).random(n * n)
        best = [float("inf")] * 3
        for _ in range(a.reps):
            (t0, d), (t1, g1), (t2, g2) = timed(ours, tris, vals), timed(gudhi_documented, tris, vals), timed(gudhi_batch, tris, vals)
            best = [min(x, y) for x, y in zip(best, [t0, t1, t2])]
        mine = Counter((int(k), float(b), float(e)) for k, b, e in d)
        theirs = [Counter((k, float(b), float(e)) for k, (b, e) in g if b != e) for g in (g1, g2)]
        equal = mine == theirs[0] == theirs[1]
        print(f"| {n}×{n} | {len(tris)} | {best[0]:.3f} | {best[1]:.3f} | {best[1] / best[0]:.1f}× "
              f"| {best[2]:.3f} | {best[2] / best[0]:.1f}× | {equal} |")


if __name__ == "__main__":
    main()
