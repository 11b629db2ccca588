"""Maps to and from the Python mesh world: meshio meshes and pyvista grids.

``GMap.to_meshio()`` (or ``gmap.mesh.to_meshio(g)``) gives a ``meshio.Mesh`` of a map of
dimension at most 3 with points: the points of the 0-cells, the top cells with VTK's corner
orders (positive volumes), the labelled lower cells after them, each label as cell data
(texts as arrays of ``str``), ``dim`` the dimension of each cell, and the names of the
physical groups in ``field_data`` as meshio's Gmsh reader gives them (``name: [tag, dim]``).
``GMap.from_meshio(mesh)`` makes the map of a meshio mesh (cells sewn along their shared
facets, cell data as labels, texts included, and Gmsh's ``field_data`` names as
``gmsh:physical_name``). ``GMap.to_pyvista()`` gives a ``pyvista.UnstructuredGrid`` (pyvista
installed). Both directions go through the ``.vtu`` writer and reader of the command, so
they keep, refuse and say what ``gmap convert`` does: a map no mesh can hold as it is (a
slit, a digon) is refused with the reason.
"""

from __future__ import annotations

import os
import tempfile
from typing import Any

import numpy as np

TABLE = "gmap:texts:"


def _texts(table: Any) -> list:
    return [t.decode("utf-8") for t in bytes(np.asarray(table, dtype=np.uint8).ravel()).split(b"\0")[:-1]]


def _table(texts: list) -> np.ndarray:
    return np.frombuffer(b"".join(t.encode("utf-8") + b"\0" for t in texts), dtype=np.uint8)


def to_meshio(g: Any) -> Any:
    """The ``meshio.Mesh`` of a map (see the module documentation)."""
    import meshio

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "map.vtu")
        g.save(path)
        m = meshio.read(path)
    tables = {k[len(TABLE):]: _texts(v) for k, v in m.field_data.items() if k.startswith(TABLE)}
    for name, texts in tables.items():
        if name in m.cell_data:
            m.cell_data[name] = [
                np.array([texts[r] if r >= 0 else "" for r in block], dtype=object) for block in m.cell_data[name]
            ]
    m.field_data = {k: v for k, v in m.field_data.items() if not k.startswith(TABLE)}
    names, tags = m.cell_data.get("gmsh:physical_name"), m.cell_data.get("gmsh:physical")
    dims = m.cell_data.get("dim")
    if names is not None and tags is not None and dims is not None:
        for nb, tb, db in zip(names, tags, dims):
            for n, t, dd in zip(nb, tb, db):
                if n and t != np.iinfo(np.int32).min:
                    m.field_data[str(n)] = np.array([int(t), int(dd)])
    return m


def from_meshio(mesh: Any) -> Any:
    """The map of a ``meshio.Mesh`` (see the module documentation)."""
    import meshio

    from . import open as gmap_open

    cell_data = {}
    field_data = {}
    for name, blocks in mesh.cell_data.items():
        arrays = [np.asarray(b) for b in blocks]
        if any(a.dtype.kind in "OUS" for a in arrays):
            texts = sorted({str(x) for a in arrays for x in a.ravel() if str(x) != ""})
            rank = {t: k for k, t in enumerate(texts)}
            cell_data[name] = [np.array([rank.get(str(x), -1) for x in a.ravel()], dtype=np.int32) for a in arrays]
            field_data[TABLE + name] = _table(texts)
        else:
            cell_data[name] = arrays
    phys = cell_data.get("gmsh:physical")
    named = {(int(v[1]), int(v[0])): k for k, v in mesh.field_data.items() if np.size(v) == 2}
    if phys is not None and named and "gmsh:physical_name" not in cell_data:
        texts = sorted(set(named.values()))
        rank = {t: k for k, t in enumerate(texts)}
        blocks = []
        for block, a in zip(mesh.cells, phys):
            dim = meshio._mesh.topological_dimension.get(block.type, -1)
            blocks.append(np.array([rank.get(named.get((dim, int(t))), -1) for t in a], dtype=np.int32))
        cell_data["gmsh:physical_name"] = blocks
        field_data[TABLE + "gmsh:physical_name"] = _table(texts)
    out = meshio.Mesh(mesh.points, mesh.cells, point_data=mesh.point_data, cell_data=cell_data)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "mesh.vtu")
        meshio.write(path, out, binary=False)
        if field_data:
            # meshio's writer writes no field data: the tables of texts go in by hand
            arrays = "".join(
                f'<DataArray type="UInt8" Name="{k}" NumberOfTuples="{len(v)}" format="ascii">'
                f'{" ".join(map(str, v.tolist()))}</DataArray>'
                for k, v in field_data.items()
            )
            with open_text(path) as f:
                text = f.read()
            text = text.replace("<UnstructuredGrid>", f"<UnstructuredGrid><FieldData>{arrays}</FieldData>", 1)
            with open_text(path, "w") as f:
                f.write(text)
        return gmap_open(path)


def open_text(path: str, mode: str = "r") -> Any:
    """A text file in UTF-8."""
    import builtins

    return builtins.open(path, mode, encoding="utf-8")


def to_pyvista(g: Any) -> Any:
    """The ``pyvista.UnstructuredGrid`` of a map (pyvista installed): the grid of the
    ``.vtu`` the map is written as, its text labels as arrays of ``str``."""
    import pyvista

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "map.vtu")
        g.save(path)
        grid = pyvista.read(path)
    for key in list(grid.field_data.keys()):
        if key.startswith(TABLE):
            name, texts = key[len(TABLE):], _texts(grid.field_data[key])
            if name in grid.cell_data:
                grid.cell_data[name] = np.array([texts[r] if r >= 0 else "" for r in grid.cell_data[name]])
    return grid
