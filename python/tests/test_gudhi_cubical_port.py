"""Our port of GUDHI's cubical tests (GUDHI/gudhi-devel, src/python/test/test_cubical_complex.py),
run on gmap.gudhi: each test names the peer test it follows. Where GUDHI's answer is a
cell chosen among cells of equal value (its tie-breaking, which its documentation calls
arbitrary), we assert the values of the cells given, and the cell itself where it is the
only one of its value."""

import numpy as np
import pytest

from gmap.gudhi import CubicalComplex, PeriodicCubicalComplex

INF = float("inf")


def test_empty_constructor():
    # test_cubical_complex.py::test_empty_constructor
    with pytest.raises(ValueError):
        CubicalComplex()


def test_non_existing_perseus_file_constructor():
    # test_cubical_complex.py::test_non_existing_perseus_file_constructor
    with pytest.raises(OSError):
        CubicalComplex(perseus_file="no-such-file-anywhere.txt")


@pytest.fixture
def one_sphere(tmp_path):
    p = tmp_path / "CubicalOneSphere.txt"
    p.write_text("2\n3\n3\n0\n0\n0\n0\n100\n0\n0\n0\n0\n")
    return str(p)


def test_dimensions_one_cells_type_or_perseus_file_constructor(one_sphere):
    # test_cubical_complex.py::test_dimensions_one_cells_type_or_perseus_file_constructor
    nine = list(range(1, 10))
    bad = [
        dict(dimensions=[3, 3], top_dimensional_cells=nine, perseus_file=one_sphere),
        dict(top_dimensional_cells=nine, perseus_file=one_sphere),
        dict(dimensions=[3, 3], perseus_file=one_sphere),
        dict(dimensions=[3, 3], top_dimensional_cells=[1, 2, 3, 4], vertices=nine, perseus_file=one_sphere),
        dict(top_dimensional_cells=[1, 2, 3, 4], vertices=nine, perseus_file=one_sphere),
        dict(dimensions=[3, 3], top_dimensional_cells=[1, 2, 3, 4], vertices=nine),
        dict(top_dimensional_cells=[1, 2, 3, 4], vertices=nine),
        dict(dimensions=[3, 3], vertices=nine, perseus_file=one_sphere),
        dict(vertices=nine, perseus_file=one_sphere),
    ]
    for kw in bad:
        with pytest.raises(ValueError):
            CubicalComplex(**kw)


def check_simple(cub):
    # test_cubical_complex.py::simple_constructor
    assert cub._is_defined()
    assert not cub._is_persistence_defined()
    assert cub.persistence() == [(0, (1.0, INF))]
    assert cub._is_persistence_defined()
    assert cub.betti_numbers() == [1, 0, 0]
    assert cub.persistent_betti_numbers(0, 1000) == [0, 0, 0]


def test_simple_constructor_from_top_cells():
    # test_cubical_complex.py::test_simple_constructor_from_top_cells
    check_simple(CubicalComplex(dimensions=[3, 3], top_dimensional_cells=list(range(1, 10))))


def test_simple_constructor_from_numpy_array():
    # test_cubical_complex.py::test_simple_constructor_from_numpy_array
    check_simple(CubicalComplex(top_dimensional_cells=np.arange(1, 10).reshape(3, 3)))


def test_constructor_from_vertices():
    # test_cubical_complex.py::test_constructor_from_vertices
    check_simple(CubicalComplex(dimensions=[4, 4], vertices=[1, 1, 2, 3, 1, 1, 2, 3, 4, 4, 5, 6, 7, 7, 8, 9]))
    a = np.random.default_rng(0).random((10, 20, 30))
    cub = PeriodicCubicalComplex(vertices=a, periodic_dimensions=(True, False, True))
    assert np.array_equal(a, cub.vertices())


def check_user_case(cub):
    # test_cubical_complex.py::user_case_simple_constructor
    assert cub.persistence() == [(1, (0.0, 1.0)), (0, (0.0, INF))]
    other = CubicalComplex(dimensions=[3, 3], top_dimensional_cells=[1000.0, 0, 0, 0, 1, 0, 0, 0, 0])
    assert other.persistence() == [(1, (0.0, 1.0)), (0, (0.0, INF))]


