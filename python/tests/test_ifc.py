"""IFC in (``gmap.ifc.open``): a two-storey house made in the test with IfcOpenShell's API —
an L-shaped living room and a square bedroom on the ground storey (spaces extruded from
arbitrary profiles, not boxes), an attic above them, walls on the spaces' common lines, a
slab, a roof, a door between living room and bedroom and a window in the living room's
outer wall — gives its three rooms named as the file names them, the door as the aperture
between the two ground rooms, the window to the outside, storeys and GlobalIds as labels,
and H = (Z, 0, 0, 0). Skipped with a notice where IfcOpenShell is not installed."""

import pytest

import gmap

ifcopenshell = pytest.importorskip("ifcopenshell", reason="IfcOpenShell not installed: pip install ./python[ifc]")
api = pytest.importorskip("ifcopenshell.api")


def prism(f, body, pts, z0, h):
    """A body extruded up from z0 by h over the polygon pts."""
    prof = f.createIfcArbitraryClosedProfileDef(
        "AREA", None, f.createIfcPolyline([f.createIfcCartesianPoint((float(x), float(y))) for x, y in pts + [pts[0]]])
    )
    place = f.createIfcAxis2Placement3D(f.createIfcCartesianPoint((0.0, 0.0, float(z0))), None, None)
    solid = f.createIfcExtrudedAreaSolid(prof, place, f.createIfcDirection((0.0, 0.0, 1.0)), float(h))
    return f.createIfcShapeRepresentation(body, "Body", "SweptSolid", [solid])


