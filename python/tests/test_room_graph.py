"""Room graphs (``gmap.room_graph``, ``gmap graph --dual``) against TopologicPy's
``Graph.ByTopology`` (0.9.87's TGraph) on the six buildings of issue 45
(scripts/arch_buildings.py; tests/data/arch/buildings/*.json): rooms adjacent through a
shared face (``direct``) with its area, through apertures (``viaSharedApertures``) by the
apertures' ids, and to the exterior (``toExteriorTopologies``) with the number of
exterior faces (apertures apart: TopologicPy hosts them in a face, gmap has them as faces of
their own) and their area. The answers recorded in
tests/data/arch/buildings/topologicpy/room_graphs.json are checked always; TopologicPy's live answers
too where it imports."""

import importlib.util
import json

import pytest

import gmap
from conftest import DATA, REPO

nx = pytest.importorskip("networkx")

BUILDINGS = DATA / "arch" / "buildings"
RECORDED = json.loads((DATA / "arch" / "buildings" / "topologicpy" / "room_graphs.json").read_text())["buildings"]
NAMES = sorted(RECORDED)


def gmap_answers(path):
    """gmap's room graphs of a building, in the recorded form."""
    out = {}
    g = gmap.room_graph(path, via="faces")
    out["faces"] = sorted([*sorted((a, b)), round(d["area"], 6)] for a, b, d in g.edges(data=True))
    g = gmap.room_graph(path, via="apertures")
    out["apertures"] = sorted([*sorted((a, b)), sorted(d["faces"])] for a, b, d in g.edges(data=True))
    g = gmap.room_graph(path, via="exterior")
    out["exterior"] = {}
    for room in g.neighbors("exterior"):
        d = g.edges[room, "exterior"]
        walls = [k for k in d["kinds"] if k not in ("door", "window", "opening", "aperture")]
        out["exterior"][room] = [len(walls), round(d["area"], 6)]
    return out


def test_the_six_buildings_are_there():
    assert NAMES == ["courtyard", "door_window", "grid_2x2", "l_flat", "shaft", "stair_two_storeys"]
    assert sorted(p.stem for p in BUILDINGS.glob("*.json")) == NAMES


@pytest.mark.parametrize("name", NAMES)
def test_room_graphs_equal_topologicpys_recorded_answers(name):
    assert gmap_answers(BUILDINGS / f"{name}.json") == RECORDED[name]


def test_the_stair_cell_links_the_storeys_through_its_opening():
    g = gmap.room_graph(BUILDINGS / "stair_two_storeys.json", via="apertures")
    assert g.edges["stair 0", "stair 1"]["faces"] == ["stair opening"]
    assert g.edges["stair 0", "stair 1"]["kinds"] == ["opening"]
    assert g.edges["stair 0", "stair 1"]["area"] == pytest.approx(4.0)
    assert g.nodes["stair 0"]["name"] == "stair 0 (stair, ground)"
    assert g.nodes["stair 0"]["storey"] == "ground"
    # the hall and the office meet through the slab only: no aperture between them
    assert not g.has_edge("hall", "office")
    assert gmap.room_graph(BUILDINGS / "stair_two_storeys.json").edges["hall", "office"]["faces"] == [
        "slab hall/office"
    ]


def test_the_command_writes_the_same_graph():
    import os
    import subprocess

    exe = os.environ.get("GMAP_BIN")
    if not exe:
        pytest.skip("GMAP_BIN not set (python/run-tests.sh sets it)")
    path = BUILDINGS / "l_flat.json"
    for via in ("faces", "apertures", "exterior"):
        out = subprocess.run([exe, "graph", str(path), "--dual", via], capture_output=True, text=True, check=True)
        d = json.loads(out.stdout)
        g = gmap.room_graph(path, via=via)
        assert {frozenset((e["source"], e["target"])): e["faces"] for e in d["edges"]} == {
            frozenset((a, b)): f for a, b, f in g.edges(data="faces")
        }


def topologicpy():
    """The recording script, where TopologicPy imports; None with a notice elsewhere."""
    try:
        import topologicpy  # noqa: F401
        from topologicpy.TGraph import TGraph  # noqa: F401
        from topologicpy.Cell import Cell

        Cell.Prism()
    except Exception as e:  # not installed, or its core library missing
        return None, f"{type(e).__name__}: {e}"
    spec = importlib.util.spec_from_file_location("topologicpy_room_graphs", REPO / "scripts" / "topologicpy_room_graphs.py")
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m, None


@pytest.mark.parametrize("name", NAMES)
def test_room_graphs_equal_topologicpys_live_answers(name):
    m, why = topologicpy()
    if m is None:
        pytest.skip(f"TopologicPy not importable ({why}); the recorded answers are checked instead")
    live = m.answers(name)
    assert live == RECORDED[name]
    assert gmap_answers(BUILDINGS / f"{name}.json") == live
