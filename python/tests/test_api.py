"""The package's API on known objects: exact groups, maps, labels, points, files, errors."""

import pickle

import numpy as np
import pytest

import gmap
from conftest import DATA

TETRA_BOUNDARY = [[0, 1, 2], [0, 2, 3], [0, 1, 3], [1, 2, 3]]


def test_sphere_from_a_list():
    h = gmap.homology(TETRA_BOUNDARY)
    assert h.betti == [1, 0, 1]
    assert h.torsion == [[], [], []]
    assert h.dimension == 2
    assert h.route == "direct"
    assert h.method == "cellular"
    assert h.euler_characteristic == 2
    assert str(h) == "(Z, 0, Z)"


def test_labels_of_any_size():
    big = 2**64 - 1
    h = gmap.homology([[big, 7, 10**12]])
    assert h.betti == [1, 0, 0]


def test_torsion_and_fields():
    rp2 = gmap.open(DATA / "lutz" / "RP4.facets")
    assert isinstance(rp2, gmap.SimplicialComplex)
    h = gmap.homology(rp2)
    assert h.betti == [1, 0, 0, 0, 0]
    assert h.torsion == [[], [2], [], [2], []]
    assert all(isinstance(t, int) for ts in h.torsion for t in ts)
    assert gmap.homology(rp2, field=2).betti == [1, 1, 1, 1, 1]
    assert gmap.homology(rp2, field=3).betti == [1, 0, 0, 0, 0]
    with pytest.raises(gmap.InputError):
        gmap.homology(rp2, field=4)


def test_lens_space_torsion():
    h = gmap.homology(gmap.build.lens_space(7, 2))
    assert h.betti == [1, 0, 0, 1]
    assert h.torsion == [[], [7], [], []]


def test_generators_in_input_terms():
    h = gmap.homology(TETRA_BOUNDARY, generators=True)
    orders = [(g.dim, g.order) for g in h.generators]
    assert orders == [(0, 0), (2, 0)]
    top = h.generators[1]
    assert sorted(top.cells) == sorted(tuple(f) for f in TETRA_BOUNDARY)
    assert sorted(np.abs(top.coefficients).tolist()) == [1, 1, 1, 1]
    # the lens space's torsion generator is a chain of darts
    g = gmap.homology(gmap.build.lens_space(5, 2), generators=True).generators
    z5 = [x for x in g if x.order == 5]
    assert len(z5) == 1 and z5[0].dim == 1 and z5[0].cells.dtype == np.uint32


def test_cubical_generators_are_coordinates():
    ring = np.ones((3, 3), dtype=bool)
    ring[1, 1] = False
    h = gmap.homology(ring, generators=True)
    assert h.betti == [1, 1, 0]
    loop = [g for g in h.generators if g.dim == 1][0]
    assert loop.cells.shape[1] == 2 and loop.extents.shape == loop.cells.shape
    # every edge of the loop lies on the ring (not through the hole's inside)
    assert loop.extents.sum(axis=1).tolist() == [1] * len(loop.cells)
    # the four edges around the hole, in the array's axis order: [0,1] along an axis is the
    # hole's side at 1 along the other
    assert sorted(map(tuple, np.hstack([loop.cells, loop.extents]).tolist())) == [
        (1, 1, 0, 1), (1, 1, 1, 0), (1, 2, 1, 0), (2, 1, 0, 1)]
    # the arrays are made once, when first read, and kept; the repr does not make them
    assert "cells=4" in repr(loop)
    assert loop.cells is loop.cells and loop.coefficients is loop.coefficients
    assert sorted(loop.coefficients.tolist()) == [-1, -1, 1, 1]


def test_cubical_arrays_any_layout():
    rng = np.random.default_rng(1)
    a = rng.random((7, 5, 6)) < 0.5
    ref = gmap.homology(a)
    assert gmap.homology(np.asfortranarray(a)) == ref
    assert gmap.homology(a.astype(np.uint8) * 3) == ref
    assert gmap.homology(a.astype(np.float64)) == ref
    assert gmap.homology(a[:, :, ::-1].copy()) == ref  # mirrored: same space
    assert gmap.homology(a.transpose(2, 0, 1)) == ref  # a strided view
    assert gmap.homology(gmap.CubicalSet(a)) == ref


