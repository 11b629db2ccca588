"""obj.view() and the notebook's _repr_html_, gmap.persistence against GUDHI, and the
names of build.from_facets' generators."""

import html
import json
import re
from collections import Counter

import numpy as np
import pytest

import gmap

from conftest import DATA

ROOMS = ["hall", "kitchen", "study"]


def meta(page):
    """The page's data: the JSON of its `gmap-meta` element."""
    m = re.search(r'<script type="application/json" id="gmap-meta">(.*?)</script>', page, re.S)
    assert m, "no gmap-meta element"
    return json.loads(m.group(1))


def three_rooms():
    """Three cubes in a row, each 3-cell named after a room."""
    m = gmap.build.grid((3, 1, 1))
    darts = m.cells(3).tolist()
    assert len(darts) == 3
    for d, room in zip(darts, ROOMS):
        m.set_label(3, d, "room", room)
    return m


# ---------------------------------------------------------------- view


def test_view_of_a_labelled_map_lists_its_rooms_and_darts(tmp_path):
    m = three_rooms()
    page = m.view()
    assert page.startswith("<!DOCTYPE html>")
    data = meta(page)
    assert data["darts"] == len(m)
    assert data["counts"] == m.cell_counts()
    assert data["colorBy"] == "room"
    # each label as [name, [value, type]]
    named = sorted(v[0] for _, labels in data["labels"][3] for n, v in labels if n == "room")
    assert named == sorted(ROOMS)
    assert "http://" not in page and "https://" not in page
    # written to a file: the same page, the path given back
    out = tmp_path / "rooms.html"
    assert m.view(out) == str(out)
    assert out.read_text(encoding="utf-8") == page


def test_view_color_by_an_unknown_label_is_an_error():
    with pytest.raises(gmap.GmapError, match="colour"):
        three_rooms().view(color_by="colour")


def test_view_with_generators_names_each_summand():
    torus = gmap.build.surface("a b a^-1 b^-1")
    data = meta(torus.view(generators=True))
    assert [g["name"] for g in data["generators"]] == ["H0 #0 (Z)", "H1 #0 (Z)", "H1 #1 (Z)", "H2 #0 (Z)"]
    assert data["view"] == "homology"
    assert all(g["cells"] for g in data["generators"])
    assert meta(torus.view())["generators"] == []


@pytest.mark.parametrize(
    "obj",
    [
        lambda: gmap.SimplicialComplex([[0, 1, 2], [0, 2, 3], [0, 1, 3], [1, 2, 3]]),
        lambda: gmap.CubicalSet(np.array([[1, 1, 1], [1, 0, 1], [1, 1, 1]], dtype=bool)),
        lambda: gmap.open(DATA / "arch" / "tetrahedron.json"),
        lambda: gmap.open(DATA / "lutz" / "poincare.facets"),
    ],
    ids=["simplicial", "cubical", "arch", "lutz"],
)
def test_every_object_has_a_page_and_an_inline_frame(obj):
    x = obj()
    page = x.view(generators=True)
    data = meta(page)
    assert data["generators"], "generators drawn"
    frame = x._repr_html_()
    assert frame.startswith("<iframe srcdoc=\"") and "height: 600px" in frame
    srcdoc = re.fullmatch(r'<iframe srcdoc="([^"]*)".*</iframe>', frame, re.S).group(1)
    # nothing in the attribute can end it or open a tag; unescaped it is exactly the page
    assert "<" not in srcdoc and '"' not in srcdoc
    assert html.unescape(srcdoc) == x.view()


def test_the_cubical_page_holds_its_cubes():
    a = np.zeros((5, 6), dtype=bool)
    a[1:4, 1:4] = True
    a[2, 2] = False  # a ring of 8 squares
    data = meta(gmap.CubicalSet(a).view(generators=True))
    assert data["dim"] == 2
    assert data["counts"][2] == int(a.sum())
    assert [g["name"] for g in data["generators"]] == ["H0 #0 (Z)", "H1 #0 (Z)"]


def test_a_page_too_big_for_a_notebook_is_not_embedded():
    # about 1.2 M cubes: a page of many megabytes
    rng = np.random.default_rng(7)
    big = gmap.CubicalSet(rng.random((110, 110, 110)) < 0.9)
    shown = big._repr_html_()
    assert "<iframe" not in shown and "MB" in shown and "view(" in shown
    assert len(shown) < 1000


# ---------------------------------------------------------------- from_facets names


