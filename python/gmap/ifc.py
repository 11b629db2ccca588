"""IFC in, through IfcOpenShell (``pip install ./python[ifc]``).

``gmap.ifc.open(path)`` makes the architectural complex of a building:

* each ``IfcSpace`` is a 3-region (a room) named by its ``Name``, with its ``LongName``
  as its ``name`` label, its storey and its ``GlobalId`` as labels; its shape is whatever
  ``ifcopenshell.geom`` tessellates (extrusions of any profile, B-reps, booleans);
* the boundary of the spaces is cut into planar faces where the spaces meet: a face lies on
  one space (the outside beyond it) or on two (a wall, a slab between them); each face is
  labelled by the ``IfcWall``/``IfcSlab``/``IfcRoof`` (or other building element) whose
  body holds it or lies just beyond it (``kind`` wall, slab, roof; ``element``, its
  ``GlobalId``), so each element is split into the 2-regions where spaces meet it;
* each ``IfcDoor``/``IfcWindow`` is an aperture (``kind`` door or window, its name and
  ``GlobalId``): the part of the faces of its host wall (through ``IfcRelFillsElement`` and
  ``IfcRelVoidsElement``) that the opening covers, cut out of the wall's face as a hole;
* the edges and vertices are the faces' sides and corners, welded and split where they
  meet (``snap=``), so the complex conforms.

What could not be placed (a space or element IfcOpenShell cannot tessellate, an element
that bounds no space, an opening in no face, spaces that overlap) is listed in the
returned model's ``report`` instead of being dropped silently.

Spaces must meet to be adjacent: modelled to the walls' centre lines they share the faces
inside the walls. Modelled to the walls' inner faces they are apart by the walls'
thickness, and are not made adjacent (that would move their faces and change the
building): each such pair, facing each other across one element, is in the ``report``.
"""

from __future__ import annotations

import builtins
import json
import os
import tempfile
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple

from . import _gmap
from ._gmap import ArchComplex

ELEMENT_KINDS = {
    "IfcWall": "wall",
    "IfcWallStandardCase": "wall",
    "IfcCurtainWall": "wall",
    "IfcSlab": "slab",
    "IfcRoof": "roof",
    "IfcCovering": "covering",
    "IfcPlate": "wall",
    "IfcColumn": "column",
    "IfcBeam": "beam",
}
APERTURE_KINDS = {"IfcDoor": "door", "IfcWindow": "window"}


@dataclass
class IfcModel:
    """The architectural complex of an IFC file and what could not be placed in it."""

    complex: ArchComplex
    report: List[str] = field(default_factory=list)
    spaces: List[str] = field(default_factory=list)
    snapped: List[str] = field(default_factory=list)


def _need():
    try:
        import ifcopenshell  # noqa: F401
        import ifcopenshell.geom  # noqa: F401
        import numpy  # noqa: F401
        import shapely  # noqa: F401
    except ImportError as e:
        raise ImportError("gmap.ifc needs IfcOpenShell: pip install ifcopenshell (or pip install ./python[ifc])") from e


def _mesh(settings: Any, product: Any) -> Tuple[Any, Any]:
    """The world-coordinate vertices and triangles of a product's body."""
    import ifcopenshell.geom
    import numpy as np

    shape = ifcopenshell.geom.create_shape(settings, product)
    v = np.asarray(shape.geometry.verts, dtype=float).reshape(-1, 3)
    t = np.asarray(shape.geometry.faces, dtype=int).reshape(-1, 3)
    return v, t


def _label(p: Any) -> str:
    return (getattr(p, "Name", None) or p.is_a()) + ""


def _storey(p: Any) -> Optional[str]:
    """The name of the storey a product belongs to (aggregated or contained)."""
    for rel in list(getattr(p, "Decomposes", None) or []) + list(getattr(p, "ContainedInStructure", None) or []):
        s = getattr(rel, "RelatingObject", None) or getattr(rel, "RelatingStructure", None)
        while s is not None and not s.is_a("IfcBuildingStorey"):
            up = list(getattr(s, "Decomposes", None) or [])
            s = up[0].RelatingObject if up else None
        if s is not None:
            return s.Name or s.GlobalId
    return None


