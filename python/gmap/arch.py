"""Architectural complexes from Python as from the command line.

``open(path, snap=EPS)`` welds points and splits cells at T-junctions (what it did is
issued as ``SnapWarning``s), ``homology(x, topological=True)`` gives the groups of the space
the regions make, ``tm_check`` and ``tm_views`` the TM edit check (topological and
metrical) and views, ``rooms`` the rooms found in walls, ``incidence_graph`` the incidence
graph of an ``ArchComplex`` with the file's ids, and ``room_graph`` the dual graphs of
TopologicPy's ``Graph.ByTopology`` (rooms through shared faces, through apertures, to the
exterior) as networkx graphs with names and areas on the edges.
"""

from __future__ import annotations

import json
import math
import os
import warnings
from typing import Any, Dict, List, Optional, Tuple, Union

from . import _gmap
from ._gmap import ArchComplex

Path = Union[str, "os.PathLike[str]"]


class SnapWarning(UserWarning):
    """One point welded or one cell split by ``gmap.open(path, snap=EPS)``."""


def open_snapped(path: Path, snap: float) -> ArchComplex:
    """The architectural complex of a ``.json`` file with its points within ``snap`` welded
    and its edges and faces split where a point or an edge lies inside them; each weld and
    split is issued as a ``SnapWarning``."""
    x, notes = _gmap._open_arch(os.fspath(path), float(snap))
    for n in notes:
        warnings.warn("snap: " + n, SnapWarning, stacklevel=3)
    return x


def arch_homology(x: Any, topological: bool, generators: bool = False, field: Optional[int] = None) -> Any:
    """The homology of an ArchComplex or ``.json`` path, of the region complex or (with
    ``topological``) of the space the regions make (``gmap homology --topological``)."""
    if not isinstance(x, ArchComplex):
        x = os.fspath(x)
    return _gmap._arch_homology(x, topological, generators, field)


def tm_check(x: Union[ArchComplex, Path]) -> Dict[str, Any]:
    """The TM edit check of an ArchComplex or a file (``gmap tm check``): a dict with
    ``dim``, ``counts``, ``defects``, ``closed``, ``metric`` (``(tolerance, defects)`` or
    None), ``passes`` and ``text``."""
    return _gmap._tm_check(x if isinstance(x, ArchComplex) else os.fspath(x))


def tm_views(x: Union[ArchComplex, Path], cell: Optional[str] = None) -> str:
    """The views of the (n-1)-cells, or of one cell (``gmap tm views [--cell]``)."""
    return _gmap._tm_views(x if isinstance(x, ArchComplex) else os.fspath(x), cell)


def rooms(path: Path) -> Tuple[ArchComplex, List[Tuple[str, int, float, List[str]]]]:
    """The rooms of the faces of an ``.off`` or ``.json`` file (``gmap rooms``): the
    3-complex and, per room, its name, number of faces, volume and neighbours."""
    return _gmap._rooms(os.fspath(path))


def _parsed(x: ArchComplex) -> Tuple[Dict[str, dict], List[dict]]:
    d = json.loads(x.to_json())
    regions = {str(r["id"]): r for r in d["regions"]}
    return regions, d["incidence"]


def _name(r: dict) -> str:
    label = r.get("labels", {}).get("name")
    return str(r["id"]) if label is None or label == r["id"] else f"{r['id']} ({label})"


def arch_incidence_graph(x: ArchComplex) -> Any:
    """The incidence graph of an ArchComplex as a ``networkx.DiGraph``: a node per region,
    keyed by the file's id, with its labels, ``dim`` and ``name`` (the id and the ``name``
    label, as messages name it); an edge per defined
    entry from the higher region to the lower one, with its ``weight``."""
    import networkx as nx

    regions, incidence = _parsed(x)
    g = nx.DiGraph()
    for k, r in regions.items():
        g.add_node(k, **{**r.get("labels", {}), "dim": r["dim"], "name": _name(r)})
    for e in incidence:
        g.add_edge(str(e["from"]), str(e["to"]), weight=e.get("weight", 0))
    return g


def _areas(regions: Dict[str, dict], incidence: List[dict]) -> Dict[str, float]:
    """The area of each face with points: half the norm of its vector area."""
    down: Dict[str, List[Tuple[str, int]]] = {}
    for e in incidence:
        down.setdefault(str(e["from"]), []).append((str(e["to"]), e.get("weight", 0)))
    areas = {}
    for f, r in regions.items():
        if r["dim"] != 2:
            continue
        a = [0.0, 0.0, 0.0]
        ok = True
        for e, w in down.get(f, []):
            ends = down.get(e, [])
            frm = [v for v, s in ends if s < 0]
            to = [v for v, s in ends if s > 0]
            if not frm or not to or "point" not in regions[frm[0]] or "point" not in regions[to[0]]:
                ok = False
                break
            p, q = (list(regions[v]["point"]) + [0.0] * 3 for v in (frm[0], to[0]))
            c = (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])
            a = [a[i] + w * c[i] for i in range(3)]
        if ok and down.get(f):
            areas[f] = 0.5 * math.sqrt(sum(v * v for v in a))
    return areas


APERTURE_KINDS = ("door", "window", "aperture", "opening")


def room_graph(x: Union[ArchComplex, Path], via: str = "faces", exterior: str = "exterior") -> Any:
    """The dual graph of the rooms (the top regions) as a ``networkx.Graph``, as
    TopologicPy's ``Graph.ByTopology``: ``via="faces"`` (``direct``) joins two rooms with a
    face in common; ``via="apertures"`` (``viaSharedApertures``) two rooms with a common face
    whose ``kind`` label is a door, window or aperture; ``via="exterior"``
    (``toExteriorTopologies``) each room to the node ``exterior`` through its faces on no
    other room. Nodes are the rooms' ids with ``name`` and their labels; edges carry
    ``faces`` (the faces' ids) and ``area`` (their total area, when the faces have points).
    """
    import networkx as nx

    if via not in ("faces", "apertures", "exterior"):
        raise ValueError(f"via={via!r}: one of 'faces', 'apertures', 'exterior'")
    if not isinstance(x, ArchComplex):
        x = _gmap.open(os.fspath(x))
    regions, incidence = _parsed(x)
    top = max((r["dim"] for r in regions.values()), default=0)
    on: Dict[str, List[str]] = {}
    for e in incidence:
        f, t = str(e["from"]), str(e["to"])
        if regions[f]["dim"] == top and regions[t]["dim"] == top - 1:
            on.setdefault(t, []).append(f)
    areas = _areas(regions, incidence) if top == 3 else {}
    g = nx.Graph()
    for k, r in regions.items():
        if r["dim"] == top:
            g.add_node(k, **{**r.get("labels", {}), "name": _name(r)})
    if via == "exterior":
        g.add_node(exterior, name=exterior)

    def link(a: str, b: str, face: str) -> None:
        if not g.has_edge(a, b):
            g.add_edge(a, b, faces=[], area=0.0)
        g.edges[a, b]["faces"].append(face)
        g.edges[a, b]["area"] += areas.get(face, 0.0)

    for face in sorted(on, key=lambda f: list(regions).index(f)):
        rs = on[face]
        kind = str(regions[face].get("labels", {}).get("kind", "")).lower()
        if via == "exterior":
            if len(rs) == 1:
                link(rs[0], exterior, face)
        elif len(rs) == 2 and rs[0] != rs[1] and (via == "faces" or kind in APERTURE_KINDS):
            link(rs[0], rs[1], face)
    return g