def test_from_facets_generators_are_named_by_vertex_labels():
    # the boundary of a tetrahedron on labels 10, 20, 30, 40 and a torus (Möbius-Kantor)
    facets = [[10, 20, 30], [10, 30, 40], [10, 20, 40], [20, 30, 40]]
    m = gmap.build.from_facets(facets)
    h = gmap.homology(m, generators=True)
    assert h.betti == [1, 0, 1]
    ref = gmap.homology(facets, generators=True, method="gmap")
    for g, r in zip(h.generators, ref.generators):
        assert g.dim == r.dim
        assert list(g.cells) == list(r.cells)
        assert list(g.coefficients) == list(r.coefficients)
    labels = {10, 20, 30, 40}
    for g in h.generators:
        assert all(isinstance(c, tuple) and set(c) <= labels and len(c) == g.dim + 1 for c in g.cells)
    # the same groups as a map; the report is a map's
    assert h.to_dict()["betti"] == [1, 0, 1]
    assert h.route is None
    # after an edit of the darts the complex no longer names them: darts again
    m.unsew(0, 2)
    g = gmap.homology(m, generators=True)
    assert isinstance(g.generators[0].cells, np.ndarray)


def test_from_facets_torus_generators_by_labels():
    torus = [
        [1, 2, 4], [2, 3, 5], [3, 1, 6], [4, 2, 5], [5, 3, 6], [6, 1, 4],
        [4, 5, 7], [5, 6, 8], [6, 4, 9], [7, 5, 8], [8, 6, 9], [9, 4, 7],
        [7, 8, 1], [8, 9, 2], [9, 7, 3], [1, 8, 2], [2, 9, 3], [3, 7, 1],
    ]
    h = gmap.homology(gmap.build.from_facets(torus), generators=True)
    assert h.betti == [1, 2, 1]
    h1 = [g for g in h.generators if g.dim == 1]
    assert len(h1) == 2
    for g in h1:
        assert all(len(c) == 2 and set(c) <= set(range(1, 10)) for c in g.cells)


# ---------------------------------------------------------------- persistence


def gudhi_pairs(top, field, vertices=False):
    gudhi = pytest.importorskip("gudhi")
    if vertices:
        cc = gudhi.CubicalComplex(vertices=top)
    else:
        cc = gudhi.CubicalComplex(top_dimensional_cells=top)
    # persistence() computes again with its own defaults (Z/11): pass the field
    pairs = cc.persistence(homology_coeff_field=field, min_persistence=0)
    return Counter((d, float(b), float(e)) for d, (b, e) in pairs if b != e)


def ours(x, **kw):
    d = gmap.persistence(x, **kw)
    assert d.dtype == np.float64 and d.ndim == 2 and d.shape[1] == 3
    return Counter((int(k), float(b), float(e)) for k, b, e in d)


@pytest.mark.parametrize("field", [2, 3])
@pytest.mark.parametrize("shape", [(7,), (9, 8), (5, 6, 4), (3, 3, 4, 3)])
def test_persistence_equals_gudhi_cubical(shape, field):
    rng = np.random.default_rng(hash((shape, field)) % 2**32)
    for _ in range(3):
        a = rng.integers(0, 6, size=shape).astype(np.float64)
        assert ours(a, field=field) == gudhi_pairs(a, field)


@pytest.mark.parametrize("field", [2, 3])
def test_persistence_v_construction_equals_gudhi_vertices(field):
    rng = np.random.default_rng(11 + field)
    for shape in [(8, 9), (5, 4, 6)]:
        a = rng.integers(0, 5, size=shape).astype(np.float64)
        assert ours(a, field=field, construction="V") == gudhi_pairs(a, field, vertices=True)


@pytest.mark.parametrize("field", [2, 3])
@pytest.mark.parametrize("construction", ["T", "V"])
def test_persistence_of_3d_arrays_equals_gudhi(construction, field):
    # big enough for the middle dimension's long columns (added in place) and ties
    rng = np.random.default_rng(17 + field)
    for a in [rng.integers(0, 8, size=(16, 13, 15)).astype(np.float64), rng.random((14, 15, 12))]:
        want = gudhi_pairs(a, field, vertices=construction == "V")
        assert ours(a, field=field, construction=construction) == want


