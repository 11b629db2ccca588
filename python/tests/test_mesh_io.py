"""Mesh files written by gmap as other tools read them: meshio reads every `.vtk`, `.vtu`
and `.msh` with its cells, points and labels (names from the table of texts), and VTK gives
every cell a positive volume and finds no invalid cell. Skipped, with the reason, where
meshio or vtk is not installed."""

import numpy as np
import pytest

import gmap
from conftest import DATA

MESH = DATA / "mesh"
FIXTURES = ["tet_cube.msh", "mixed.msh", "ring.msh", "hex_hollow.vtu", "mixed.vtu"]


def texts(table):
    """The texts of a table of gmap's mesh writers: NUL-ended UTF-8 bytes."""
    return bytes(np.asarray(table, dtype=np.uint8)).split(b"\0")[:-1]


@pytest.mark.parametrize("name", FIXTURES)
@pytest.mark.parametrize("ext", ["vtk", "vtu", "msh"])
def test_meshio_reads_what_gmap_writes(tmp_path, name, ext):
    meshio = pytest.importorskip("meshio", reason="meshio is not installed")
    g = gmap.open(MESH / name)
    out = tmp_path / f"out.{ext}"
    g.save(out)
    m = meshio.read(out)
    top = {"tet_cube.msh": ("tetra", 48), "mixed.msh": (None, 4), "ring.msh": ("hexahedron", 8),
           "hex_hollow.vtu": ("hexahedron", 26), "mixed.vtu": (None, 4)}[name]
    kinds = {"tetra", "hexahedron", "wedge", "pyramid"}
    volumes = [c for c in m.cells if c.type in kinds]
    assert sum(len(c.data) for c in volumes) == top[1]
    if top[0]:
        assert [c.type for c in volumes] == [top[0]]
    assert len(m.points) == g.cell_counts()[0]
    if name == "tet_cube.msh":
        if ext == "msh":
            assert m.field_data["solid"].tolist() == [1, 3] and m.field_data["boundary"].tolist() == [2, 2]
        else:
            if ext == "vtu":  # meshio's legacy reader keeps no dataset field data
                assert texts(m.field_data["gmap:texts:gmsh:physical_name"]) == [b"boundary", b"solid"]
            ranks = np.concatenate(m.cell_data["gmsh:physical_name"])
            assert sorted(np.unique(ranks).tolist()) == [0, 1]


@pytest.mark.parametrize("name", FIXTURES)
@pytest.mark.parametrize("ext", ["vtk", "vtu"])
def test_vtk_finds_every_cell_valid_and_of_positive_volume(tmp_path, name, ext):
    vtk = pytest.importorskip("vtkmodules.all", reason="vtk is not installed")
    from vtkmodules.util.numpy_support import vtk_to_numpy

    out = tmp_path / f"out.{ext}"
    gmap.open(MESH / name).save(out)
    reader = vtk.vtkUnstructuredGridReader() if ext == "vtk" else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(out))
    reader.Update()
    grid = reader.GetOutput()
    size = vtk.vtkCellSizeFilter()
    size.SetInputData(grid)
    size.Update()
    dims = vtk_to_numpy(grid.GetCellData().GetArray("dim"))
    vol = vtk_to_numpy(size.GetOutput().GetCellData().GetArray("Volume"))[dims == 3]
    assert len(vol) > 0 and (vol > 1e-9).all(), vol
    validator = vtk.vtkCellValidator()
    validator.SetInputData(grid)
    validator.Update()
    state = vtk_to_numpy(validator.GetOutput().GetCellData().GetArray("ValidityState"))[dims == 3]
    assert (state == 0).all(), state


def label_sets(g):
    """The labels of each dimension as sorted lists of (name, value), sorted; the writer's
    `dim` column is not a label."""
    return [sorted(sorted((k, v) for k, v in d.items()) for d in g.labels(i) if d) for i in range(g.dim + 1)]


@pytest.mark.parametrize("name", FIXTURES)
def test_to_meshio_and_back_keeps_cells_and_labels(name):
    pytest.importorskip("meshio", reason="meshio is not installed")
    g = gmap.open(MESH / name)
    m = g.to_meshio()
    assert len(m.points) == g.cell_counts()[0]
    assert "dim" in m.cell_data
    back = gmap.GMap.from_meshio(m)
    assert back.cell_counts() == g.cell_counts()
    assert label_sets(back) == label_sets(g)


def test_physical_names_go_both_ways():
    meshio = pytest.importorskip("meshio", reason="meshio is not installed")
    m = gmap.open(MESH / "tet_cube.msh").to_meshio()
    names = {str(x) for block in m.cell_data["gmsh:physical_name"] for x in block}
    assert names == {"solid", "boundary"}
    assert m.field_data["solid"].tolist() == [1, 3] and m.field_data["boundary"].tolist() == [2, 2]
    # a mesh as meshio reads Gmsh's file: names in field_data only
    g = gmap.GMap.from_meshio(meshio.read(MESH / "tet_cube.msh"))
    assert g.cell_counts() == [27, 98, 120, 48]
    solid = [d for d in g.labels(3) if d.get("gmsh:physical_name") == "solid"]
    boundary = [d for d in g.labels(2) if d.get("gmsh:physical_name") == "boundary"]
    assert (len(solid), len(boundary)) == (48, 48)


def test_to_pyvista():
    pv = pytest.importorskip("pyvista", reason="pyvista is not installed")
    grid = gmap.open(MESH / "tet_cube.msh").to_pyvista()
    assert isinstance(grid, pv.UnstructuredGrid)
    assert grid.n_points == 27 and grid.n_cells == 96
    assert set(grid.cell_data["gmsh:physical_name"]) == {"solid", "boundary"}
