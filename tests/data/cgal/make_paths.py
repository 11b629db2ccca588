"""Writes double-torus-paths.txt: deterministic paths (vertex indices of the .off) and the
homotopy questions asked about them, for homotopy.cpp (CGAL) and tests/curves_homotopy.rs
(gmap). Usage: python3 make_paths.py double-torus-example.off > double-torus-paths.txt"""
import random
import sys
from collections import deque

lines = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
nv, nf = int(lines[1][0]), int(lines[1][1])
faces = [[int(x) for x in l[1:1 + int(l[0])]] for l in lines[2 + nv:2 + nv + nf]]
adj = {v: set() for v in range(nv)}
third = {}  # (a, b) -> the vertices between a and b the other way round a face
for f in faces:
    for i in range(len(f)):
        a, b = f[i], f[(i + 1) % len(f)]
        adj[a].add(b)
        adj[b].add(a)
        # the face's other sides from a to b: a f[i-1] … f[i+2] b
        other = [f[(i - j) % len(f)] for j in range(1, len(f) - 1)]
        third[(a, b)] = other
        third[(b, a)] = other[::-1]


def bfs(s, t):
    prev = {s: None}
    q = deque([s])
    while q:
        x = q.popleft()
        for y in sorted(adj[x]):
            if y not in prev:
                prev[y] = x
                q.append(y)
    p = [t]
    while p[-1] != s:
        p.append(prev[p[-1]])
    return p[::-1]


rng = random.Random(48)


def walk(s, k):
    p = [s]
    for _ in range(k):
        p.append(rng.choice(sorted(adj[p[-1]])))
    return p


def closed(s, k):
    p = walk(s, k)
    return p + bfs(p[-1], s)[1:]


def push(p):
    """p with one step a b replaced by the other sides of a face a b … (pushed across it)"""
    i = rng.randrange(len(p) - 1)
    return p[:i + 1] + third[(p[i], p[i + 1])] + p[i + 1:]


def rotate(p):
    i = rng.randrange(1, len(p) - 1)
    return p[i:-1] + p[:i + 1]


paths = {}
qs = []
for k in range(8):
    s = rng.randrange(nv)
    p = closed(s, 10 + 10 * k)
    paths[f"c{k}"] = p
    q = p
    for _ in range(5):
        q = push(q)
    paths[f"c{k}push"] = q
    paths[f"c{k}rot"] = rotate(q)
    back = p + p[::-1][1:]
    paths[f"c{k}back"] = back
    qs += [f"contractible c{k}", f"contractible c{k}back", f"free c{k} c{k}push", f"free c{k} c{k}rot",
           f"fixed c{k} c{k}push"]
    if k > 0:
        qs.append(f"free c{k} c{k - 1}")
for k in range(4):
    # open paths with the same ends
    s, t = rng.randrange(nv), rng.randrange(nv)
    a = walk(s, 15 + 5 * k)
    p = a + bfs(a[-1], t)[1:]
    b = walk(s, 20)
    q = b + bfs(b[-1], t)[1:]
    paths[f"o{k}"] = p
    paths[f"o{k}b"] = q
    pp = p
    for _ in range(4):
        pp = push(pp)
    paths[f"o{k}push"] = pp
    qs += [f"fixed o{k} o{k}b", f"fixed o{k} o{k}push"]
for name, p in paths.items():
    print("path", name, *p)
for q in qs:
    print(q)