def test_periodic_torus():
    h = gmap.homology(np.ones((4, 5), dtype=bool), periodic=True)
    assert h.betti == [1, 2, 1]
    assert gmap.homology(np.ones((3, 3, 3), dtype=bool), periodic=True).betti == [1, 3, 3, 1]
    with pytest.raises(gmap.InputError):
        gmap.homology(TETRA_BOUNDARY, periodic=True)


def test_gmap_from_alphas_and_back():
    sq = gmap.build.polygon(4)
    a = sq.alphas
    assert a.shape == (3, len(sq)) and a.dtype == np.uint32
    again = gmap.GMap.from_alphas(a.astype(np.int64))
    assert (again.alphas == a).all()
    assert again.cell_counts() == [4, 4, 1]
    assert again.euler_characteristic() == 1
    assert again.is_orientable()
    again.check()


def test_sew_and_unsew():
    m = gmap.GMap(1, 4)  # two loose edges' worth of darts
    m.sew(0, 1, 0)
    m.sew(2, 3, 0)
    assert m.cell_counts() == [4, 2]
    m.sew(1, 2, 1)
    assert m.cell_counts() == [3, 2]
    assert m.alpha(1, 1) == 2 and m.is_free(0, 1)
    assert sorted(m.orbit(0, [0, 1]).tolist()) == [0, 1, 2, 3]
    assert len(m.components()) == 1
    m.unsew(1, 1)
    assert m.cell_counts() == [4, 2]
    assert len(m.components()) == 2
    with pytest.raises(gmap.PreconditionError):
        m.sew(0, 1, 0)
    with pytest.raises(gmap.InputError):
        m.sew(0, 99, 1)


def test_builders():
    assert gmap.homology(gmap.build.grid((3, 4))).betti == [1, 0, 0]
    assert gmap.homology(gmap.build.grid((3, 4), periodic=[True, False])).betti == [1, 1, 0]
    assert gmap.build.simplex(3).cell_counts() == [4, 6, 4, 1]
    assert gmap.build.cube(3).cell_counts() == [8, 12, 6, 1]
    assert gmap.homology(gmap.build.surface("a b a^-1 b^-1")).betti == [1, 2, 1]
    assert gmap.homology(gmap.build.surface("a a")).torsion == [[], [2], []]
    assert gmap.homology(gmap.build.solid_torus(4)).betti == [1, 1, 0, 0]
    s = gmap.build.from_facets(TETRA_BOUNDARY)
    assert s.cell_counts() == [4, 6, 4]
    h = gmap.homology(s, generators=True)
    assert h.route is None and h.betti == [1, 0, 1]
    # the map of facets names its cells by the facets' labels, as the facet list does
    assert h.generators[1].cells == gmap.homology(TETRA_BOUNDARY, generators=True, method="gmap").generators[1].cells
    assert all(isinstance(c, tuple) for c in h.generators[1].cells)
    # other maps by darts
    assert gmap.homology(gmap.build.cube(2), generators=True).generators[0].cells.dtype == np.uint32


def test_euler_operators_cgal_names():
    m = gmap.build.polygon(4)
    d = m.insert_cell_0_in_cell_1(0)
    assert m.cell_counts() == [5, 5, 1]
    assert m.is_removable(d, 0)
    m.remove_cell(d, 0)
    assert m.cell_counts() == [4, 4, 1]
    e = m.insert_cell_1_in_cell_2(0, int(m.orbit(0, [0, 1])[4]))
    assert m.cell_counts() == [4, 5, 2]
    assert m.is_removable(e, 1)
    m.remove_cell(e, 1)
    assert m.cell_counts() == [4, 4, 1]
    # the face of a 2-map: CGAL's remove_cell<2> takes it with its darts; the
    # homology-keeping removal refuses (a face is not between two cells)
    with pytest.raises(gmap.PreconditionError):
        m.remove_cell_keeping_homology(0, 2)
    assert not m.is_removable_keeping_homology(0, 2) and m.is_removable(0, 2)
    assert m.remove_cell(0, 2) == 8 and len(m) == 0
    h = gmap.GMap(3)
    h.make_combinatorial_hexahedron()
    assert h.cell_counts() == [8, 12, 6, 1]


