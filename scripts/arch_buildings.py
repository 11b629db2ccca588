# The six small buildings of issue 45, compared with TopologicPy's room graphs: a 2x2 grid
# of rooms, two storeys with a stair cell, a shaft through two storeys, a room with a door
# and a window, an L-shaped flat, a courtyard. Each room is a vertical prism (a rectilinear
# polygon between two heights); apertures are rectangles on a wall or a slab.
#
#   python3 scripts/arch_buildings.py tests/data/arch/buildings
#
# writes one architectural complex (.json: string ids, points, no weights) per building: the
# faces are where two rooms, or a room and the outside, meet, split where an aperture or
# another room begins, so the complex conforms. The same definitions (BUILDINGS) make the
# TopologicPy cells in scripts/topologicpy_room_graphs.py and python/tests/test_room_graph.py.
import json
import os
import sys

# name -> (rooms: [(id, labels, polygon [(x, y)] counter-clockwise, z0, z1)],
#          apertures: [(id, kind, axis, coordinate, (u0, u1), (v0, v1))]) where an aperture
# lies on the plane axis = coordinate, (u, v) its other two coordinates in x, y, z order
BUILDINGS = {
    "grid_2x2": (
        [
            ("sw", {"name": "south-west room"}, [(0, 0), (4, 0), (4, 4), (0, 4)], 0, 3),
            ("se", {"name": "south-east room"}, [(4, 0), (8, 0), (8, 4), (4, 4)], 0, 3),
            ("nw", {"name": "north-west room"}, [(0, 4), (4, 4), (4, 8), (0, 8)], 0, 3),
            ("ne", {"name": "north-east room"}, [(4, 4), (8, 4), (8, 8), (4, 8)], 0, 3),
        ],
        [],
    ),
    "stair_two_storeys": (
        [
            ("hall", {"name": "hall", "storey": "ground"}, [(0, 0), (4, 0), (4, 4), (0, 4)], 0, 3),
            ("stair 0", {"name": "stair, ground", "storey": "ground"}, [(4, 0), (6, 0), (6, 4), (4, 4)], 0, 3),
            ("office", {"name": "office", "storey": "first"}, [(0, 0), (4, 0), (4, 4), (0, 4)], 3, 6),
            ("stair 1", {"name": "stair, first", "storey": "first"}, [(4, 0), (6, 0), (6, 4), (4, 4)], 3, 6),
        ],
        [
            ("door 0", "door", "x", 4, (1, 2), (0, 2)),
            ("door 1", "door", "x", 4, (1, 2), (3, 5)),
            ("stair opening", "opening", "z", 3, (4, 6), (1, 3)),
        ],
    ),
    "shaft": (
        [
            ("ground", {"name": "ground floor"}, [(0, 0), (4, 0), (4, 4), (0, 4)], 0, 3),
            ("upper", {"name": "upper floor"}, [(0, 0), (4, 0), (4, 4), (0, 4)], 3, 6),
            ("shaft", {"name": "service shaft"}, [(4, 0), (6, 0), (6, 2), (4, 2)], 0, 6),
        ],
        [],
    ),
    "door_window": (
        [
            ("kitchen", {"name": "kitchen"}, [(0, 0), (4, 0), (4, 6), (0, 6)], 0, 3),
            ("living", {"name": "living room"}, [(4, 0), (8, 0), (8, 6), (4, 6)], 0, 3),
        ],
        [
            ("door", "door", "x", 4, (1, 2), (0, 2)),
            ("window", "window", "x", 4, (3, 5), (1, 2)),
            ("front door", "door", "y", 0, (1, 2), (0, 2)),
        ],
    ),
    "l_flat": (
        [
            ("living", {"name": "living room"}, [(0, 0), (6, 0), (6, 3), (3, 3), (3, 6), (0, 6)], 0, 3),
            ("bedroom", {"name": "bedroom"}, [(3, 3), (6, 3), (6, 6), (3, 6)], 0, 3),
            ("bath", {"name": "bathroom"}, [(6, 0), (8, 0), (8, 6), (6, 6)], 0, 3),
        ],
        [
            ("bedroom door", "door", "y", 3, (4, 5), (0, 2)),
            ("bath door", "door", "x", 6, (1, 2), (0, 2)),
        ],
    ),
    "courtyard": (
        [
            ("south", {"name": "south wing"}, [(0, 0), (9, 0), (9, 3), (0, 3)], 0, 3),
            ("north", {"name": "north wing"}, [(0, 6), (9, 6), (9, 9), (0, 9)], 0, 3),
            ("west", {"name": "west wing"}, [(0, 3), (3, 3), (3, 6), (0, 6)], 0, 3),
            ("east", {"name": "east wing"}, [(6, 3), (9, 3), (9, 6), (6, 6)], 0, 3),
        ],
        [
            ("court door", "door", "y", 3, (4, 5), (0, 2)),
            ("west door", "door", "y", 3, (1, 2), (0, 2)),
        ],
    ),
}


