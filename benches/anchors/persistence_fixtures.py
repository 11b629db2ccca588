#!/usr/bin/env python3
"""Writes the persistence fixtures the Rust tests compare with, using GUDHI.

    python3 benches/anchors/persistence_fixtures.py     # from the workspace root

* tests/data/images/NAME.pgm (8-bit, P5) and NAME.npy: scikit-image's sample images
  shipped with the package, grey, downsampled by slicing to at most 64 pixels a side;
  tests/data/images/NAME.json: GUDHI's diagrams of each image.
* tests/data/persistence/random.json: random 1-D to 4-D arrays (small integers, so with
  ties, and floats) with GUDHI's diagrams.
* tests/data/persistence/lutz.json: Lutz files (tests/data/lutz) with random values per
  facet and per vertex, GUDHI SimplexTree diagrams (per facet: insert each facet with its
  value, faces take the minimum; lower star: each simplex the maximum of its vertices).

Each diagram is a list of [dim, birth, death] (death "inf"), zero-persistence pairs left
out, under a key `C_S_P_F`: construction T or V, sub or super(level), p(eriodic) or
n(ot), field. Superlevel diagrams are those of the negated array, negated back.
"""
import json
import os
import sys

import gudhi
import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
IMAGES = os.path.join(ROOT, "tests", "data", "images")
PERS = os.path.join(ROOT, "tests", "data", "persistence")


def num(x):
    if x == float("inf"):
        return "inf"
    if x == float("-inf"):
        return "-inf"
    return float(x)


def cubical(arr, construction, superlevel, periodic, field):
    a = -arr if superlevel else arr
    a = np.asarray(a, dtype=np.float64)
    kw = {"top_dimensional_cells": a} if construction == "T" else {"vertices": a}
    if periodic:
        c = gudhi.PeriodicCubicalComplex(periodic_dimensions=[True] * a.ndim, **kw)
    else:
        c = gudhi.CubicalComplex(**kw)
    s = -1.0 if superlevel else 1.0
    out = []
    for dim, (b, d) in c.persistence(homology_coeff_field=field, min_persistence=0):
        if b == d:
            continue
        out.append([int(dim), num(s * b), num(s * d)])
    return sorted(out, key=lambda p: (p[0], str(p[1]), str(p[2])))


def all_cubical(arr, fields=(2, 3), periodic=True):
    out = {}
    for c in "TV":
        for sup in (False, True):
            for per in ((False, True) if periodic else (False,)):
                for f in fields:
                    key = f"{c}_{'super' if sup else 'sub'}_{'p' if per else 'n'}_{f}"
                    out[key] = cubical(arr, c, sup, per, f)
    return out


def write_pgm(path, a):
    h, w = a.shape
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (w, h))
        f.write(np.ascontiguousarray(a, dtype=np.uint8).tobytes())


def images():
    import skimage.data as data

    os.makedirs(IMAGES, exist_ok=True)
    for name in ["camera", "coins", "moon", "page", "text", "clock", "brick", "grass", "gravel", "checkerboard"]:
        img = getattr(data, name)()
        if img.ndim != 2:
            continue
        step = max(1, (max(img.shape) + 63) // 64)
        small = np.ascontiguousarray(img[::step, ::step]).astype(np.uint8)
        write_pgm(os.path.join(IMAGES, name + ".pgm"), small)
        np.save(os.path.join(IMAGES, name + ".npy"), small)
        rec = {"name": name, "shape": list(small.shape), "step": step,
               "diagrams": all_cubical(small.astype(np.float64))}
        with open(os.path.join(IMAGES, name + ".json"), "w") as f:
            json.dump(rec, f)
        print(name, small.shape, file=sys.stderr)


def randoms():
    rng = np.random.default_rng(20261125)
    cases = []
    shapes = [(9,), (7, 8), (12, 10), (5, 6, 7), (6, 6, 6), (3, 4, 3, 4), (4, 4, 4, 4)]
    for shape in shapes:
        for kind in ("int", "float"):
            if kind == "int":
                a = rng.integers(0, 6, size=shape).astype(np.float64)
            else:
                a = np.round(rng.random(size=shape), 6)
            cases.append({"shape": list(shape), "values": a.ravel().tolist(),
                          "diagrams": all_cubical(a)})
    os.makedirs(PERS, exist_ok=True)
    with open(os.path.join(PERS, "random.json"), "w") as f:
        json.dump(cases, f)


def facets_of(path):
    out = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line:
                out.append(sorted(int(x) for x in line.replace(",", " ").split()))
    return out


def simplex_tree_diagram(st, field):
    out = []
    for dim, (b, d) in st.persistence(homology_coeff_field=field, min_persistence=0, persistence_dim_max=True):
        if b == d:
            continue
        out.append([int(dim), num(b), num(d)])
    return sorted(out, key=lambda p: (p[0], str(p[1]), str(p[2])))


def lutz():
    rng = np.random.default_rng(7)
    files = ["scTest", "dunce_hat", "B_3_9_18", "Barnette_sphere", "CP2", "trefoil", "d2n12g6",
             "poincare", "RP4", "SU2_SO3", "rudin", "non_PL"]
    cases = []
    for name in files:
        facets = facets_of(os.path.join(ROOT, "tests", "data", "lutz", name + ".facets"))
        fvals = rng.integers(0, 20, size=len(facets)).astype(float).tolist()
        verts = sorted({v for f in facets for v in f})
        vvals = {v: float(rng.integers(0, 10)) for v in verts}
        per_facet, lower_star = {}, {}
        for field in (2, 3):
            st = gudhi.SimplexTree()
            for f, x in zip(facets, fvals):
                st.insert(f, filtration=x)
            per_facet[str(field)] = simplex_tree_diagram(st, field)
            st = gudhi.SimplexTree()
            for f in facets:
                st.insert(f)
            for s, _ in st.get_simplices():
                st.assign_filtration(s, max(vvals[v] for v in s))
            st.make_filtration_non_decreasing()
            lower_star[str(field)] = simplex_tree_diagram(st, field)
        cases.append({"file": name + ".facets", "facet_values": fvals,
                      "vertex_values": [[v, vvals[v]] for v in verts],
                      "per_facet": per_facet, "lower_star": lower_star})
        print(name, len(facets), file=sys.stderr)
    with open(os.path.join(PERS, "lutz.json"), "w") as f:
        json.dump(cases, f)


if __name__ == "__main__":
    images()
    randoms()
    lutz()