def test_user_case_simple_constructor_from_top_cells():
    # test_cubical_complex.py::test_user_case_simple_constructor_from_top_cells
    check_user_case(CubicalComplex(dimensions=[3, 3], top_dimensional_cells=[INF, 0, 0, 0, 1, 0, 0, 0, 0]))


def test_user_case_simple_constructor_from_numpy_array():
    # test_cubical_complex.py::test_user_case_simple_constructor_from_numpy_array
    check_user_case(CubicalComplex(top_dimensional_cells=np.array([[INF, 0, 0], [0, 1, 0], [0, 0, 0]])))


def test_dimension_file_constructor(one_sphere):
    # test_cubical_complex.py::test_dimension_file_constructor
    cub = CubicalComplex(perseus_file=one_sphere)
    assert not cub._is_persistence_defined()
    assert cub.persistence() == [(1, (0.0, 100.0)), (0, (0.0, INF))]
    assert cub.betti_numbers() == [1, 0, 0]
    assert cub.persistent_betti_numbers(0, 1000) == [1, 0, 0]


def test_connected_sublevel_sets():
    # test_cubical_complex.py::test_connected_sublevel_sets
    array_cells = np.array([[3, 3], [2, 2], [4, 4]])
    linear = [3, 3, 2, 2, 4, 4]
    for cub in (
        CubicalComplex(top_dimensional_cells=array_cells),
        CubicalComplex(dimensions=[2, 3], top_dimensional_cells=linear),
        PeriodicCubicalComplex(top_dimensional_cells=array_cells, periodic_dimensions=[False, False]),
        PeriodicCubicalComplex(dimensions=[2, 3], top_dimensional_cells=linear, periodic_dimensions=[False, False]),
    ):
        assert cub.persistence() == [(0, (2.0, INF))]
        assert cub.betti_numbers() == [1, 0, 0]


def values_at(array, flat):
    return [float(x) for x in np.ravel(array, order="F")[np.asarray(flat, dtype=int).ravel()]]


def test_cubical_generators_from_top_dimensional_cells():
    # test_cubical_complex.py::test_cubical_generators_from_top_dimensional_cells
    top = [[0, 0, 0], [0, 1, 0], [0, 0, 0]]
    cub = CubicalComplex(top_dimensional_cells=top)
    cub.persistence()
    g = cub.cofaces_of_persistence_pairs()
    assert len(g[0]) == 2 and len(g[1]) == 1
    assert np.array_equal(g[0][0], np.empty(shape=[0, 2]))
    # GUDHI: [[7, 4]]; 4 is the only cell of value 1, any cell of value 0 gives the birth
    assert g[0][1].shape == (1, 2) and g[0][1][0, 1] == 4 and values_at(top, g[0][1][:, 0]) == [0.0]
    # GUDHI: [8], a cell of value 0
    assert g[1][0].shape == (1,) and values_at(top, g[1][0]) == [0.0]


def test_cubical_generators_from_vertices():
    # test_cubical_complex.py::test_cubical_generators_from_vertices
    v = [[0, 0, 0, 0], [0, 1, 1, 0], [0, 1, 1, 0], [0, 0, 0, 0]]
    cub = CubicalComplex(vertices=v)
    cub.persistence()
    g = cub.vertices_of_persistence_pairs()
    assert len(g[0]) == 2 and len(g[1]) == 1
    assert np.array_equal(g[0][0], np.empty(shape=[0, 2]))
    # GUDHI: [[14, 10]] (a vertex of value 0, one of value 1) and [14]
    assert g[0][1].shape == (1, 2) and values_at(v, g[0][1][0]) == [0.0, 1.0]
    assert g[1][0].shape == (1,) and values_at(v, g[1][0]) == [0.0]

    v = [[2, 1, 6, 8], [5, 9, 4, 7], [4, 7, 3, 9]]
    cub = CubicalComplex(vertices=v)
    assert set(cub.persistence()) == {(1, (7.0, 9.0)), (0, (1.0, INF)), (0, (3.0, 6.0)), (0, (4.0, 5.0))}
    g = cub.vertices_of_persistence_pairs()
    assert [a.tolist() for a in g[1]] == [[3]]
    assert len(g[0]) == 2
    assert sorted(map(tuple, g[0][0].tolist())) == [(2, 1), (8, 6)]
    # GUDHI: [[5, 4]]: a vertex of value 7 and one of value 9
    assert g[0][1].shape == (1, 2) and values_at(v, g[0][1][0]) == [7.0, 9.0]