def _inside(point: Any, v: Any, t: Any) -> bool:
    """Whether a point is inside a closed triangle mesh (ray parity along a skewed ray)."""
    import numpy as np

    if np.any(point < v.min(0) - 1e-9) or np.any(point > v.max(0) + 1e-9):
        return False
    d = np.array([0.5773, 0.5779, 0.5768])
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    e1, e2 = b - a, c - a
    h = np.cross(d, e2)
    det = np.einsum("ij,ij->i", e1, h)
    ok = np.abs(det) > 1e-12
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = point - a
    u = inv * np.einsum("ij,ij->i", s, h)
    q = np.cross(s, e1)
    w = inv * (q @ d)
    dist = inv * np.einsum("ij,ij->i", e2, q)
    hit = ok & (u >= 0) & (w >= 0) & (u + w <= 1) & (dist > 0)
    return bool(np.count_nonzero(hit) % 2)


def _basis(n: Any) -> Tuple[Any, Any]:
    import numpy as np

    a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(n, a)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def _planes(v: Any, t: Any, digits: int) -> Dict[Tuple, Tuple[int, List[Any]]]:
    """The triangles of a closed mesh grouped by plane: canonical (normal, offset) key ->
    (side, [triangles as 3x3 arrays]); side +1 when the outward normal is the canonical one."""
    import numpy as np

    out: Dict[Tuple, Tuple[int, List[Any]]] = {}
    for tri in t:
        p = v[tri]
        n = np.cross(p[1] - p[0], p[2] - p[0])
        norm = np.linalg.norm(n)
        if norm < 1e-12:
            continue
        n = n / norm
        k = int(np.argmax(np.abs(n)))
        side = 1 if n[k] > 0 else -1
        n = n * side
        key = (tuple(np.round(n, 6) + 0.0), round(float(n @ p[0]), digits) + 0.0)
        out.setdefault(key, (side, []))[1].append(p)
    return out


