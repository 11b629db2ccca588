"""What gmap.gudhi adds to GUDHI or reads as GUDHI does: cycles in GUDHI's flat indexing,
Perseus files, lower-star generators, and the native API's list and mask rule."""

from pathlib import Path

import numpy as np
import pytest

import gmap
import gmap.gudhi as gg

DATA = Path(__file__).resolve().parents[2] / "tests" / "data" / "persistence"
INF = float("inf")


def dim_of(index, shape):
    """The dimension of the cell of flat (Fortran-order) index ``index`` in all_cells()."""
    return sum(int(c) % 2 for c in np.unravel_index(index, shape, order="F"))


@pytest.mark.parametrize("flags", [(False, False), (True, True), (True, False)])
def test_cycles_are_cells_of_their_dimension_born_at_their_birth(flags):
    a = np.random.default_rng(5).integers(0, 8, size=(5, 6)).astype(float)
    cc = gg.PeriodicCubicalComplex(top_dimensional_cells=a, periodic_dimensions=flags)
    p = cc.persistence(homology_coeff_field=3)
    cycles = cc.cycles_of_persistence_pairs()
    assert sorted(c[0] for c in cycles) == sorted(p)
    cells = cc.all_cells()
    flat = np.ravel(cells, order="F")
    for (dim, (birth, _)), idx, coef in cycles:
        assert len(idx) > 0 and all(dim_of(i, cells.shape) == dim for i in idx)
        assert flat[idx].max() == birth
        assert coef.min() >= 1 and coef.max() <= 2


def test_perseus_files_as_gudhi_reads_them():
    # a periodic file: its axes wrap in PeriodicCubicalComplex, as GUDHI's reader makes them
    torus = str(DATA / "torus.txt")
    cc = gg.PeriodicCubicalComplex(perseus_file=torus)
    assert cc.top_dimensional_cells().tolist() == [[0.0, 2.0], [1.0, 3.0]]
    assert sorted(cc.persistence()) == [(0, (0.0, INF)), (1, (1.0, INF)), (1, (2.0, INF)), (2, (3.0, INF))]
    gudhi = pytest.importorskip("gudhi")
    # GUDHI 3.13's PeriodicCubicalComplex(perseus_file=...) crashes the interpreter (a segmentation
    # fault): its side is the same torus from its array
    theirs = gudhi.PeriodicCubicalComplex(top_dimensional_cells=np.array([[0.0, 2.0], [1.0, 3.0]]), periodic_dimensions=[True, True])
    assert sorted(cc.persistence()) == sorted(theirs.persistence())
    # (GUDHI 3.13 does not return on a Perseus file that begins with a comment line: its side
    # of one_sphere.txt is test_dimension_file_constructor's expectation, in the cubical port)


def test_perseus_files_through_the_native_api():
    assert gmap.persistence(str(DATA / "one_sphere.txt")).tolist() == [[0, 0, INF], [1, 0, 100]]
    assert gmap.persistence(str(DATA / "hollow_triangle.txt")).tolist() == [[0, 0, 1], [0, 0, 2], [0, 0, INF], [1, 3.5, INF]]
    with pytest.raises(gmap.GmapError, match="periodic axes"):
        gmap.open(str(DATA / "torus.txt"))
    img = gmap.open(str(DATA / "one_sphere.txt"))
    assert isinstance(img, gmap.Image)


def test_lower_star_generators():
    # GUDHI src/python/test/test_simplex_generators.py::test_lower_star_generators, without the
    # bars of length zero (its min_persistence=-1: gmap makes none)
    st = gg.SimplexTree()
    st.insert([0, 1, 2], -10)
    st.insert([0, 3], -10)
    st.insert([1, 3], -10)
    for v, f in ((2, -1), (3, 0), (0, 1), (1, 2)):
        st.assign_filtration([v], f)
    st.make_filtration_non_decreasing()
    st.persistence()
    g = st.lower_star_persistence_generators()
    assert len(g[0]) == 1 and np.array_equal(g[0][0], [[3, 0]])
    assert len(g[1]) == 2 and np.array_equal(g[1][0], [2]) and np.array_equal(g[1][1], [1])


def test_empty():
    # test_simplex_generators.py::test_empty (the lower-star half)
    st = gg.SimplexTree()
    st.persistence()
    assert st.lower_star_persistence_generators() == ([], [])


def test_one_rule_for_masks_and_lists():
    mask = np.zeros((6, 6), dtype=bool)
    mask[1:5, 1:5] = True
    mask[2:4, 2:4] = False  # a ring
    d = gmap.persistence(mask)
    assert np.array_equal(d, gmap.persistence(gmap.CubicalSet(mask)))
    assert gmap.homology(mask).betti[:2] == [1, 1]
    assert [r for r in d.tolist() if r[0] == 1] == [[1.0, 0.0, 1.0]]  # the ring is there at 0
    # a nested list of numbers is an image, as its array is
    assert np.array_equal(gmap.persistence([[1.0, 0.0], [2.0, 3.0]]), gmap.persistence(np.array([[1.0, 0.0], [2.0, 3.0]])))
    assert gmap.persistence([[1, 2, 3], [4, 5, 6]]).tolist() == [[0.0, 1.0, INF]]


def test_float32_pairs_and_min_persistence():
    a = np.random.default_rng(2).random((8, 9)).astype(np.float32)
    d32 = gmap.persistence(a)
    assert d32.dtype == np.float32
    assert np.array_equal(d32, gmap.persistence(a.astype(np.float64)).astype(np.float32))
    d = gmap.persistence(a.astype(np.float64), min_persistence=0.2)
    full = gmap.persistence(a.astype(np.float64))
    assert d.tolist() == [r for r in full.tolist() if r[2] - r[1] > 0.2]
    assert gmap.persistence(a, construction="top_dimensional_cells").tolist() == d32.tolist()
