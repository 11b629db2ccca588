#!/usr/bin/env python3
"""Writes the K^3 cube grid cut into 6 K^3 tetrahedra (Kuhn's triangulation: each unit cube
split along its main diagonal, the same cut in every cube, so the faces match), without using
this project: a legacy VTK file (binary, big-endian, as the format says) for gmap, and a
plain text file for CGAL's harness (cgal_mesh_tets.cpp): the point count, one point a line,
the tetrahedron count, four point indices a line.

usage: tetgrid.py K [--vtk OUT.vtk] [--txt OUT.txt] [--label]

--label adds an integer cell-data array `region` (the cube's layer z) to the .vtk file.
Every tetrahedron is written with VTK's orientation (positive volume). Standard library only.
"""
import argparse
import itertools
import struct
import sys
from array import array


def grid(k):
    n = k + 1
    pts = array("d")
    for z in range(n):
        for y in range(n):
            for x in range(n):
                pts.extend((x, y, z))
    tets = array("i")
    layer = array("i")
    unit = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    perms = []
    for p in itertools.permutations(range(3)):
        inversions = sum(1 for a in range(3) for b in range(a + 1, 3) if p[a] > p[b])
        perms.append((p, inversions % 2))
    for z in range(k):
        for y in range(k):
            for x in range(k):
                for p, odd in perms:
                    c = [x, y, z]
                    ids = [(c[2] * n + c[1]) * n + c[0]]
                    for axis in p:
                        c[axis] += 1
                        ids.append((c[2] * n + c[1]) * n + c[0])
                    # corners 0, 1, 2, 3 along e_p0, e_p1, e_p2: the volume has the sign of
                    # det(e_p0, e_p1, e_p2), the permutation's; swap two corners of odd ones
                    if odd:
                        ids[2], ids[3] = ids[3], ids[2]
                    tets.extend(ids)
                    layer.append(z)
    return pts, tets, layer


def write_vtk(path, pts, tets, layer, label):
    n_pts, n_tets = len(pts) // 3, len(tets) // 4
    with open(path, "wb") as f:
        f.write(b"# vtk DataFile Version 4.2\ncube grid in tetrahedra\nBINARY\nDATASET UNSTRUCTURED_GRID\n")
        f.write(b"POINTS %d double\n" % n_pts)
        a = array("d", pts)
        if sys.byteorder == "little":
            a.byteswap()
        f.write(a.tobytes())
        f.write(b"\nCELLS %d %d\n" % (n_tets, 5 * n_tets))
        cells = array("i", [4]) * (5 * n_tets)
        for j in range(4):
            cells[1 + j :: 5] = tets[j::4]
        if sys.byteorder == "little":
            cells.byteswap()
        f.write(cells.tobytes())
        f.write(b"\nCELL_TYPES %d\n" % n_tets)
        types = array("i", [10]) * n_tets
        if sys.byteorder == "little":
            types.byteswap()
        f.write(types.tobytes())
        if label:
            f.write(b"\nCELL_DATA %d\nSCALARS region int 1\nLOOKUP_TABLE default\n" % n_tets)
            a = array("i", layer)
            if sys.byteorder == "little":
                a.byteswap()
            f.write(a.tobytes())
        f.write(b"\n")


def write_txt(path, pts, tets):
    with open(path, "w") as f:
        f.write("%d\n" % (len(pts) // 3))
        for i in range(0, len(pts), 3):
            f.write("%d %d %d\n" % (pts[i], pts[i + 1], pts[i + 2]))
        f.write("%d\n" % (len(tets) // 4))
        for i in range(0, len(tets), 4):
            f.write("%d %d %d %d\n" % (tets[i], tets[i + 1], tets[i + 2], tets[i + 3]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("k", type=int)
    ap.add_argument("--vtk")
    ap.add_argument("--txt")
    ap.add_argument("--label", action="store_true")
    a = ap.parse_args()
    pts, tets, layer = grid(a.k)
    if a.vtk:
        write_vtk(a.vtk, pts, tets, layer, a.label)
    if a.txt:
        write_txt(a.txt, pts, tets)
    print("%d points, %d tetrahedra, %d darts" % (len(pts) // 3, len(tets) // 4, 24 * (len(tets) // 4)))


if __name__ == "__main__":
    main()
