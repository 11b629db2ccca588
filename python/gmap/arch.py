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


def room_graph(x: Union[ArchComplex, Path], via: str = "faces") -> Any:
    """The dual graph of the rooms (the top regions) as a ``networkx.Graph``, as
    TopologicPy's ``Graph.ByTopology`` and ``gmap graph FILE --dual VIA`` (one
    implementation, the facade's ``gmap::room_graph``): ``via="faces"`` (``direct``) joins
    two rooms with a face in common; ``via="apertures"`` (``viaSharedApertures``) two rooms
    with a common face whose ``kind`` label is a door, window, aperture or opening;
    ``via="exterior"`` (``toExteriorTopologies``) each room to the node ``exterior`` through
    its faces on no other room. ``x`` is an ArchComplex or a path to any input with an
    incidence graph. Nodes are the rooms' ids (the file's string ids, else their numbers)
    with ``name`` and their labels; edges carry ``faces`` (the faces' ids), ``face_names``,
    ``kinds`` (their ``kind`` labels) and ``area`` (their total area; None when a face has
    no points).
    """
    import networkx as nx

    if via not in ("faces", "apertures", "exterior"):
        raise ValueError(f"via={via!r}: one of 'faces', 'apertures', 'exterior'")
    d = json.loads(_gmap._room_graph(x if isinstance(x, ArchComplex) else os.fspath(x), via))
    g = nx.Graph(dual=d["dual"])
    for n in d["nodes"]:
        g.add_node(n["id"], **{**n["labels"], "name": n["name"]})
    for e in d["edges"]:
        g.add_edge(
            e["source"], e["target"], faces=e["faces"], face_names=e["face_names"], kinds=e["kinds"], area=e["area"]
        )
    return g