def inside(poly, x, y):
    """Whether (x, y) is inside the polygon (even-odd rule; never on an edge here)."""
    n, c = len(poly), False
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            c = not c
    return c


def faces_of(rooms, apertures):
    """The conforming faces: [(id, labels, [unit squares], (lo room, hi room))], the grid
    and the squares as (axis, i, j, k) on the grid."""
    xs = sorted({p[0] for r in rooms for p in r[2]} | {c for a in apertures for c in (a[3],) if a[2] == "x"}
                | {u for a in apertures if a[2] != "x" for u in a[4]})
    ys = sorted({p[1] for r in rooms for p in r[2]} | {a[3] for a in apertures if a[2] == "y"}
                | {u for a in apertures if a[2] == "x" for u in a[4]}
                | {v for a in apertures if a[2] == "z" for v in a[5]})
    zs = sorted({z for r in rooms for z in (r[3], r[4])} | {a[3] for a in apertures if a[2] == "z"}
                | {v for a in apertures if a[2] != "z" for v in a[5]})
    g = (xs, ys, zs)
    mid = [[(c[i] + c[i + 1]) / 2 for i in range(len(c) - 1)] for c in g]

    def owner(i, j, k):
        if not (0 <= i < len(mid[0]) and 0 <= j < len(mid[1]) and 0 <= k < len(mid[2])):
            return None
        x, y, z = mid[0][i], mid[1][j], mid[2][k]
        for r in rooms:
            if r[3] < z < r[4] and inside(r[2], x, y):
                return r[0]
        return None

    squares = {}  # (axis, plane index, a, b) -> key
    for axis in range(3):
        others = [a for a in range(3) if a != axis]
        for p in range(len(g[axis])):
            for a in range(len(mid[others[0]])):
                for b in range(len(mid[others[1]])):
                    lo, hi = [0, 0, 0], [0, 0, 0]
                    lo[axis], hi[axis] = p - 1, p
                    lo[others[0]] = hi[others[0]] = a
                    lo[others[1]] = hi[others[1]] = b
                    o1, o2 = owner(*lo), owner(*hi)
                    if o1 == o2:
                        continue
                    u, v = mid[others[0]][a], mid[others[1]][b]
                    ap = None
                    for (aid, kind, ax, c, (u0, u1), (v0, v1)) in apertures:
                        if "xyz".index(ax) == axis and c == g[axis][p] and u0 < u < u1 and v0 < v < v1:
                            ap = (aid, kind)
                    squares[(axis, p, a, b)] = (o1, o2, ap)
    # connected components of squares with the same key, in a fixed order
    seen, comps = set(), []
    for sq in sorted(squares):
        if sq in seen:
            continue
        key, comp, todo = squares[sq], [], [sq]
        seen.add(sq)
        while todo:
            s = todo.pop()
            comp.append(s)
            axis, p, a, b = s
            for n in ((axis, p, a + 1, b), (axis, p, a - 1, b), (axis, p, a, b + 1), (axis, p, a, b - 1)):
                if n not in seen and squares.get(n) == key:
                    seen.add(n)
                    todo.append(n)
        comps.append((key, sorted(comp)))
    faces, used = [], {}
    for (o1, o2, ap), comp in comps:
        axis = comp[0][0]
        if ap is not None:
            name, labels = ap[0], {"kind": ap[1]}
        elif o1 is not None and o2 is not None:
            name = ("slab %s/%s" if axis == 2 else "wall %s/%s") % (o1, o2)
            labels = {"kind": "slab" if axis == 2 else "wall"}
        else:
            room = o1 if o1 is not None else o2
            if axis == 2:
                side = "roof" if o1 is not None else "floor"
                labels = {"kind": side}
            else:
                side = [["west", "east"], ["south", "north"]][axis][o1 is not None] + " wall"
                labels = {"kind": "wall"}
            name = "%s %s" % (side, room)
        used[name] = used.get(name, 0) + 1
        if used[name] > 1:
            name = "%s %d" % (name, used[name])
        faces.append((name, labels, comp, (o1, o2)))
    return faces, g


