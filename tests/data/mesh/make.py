"""Writes the gmsh- and VTK-written mesh fixtures of this directory (see README.md).

Needs gmsh's and VTK's own Python packages (`pip install gmsh vtk`, gmsh 4.15.2 and
VTK 9.7.2 made the committed files). Run from this directory: python3 make.py

Every file holds the same solid: the unit cube meshed by gmsh (OpenCASCADE kernel, mesh
size 0.5, the default 3D algorithm), with the physical volume 1 "solid" and the physical
surface 2 "skin" (its six faces); orders 1, 2 and 3. The script prints each file's element
counts, which the tests (gmap-ops/tests/mesh_fixtures.rs) assert.
"""
import struct

import gmsh
import vtk


def cube(order):
    """Meshes the unit cube in the current gmsh model, at the given element order."""
    gmsh.clear()
    gmsh.model.add("cube")
    gmsh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    gmsh.model.occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [1], 1, "solid")
    faces = [t for (_, t) in gmsh.model.getEntities(2)]
    gmsh.model.addPhysicalGroup(2, faces, 2, "skin")
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
    gmsh.option.setNumber("Mesh.MeshSizeMin", 0.5)
    gmsh.model.mesh.generate(3)
    if order > 1:
        gmsh.model.mesh.setOrder(order)


def write_msh(name, version, binary):
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", 1 if binary else 0)
    gmsh.write(name)
    types, tags, _ = gmsh.model.mesh.getElements()
    counts = {int(t): len(g) for t, g in zip(types, tags)}
    print(name, "element types and counts:", counts)


def swap_msh41_binary(src, dst):
    """A big-endian copy of a binary 4.1 file written by gmsh (which writes the machine's
    byte order): every binary int, size_t and double of $Entities, $Nodes and $Elements
    reversed, the ASCII lines kept."""
    data = open(src, "rb").read()
    out = bytearray()
    pos = 0

    def take(fmt):
        nonlocal pos
        size = struct.calcsize("<" + fmt)
        vals = struct.unpack_from("<" + fmt, data, pos)
        out.extend(struct.pack(">" + fmt, *vals))
        pos += size
        return vals

    def line():
        nonlocal pos
        end = data.index(b"\n", pos) + 1
        out.extend(data[pos:end])
        text = data[pos:end]
        pos = end
        return text

    while pos < len(data):
        head = line().strip()
        if head == b"$MeshFormat":
            line()
            take("i")  # the binary one
            line()  # rest of the line after the one
        elif head == b"$Entities":
            n = take("4Q")
            for dim, count in enumerate(n):
                for _ in range(count):
                    take("i")
                    take("3d" if dim == 0 else "6d")
                    (np_,) = take("Q")
                    take(f"{np_}i")
                    if dim > 0:
                        (nb,) = take("Q")
                        take(f"{nb}i")
            line()
        elif head == b"$Nodes":
            blocks, _, _, _ = take("4Q")
            for _ in range(blocks):
                dim, _, param = take("3i")
                (k,) = take("Q")
                take(f"{k}Q")
                take(f"{k * (3 + (dim if param else 0))}d")
            line()
        elif head == b"$Elements":
            blocks, _, _, _ = take("4Q")
            for _ in range(blocks):
                _, _, etype = take("3i")
                (k,) = take("Q")
                per = gmsh.model.mesh.getElementProperties(etype)[3]
                take(f"{k * (1 + per)}Q")
            line()
        elif head.startswith(b"$") and not head.startswith(b"$End"):
            # a section read past: copy up to its end
            end = data.index(b"$End" + head[1:], pos)
            out.extend(data[pos:end])
            pos = end
    open(dst, "wb").write(bytes(out))
    print(dst, "big-endian copy of", src)


# gmsh's own VTK-numbered orders (as meshio permutes them): the corners first in both
TETRA10_GMSH_TO_VTK = [0, 1, 2, 3, 4, 5, 6, 7, 9, 8]


def vtk_grid(vtk_type, permutation):
    """The tetrahedra of the current gmsh model as a VTK unstructured grid of `vtk_type`,
    with the cell data `physical` (1) and the point data `x` (the first coordinate)."""
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    index = {int(t): k for k, t in enumerate(node_tags)}
    points = vtk.vtkPoints()
    points.SetDataTypeToDouble()
    for k in range(len(node_tags)):
        points.InsertNextPoint(coords[3 * k], coords[3 * k + 1], coords[3 * k + 2])
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(points)
    types, _, nodes = gmsh.model.mesh.getElements(3)
    per = len(permutation)
    physical = vtk.vtkIntArray()
    physical.SetName("physical")
    for t, ns in zip(types, nodes):
        for c in range(len(ns) // per):
            cell = [index[int(ns[c * per + j])] for j in permutation]
            ids = vtk.vtkIdList()
            for v in cell:
                ids.InsertNextId(v)
            grid.InsertNextCell(vtk_type, ids)
            physical.InsertNextValue(1)
    grid.GetCellData().AddArray(physical)
    x = vtk.vtkDoubleArray()
    x.SetName("x")
    for k in range(len(node_tags)):
        x.InsertNextValue(coords[3 * k])
    grid.GetPointData().AddArray(x)
    print("  VTK grid:", grid.GetNumberOfCells(), "cells of type", vtk_type, "on", grid.GetNumberOfPoints(), "points")
    return grid


def write_vtu(name, grid, compressor):
    w = vtk.vtkXMLUnstructuredGridWriter()
    w.SetFileName(name)
    w.SetInputData(grid)
    w.SetDataModeToAppended()
    w.EncodeAppendedDataOff()  # raw bytes
    if compressor == "zlib":
        w.SetCompressorTypeToZLib()
    elif compressor == "lzma":
        w.SetCompressorTypeToLZMA()
    elif compressor == "lz4":
        w.SetCompressorTypeToLZ4()
    else:
        w.SetCompressorTypeToNone()
    w.Write()
    print(name, "written by vtkXMLUnstructuredGridWriter,", compressor)


def write_vtk(name, grid, binary):
    w = vtk.vtkUnstructuredGridWriter()
    w.SetFileName(name)
    w.SetInputData(grid)
    if binary:
        w.SetFileTypeToBinary()
    else:
        w.SetFileTypeToASCII()
    w.Write()
    print(name, "written by vtkUnstructuredGridWriter", "binary" if binary else "ASCII")


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
cube(1)
write_msh("cube_22.msh", 2.2, False)
write_msh("cube_22_bin.msh", 2.2, True)
write_msh("cube_41_bin.msh", 4.1, True)
swap_msh41_binary("cube_41_bin.msh", "cube_41_bin_be.msh")
linear = vtk_grid(vtk.VTK_TETRA, [0, 1, 2, 3])
for c in ["zlib", "lzma", "lz4"]:
    write_vtu(f"cube_{c}.vtu", linear, c)
cube(2)
write_msh("cube_o2_41.msh", 4.1, False)
write_msh("cube_o2_22_bin.msh", 2.2, True)
quadratic = vtk_grid(vtk.VTK_QUADRATIC_TETRA, TETRA10_GMSH_TO_VTK)
write_vtu("cube_o2_zlib.vtu", quadratic, "zlib")
write_vtk("cube_o2.vtk", quadratic, True)
lagrange = vtk_grid(vtk.VTK_LAGRANGE_TETRAHEDRON, TETRA10_GMSH_TO_VTK)
write_vtu("cube_o2_lagrange.vtu", lagrange, "none")
cube(3)
write_msh("cube_o3_41_bin.msh", 4.1, True)
gmsh.finalize()