def test_periodic_cubical_generators_from_vertices():
    # test_cubical_complex.py::test_periodic_cubical_generators_from_vertices
    v = [[0, 0, 0, 0], [0, 1, 1, 0], [0, 1, 1, 0], [0, 0, 0, 0]]
    cub = PeriodicCubicalComplex(vertices=v, periodic_dimensions=[False, False])
    cub.persistence()
    g = cub.vertices_of_persistence_pairs()
    assert len(g[0]) == 2 and len(g[1]) == 1
    assert np.array_equal(g[0][0], np.empty(shape=[0, 2]))
    assert values_at(v, g[0][1][0]) == [0.0, 1.0]  # GUDHI: [[15, 10]]
    assert values_at(v, g[1][0]) == [0.0]  # GUDHI: [0]

    v = np.array([[2, 1, 6, 8], [5, 8, 4, 0], [4, 7, 3, 9]], dtype=float)
    cub = PeriodicCubicalComplex(vertices=v, periodic_dimensions=(True, True))
    assert np.array_equal(
        cub.all_cells(),
        np.array(
            [
                [2, 2, 1, 6, 6, 8, 8, 8],
                [5, 8, 8, 8, 6, 8, 8, 8],
                [5, 8, 8, 8, 4, 4, 0, 5],
                [5, 8, 8, 8, 4, 9, 9, 9],
                [4, 7, 7, 7, 3, 9, 9, 9],
                [4, 7, 7, 7, 6, 9, 9, 9],
            ],
            dtype=float,
        ),
    )
    p = cub.persistence()
    g = cub.vertices_of_persistence_pairs()
    assert set(p) == {
        (2, (9.0, INF)), (1, (5.0, INF)), (1, (6.0, INF)), (1, (6.0, 8.0)),
        (0, (0.0, INF)), (0, (1.0, 5.0)), (0, (3.0, 4.0)),
    }
    vr = np.ravel(v, order="F")
    diag = set()
    for i, a in enumerate(g[0]):
        for b, d in a:
            diag.add((i, (vr[b], vr[d])))
    for i, a in enumerate(g[1]):
        for b in a:
            diag.add((i, (vr[b], INF)))
    assert set(p) == diag


def test_cubical_cofaces_of_persistence_pairs_when_pd_has_no_paired_birth_and_death():
    # test_cubical_complex.py::test_cubical_cofaces_of_persistence_pairs_when_pd_has_no_paired_birth_and_death
    cub = CubicalComplex(dimensions=[1, 2], top_dimensional_cells=[0.0, 1.0])
    cub.persistence(homology_coeff_field=2, min_persistence=0)
    pairs = cub.cofaces_of_persistence_pairs()
    assert pairs[0] == []
    assert np.array_equal(pairs[1][0], np.array([0]))


def test_periodic_cofaces_of_persistence_pairs_when_pd_has_no_paired_birth_and_death():
    # test_cubical_complex.py::test_periodic_cofaces_of_persistence_pairs_when_pd_has_no_paired_birth_and_death
    cub = PeriodicCubicalComplex(dimensions=[1, 2], top_dimensional_cells=[0.0, 1.0], periodic_dimensions=[True, True])
    cub.persistence(homology_coeff_field=2, min_persistence=0)
    pairs = cub.cofaces_of_persistence_pairs()
    assert pairs[0] == []
    assert np.array_equal(pairs[1][0], np.array([0]))
    assert np.array_equal(pairs[1][1], np.array([0, 1]))
    assert np.array_equal(pairs[1][2], np.array([1]))