def model(rooms, apertures):
    """The architectural complex of a building, as a dict written to .json."""
    faces, g = faces_of(rooms, apertures)

    def corners(sq):
        axis, p, a, b = sq
        others = [x for x in range(3) if x != axis]
        pts = []
        for da, db in ((0, 0), (1, 0), (1, 1), (0, 1)):
            q = [0, 0, 0]
            q[axis], q[others[0]], q[others[1]] = p, a + da, b + db
            pts.append(tuple(q))
        return pts

    # each face's boundary: the unit segments on one of its squares only
    seg_faces = []
    count = {}
    for name, labels, comp, _ in faces:
        c = {}
        for sq in comp:
            q = corners(sq)
            for i in range(4):
                s = tuple(sorted((q[i], q[(i + 1) % 4])))
                c[s] = c.get(s, 0) + 1
        segs = sorted(s for s, n in c.items() if n == 1)
        seg_faces.append(segs)
        for s in segs:
            count[s] = 1
    # vertices: grid points where segments meet other than straight through two
    at = {}
    for s in count:
        for p in s:
            at.setdefault(p, []).append(s)

    def straight(p):
        ss = at[p]
        if len(ss) != 2:
            return False
        d = [tuple(b[i] - a[i] for i in range(3)) for a, b in ss]
        return d[0] == d[1]

    verts = sorted(p for p in at if not straight(p))
    vid = {p: "v%d" % i for i, p in enumerate(verts)}
    # edges: chains of segments through straight points
    chain_of, edges = {}, []
    for s in sorted(count):
        if s in chain_of:
            continue
        chain, ends = [s], []
        for start in s:
            p, prev = start, s
            while p not in vid:
                nxt = [t for t in at[p] if t != prev][0]
                chain.append(nxt)
                prev = nxt
                p = nxt[0] if nxt[1] == p else nxt[1]
            ends.append(p)
        eid = "e%d" % len(edges)
        for t in chain:
            chain_of[t] = eid
        edges.append((eid, ends))
    regions, inc = [], []
    for p in verts:
        regions.append({"id": vid[p], "dim": 0, "point": [g[i][p[i]] for i in range(3)]})
    for eid, (a, b) in edges:
        regions.append({"id": eid, "dim": 1})
        inc.append({"from": eid, "to": vid[a]})
        inc.append({"from": eid, "to": vid[b]})
    for (name, labels, _, _), segs in zip(faces, seg_faces):
        regions.append({"id": name, "dim": 2, "labels": labels})
        for eid in sorted({chain_of[s] for s in segs}, key=lambda e: int(e[1:])):
            inc.append({"from": name, "to": eid})
    for rid, labels, _, _, _ in rooms:
        regions.append({"id": rid, "dim": 3, "labels": labels})
        for name, _, _, owners in faces:
            if rid in owners:
                inc.append({"from": rid, "to": name})
    return {"dimension": 3, "regions": regions, "incidence": inc}


def dump(m, path):
    lines = ['{"dimension": %d,' % m["dimension"], ' "regions": [']
    lines.append("  " + ",\n  ".join(json.dumps(r) for r in m["regions"]) + "],")
    lines.append(' "incidence": [')
    lines.append("  " + ",\n  ".join(json.dumps(r) for r in m["incidence"]) + "]}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, (rooms, apertures) in BUILDINGS.items():
        dump(model(rooms, apertures), os.path.join(out, name + ".json"))
