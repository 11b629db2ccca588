"""gmap: generalized maps and their integer homology, in process.

The library of the ``gmap`` command (a Rust workspace) for Python: read any file the
command reads, build and edit generalized maps, and compute homology over Z or Z/p of
G-maps, simplicial complexes, cubical sets (numpy arrays), grey images and architectural complexes,
with the command's routes, checks and messages.

>>> import gmap
>>> gmap.homology([[0, 1, 2], [0, 2, 3], [0, 1, 3], [1, 2, 3]]).betti
[1, 0, 1]

``gmap.persistence(x)`` gives the persistence diagram of a grey numpy array, an image file,
a ``.facets`` file with values or a map with a value per cell as a (k, 3) array of
(dimension, birth, death); ``obj.view(path)`` writes a self-contained HTML page of any
object (a notebook shows it inline through ``_repr_html_``).

Submodules: :mod:`gmap.build` (grids, simplices, cubes, lens spaces, maps from facets),
:mod:`gmap.mesh` (``GMap.from_meshio``, ``GMap.to_meshio``, ``GMap.to_pyvista``) and
:mod:`gmap.dask` (a corpus on a Dask cluster).
"""

from __future__ import annotations

import json
import os
import time
from typing import Any, Iterable, List, Sequence, Union

from ._gmap import (
    ArchComplex,
    ComputationError,
    CubicalSet,
    Generator,
    GMap,
    GmapError,
    Homology,
    Image,
    InputError,
    LimitError,
    ParseError,
    PreconditionError,
    SimplicialComplex,
    ValidityError,
    _bench_json,
    _page,
    _page_frame,
    are_freely_homotopic,
    are_homotopic_with_fixed_endpoints,
    edge_width,
    face_width,
    homology as _homology,
    is_contractible,
    is_homotopic_to_simple_cycle,
    max_memory,
    open as _open,
    persistence,
    set_max_memory,
    shortest_non_contractible_cycle,
)
from . import build, ifc, mesh
from .arch import (
    SnapWarning,
    arch_homology as _arch_homology,
    arch_incidence_graph as _arch_incidence_graph,
    open_snapped as _open_snapped,
    room_graph,
    rooms,
    tm_check,
    tm_views,
)

# the bridges to meshio and pyvista (gmap.mesh), as methods of GMap where the type takes them
try:
    GMap.from_meshio = staticmethod(mesh.from_meshio)
    GMap.to_meshio = mesh.to_meshio
    GMap.to_pyvista = mesh.to_pyvista
except TypeError:  # an immutable extension type: the functions of gmap.mesh only
    pass

__all__ = [
    "ArchComplex",
    "ComputationError",
    "CubicalSet",
    "Generator",
    "GMap",
    "GmapError",
    "Homology",
    "Image",
    "InputError",
    "LimitError",
    "ParseError",
    "PreconditionError",
    "SimplicialComplex",
    "SnapWarning",
    "ValidityError",
    "bench",
    "build",
    "edge_width",
    "are_freely_homotopic",
    "are_homotopic_with_fixed_endpoints",
    "face_width",
    "homology",
    "incidence_graph",
    "is_contractible",
    "is_homotopic_to_simple_cycle",
    "max_memory",
    "ifc",
    "mesh",
    "open",
    "persistence",
    "room_graph",
    "rooms",
    "set_max_memory",
    "shortest_non_contractible_cycle",
    "tm_check",
    "tm_views",
]

__version__ = "0.1.0"


def _view(
    self: Union[GMap, SimplicialComplex, CubicalSet, Image, ArchComplex],
    path: Union[None, str, "os.PathLike[str]"] = None,
    *,
    generators: bool = False,
    color_by: Union[None, str] = None,
) -> str:
    """The page of ``gmap view``: one self-contained HTML file (nothing fetched; opens from
    file:// in Chromium and Firefox) with the exploded darts and their alpha links (maps and
    simplicial complexes), the cubes (cubical sets; an image's at its default level) or the regions (architectural
    complexes), the cells coloured by the label ``color_by`` (default: the first text label
    of the highest dimension with labels; an InputError when no cell has it), and with
    ``generators=True`` each homology generator highlighted. Written to ``path`` (the path is
    returned as a str), or returned as text when ``path`` is None."""
    return _page(self, path, generators, color_by)


def _repr_html_(self: Union[GMap, SimplicialComplex, CubicalSet, Image, ArchComplex]) -> str:
    """The page of ``view()`` for Jupyter: an ``<iframe srcdoc>`` 600 px high holding the
    escaped page, or a short note when the page is over 8 MB (write it with ``view(path)``)."""
    return _page_frame(self)


for _cls in (GMap, SimplicialComplex, CubicalSet, Image, ArchComplex):
    _cls.view = _view
    _cls._repr_html_ = _repr_html_
del _cls