def test_points_and_labels_round_trip(tmp_path):
    m = gmap.build.polygon(3)
    pts = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    m.points = pts
    assert m.points.shape == (3, 3) and m.points.dtype == np.float64
    m.set_label(2, 0, "name", "triangle")
    m.set_label(0, 0, "weight", 2.5)
    m.set_label(1, 0, "id", 7)
    assert m.labels(2) == [{"name": "triangle"}]
    p = tmp_path / "t.gmap"
    m.save(p)
    back = gmap.open(p)
    assert isinstance(back, gmap.GMap)
    assert (back.alphas == m.alphas).all()
    assert np.array_equal(back.points, m.points)
    assert back.labels(2) == [{"name": "triangle"}]
    assert sorted(map(str, back.labels(0))) == sorted(map(str, m.labels(0)))
    assert sorted(map(str, back.labels(1))) == sorted(map(str, m.labels(1)))
    moka = tmp_path / "t.moka"
    m.save(moka, lossy=True)  # .moka drops the labels: refused without lossy=True
    assert (gmap.open(moka).alphas == m.alphas).all()


def test_incidence_graph():
    nx = pytest.importorskip("networkx")
    g = gmap.build.simplex(2).incidence_graph()
    assert isinstance(g, nx.Graph)
    assert g.number_of_nodes() == 3 + 3 + 1
    assert g.number_of_edges() == 6 + 3


def test_objects_save_and_open(tmp_path):
    sc = gmap.SimplicialComplex(TETRA_BOUNDARY)
    sc.save(tmp_path / "s.facets")
    assert gmap.open(tmp_path / "s.facets").facets == sc.facets
    a = np.zeros((3, 4), dtype=bool)
    a[0, 1] = a[2, 3] = True
    cs = gmap.CubicalSet(a)
    cs.save(tmp_path / "c.cub")
    back = gmap.open(tmp_path / "c.cub")
    assert isinstance(back, gmap.CubicalSet)
    # the file's box is the cubes' bounding box
    assert sorted(map(tuple, np.argwhere(back.array) + back.min)) == sorted(map(tuple, np.argwhere(a)))
    assert gmap.homology(back) == gmap.homology(a)


def test_pickle():
    for x in (gmap.build.lens_space(3, 1), gmap.SimplicialComplex(TETRA_BOUNDARY), gmap.CubicalSet(np.eye(3, dtype=bool))):
        y = pickle.loads(pickle.dumps(x))
        assert gmap.homology(y) == gmap.homology(x)
    h = gmap.homology(TETRA_BOUNDARY, generators=True)
    assert pickle.loads(pickle.dumps(h)).to_dict() == h.to_dict()


def test_parse_error_names_file_and_line(tmp_path):
    p = tmp_path / "bad.gmap"
    p.write_text("this is not a gmap\n")
    with pytest.raises(gmap.ParseError) as e:
        gmap.open(p)
    assert e.value.file == str(p) and e.value.line == 1
    assert isinstance(e.value, gmap.GmapError)


def test_unsupported_and_missing(tmp_path):
    with pytest.raises(gmap.InputError, match="unsupported input format"):
        gmap.open(tmp_path / "x.dot")
    with pytest.raises(OSError):
        gmap.open(tmp_path / "missing.facets")


def test_precondition_error():
    # a ridge in three facets has no G-map (the facade calls it a parse error of the facets)
    with pytest.raises(gmap.GmapError, match="not a pseudo-manifold"):
        gmap.build.from_facets([[0, 1, 2], [0, 1, 3], [0, 1, 4]])
    # but the direct route takes any complex
    assert gmap.homology([[0, 1, 2], [0, 1, 3], [0, 1, 4]]).betti == [1, 0, 0]


def test_bench_rows():
    ring = DATA / "cubical" / "ring.cub"
    rows = gmap.bench([DATA / "lutz" / "poincare.facets", ring])
    poincare = [r for r in rows if r["input"].endswith("poincare.facets")]
    assert {r["route"] for r in poincare} >= {"direct"}
    assert all(r["betti"] == [1, 0, 0, 1] for r in poincare if r["error"] is None)
    # a cubical set of dimension 2: the one-pass route, the slabs and the whole complex
    ring_rows = [r for r in rows if r["input"] == str(ring)]
    assert [r["route"] for r in ring_rows] == ["one-pass", "slabs", "cubical"]
    assert all(r["betti"] == gmap.homology(ring).betti for r in ring_rows)
    assert all(r["times_ms"]["total"] >= 0 and r["agree"] for r in rows)
    # each row's peak memory, where the kernel lets the high-water mark be reset
    assert all("peak_rss_bytes" in r for r in rows)