def test_persistence_of_a_path_and_of_other_dtypes(tmp_path):
    rng = np.random.default_rng(5)
    a = rng.integers(0, 9, size=(12, 10))
    p = tmp_path / "img.npy"
    np.save(p, a)
    ref = gmap.persistence(a.astype(np.float64))
    assert np.array_equal(gmap.persistence(p), ref)
    assert np.array_equal(gmap.persistence(str(p)), ref)
    assert np.array_equal(gmap.persistence(a), ref)  # int64, converted
    assert np.array_equal(gmap.persistence(np.asfortranarray(a)), ref)
    # essential classes die at inf; one essential H0 on a box
    d = gmap.persistence(a)
    assert np.isinf(d[:, 2]).sum() == 1 and d[np.isinf(d[:, 2])][0, 0] == 0
    # superlevel: births above deaths, the essential class dies at -inf
    s = gmap.persistence(a, superlevel=True)
    assert np.all(s[:, 1] >= s[:, 2]) and np.isneginf(s[:, 2]).sum() == 1


def test_persistence_cycles_in_grid_coordinates():
    a = np.ones((7, 7))
    a[1:6, 1:6] = 0.0
    a[2:5, 2:5] = 2.0  # a ring of value 0 around a hole filled at 2
    pairs, cycles = gmap.persistence(a, cycles=True)
    assert len(cycles) == len(pairs)
    ring = [i for i, (k, b, e) in enumerate(pairs) if k == 1 and b == 0.0 and e == 2.0]
    assert len(ring) == 1
    cells, coefficients = cycles[ring[0]]
    assert cells.shape[1] == 2 and len(cells) == len(coefficients) > 0
    # edges of the doubled grid (one odd coordinate), on the ring of pixels 1..5
    assert np.all(cells.sum(axis=1) % 2 == 1)
    assert cells.min() >= 2 and cells.max() <= 12


def test_persistence_errors():
    with pytest.raises(gmap.GmapError):
        gmap.persistence(np.zeros((2,) * 9))
    with pytest.raises(gmap.GmapError):
        gmap.persistence(np.array([1.0, np.nan]))
    with pytest.raises(gmap.GmapError):
        gmap.persistence(np.zeros((3, 3)), construction="X")
    with pytest.raises(gmap.GmapError):
        gmap.persistence(np.zeros((3, 3)), field=4)
    with pytest.raises(gmap.GmapError):
        gmap.persistence(gmap.SimplicialComplex([[0, 1]]))
    with pytest.raises(gmap.GmapError):
        gmap.persistence(3)
    # refused before any copy, with the estimate: 10^10 pixels (a view of one number), past
    # the pixel route's u32 cell numbers, so 64 bytes per cell of the 200001² grid and 16 MiB
    huge = np.broadcast_to(np.float64(0.0), (100_000, 100_000))
    with pytest.raises(gmap.LimitError, match=r"100000×100000 image would take an estimated 2560042377280 bytes"):
        gmap.persistence(huge)


def test_an_array_past_the_memory_limit_takes_its_lower_stars():
    rng = np.random.default_rng(5)
    assert gmap.max_memory() > 1 << 30
    program = 16 << 20
    try:
        # the limit one byte below the whole grid's estimate: 64 bytes a pixel in 2-D,
        # 108 (V over Z/3) or 160 (T over Z/3) per point of the padded grid in 3-D
        y, x = np.mgrid[0:60, 0:70]
        smooth = np.sin(x / 5.0) * np.cos(y / 7.0) + 0.3 * np.sin((x + y) / 3.0) + 0.05 * rng.random((60, 70))
        three = lambda n, c: (16 * 17 * 18) * (108 if c == "V" else 160)
        for a, per in [(smooth, lambda n, c: 64 * n), (rng.random((14, 15, 16)), three)]:
            for c in "TV":
                for superlevel in (False, True):
                    kw = dict(construction=c, superlevel=superlevel, field=3)
                    gmap.set_max_memory(None)
                    whole = ours(a, **kw)
                    gmap.set_max_memory(program + per(a.size, c) - 1)
                    assert ours(a, **kw) == whole, (a.shape, kw)
                    # read in place in its own type, or converted when not contiguous
                    grey = ((a - a.min()) * 60).astype(np.uint8)
                    assert ours(grey, **kw) == ours(grey.astype(float), **kw)
                    assert ours(np.asfortranarray(a), **kw) == whole
        # no cycles, no torus, and no room for the critical cells: refused with the reason
        gmap.set_max_memory(program + 64 * 4200 - 1)
        a = rng.random((60, 70))
        with pytest.raises(gmap.LimitError, match=r"neither periodic images nor cycles"):
            gmap.persistence(a, cycles=True)
        with pytest.raises(gmap.LimitError, match=r"neither periodic images nor cycles"):
            gmap.persistence(a, periodic=True)
        with pytest.raises(gmap.LimitError, match=r"which takes 1 to 4 axes"):
            gmap.persistence(rng.random((3, 3, 3, 3, 3)))
        gmap.set_max_memory(program + 96 * 10)
        with pytest.raises(gmap.LimitError, match=r"more than 10 critical cells"):
            gmap.persistence(rng.random((200, 200)))
        with pytest.raises(gmap.InputError):
            gmap.set_max_memory(0)
    finally:
        gmap.set_max_memory(None)