def open(path: Any, snap: "float | None" = None) -> Any:
    """open(path, snap=None): what the file holds, in the class its format's kind names (a
    GMap, SimplicialComplex, CubicalSet, Image or ArchComplex). ``snap=EPS`` (a ``.json``
    complex with points): weld the points closer than EPS and split the edges and faces at
    T-junctions, each weld and split issued as a ``SnapWarning``; without it such a complex
    is refused naming the place (``gmap --snap EPS``)."""
    if snap is None:
        return _open(path)
    return _open_snapped(path, snap)


def homology(x: Any, *, topological: bool = False, **options: Any) -> Homology:
    """homology(x, *, field=None, generators=False, method=None, periodic=False,
    level=None, topological=False): the homology groups of ``x`` (see the compiled
    ``homology``). ``topological=True`` (an ArchComplex or ``.json`` path): the groups of
    the space the regions make, as ``gmap homology --topological``."""
    if not topological:
        return _homology(x, **options)
    unknown = set(options) - {"generators", "field"}
    if unknown:
        raise TypeError(f"homology(topological=True) takes generators= and field= only, not {sorted(unknown)}")
    return _arch_homology(x, True, bool(options.get("generators", False)), options.get("field"))


homology.__doc__ = (homology.__doc__ or "") + "\n\n" + (_homology.__doc__ or "")


def incidence_graph(m: Any) -> Any:
    """The incidence graph of a map's cells as a ``networkx.Graph``, or of an ArchComplex's
    regions as a ``networkx.DiGraph``.

    For a map, nodes are ``(i, c)`` for the i-cell numbered ``c`` (the order of
    ``m.cells(i)``), with the attributes ``dim`` and ``dart`` (one of its darts); an edge
    joins an i-cell to each (i+1)-cell it bounds. For an ArchComplex, nodes are the file's
    region ids with ``dim``, ``name`` and the labels, edges the defined entries with their
    ``weight``. Needs networkx (``pip install networkx``).
    """
    try:
        import networkx as nx
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("gmap.incidence_graph needs networkx: pip install networkx") from e
    if isinstance(m, ArchComplex):
        return _arch_incidence_graph(m)
    g = nx.Graph()
    for i in range(m.dim + 1):
        for c, d in enumerate(m.cells(i).tolist()):
            g.add_node((i, c), dim=i, dart=d)
    g.add_edges_from(m.incidences())
    return g


GMap.incidence_graph = incidence_graph  # type: ignore[attr-defined]
ArchComplex.incidence_graph = incidence_graph  # type: ignore[attr-defined]


def _facets_of(path: str) -> "list[list[int]] | None":
    """The facets of a .facets/.lex input (for GUDHI's side of a benchmark), else None."""
    ext = os.path.splitext(str(path).split("#")[0])[1].lower()
    if ext not in (".facets", ".lex"):
        return None
    obj = open(path)
    return obj.facets if isinstance(obj, SimplicialComplex) else None


def _gudhi_time(facets: "list[list[int]]") -> "tuple[float, list[int]]":
    """GUDHI's time on the same cells: a SimplexTree of the facets and its persistence."""
    import gudhi

    t = time.perf_counter()
    st = gudhi.SimplexTree()
    for f in facets:
        st.insert(f)
    st.compute_persistence(persistence_dim_max=True)
    betti = st.betti_numbers()
    return time.perf_counter() - t, betti


def bench(paths: Union[str, os.PathLike, Iterable[Union[str, os.PathLike]]], gudhi: bool = True) -> List[dict]:
    """Times every route of each input in process, as ``gmap bench --json`` does: a list of
    dicts, one per input and route, with ``input``, ``route``, ``cells``, ``times_ms``
    (``read``, ``cells``, ``border``, ``reduction``, ``smith``, ``total``), ``groups``,
    ``betti``, ``torsion``, ``error``, ``agree`` and ``peak_rss_bytes`` (the process's peak
    resident memory while the row ran, ``None`` where the kernel's high-water mark cannot be
    reset). For a simplicial complex, when ``gudhi``
    is true and GUDHI is installed, ``gudhi_ms`` is GUDHI's time on the same facets (a
    SimplexTree and its persistence in all dimensions over Z/2) and ``gudhi_betti`` its Betti
    numbers.

    A folder stands for every file in it that gmap reads, sorted.
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    rows = json.loads(_bench_json([os.fspath(p) for p in paths]))["rows"]
    have_gudhi = False
    if gudhi:
        try:
            import gudhi as _  # noqa: F401

            have_gudhi = True
        except ImportError:
            pass
    if have_gudhi:
        done = {}
        for row in rows:
            f = row["input"]
            if f not in done:
                facets = _facets_of(f)
                done[f] = None if facets is None else _gudhi_time(facets)
            if done[f] is not None:
                seconds, betti = done[f]
                row["gudhi_ms"], row["gudhi_betti"] = seconds * 1e3, betti
    return rows
