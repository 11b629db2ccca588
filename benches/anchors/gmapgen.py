#!/usr/bin/env python3
"""Generators of G-maps for independent checks and benchmarks, written without the project's code.

Writes the native text format of docs/FORMATS.md:
    gmap <n> <darts>
    <a0> ... <an>        one line per dart, 0-based, a value equal to the line's own index is a fixed point

Usage:
    gmapgen.py cubegrid D K [--periodic] > out.gmap       # K^D grid of D-cubes (D-torus with --periodic)
    gmapgen.py simplicial FACETS_FILE > out.gmap          # pure simplicial complex, one facet per line
    gmapgen.py lutz FILE NAME > out.gmap                  # one complex of a Lutz 'name=[[...],...]' file
"""
import itertools
import sys


def write(n, alpha, out=sys.stdout):
    w = out.write
    w(f"gmap {n} {len(alpha)}\n")
    w("".join(" ".join(map(str, a)) + "\n" for a in alpha))


def cubegrid(d, k, periodic=False):
    """Darts of cube p are (p, eps, perm): vertex corner eps in {0,1}^d, perm orders the freed coordinates."""
    perms = list(itertools.permutations(range(d)))
    corners = list(itertools.product((0, 1), repeat=d))
    pidx = {p: i for i, p in enumerate(perms)}
    per_cube = len(perms) * len(corners)
    cubes = list(itertools.product(range(k), repeat=d))
    cidx = {c: i for i, c in enumerate(cubes)}

    def dart(ci, eps, pi):
        return ci * per_cube + pidx[pi] * len(corners) + int("".join(map(str, eps)), 2)

    alpha = [None] * (len(cubes) * per_cube)
    for c in cubes:
        ci = cidx[c]
        for pi in perms:
            for eps in corners:
                me = dart(ci, eps, pi)
                row = []
                e = list(eps)
                e[pi[0]] ^= 1
                row.append(dart(ci, tuple(e), pi))
                for i in range(1, d):
                    q = list(pi)
                    q[i - 1], q[i] = q[i], q[i - 1]
                    row.append(dart(ci, eps, tuple(q)))
                ax = pi[d - 1]
                step = 1 if eps[ax] == 1 else -1
                nb = list(c)
                nb[ax] += step
                if periodic:
                    nb[ax] %= k
                if 0 <= nb[ax] < k:
                    e = list(eps)
                    e[ax] ^= 1
                    row.append(dart(cidx[tuple(nb)], tuple(e), pi))
                else:
                    row.append(me)
                alpha[me] = row
    return d, alpha


def simplicial(facets):
    """Darts are (facet, ordering of its vertices); alpha_i swaps positions i, i+1; alpha_n crosses the ridge."""
    facets = [tuple(sorted(f)) for f in facets]
    n = len(facets[0]) - 1
    assert all(len(f) == n + 1 for f in facets), "pure complexes only"
    perms = list(itertools.permutations(range(n + 1)))
    index = {}
    darts = []
    for fi, f in enumerate(facets):
        for p in perms:
            seq = tuple(f[j] for j in p)
            index[(fi, seq)] = len(darts)
            darts.append((fi, seq))
    ridges = {}
    for fi, f in enumerate(facets):
        for j in range(n + 1):
            ridges.setdefault(f[:j] + f[j + 1:], []).append(fi)
    for r, fs in ridges.items():
        if len(fs) > 2:
            raise SystemExit(f"ridge {r} has {len(fs)} cofacets: not a pseudo-manifold")
    alpha = []
    for me, (fi, seq) in enumerate(darts):
        row = []
        for i in range(n):
            s = list(seq)
            s[i], s[i + 1] = s[i + 1], s[i]
            row.append(index[(fi, tuple(s))])
        ridge = tuple(sorted(seq[:n]))
        other = [g for g in ridges[ridge] if g != fi]
        if other:
            g = other[0]
            extra = [v for v in facets[g] if v not in ridge][0]
            row.append(index[(g, seq[:n] + (extra,))])
        else:
            row.append(me)
        alpha.append(row)
    return n, alpha


def read_facets(path):
    out = []
    for line in open(path):
        line = line.split("#")[0].strip()
        if line:
            out.append([int(x) for x in line.replace(",", " ").split()])
    return out


def read_lutz(path, name):
    import ast
    text = open(path).read().replace("\n", "")
    for chunk in text.split("manifold")[1:] if "manifold" in text else [text]:
        pass
    start = text.index(name + "=")
    body = text[start + len(name) + 1:]
    depth = 0
    for i, ch in enumerate(body):
        depth += ch == "["
        depth -= ch == "]"
        if depth == 0:
            return ast.literal_eval(body[: i + 1])
    raise SystemExit("unterminated list")


if __name__ == "__main__":
    a = sys.argv[1:]
    if a[0] == "cubegrid":
        write(*cubegrid(int(a[1]), int(a[2]), "--periodic" in a))
    elif a[0] == "simplicial":
        write(*simplicial(read_facets(a[1])))
    elif a[0] == "lutz":
        write(*simplicial(read_lutz(a[1], a[2])))
    else:
        raise SystemExit(__doc__)