def test_persistence_of_a_cubical_set_and_a_valued_map():
    a = np.array([[1, 1, 1], [1, 0, 1], [1, 1, 1]], dtype=bool)
    d = gmap.persistence(gmap.CubicalSet(a))
    # the ring (value 0) has one essential H0 and an H1 filled at 1
    assert ours(gmap.CubicalSet(a)) == Counter({(0, 0.0, float("inf")): 1, (1, 0.0, 1.0): 1})
    assert d.shape == (2, 3)
    # a map whose cells carry a value
    m = gmap.build.polygon(4)
    for i in range(3):
        for k, dart in enumerate(m.cells(i).tolist()):
            m.set_label(i, dart, "value", float(i))
    p = gmap.persistence(m)
    # four vertices at 0 joined by the edges at 1 (three die), the loop closed at 1 and
    # filled by the face at 2
    assert Counter(map(tuple, p.tolist())) == Counter({(0.0, 0.0, float("inf")): 1, (0.0, 0.0, 1.0): 3, (1.0, 1.0, 2.0): 1})


def gudhi_simplex_tree(facets, field, facet_values=None, vertex_values=None):
    """GUDHI's diagram of a simplicial complex: facet values (a face takes the minimum of its
    cofacets', SimplexTree.insert's rule) or vertex values (each simplex the maximum of its
    vertices', the lower star)."""
    gudhi = pytest.importorskip("gudhi")
    st = gudhi.SimplexTree()
    for i, f in enumerate(facets):
        st.insert(list(f), 0.0 if facet_values is None else float(facet_values[i]))
    if vertex_values is not None:
        for s, _ in list(st.get_simplices()):
            st.assign_filtration(s, max(float(vertex_values[v]) for v in s))
        st.make_filtration_non_decreasing()
    # persistence() computes again with its own defaults (Z/11, no top dimension): pass them
    pairs = st.persistence(homology_coeff_field=field, min_persistence=0, persistence_dim_max=True)
    return Counter((d, float(b), float(e)) for d, (b, e) in pairs if b != e)


def random_facets(rng, vertices, count, size):
    return [sorted(rng.choice(vertices, size=size, replace=False).tolist()) for _ in range(count)]


@pytest.mark.parametrize("field", [2, 3])
@pytest.mark.parametrize("name", ["rp2.facets", "lutz/dunce_hat.facets", "lutz/CP2.facets", "lutz/poincare.facets"])
def test_lower_star_equals_gudhi_on_lutz_files(name, field):
    path = DATA / name
    sc = gmap.open(path)
    labels = sorted({v for f in sc.facets for v in f})
    rng = np.random.default_rng(len(labels) * 7 + field)
    for values in [rng.integers(0, 4, size=len(labels)), rng.random(len(labels))]:
        by_label = {v: float(x) for v, x in zip(labels, values)}
        want = gudhi_simplex_tree(sc.facets, field, vertex_values=by_label)
        assert ours(sc, field=field, vertex_values=by_label) == want
        # the path, and a sequence indexed by label, give the same diagram
        seq = [by_label.get(i, 0.0) for i in range(max(labels) + 1)]
        assert ours(path, field=field, vertex_values=seq) == want
        # superlevel sets (the upper star) are the lower star of the values negated
        up = gudhi_simplex_tree(sc.facets, field, vertex_values={v: -x for v, x in by_label.items()})
        want_up = Counter({(k, -b, -e): n for (k, b, e), n in up.items()})
        assert ours(sc, field=field, vertex_values=by_label, superlevel=True) == want_up