def test_cubical_persistence_intervals_in_dimension():
    # test_cubical_complex.py::test_cubical_persistence_intervals_in_dimension
    cub = CubicalComplex(dimensions=[3, 3], top_dimensional_cells=list(range(1, 10)))
    cub.compute_persistence()
    assert np.array_equal(cub.persistence_intervals_in_dimension(0), np.array([[1.0, INF]]))
    assert cub.persistence_intervals_in_dimension(1).shape == (0, 2)


def test_periodic_cubical_persistence_intervals_in_dimension():
    # test_cubical_complex.py::test_periodic_cubical_persistence_intervals_in_dimension
    cub = PeriodicCubicalComplex(dimensions=[3, 3], top_dimensional_cells=list(range(1, 10)), periodic_dimensions=[True, True])
    cub.compute_persistence()
    assert np.array_equal(cub.persistence_intervals_in_dimension(0), np.array([[1.0, INF]]))
    assert np.array_equal(cub.persistence_intervals_in_dimension(1), np.array([[3.0, INF], [7.0, INF]]))
    assert np.array_equal(cub.persistence_intervals_in_dimension(2), np.array([[9.0, INF]]))
    assert cub.persistence_intervals_in_dimension(3).shape == (0, 2)


def test_array_access():
    # test_cubical_complex.py::test_array_access
    a = np.arange(6, dtype=float).reshape(3, 2)
    cplx = CubicalComplex(top_dimensional_cells=a)
    assert np.array_equal(cplx.top_dimensional_cells(), a)
    assert np.array_equal(cplx.vertices(), np.array([[0, 0, 1], [0, 0, 1], [2, 2, 3], [4, 4, 5]], dtype=float))
    assert np.array_equal(
        cplx.all_cells(),
        np.array([[0, 0, 0, 1, 1]] * 3 + [[2, 2, 2, 3, 3]] * 2 + [[4, 4, 4, 5, 5]] * 2, dtype=float),
    )
    cplx.top_dimensional_cells()[0, 0] = 42
    assert cplx.all_cells()[1, 1] == 42

    a = np.array([[1.0, 2.0], [4.0, 3.0], [0.0, 5.0]])
    cplx = PeriodicCubicalComplex(top_dimensional_cells=a, periodic_dimensions=(True, False))
    assert np.array_equal(cplx.top_dimensional_cells(), a)
    assert np.array_equal(cplx.vertices(), np.array([[0, 0, 2], [1, 1, 2], [0, 0, 3]], dtype=float))
    assert np.array_equal(
        cplx.all_cells(),
        np.array(
            [[0, 0, 0, 2, 2], [1, 1, 1, 2, 2], [1, 1, 1, 2, 2], [4, 4, 3, 3, 3], [0, 0, 0, 3, 3], [0, 0, 0, 5, 5]],
            dtype=float,
        ),
    )


def test_mixed_periodicity_as_gudhi():
    # not in GUDHI's tests: a box wrapping along some axes only, against GUDHI when installed
    gudhi = pytest.importorskip("gudhi")
    rng = np.random.default_rng(7)
    for shape, flags in (((4, 5), (True, False)), ((3, 4, 5), (False, True, False)), ((6, 3), (False, True))):
        a = rng.integers(0, 6, size=shape).astype(float)
        ours = PeriodicCubicalComplex(top_dimensional_cells=a, periodic_dimensions=flags).persistence()
        theirs = gudhi.PeriodicCubicalComplex(top_dimensional_cells=a, periodic_dimensions=flags).persistence()
        assert sorted(ours) == sorted(theirs), (shape, flags)
        ours = PeriodicCubicalComplex(vertices=a, periodic_dimensions=flags).persistence()
        theirs = gudhi.PeriodicCubicalComplex(vertices=a, periodic_dimensions=flags).persistence()
        assert sorted(ours) == sorted(theirs), (shape, flags, "vertices")