def box(x0, x1, y0, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def house(path):
    run = api.run
    f = run("project.create_file", version="IFC4")
    project = run("root.create_entity", f, ifc_class="IfcProject", name="house")
    metre = run("unit.add_si_unit", f, unit_type="LENGTHUNIT")
    run("unit.assign_unit", f, units=[metre])
    model = run("context.add_context", f, context_type="Model")
    body = run("context.add_context", f, context_type="Model", context_identifier="Body", target_view="MODEL_VIEW", parent=model)
    site = run("root.create_entity", f, ifc_class="IfcSite", name="site")
    building = run("root.create_entity", f, ifc_class="IfcBuilding", name="house")
    run("aggregate.assign_object", f, relating_object=project, products=[site])
    run("aggregate.assign_object", f, relating_object=site, products=[building])
    storeys = {}
    for name, z in (("ground", 0.0), ("first", 3.0)):
        s = run("root.create_entity", f, ifc_class="IfcBuildingStorey", name=name)
        s.Elevation = z
        run("aggregate.assign_object", f, relating_object=building, products=[s])
        storeys[name] = s

    def product(cls, name, storey, rep, long_name=None):
        p = run("root.create_entity", f, ifc_class=cls, name=name)
        if long_name:
            p.LongName = long_name
        if cls == "IfcSpace":
            run("aggregate.assign_object", f, relating_object=storeys[storey], products=[p])
        elif cls != "IfcOpeningElement":
            run("spatial.assign_container", f, relating_structure=storeys[storey], products=[p])
        run("geometry.assign_representation", f, product=p, representation=rep)
        run("geometry.edit_object_placement", f, product=p)
        return p

    t = 0.1  # half a wall's thickness
    product("IfcSpace", "1.01", "ground", prism(f, body, [(0, 0), (6, 0), (6, 3), (3, 3), (3, 6), (0, 6)], 0, 3), "living room")
    product("IfcSpace", "1.02", "ground", prism(f, body, box(3, 6, 3, 6), 0, 3), "bedroom")
    product("IfcSpace", "2.01", "first", prism(f, body, box(0, 6, 0, 6), 3, 3), "attic")
    walls = {}
    for name, pts in (
        ("south wall", box(-t, 6 + t, -t, t)),
        ("north wall", box(-t, 6 + t, 6 - t, 6 + t)),
        ("west wall", box(-t, t, t, 6 - t)),
        ("east wall", box(6 - t, 6 + t, t, 6 - t)),
        ("bedroom wall", box(3 + t, 6 - t, 3 - t, 3 + t)),
        ("hall wall", box(3 - t, 3 + t, 3 - t, 6 - t)),
    ):
        walls[name] = product("IfcWall", name, "ground", prism(f, body, pts, 0, 3))
        if name.split()[0] in ("south", "north", "west", "east"):
            product("IfcWall", name + " upstairs", "first", prism(f, body, pts, 3, 3))
    product("IfcSlab", "first floor", "first", prism(f, body, box(-t, 6 + t, -t, 6 + t), 3 - t, 2 * t))
    product("IfcRoof", "roof", "first", prism(f, body, box(-t, 6 + t, -t, 6 + t), 6, 0.2))
    for cls, name, wall, pts, z0, h in (
        ("IfcDoor", "bedroom door", "bedroom wall", box(4, 5, 3 - t, 3 + t), 0, 2),
        ("IfcWindow", "living window", "west wall", box(-t, t, 2, 4), 1, 1),
    ):
        opening = product("IfcOpeningElement", name + " opening", "ground", prism(f, body, pts, z0, h))
        run("feature.add_feature", f, feature=opening, element=walls[wall])
        filling = product(cls, name, "ground", prism(f, body, pts, z0, h))
        run("feature.add_filling", f, opening=opening, element=filling)
    f.write(str(path))
    return f


def test_an_ifc_house_gives_its_rooms_doors_and_homology(tmp_path):
    nx = pytest.importorskip("networkx")
    path = tmp_path / "house.ifc"
    f = house(path)
    m = gmap.ifc.open(path)
    assert sorted(m.spaces) == ["1.01", "1.02", "2.01"]
    x = m.complex
    assert isinstance(x, gmap.ArchComplex)
    # H of the space the rooms make: one solid piece (the window's and the door's holes in
    # their walls are filled by the apertures)
    assert gmap.homology(x, topological=True).betti == [1, 0, 0, 0]
    g = gmap.room_graph(x, via="faces")
    assert isinstance(g, nx.Graph)
    assert sorted(g.nodes) == ["1.01", "1.02", "2.01"]
    assert g.nodes["1.01"]["name"] == "1.01 (living room)"
    assert g.nodes["1.01"]["storey"] == "ground"
    assert g.nodes["2.01"]["storey"] == "first"
    spaces = {s.Name: s.GlobalId for s in f.by_type("IfcSpace")}
    assert g.nodes["1.02"]["globalid"] == spaces["1.02"]
    assert sorted(map(sorted, g.edges)) == [["1.01", "1.02"], ["1.01", "2.01"], ["1.02", "2.01"]]
    # the L-shaped room meets the bedroom along two walls, 3 m long each, 3 m high
    assert g.edges["1.01", "1.02"]["area"] == pytest.approx(18.0)
    assert g.edges["1.01", "2.01"]["area"] == pytest.approx(27.0)
    kinds = sorted(g.edges["1.01", "2.01"]["kinds"])
    assert kinds == ["slab"]
    doors = gmap.room_graph(x, via="apertures")
    assert list(doors.edges) == [("1.01", "1.02")]
    door = doors.edges["1.01", "1.02"]
    assert door["kinds"] == ["door"] and door["face_names"] == ["bedroom door"]
    assert door["area"] == pytest.approx(2.0)
    out = gmap.room_graph(x, via="exterior")
    living = out.edges["1.01", "exterior"]
    assert "window" in living["kinds"]
    assert living["face_names"][living["kinds"].index("window")] == "living window"
    # the walls are split where the spaces meet them: the L-room's part of the west wall
    # and the bedroom's and attic's parts of the east wall are regions of their own
    walls = [n for n in living["face_names"] if n.startswith("west wall ")]
    assert walls, living["face_names"]
    # everything placed
    assert m.report == []


def test_the_command_says_how_to_read_ifc(tmp_path):
    import os
    import subprocess

    exe = os.environ.get("GMAP_BIN")
    if not exe:
        pytest.skip("GMAP_BIN not set (python/run-tests.sh sets it)")
    path = tmp_path / "house.ifc"
    house(path)
    o = subprocess.run([exe, "info", str(path)], capture_output=True, text=True)
    assert o.returncode == 1
    assert "gmap.ifc.open" in o.stderr and "pip install" in o.stderr, o.stderr


def test_a_file_that_is_no_ifc_is_refused(tmp_path):
    bad = tmp_path / "bad.ifc"
    bad.write_text("not an ifc file\n")
    with pytest.raises(gmap.ParseError, match="IfcOpenShell cannot read it"):
        gmap.ifc.open(bad)


def test_spaces_apart_across_a_wall_and_a_space_without_body_are_reported(tmp_path):
    run = api.run
    f = run("project.create_file", version="IFC4")
    project = run("root.create_entity", f, ifc_class="IfcProject", name="flat")
    run("unit.assign_unit", f, units=[run("unit.add_si_unit", f, unit_type="LENGTHUNIT")])
    model = run("context.add_context", f, context_type="Model")
    body = run("context.add_context", f, context_type="Model", context_identifier="Body", target_view="MODEL_VIEW", parent=model)
    storey = run("root.create_entity", f, ifc_class="IfcBuildingStorey", name="ground")
    run("aggregate.assign_object", f, relating_object=project, products=[storey])

    def product(cls, name, rep):
        p = run("root.create_entity", f, ifc_class=cls, name=name)
        if cls == "IfcSpace":
            run("aggregate.assign_object", f, relating_object=storey, products=[p])
        else:
            run("spatial.assign_container", f, relating_structure=storey, products=[p])
        if rep is not None:
            run("geometry.assign_representation", f, product=p, representation=rep)
            run("geometry.edit_object_placement", f, product=p)
        return p

    # two rooms modelled to the inner faces of the 0.2 m wall between them
    product("IfcSpace", "A", prism(f, body, box(0, 2.9, 0, 3), 0, 3))
    product("IfcSpace", "B", prism(f, body, box(3.1, 6, 0, 3), 0, 3))
    product("IfcSpace", "C", None)
    product("IfcWall", "party wall", prism(f, body, box(2.9, 3.1, 0, 3), 0, 3))
    product("IfcWall", "garden wall", prism(f, body, box(20, 21, 0, 3), 0, 3))
    path = tmp_path / "flat.ifc"
    f.write(str(path))
    m = gmap.ifc.open(path)
    assert m.spaces == ["A", "B"]
    assert len(m.report) == 3, m.report
    assert m.report[0].startswith("IfcSpace 'C' (") and m.report[0].endswith("; left out"), m.report
    assert m.report[1].startswith("spaces A and B face each other across IfcWall 'party wall' ("), m.report
    assert "0.2 apart: not adjacent" in m.report[1], m.report
    assert m.report[2].startswith("IfcWall 'garden wall' (") and m.report[2].endswith("bounds no space; not placed")
    # not adjacent, as the file has them; each room's face on the wall is labelled by it
    g = gmap.room_graph(m.complex, via="faces")
    assert sorted(g.nodes) == ["A", "B"] and g.number_of_edges() == 0
    out = gmap.room_graph(m.complex, via="exterior")
    assert "party wall A" in out.edges["A", "exterior"]["faces"]