@pytest.mark.parametrize("field", [2, 3])
def test_lower_star_and_facet_values_equal_gudhi_on_random_complexes(field):
    rng = np.random.default_rng(40 + field)
    for trial in range(12):
        facets = random_facets(rng, 9, int(rng.integers(3, 15)), int(rng.integers(2, 5)))
        # a complex is a set of facets: drop repeats and faces of other facets
        facets = [f for f in {tuple(f) for f in facets}]
        facets = [list(f) for f in facets if not any(set(f) < set(g) for g in facets)]
        sc = gmap.SimplicialComplex(facets)
        vertex_values = rng.integers(0, 5, size=9).astype(float)
        want = gudhi_simplex_tree(sc.facets, field, vertex_values=vertex_values)
        assert ours(sc, field=field, vertex_values=vertex_values) == want, facets
        facet_values = rng.integers(0, 5, size=len(sc.facets)).astype(float)
        want = gudhi_simplex_tree(sc.facets, field, facet_values=facet_values)
        assert ours(sc, field=field, facet_values=facet_values) == want, facets
        up = gudhi_simplex_tree(sc.facets, field, facet_values=-facet_values)
        want_up = Counter({(k, -b, -e): n for (k, b, e), n in up.items()})
        assert ours(sc, field=field, facet_values=facet_values, superlevel=True) == want_up, facets


def test_facets_given_as_lists_take_values():
    facets = [[1, 2, 5], [2, 3, 5], [3, 4, 5], [1, 4, 5]]
    values = {1: 0, 2: 1, 3: 0, 4: 1, 5: 3}
    want = gmap.persistence(gmap.SimplicialComplex(facets), vertex_values=values)
    assert want.tolist() == [[0, 0, 1], [0, 0, float("inf")], [1, 1, 3]]
    assert np.array_equal(gmap.persistence(facets, vertex_values=values), want)
    assert np.array_equal(gmap.persistence(tuple(map(tuple, facets)), vertex_values=values), want)
    # a value per facet: the fan around vertex 5 grows as a disk, one component throughout
    d = gmap.persistence(facets, facet_values=[0, 0, 1, 3])
    assert Counter(map(tuple, d.tolist())) == Counter({(0.0, 0.0, float("inf")): 1})
    assert np.array_equal(d, gmap.persistence(gmap.SimplicialComplex(facets), facet_values=[0, 0, 1, 3]))
    # without values a nested list is an image of numbers (python/README.md, "Lists and masks")
    assert np.array_equal(gmap.persistence(facets), gmap.persistence(np.asarray(facets)))
    with pytest.raises(gmap.InputError, match="an image of numbers"):
        gmap.persistence([[0, 1], [1, 2, 3]])
    with pytest.raises(gmap.InputError, match="facet 1"):
        gmap.persistence([[0, 1], [2, -1]], vertex_values=[0, 0, 0])


def test_lower_star_cycles_and_refusals(tmp_path):
    cone = gmap.SimplicialComplex([[1, 2, 5], [2, 3, 5], [3, 4, 5], [1, 4, 5]])
    values = {1: 0, 2: 1, 3: 0, 4: 1, 5: 3}
    pairs, cycles = gmap.persistence(cone, vertex_values=values, cycles=True)
    assert pairs.tolist() == [[0, 0, 1], [0, 0, float("inf")], [1, 1, 3]]
    # the square's loop, on its four edges
    assert sorted(cycles[2][0]) == [(1, 2), (1, 4), (2, 3), (3, 4)]
    with pytest.raises(gmap.InputError, match="vertex 5 has no value"):
        gmap.persistence(cone, vertex_values={1: 0, 2: 1, 3: 0, 4: 1})
    with pytest.raises(gmap.GmapError, match="not both"):
        gmap.persistence(cone, vertex_values=values, facet_values=[0, 0, 0, 0])
    with pytest.raises(gmap.GmapError, match="3 values for 4 facets"):
        gmap.persistence(cone, facet_values=[0, 0, 0])
    with pytest.raises(gmap.GmapError, match="NaN"):
        gmap.persistence(cone, vertex_values={1: float("nan")})
    with pytest.raises(gmap.GmapError, match="SimplicialComplex"):
        gmap.persistence(np.zeros((3, 3)), vertex_values=[0.0])
    with pytest.raises(gmap.GmapError, match="periodic applies to images"):
        gmap.persistence(cone, vertex_values=values, periodic=True)
    # the upper star: the apex first, everything else joins it
    assert gmap.persistence(cone, vertex_values=values, superlevel=True).tolist() == [[0, 3, float("-inf")]]
    p = tmp_path / "v.facets"
    p.write_text("1 2 : 0\n2 3 : 1\n")
    with pytest.raises(gmap.GmapError, match="give one filtration"):
        gmap.persistence(p, vertex_values={1: 0, 2: 0, 3: 0})


