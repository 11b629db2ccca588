# TopologicPy's room graphs of the six buildings of scripts/arch_buildings.py, recorded in
# tests/data/arch/buildings/topologicpy/room_graphs.json so that gmap's are checked against them
# where TopologicPy is not installed (tests/room_graph_cli.rs, python/tests/test_room_graph.py).
#
#   pip install topologicpy topologic-core     # TopologicPy 0.9.87 was used
#   python3 scripts/topologicpy_room_graphs.py tests/data/arch/buildings/topologicpy/room_graphs.json
#
# Each room is TopologicPy's own cell: Cell.ByFaces of its prism (floor, roof, one face per
# side of its polygon), the building CellComplex.ByCells of them (TopologicPy splits and
# shares the faces itself), the apertures added to its faces with Topology.AddApertures. The
# graphs are TGraph.ByTopology (0.9.87's Graph) with direct=True, viaSharedApertures=True and
# toExteriorTopologies=True. Recorded per building:
#   faces:     [room, room, area of Topology.SharedFaces] per edge of the direct graph
#   apertures: [room, room, [aperture ids]] per pair of rooms with apertures in between
#   exterior:  {room: [number of exterior-face nodes, their total area]}
# rooms named by their ids, each pair in sorted order, the lists sorted, areas rounded to 6
# decimals.
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from arch_buildings import BUILDINGS  # noqa: E402


def answers(name):
    """TopologicPy's room graphs of one building (module comment)."""
    from topologicpy.Cell import Cell
    from topologicpy.CellComplex import CellComplex
    from topologicpy.Dictionary import Dictionary
    from topologicpy.Face import Face
    from topologicpy.TGraph import TGraph
    from topologicpy.Topology import Topology
    from topologicpy.Vertex import Vertex

    rooms, apertures = BUILDINGS[name]

    def prism(poly, z0, z1):
        fs = [Face.ByVertices([Vertex.ByCoordinates(x, y, z0) for x, y in reversed(poly)]),
              Face.ByVertices([Vertex.ByCoordinates(x, y, z1) for x, y in poly])]
        for i in range(len(poly)):
            (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % len(poly)]
            fs.append(Face.ByVertices([Vertex.ByCoordinates(x0, y0, z0), Vertex.ByCoordinates(x1, y1, z0),
                                       Vertex.ByCoordinates(x1, y1, z1), Vertex.ByCoordinates(x0, y0, z1)]))
        return Cell.ByFaces(fs)

    def rect(axis, c, u, v):
        pts = []
        for a, b in ((u[0], v[0]), (u[1], v[0]), (u[1], v[1]), (u[0], v[1])):
            pts.append(Vertex.ByCoordinates(*{"x": (c, a, b), "y": (a, c, b), "z": (a, b, c)}[axis]))
        return Face.ByVertices(pts)

    cells = []
    for rid, _, poly, z0, z1 in rooms:
        cells.append(Topology.SetDictionary(prism(poly, z0, z1), Dictionary.ByKeysValues(["room"], [rid])))
    cc = CellComplex.ByCells(cells, transferDictionaries=True, silent=True)
    faces = [Topology.SetDictionary(rect(axis, c, u, v), Dictionary.ByKeysValues(["aperture"], [aid]))
             for aid, _, axis, c, u, v in apertures]
    if faces:
        cc = Topology.AddApertures(cc, faces, subTopologyType="Face")
    cell_of = {}
    for c in Topology.Cells(cc):
        cell_of[Dictionary.ValueAtKey(Topology.Dictionary(c), "room")] = c
    assert sorted(cell_of) == sorted(r[0] for r in rooms), (name, sorted(cell_of))

    def graph(**kw):
        return TGraph.NetworkXGraph(TGraph.ByTopology(cc, silent=True, **kw))

    def room(d):
        return d.get("room")

    out = {"faces": [], "apertures": [], "exterior": {}}
    g = graph(direct=True)
    for a, b in g.edges():
        ra, rb = sorted((room(g.nodes[a]), room(g.nodes[b])))
        area = sum(Face.Area(f) for f in Topology.SharedFaces(cell_of[ra], cell_of[rb]))
        out["faces"].append([ra, rb, round(area, 6)])
    g = graph(direct=False, viaSharedApertures=True)
    via = {}
    for a, b, d in g.edges(data=True):
        r = room(g.nodes[a]) or room(g.nodes[b])
        other = b if room(g.nodes[a]) else a
        via.setdefault(other, (d.get("aperture"), set()))[1].add(r)
    pairs = {}
    for aperture, rs in via.values():
        if len(rs) == 2:
            pairs.setdefault(tuple(sorted(rs)), []).append(aperture)
    out["apertures"] = [[a, b, sorted(ids)] for (a, b), ids in pairs.items()]
    g = graph(direct=False, toExteriorTopologies=True)
    for n, d in g.nodes(data=True):
        if room(d) is not None:
            ext = [f for f in Topology.Faces(cell_of[room(d)])
                   if len(Topology.SuperTopologies(f, cc, topologyType="Cell") or []) == 1]
            out["exterior"][room(d)] = [g.degree(n), round(sum(Face.Area(f) for f in ext), 6)]
    out["faces"].sort()
    out["apertures"].sort()
    return out


def all_answers():
    """TopologicPy's room graphs of every building, with the version that made them."""
    import topologicpy

    return {"topologicpy": topologicpy.__version__, "buildings": {n: answers(n) for n in BUILDINGS}}


if __name__ == "__main__":
    with open(sys.argv[1], "w") as f:
        json.dump(all_answers(), f, indent=1, sort_keys=True)
        f.write("\n")
