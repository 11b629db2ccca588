"""Writes the mesh fixtures of this directory with meshio (see README.md).

Run from this directory: python3 make_fixtures.py
"""
import base64
import itertools
import struct
import zlib

import meshio
import numpy as np


def grid_points(n):
    """The (n+1)^3 points of the unit-step grid, x fastest."""
    return np.array(
        [[x, y, z] for z in range(n + 1) for y in range(n + 1) for x in range(n + 1)],
        dtype=float,
    )


def pid(n, x, y, z):
    return x + (n + 1) * (y + (n + 1) * z)


def hex_of(n, x, y, z):
    """VTK order: bottom face counterclockwise, then the top face above it."""
    b = [pid(n, x, y, z), pid(n, x + 1, y, z), pid(n, x + 1, y + 1, z), pid(n, x, y + 1, z)]
    t = [pid(n, x, y, z + 1), pid(n, x + 1, y, z + 1), pid(n, x + 1, y + 1, z + 1), pid(n, x, y + 1, z + 1)]
    return b + t


# 1. hex_hollow: the 3x3x3 block of hexahedra without its middle one (a ball with a cavity)
n = 3
pts = grid_points(n)
cubes = [c for c in itertools.product(range(n), repeat=3) if c != (1, 1, 1)]
hexes = np.array([hex_of(n, x, y, z) for (x, y, z) in cubes])
region = np.array([x + y + z for (x, y, z) in cubes], dtype=np.int32)
temperature = pts.sum(axis=1)
hollow = meshio.Mesh(
    pts,
    [("hexahedron", hexes)],
    point_data={"temperature": temperature},
    cell_data={"region": [region]},
)
meshio.write("hex_hollow.vtu", hollow)  # binary, zlib, UInt32 headers
meshio.write("hex_hollow.vtk", hollow)  # version 5.1, binary
meshio.vtk.write("hex_hollow_42.vtk", hollow, fmt_version="4.2", binary=False)
meshio.vtu.write("hex_hollow_ascii.vtu", hollow, binary=False)

# 2. tet_cube: the 2x2x2 block, each cube cut into 6 tetrahedra around its diagonal
# (Freudenthal), with its 48 boundary triangles as physical surface 2 and the solid as
# physical volume 1
n = 2
pts = grid_points(n)
tets = []
for x, y, z in itertools.product(range(n), repeat=3):
    for perm in itertools.permutations(range(3)):
        c = [x, y, z]
        path = [pid(n, *c)]
        for axis in perm:
            c[axis] += 1
            path.append(pid(n, *c))
        tets.append(path)
tets = np.array(tets)
faces = {}
for t in tets:
    for f in itertools.combinations(sorted(t), 3):
        faces[f] = faces.get(f, 0) + 1
boundary = np.array([f for f, k in faces.items() if k == 1])
cells = [("tetra", tets), ("triangle", boundary)]
phys = [np.full(len(tets), 1, dtype=np.int32), np.full(len(boundary), 2, dtype=np.int32)]
geom = [np.full(len(tets), 1, dtype=np.int32), np.full(len(boundary), 1, dtype=np.int32)]
# every node in the volume entity (3, 1), the boundary nodes in the surface entity (2, 1)
on_boundary = np.zeros(len(pts), dtype=bool)
on_boundary[np.unique(boundary)] = True
dim_tags = np.array([[2, 1] if b else [3, 1] for b in on_boundary])
tet = meshio.Mesh(
    pts,
    cells,
    point_data={"gmsh:dim_tags": dim_tags},
    cell_data={"gmsh:physical": phys, "gmsh:geometrical": geom},
    field_data={"solid": np.array([1, 3]), "boundary": np.array([2, 2])},
)
meshio.write("tet_cube.msh", tet, file_format="gmsh", binary=False)
plain = meshio.Mesh(pts, cells, cell_data={"physical": phys})
meshio.vtu.write("tet_cube.vtu", plain, binary=False)
meshio.vtk.write("tet_cube_42bin.vtk", plain, fmt_version="4.2", binary=True)

