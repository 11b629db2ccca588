"""Our port of GUDHI's scikit-learn wrapper tests (GUDHI/gudhi-devel,
src/python/test/test_sklearn_cubical_persistence.py) and low-dimension cubical tests
(src/python/test/test_cubical_persistence_low_dim.py), on gmap.gudhi."""

import numpy as np
import pytest

import gmap.gudhi as gg
from gmap.gudhi.sklearn import CubicalPersistence

INF = np.inf


def digits():
    datasets = pytest.importorskip("sklearn.datasets")
    return datasets.load_digits().images[:10]


def rows(a):
    return sorted(map(tuple, np.asarray(a).tolist()))


def test_simple_constructor_from_top_cells_list():
    # test_sklearn_cubical_persistence.py::test_simple_constructor_from_top_cells_list (the first)
    d = digits()
    diags = CubicalPersistence(homology_dimensions=0, n_jobs=-2).fit_transform(d)
    assert len(diags) == 10
    np.testing.assert_array_equal(diags[0], np.array([[0.0, 6.0], [0.0, 8.0], [0.0, INF]]))
    both = CubicalPersistence(homology_dimensions=[0, 1], n_jobs=-1).fit_transform(d)
    assert len(both) == 10
    for i in range(10):
        np.testing.assert_array_equal(diags[i], both[i][0])


def test_simple_constructor_from_vertices():
    # test_sklearn_cubical_persistence.py::test_simple_constructor_from_top_cells_list (the second,
    # input_type="vertices"; GUDHI's rows in its own order, compared here as a set of rows)
    diags = CubicalPersistence(homology_dimensions=0, input_type="vertices", n_jobs=-2).fit_transform(digits())
    assert len(diags) == 10
    assert rows(diags[2]) == rows([[8, 13], [0, 15], [0, INF]])


def test_1d():
    # test_sklearn_cubical_persistence.py::test_1d
    a = np.array([2, 4, 3, 5])
    r = np.array([[3, 4], [2, INF]])
    ri = CubicalPersistence(0).fit_transform([a])[0]
    rf = CubicalPersistence(0).fit_transform([a.astype("float32")[::-1]])[0]
    rd = CubicalPersistence([0]).fit_transform([a.astype("float64")])[0][0]
    assert ri.dtype == np.float64 and rf.dtype == np.float32 and rd.dtype == np.float64
    for x in (ri, rf, rd):
        assert rows(x) == rows(r)


@pytest.mark.parametrize(
    "shape_or_view",
    ["20,15,10", "20,10", "20,2", "2,20", "20,1", "1,20", "20", "F", "head", "strided"],
)
def test_compare_top_cells(shape_or_view):
    # test_sklearn_cubical_persistence.py::test_compare_top_cells (against GUDHI itself when installed)
    gudhi = pytest.importorskip("gudhi")
    rng = np.random.default_rng(3)
    a = rng.random((20, 10))
    a = {"F": np.array(a, order="F"), "head": a[0:18], "strided": a[::2, ::-1]}.get(shape_or_view)
    if a is None:
        a = rng.random(tuple(int(s) for s in shape_or_view.split(",")))
    dims = list(range(a.ndim))
    ours = CubicalPersistence(homology_dimensions=dims).fit_transform([a])[0]
    p = gudhi.CubicalComplex(top_dimensional_cells=a).persistence()
    assert sum(len(d) for d in ours) == len(p)
    theirs = [sorted(i for dim, i in p if dim == k) for k in dims]
    assert [rows(d) for d in ours] == theirs


def test_filtration_types():
    # test_sklearn_cubical_persistence.py::test_filtration_types
    for t in (np.float32, np.float64):
        for a in ([2.0, 4.0, 3.0, 5.0], [[1, 2, 3], [2, 4, 1], [3, 2, 1]], [[1, 8, 7], [4, 20, 6], [6, 4, 5]]):
            r = CubicalPersistence(0).fit_transform([np.array(a, dtype=t)])[0]
            assert r.dtype == t


def test_basic_persistence_on_a_line():
    # test_cubical_persistence_low_dim.py::test_basic_persistence_on_a_line: the bars of a line,
    # by the elder rule on the local minima
    data = np.array([0.0, 1.5, 0.7, 2.8, 3.1, -1.0, 2.0])
    cc = gg.CubicalComplex(top_dimensional_cells=data)
    cc.compute_persistence()
    assert rows(cc.persistence_intervals_in_dimension(0)) == [(-1.0, INF), (0.0, 3.1), (0.7, 1.5)]


def test_basic_persistence_on_rectangle_from_top_cells():
    # test_cubical_persistence_low_dim.py::test_basic_persistence_on_rectangle_from_top_cells
    # (digit 0 of sklearn's load_digits): its ring is one H1 bar, against GUDHI when installed
    img = np.array(
        [
            [0, 0, 5, 13, 9, 1, 0, 0], [0, 0, 13, 15, 10, 15, 5, 0], [0, 3, 15, 2, 0, 11, 8, 0],
            [0, 4, 12, 0, 0, 8, 8, 0], [0, 5, 8, 0, 0, 9, 8, 0], [0, 4, 11, 0, 1, 12, 7, 0],
            [0, 2, 14, 5, 10, 12, 0, 0], [0, 0, 6, 13, 10, 0, 0, 0],
        ],
        dtype=float,
    )
    cc = gg.CubicalComplex(top_dimensional_cells=-img)
    cc.compute_persistence()
    assert rows(cc.persistence_intervals_in_dimension(1)) == [(-8.0, 0.0)]
    gudhi = pytest.importorskip("gudhi")
    theirs = gudhi.CubicalComplex(top_dimensional_cells=img)
    theirs.compute_persistence()
    ours = gg.CubicalComplex(top_dimensional_cells=img)
    ours.compute_persistence()
    for k in (0, 1):
        assert rows(ours.persistence_intervals_in_dimension(k)) == rows(theirs.persistence_intervals_in_dimension(k))