def test_open_a_valued_facets_file(tmp_path):
    # mixed dimensions, the edge first: the complex lists the triangle first, and each value
    # stays with its own facet (the file's lines)
    p = tmp_path / "valued.facets"
    p.write_text("# a path and a triangle\n0 1 : 0\n2 4 : 0\n0 2 3 : 1\n")
    sc = gmap.open(p)
    # the registry's class for a .facets file, valued or not
    assert type(sc) is gmap.SimplicialComplex
    assert sc.facets == [[0, 2, 3], [0, 1], [2, 4]]
    assert sc.facet_values == [1.0, 0.0, 0.0]
    # GUDHI's SimplexTree of these facets and values (insert: a face takes the minimum):
    # the vertices 0, 1, 2, 4 and the edges 01, 24 at 0, vertex 3 and the rest at 1; two
    # components at 0, joined at 1
    want = Counter({(0, 0.0, float("inf")): 1, (0, 0.0, 1.0): 1})
    assert ours(sc) == want
    assert ours(p) == want
    assert ours([[0, 1], [2, 4], [0, 2, 3]], facet_values=[0, 0, 1]) == want
    assert gudhi_or(want, [[0, 1], [2, 4], [0, 2, 3]], [0, 0, 1]) == want
    # its groups are the complex's (one component, no loop)
    assert gmap.homology(sc).betti == [1, 0, 0]
    # the values go along: the constructor takes them in the order given, pickle keeps them
    made = gmap.SimplicialComplex([[0, 1], [2, 4], [0, 2, 3]], facet_values=[0, 0, 1])
    assert made.facet_values == [1.0, 0.0, 0.0]
    assert ours(made) == want
    import pickle

    again = pickle.loads(pickle.dumps(sc))
    assert again.facets == sc.facets and again.facet_values == sc.facet_values
    # without values the file opens as before, and persistence asks for values
    q = tmp_path / "plain.facets"
    q.write_text("0 1\n1 2\n")
    assert gmap.open(q).facet_values is None
    with pytest.raises(gmap.GmapError, match="needs values"):
        gmap.persistence(gmap.open(q))
    # one filtration at a time; a count of values other than the facets' is refused
    with pytest.raises(gmap.GmapError, match="give one filtration"):
        gmap.persistence(sc, facet_values=[0, 0, 0])
    with pytest.raises(gmap.GmapError, match="give one filtration"):
        gmap.persistence(sc, vertex_values={v: 0.0 for v in range(5)})
    with pytest.raises(gmap.InputError, match="2 facet_values for 3 facets"):
        gmap.SimplicialComplex([[0, 1], [2, 4], [0, 2, 3]], facet_values=[0, 0])
    with pytest.raises(gmap.InputError, match="NaN"):
        gmap.SimplicialComplex([[0, 1]], facet_values=[float("nan")])
    # a facet without a value in a valued file: the reader names its line
    r = tmp_path / "half.facets"
    r.write_text("0 1 : 0\n1 2\n")
    with pytest.raises(gmap.GmapError, match="line 2"):
        gmap.open(r)


def gudhi_or(want, facets, values):
    """GUDHI's diagram of `facets` with `values` when GUDHI is installed, else `want`."""
    try:
        import gudhi  # noqa: F401
    except ImportError:
        return want
    return gudhi_simplex_tree(facets, 2, facet_values=values)


def test_persistence_of_an_architectural_complex_by_its_labels():
    path = DATA / "persistence" / "court_valued.json"
    x = gmap.open(path)
    pairs, cycles = gmap.persistence(x, cycles=True)
    inf = float("inf")
    assert pairs.tolist() == [[0, 0, inf], [0, 1, inf], [1, 0, inf], [1, 1, 2.5]]
    # cycles name regions by id: the outer square's four edges
    assert sorted(cycles[2][0]) == [5, 6, 7, 8]
    assert np.array_equal(gmap.persistence(path), pairs)
    with pytest.raises(gmap.GmapError, match="0-region 1 has no value"):
        gmap.persistence(x, label="name")
    with pytest.raises(gmap.GmapError, match="periodic applies to images"):
        gmap.persistence(x, periodic=True)
    inf = float("inf")
    assert gmap.persistence(x, superlevel=True).tolist() == [[0, 0, -inf], [0, 1, -inf], [1, 1, -inf]]
