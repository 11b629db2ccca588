"""Architectural complexes from Python as from the command line: snapping a T-junction and
a point given twice, the TM edit check (topological and metrical) and views, homology with
topological=, generators named by the file's ids, rooms from walls, the incidence graph of
an ArchComplex, and the room graphs (TopologicPy's Graph.ByTopology: direct, through
apertures, to the exterior)."""

import warnings

import pytest

import gmap
from conftest import DATA

ARCH = DATA / "arch"


def test_a_t_junction_is_refused_naming_the_place():
    with pytest.raises(gmap.ParseError, match=r"point p400 lies inside edge p000-p800 \(a T-junction\)"):
        gmap.open(ARCH / "t_junction.json")


def test_snap_welds_and_splits_and_says_so():
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        x = gmap.open(ARCH / "t_junction.json", snap=1e-6)
    lines = [str(m.message) for m in w if issubclass(m.category, gmap.SnapWarning)]
    assert "snap: split face south wall along p400-p403 into south wall, south wall.2" in lines
    assert "snap: room 1 (kitchen) takes south wall, north wall" in lines
    assert gmap.homology(x).betti == [1, 0, 0, 0]
    with pytest.warns(gmap.SnapWarning, match=r"welded point p400 copy into p400 \(1.00e-9 apart\)"):
        y = gmap.open(ARCH / "near_points.json", snap=1e-6)
    assert gmap.homology(y).betti == [1, 0, 0, 0]


def test_tm_check_lists_the_metrical_defects():
    c = gmap.tm_check(ARCH / "t_junction.json")
    assert not c["passes"]
    tol, defects = c["metric"]
    assert tol == 8e-8
    assert len(defects) == 6
    assert "edge p400-p403 lies inside face south wall (a T-junction)" in defects
    ok = gmap.tm_check(gmap.open(ARCH / "rooms_door_window.json"))
    assert ok["passes"] and ok["metric"] == (8e-8, [])
    assert ok["counts"] == [20, 29, 13, 2]
    assert ok["text"].endswith("metrical edit (TM X, tolerance 8e-8): no defect\npasses the edit check\n")


def test_tm_views_name_the_rooms_on_each_side():
    v = gmap.tm_views(gmap.open(ARCH / "rooms_door_window.json"), "door")
    assert v.startswith("view (TM 7:1) of 2-cell door: 9 cells\nnear room 2 (living), far room 1 (kitchen) (TM 7:3)\n")


def test_topological_homology_and_named_generators():
    x = gmap.open(ARCH / "rooms_door_window.json")
    assert gmap.homology(x).betti == [2, 0, 0, 0]
    assert gmap.homology(x, topological=True).betti == [1, 0, 0, 0]
    # the file's string ids (the command prints `+1 region v0`)
    h = gmap.homology(x, generators=True)
    assert [list(g.cells) for g in h.generators] == [["v0"], ["v16"]]
    # numeric ids stay numbers
    assert [g.cells.tolist() for g in gmap.homology(ARCH / "court.json", generators=True).generators][0] == [1]
    with pytest.raises(TypeError):
        gmap.homology(x, topological=True, periodic=True)


def test_rooms_keep_the_wording_and_names():
    complex_, rooms = gmap.rooms(ARCH / "building_walls.off")
    assert len(rooms) == 8
    assert all(faces > 0 and volume > 0 for _, faces, volume, _ in rooms)
    assert isinstance(complex_, gmap.ArchComplex)


def test_incidence_graph_of_an_arch_complex_keeps_the_files_ids():
    nx = pytest.importorskip("networkx")
    x = gmap.open(ARCH / "rooms_door_window.json")
    g = gmap.incidence_graph(x)
    assert isinstance(g, nx.DiGraph)
    assert g.number_of_nodes() == len(x)
    assert g.nodes["room 1"]["name"] == "room 1 (kitchen)"
    assert g.nodes["west wall"]["dim"] == 2
    assert g.has_edge("room 1", "west wall")
    assert x.incidence_graph().number_of_edges() == g.number_of_edges()


def test_room_graphs_through_faces_apertures_and_to_the_exterior():
    pytest.importorskip("networkx")
    x = gmap.open(ARCH / "rooms_door_window.json")
    direct = gmap.room_graph(x, via="faces")
    assert sorted(direct.nodes) == ["room 1", "room 2"]
    e = direct.edges["room 1", "room 2"]
    # the wall, the door and the window between the two rooms
    assert sorted(e["faces"]) == ["door", "wall", "window"]
    assert e["area"] == pytest.approx(6 * 3)
    doors = gmap.room_graph(x, via="apertures")
    assert sorted(doors.edges["room 1", "room 2"]["faces"]) == ["door", "window"]
    assert doors.edges["room 1", "room 2"]["area"] == pytest.approx(1 * 2 + 2 * 1)
    out = gmap.room_graph(x, via="exterior")
    assert sorted(out.neighbors("exterior")) == ["room 1", "room 2"]
    assert len(out.edges["room 1", "exterior"]["faces"]) == 5
    # two rooms side by side, snapped from a T-junction: the party wall only
    y = gmap.open(ARCH / "two_rooms.json")
    g = gmap.room_graph(y)
    assert g.edges["room 1", "room 2"]["faces"] == ["party wall"]
    assert g.edges["room 1", "room 2"]["area"] == pytest.approx(18.0)
    with pytest.raises(ValueError):
        gmap.room_graph(y, via="stairs")