def open(path: Any, tolerance: float = 1e-6) -> IfcModel:
    """The architectural complex of the IFC file at ``path`` (module docs); ``tolerance``
    (metres) welds points and splits sides within it."""
    _need()
    import ifcopenshell
    import ifcopenshell.geom
    import numpy as np
    from shapely.geometry import MultiPolygon, Polygon
    from shapely.ops import polygonize, triangulate, unary_union

    path = os.fspath(path)
    try:
        f = ifcopenshell.open(path)
    except Exception as e:
        raise _gmap.ParseError(f"{path}: IfcOpenShell cannot read it: {e}") from None
    settings = ifcopenshell.geom.settings()
    settings.set(settings.USE_WORLD_COORDS, True)
    report: List[str] = []
    digits = max(0, int(-np.log10(tolerance)) - 1)

    def who(p: Any) -> str:
        return f"{p.is_a()} {_label(p)!r} ({p.GlobalId})"

    spaces = []  # (id, product, vertices, triangles)
    used: Dict[str, int] = {}
    for sp in f.by_type("IfcSpace"):
        try:
            v, t = _mesh(settings, sp)
        except Exception as e:
            report.append(f"{who(sp)}: IfcOpenShell cannot tessellate it ({e}); left out")
            continue
        if len(t) == 0:
            report.append(f"{who(sp)}: no body geometry; left out")
            continue
        sid = sp.Name or sp.GlobalId
        used[sid] = used.get(sid, 0) + 1
        if used[sid] > 1:
            sid = f"{sid} {used[sid]}"
        spaces.append((sid, sp, v, t))
    elements = []
    for cls in ELEMENT_KINDS:
        for el in f.by_type(cls, include_subtypes=False):
            try:
                v, t = _mesh(settings, el)
            except Exception as e:
                report.append(f"{who(el)}: IfcOpenShell cannot tessellate it ({e}); its faces are unlabelled")
                continue
            elements.append((el, v, t))

    # the faces of every space, by plane
    planes: Dict[Tuple, List[Tuple[int, int, Any]]] = {}
    for k, (_, _, v, t) in enumerate(spaces):
        for key, (side, tris) in _planes(v, t, digits).items():
            planes.setdefault(key, []).append((k, side, tris))

    # the overlay of each plane: pieces owned by one space (outside beyond) or two
    faces = []  # (plane key, u, v, polygon in 2-D, owners [(space, side)])
    for key, items in planes.items():
        n = np.array(key[0])
        d = key[1]
        u, w = _basis(n)
        polys = []
        for k, side, tris in items:
            poly = unary_union([Polygon([(p @ u, p @ w) for p in tri]) for tri in tris]).buffer(0)
            polys.append((k, side, poly))
        pieces = list(polygonize(unary_union([p.boundary for _, _, p in polys])))
        groups: Dict[Tuple, List[Any]] = {}
        for piece in pieces:
            if piece.area <= tolerance * tolerance:
                continue
            rp = piece.representative_point()
            owners = tuple(sorted((k, side) for k, side, p in polys if p.contains(rp)))
            if not owners:
                continue
            sides = [s for _, s in owners]
            if len(owners) > 2 or len(set(sides)) != len(sides):
                names = ", ".join(spaces[k][0] for k, _ in owners)
                report.append(f"spaces {names} overlap on the plane n={key[0]} d={d}; that part is left out")
                continue
            groups.setdefault(owners, []).append(piece)
        for owners, ps in groups.items():
            merged = unary_union(ps)
            for g in merged.geoms if isinstance(merged, MultiPolygon) else [merged]:
                faces.append([n, d, u, w, g, owners])

    def to3(n: Any, d: float, u: Any, w: Any, xy: Tuple[float, float]) -> Any:
        return n * d + u * xy[0] + w * xy[1]

    # the element holding each face (or just beyond it, on the outside)
    bound = set()
    face_elem: List[Optional[int]] = []
    for n, d, u, w, g, owners in faces:
        # probe points spread over the face (the centres of its triangles), each voting for
        # the element holding it, or just beyond it on the outside
        pts = [t.centroid for t in triangulate(g) if g.contains(t.centroid)][:24] or [g.representative_point()]
        outward = n * owners[0][1] if len(owners) == 1 else None
        votes: Dict[int, int] = {}
        for c in pts:
            p = to3(n, d, u, w, (c.x, c.y))
            probes = [p] + ([p + outward * 1e-3, p + outward * 0.05] if outward is not None else [])
            for probe in probes:
                hit = next((j for j, (_, ev, et) in enumerate(elements) if _inside(probe, ev, et)), None)
                if hit is not None:
                    votes[hit] = votes.get(hit, 0) + 1
                    break
        found = max(votes, key=lambda j: (votes[j], -j)) if votes else None
        face_elem.append(found)
        if found is not None:
            bound.add(found)
    # spaces facing each other across one element, apart: not adjacent, said so
    facing = set()
    for a, (na, da, ua, wa, ga, oa) in enumerate(faces):
        for b, (nb, db, ub, wb, gb, ob) in enumerate(faces):
            if b <= a or len(oa) != 1 or len(ob) != 1 or face_elem[a] is None or face_elem[a] != face_elem[b]:
                continue
            if tuple(na) != tuple(nb) or oa[0][0] == ob[0][0] or oa[0][1] == ob[0][1]:
                continue
            # a's outside towards b's plane
            if (db - da) * oa[0][1] <= 0:
                continue
            if ga.intersection(gb).area <= tolerance:
                continue
            key = (min(oa[0][0], ob[0][0]), max(oa[0][0], ob[0][0]), face_elem[a])
            if key not in facing:
                facing.add(key)
                report.append(
                    f"spaces {spaces[key[0]][0]} and {spaces[key[1]][0]} face each other across "
                    f"{who(elements[key[2]][0])}, {abs(db - da):g} apart: not adjacent (model the spaces "
                    "to the walls' centre lines to make them meet)"
                )
    for j, (el, _, _) in enumerate(elements):
        if j not in bound:
            report.append(f"{who(el)}: bounds no space; not placed")

    # openings: the part of their host's faces they cover
    host_of: Dict[int, Any] = {}
    for el in list(f.by_type("IfcDoor")) + list(f.by_type("IfcWindow")):
        host = None
        for rel in getattr(el, "FillsVoids", None) or []:
            for v_ in getattr(rel.RelatingOpeningElement, "VoidsElements", None) or []:
                host = v_.RelatingBuildingElement
        host_of[el.id()] = host
    apertures = []  # (face index, polygon, product)
    for el in list(f.by_type("IfcDoor")) + list(f.by_type("IfcWindow")):
        try:
            v, t = _mesh(settings, el)
        except Exception as e:
            report.append(f"{who(el)}: IfcOpenShell cannot tessellate it ({e}); not placed")
            continue
        host = host_of[el.id()]
        placed = False
        for i, (n, d, u, w, g, owners) in enumerate(faces):
            j = face_elem[i]
            if host is not None and (j is None or elements[j][0].id() != host.id()):
                continue
            if host is None and j is None:
                continue
            ev = elements[j][1] if j is not None else v
            lo, hi = min((ev @ n).min(), (v @ n).min()), max((ev @ n).max(), (v @ n).max())
            if not (lo - tolerance <= d <= hi + tolerance):
                continue
            hull = Polygon([(p @ u, p @ w) for p in v]).convex_hull if len(v) >= 3 else None
            if hull is None or hull.is_empty:
                continue
            cut = hull.intersection(g)
            if cut.area <= tolerance:
                continue
            apertures.append((i, cut, el))
            placed = True
        if not placed:
            where = f"in the faces of its host {who(host)}" if host is not None else "in any face of a space"
            report.append(f"{who(el)}: its opening lies {where} nowhere; not placed")
    for i, cut, el in apertures:
        faces[i][4] = faces[i][4].difference(cut)

    # the complex as a .json: vertices, edges, faces, rooms
    verts: Dict[Tuple, str] = {}
    regions: List[dict] = []
    inc: List[dict] = []
    edges: Dict[Tuple[str, str], str] = {}

    def vid(p: Any) -> str:
        key = tuple(round(float(c), digits) + 0.0 for c in p)
        if key not in verts:
            verts[key] = f"v{len(verts)}"
            regions.append({"id": verts[key], "dim": 0, "point": list(key)})
        return verts[key]

    def eid(a: str, b: str) -> str:
        k = (min(a, b), max(a, b))
        if k not in edges:
            edges[k] = f"e{len(edges)}"
            regions.append({"id": edges[k], "dim": 1})
            inc.append({"from": edges[k], "to": a})
            inc.append({"from": edges[k], "to": b})
        return edges[k]

    names: Dict[str, int] = {}
    room_faces: Dict[int, List[str]] = {k: [] for k in range(len(spaces))}

    def add_face(n, d, u, w, g, owners, labels, base):
        parts = g.geoms if isinstance(g, MultiPolygon) else [g]
        for part in parts:
            if part.is_empty or part.area <= tolerance:
                continue
            names[base] = names.get(base, 0) + 1
            fid = base if names[base] == 1 else f"{base} {names[base]}"
            es = []
            for ring in [part.exterior, *part.interiors]:
                pts = [vid(to3(n, d, u, w, c)) for c in list(ring.coords)[:-1]]
                for a, b in zip(pts, pts[1:] + pts[:1]):
                    if a != b:
                        es.append(eid(a, b))
            regions.append({"id": fid, "dim": 2, "labels": labels})
            for e in dict.fromkeys(es):
                inc.append({"from": fid, "to": e})
            for k, _ in owners:
                room_faces[k].append(fid)

    for i, (n, d, u, w, g, owners) in enumerate(faces):
        j = face_elem[i]
        between = " | ".join(spaces[k][0] for k, _ in owners)
        if j is not None:
            el = elements[j][0]
            labels = {"kind": ELEMENT_KINDS[el.is_a()], "element": el.GlobalId, "name": _label(el)}
            st = _storey(el)
            if st:
                labels["storey"] = st
            base = f"{_label(el)} {between}"
        else:
            labels = {"kind": "boundary"}
            base = f"boundary {between}"
        add_face(n, d, u, w, g, owners, labels, base)
    for i, cut, el in apertures:
        n, d, u, w, _, owners = faces[i]
        labels = {"kind": APERTURE_KINDS[el.is_a()], "element": el.GlobalId, "name": _label(el)}
        add_face(n, d, u, w, cut, owners, labels, _label(el))
    for k, (sid, sp, _, _) in enumerate(spaces):
        labels = {"globalid": sp.GlobalId}
        if getattr(sp, "LongName", None):
            labels["name"] = sp.LongName
        st = _storey(sp)
        if st:
            labels["storey"] = st
        regions.append({"id": sid, "dim": 3, "labels": labels})
        for fid in dict.fromkeys(room_faces[k]):
            inc.append({"from": sid, "to": fid})
    if not spaces:
        raise _gmap.ParseError(f"{path}: no IfcSpace could be placed: " + "; ".join(report or ["the file has none"]))
    with tempfile.TemporaryDirectory() as tmp:
        j = os.path.join(tmp, os.path.basename(path) + ".json")
        with builtins.open(j, "w") as out:
            json.dump({"dimension": 3, "regions": regions, "incidence": inc}, out)
        x, notes = _gmap._open_arch(j, float(tolerance))
    return IfcModel(complex=x, report=report, spaces=[s[0] for s in spaces], snapped=list(notes))