# 3. mixed: a unit cube (hexahedron), a pyramid on its top, a wedge on its x = 1 side, a
# tetrahedron on a side of the pyramid, with a cell data "kind"
pts = np.array(
    [
        [0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
        [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
        [0.5, 0.5, 1.5],  # 8: the apex
        [2, 0, 0], [2, 1, 0],  # 9, 10: the wedge's far edge
        [0.5, -0.5, 1.5],  # 11: the tetrahedron's tip
    ],
    dtype=float,
)
mixed_cells = [
    ("hexahedron", np.array([[0, 1, 2, 3, 4, 5, 6, 7]])),
    ("pyramid", np.array([[4, 5, 6, 7, 8]])),
    # meshio's wedge order (gmsh's): triangle 1-9-5 and triangle 2-10-6 above it
    ("wedge", np.array([[1, 9, 5, 2, 10, 6]])),
    ("tetra", np.array([[4, 5, 8, 11]])),
]
kind = [np.array([12]), np.array([14]), np.array([13]), np.array([10])]
mixed = meshio.Mesh(pts, mixed_cells, cell_data={"kind": kind})
meshio.vtu.write("mixed.vtu", mixed, binary=True, compression=None, header_type="UInt64")
meshio.vtk.write("mixed.vtk", mixed, fmt_version="5.1", binary=False)
meshio.vtk.write("mixed_42.vtk", mixed, fmt_version="4.2", binary=True)
# in .msh each cell its own volume entity (3, k) with physical tag k; every entity needs a
# node of its own for meshio to write it
mixed_msh = meshio.Mesh(
    pts,
    mixed_cells,
    point_data={"gmsh:dim_tags": np.array([[3, 1]] * 8 + [[3, 2], [3, 3], [3, 3], [3, 4]])},
    cell_data={"gmsh:physical": [np.array([k]) for k in (1, 2, 3, 4)],
               "gmsh:geometrical": [np.array([k]) for k in (1, 2, 3, 4)]},
)
meshio.write("mixed.msh", mixed_msh, file_format="gmsh", binary=False)

# 4. ring: eight hexahedra around the middle of a 3x3 square, one layer (a solid torus),
# written by hand as .vtu with appended raw data, uncompressed and zlib-compressed
n = 3
pts = np.array([[x, y, z] for z in range(2) for y in range(4) for x in range(4)], dtype=float)


def rid(x, y, z):
    return x + 4 * (y + 4 * z)


ring = [(x, y) for x in range(3) for y in range(3) if (x, y) != (1, 1)]
ring_hexes = np.array(
    [[rid(x, y, 0), rid(x + 1, y, 0), rid(x + 1, y + 1, 0), rid(x, y + 1, 0),
      rid(x, y, 1), rid(x + 1, y, 1), rid(x + 1, y + 1, 1), rid(x, y + 1, 1)] for (x, y) in ring]
)
meshio.write("ring.msh", meshio.Mesh(pts, [("hexahedron", ring_hexes)]), file_format="gmsh", binary=False)


def appended_vtu(path, points, conn, offsets, types, cell_data, compress):
    arrays = [
        ("Points", "Float64", 3, points.astype("<f8").tobytes()),
        ("connectivity", "Int64", 1, conn.astype("<i8").tobytes()),
        ("offsets", "Int64", 1, offsets.astype("<i8").tobytes()),
        ("types", "UInt8", 1, types.astype("u1").tobytes()),
    ] + [(name, "Int32", 1, v.astype("<i4").tobytes()) for name, v in cell_data.items()]
    blob = b""
    tags = {}
    for name, ty, comps, raw in arrays:
        tags[name] = (ty, comps, len(blob))
        if compress:
            # vtkZLibDataCompressor: blocks of 32 bytes here, to have several
            size = 32
            blocks = [raw[k:k + size] for k in range(0, len(raw), size)] or [b""]
            comp = [zlib.compress(b) for b in blocks]
            last = len(blocks[-1]) if len(raw) % size else (size if raw else 0)
            head = struct.pack("<%dI" % (3 + len(comp)), len(blocks), size, last, *[len(c) for c in comp])
            blob += head + b"".join(comp)
        else:
            blob += struct.pack("<I", len(raw)) + raw

    def da(name):
        ty, comps, off = tags[name]
        return (f'<DataArray type="{ty}" Name="{name}" NumberOfComponents="{comps}" '
                f'format="appended" offset="{off}"/>')

    compressor = ' compressor="vtkZLibDataCompressor"' if compress else ""
    xml = (
        f'<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" '
        f'byte_order="LittleEndian" header_type="UInt32"{compressor}>\n<UnstructuredGrid>\n'
        f'<Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(types)}">\n'
        f'<Points>{da("Points")}</Points>\n<Cells>{da("connectivity")}{da("offsets")}{da("types")}</Cells>\n'
        f'<CellData>{"".join(da(k) for k in cell_data)}</CellData>\n'
        '</Piece>\n</UnstructuredGrid>\n<AppendedData encoding="raw">\n_'
    ).encode()
    with open(path, "wb") as f:
        f.write(xml + blob + b"\n</AppendedData>\n</VTKFile>\n")


conn = ring_hexes.reshape(-1)
offsets = np.arange(8, 8 * len(ring_hexes) + 1, 8)
types = np.full(len(ring_hexes), 12)
index = np.arange(len(ring_hexes))
appended_vtu("ring_raw.vtu", pts, conn, offsets, types, {"index": index}, False)
appended_vtu("ring_zlib.vtu", pts, conn, offsets, types, {"index": index}, True)
for f in ["ring_raw.vtu", "ring_zlib.vtu"]:
    m = meshio.read(f)
    assert len(m.cells[0].data) == 8 and list(m.cell_data["index"][0]) == list(range(8)), f

# 5. poly: two unit cubes as polyhedra (VTK type 42) sharing their x = 1 face, in .vtu
# (meshio's polyhedron cells; it writes no other type next to polyhedra)
pts = np.array(
    [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
     [2, 0, 0], [2, 1, 0], [2, 1, 1], [2, 0, 1]],
    dtype=float,
)
cube_faces = [
    np.array([0, 3, 2, 1]), np.array([4, 5, 6, 7]), np.array([0, 1, 5, 4]),
    np.array([1, 2, 6, 5]), np.array([2, 3, 7, 6]), np.array([3, 0, 4, 7]),
]
# the cube moved by x + 1
moved = {0: 1, 1: 8, 2: 9, 3: 2, 4: 5, 5: 11, 6: 10, 7: 6}
poly = meshio.Mesh(
    pts,
    [("polyhedron8", [cube_faces, [np.array([moved[v] for v in f]) for f in cube_faces]])],
    cell_data={"id": [np.array([7, 8])]},
)
meshio.vtu.write("poly.vtu", poly, binary=False)
print("written")
