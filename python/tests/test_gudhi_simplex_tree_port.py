"""Our port of GUDHI's SimplexTree tests (GUDHI/gudhi-devel, src/python/test/test_simplex_tree.py)
and of its lower-star use, run on gmap.gudhi: each test names the peer test it follows."""

import numpy as np
import pytest

import gmap
from gmap.gudhi import SimplexTree

INF = float("inf")


def test_insertion():
    # test_simplex_tree.py::test_insertion
    st = SimplexTree()
    assert st._is_defined() and not st._is_persistence_defined()
    assert st.insert([0, 1])
    assert st.dimension() == 1
    assert st.insert([0, 1, 2], filtration=4.0)
    assert st.dimension() == 2
    assert st.num_simplices() == 7 and st.num_vertices() == 3
    for s in ([0, 1, 2], [0, 1], [0, 2], [0], [1], [2]):
        assert st.find(s)
    for s in ([3], [0, 3], [1, 3], [2, 3]):
        assert not st.find(s)
    assert [st.filtration(s) for s in ([0, 1, 2], [0, 2], [1, 2], [2], [0, 1], [0], [1])] == [4, 4, 4, 4, 0, 0, 0]
    assert list(st.get_skeleton(2)) == [
        ([0, 1, 2], 4.0), ([0, 1], 0.0), ([0, 2], 4.0), ([0], 0.0), ([1, 2], 4.0), ([1], 0.0), ([2], 4.0),
    ]
    assert list(st.get_skeleton(1)) == [([0, 1], 0.0), ([0, 2], 4.0), ([0], 0.0), ([1, 2], 4.0), ([1], 0.0), ([2], 4.0)]
    assert list(st.get_skeleton(0)) == [([0], 0.0), ([1], 0.0), ([2], 4.0)]
    assert st.get_cofaces([0, 1, 2], 1) == []
    st.remove_maximal_simplex([0, 1, 2])
    assert not st.find([0, 1, 2]) and st.find([0, 1]) and st.find([2])
    assert st.persistence(persistence_dim_max=True) == [(1, (4.0, INF)), (0, (0.0, INF))]
    assert st._is_persistence_defined()
    assert st.betti_numbers() == [1, 1]
    assert st.persistent_betti_numbers(-0.1, 10000.0) == [0, 0]
    assert st.persistent_betti_numbers(0.0, 10000.0) == [1, 0]
    assert st.persistent_betti_numbers(3.9, 10000.0) == [1, 0]
    assert st.persistent_betti_numbers(4.0, 10000.0) == [1, 1]
    assert st.persistent_betti_numbers(9999.0, 10000.0) == [1, 1]


EDGES = [([3, 2], 0.1), ([2, 0], 0.2), ([1, 0], 0.3), ([3, 1], 0.4), ([2, 1], 0.5),
         ([6, 5], 0.6), ([4, 2], 0.7), ([3, 0], 0.8), ([6, 4], 0.9), ([6, 3], 1.0)]


def test_expansion():
    # test_simplex_tree.py::test_expansion
    st = SimplexTree()
    for e, f in EDGES:
        assert st.insert(e, f)
    assert st.num_vertices() == 7 and st.num_simplices() == 17
    assert [s for s, _ in st.get_filtration()][:6] == [[2], [3], [2, 3], [0], [0, 2], [1]]
    st.expansion(3)
    assert st.num_vertices() == 7 and st.num_simplices() == 22
    assert list(st.get_filtration()) == [
        ([2], 0.1), ([3], 0.1), ([2, 3], 0.1), ([0], 0.2), ([0, 2], 0.2), ([1], 0.3), ([0, 1], 0.3),
        ([1, 3], 0.4), ([1, 2], 0.5), ([0, 1, 2], 0.5), ([1, 2, 3], 0.5), ([5], 0.6), ([6], 0.6),
        ([5, 6], 0.6), ([4], 0.7), ([2, 4], 0.7), ([0, 3], 0.8), ([0, 1, 3], 0.8), ([0, 2, 3], 0.8),
        ([0, 1, 2, 3], 0.8), ([4, 6], 0.9), ([3, 6], 1.0),
    ]


def test_automatic_dimension():
    # test_simplex_tree.py::test_automatic_dimension
    st = SimplexTree()
    assert st.insert([0, 1, 3], filtration=0.5)
    assert st.insert([0, 1, 2], filtration=1.0)
    assert st.num_vertices() == 4 and st.num_simplices() == 11
    assert st.dimension() == 2 and st.upper_bound_dimension() == 2
    assert st.prune_above_filtration(0.6)
    assert st.dimension() == 2
    st.assign_filtration([0, 1, 3], 0.7)
    assert st.filtration([0, 1, 3]) == 0.7
    st.remove_maximal_simplex([0, 1, 3])
    assert st.dimension() == 1 and st.upper_bound_dimension() == 1


def test_make_filtration_non_decreasing():
    # test_simplex_tree.py::test_make_filtration_non_decreasing
    st = SimplexTree()
    assert st.insert([2, 1, 0], filtration=2.0)
    assert st.insert([3, 0], filtration=2.0)
    assert st.insert([3, 4, 5], filtration=2.0)
    assert not st.make_filtration_non_decreasing()
    st.insert([0, 1, 6, 7], filtration=1.0)
    assert not st.make_filtration_non_decreasing()
    st.assign_filtration([0, 1, 6, 7], 0.8)
    st.assign_filtration([0, 1, 6], 0.9)
    st.assign_filtration([0, 6], 0.6)
    st.assign_filtration([3, 4, 5], 1.2)
    st.assign_filtration([3, 4], 1.1)
    st.assign_filtration([4, 5], 1.99)
    assert st.make_filtration_non_decreasing()
    for s, f in (([0, 1, 6, 7], 1.0), ([0, 1, 6], 1.0), ([0, 1], 1.0), ([0], 1.0), ([1], 1.0),
                 ([3, 4, 5], 2.0), ([3, 4], 2.0), ([4, 5], 2.0)):
        assert st.filtration(s) == f


def test_simplices_iterator():
    # test_simplex_tree.py::test_simplices_iterator
    st = SimplexTree()
    assert st.insert([0, 1, 2], filtration=4.0)
    assert st.insert([2, 3, 4], filtration=2.0)
    for s, f in st.get_simplices():
        assert st.find(s) and st.filtration(s) == f
    assert st.num_simplices() == 13


def test_reset_filtration():
    # test_simplex_tree.py::test_reset_filtration
    st = SimplexTree()
    assert st.insert([0, 1, 2], 3.0)
    assert st.insert([0, 3], 2.0)
    assert st.insert([3, 4, 5], 3.0)
    assert st.insert([0, 1, 6, 7], 4.0)
    for dimension in range(5, -1, -1):
        st.reset_filtration(0.0, dimension)
        for s, _ in st.get_skeleton(3):
            if len(s) < dimension + 1:
                assert st.filtration(s) >= 2.0
            else:
                assert st.filtration(s) == 0.0


def test_boundaries_iterator():
    # test_simplex_tree.py::test_boundaries_iterator
    st = SimplexTree()
    assert st.insert([0, 1, 2, 3], filtration=1.0)
    assert st.insert([1, 2, 3, 4], filtration=2.0)
    assert sorted(st.get_boundaries([1, 2, 3])) == [([1, 2], 1.0), ([1, 3], 1.0), ([2, 3], 1.0)]
    assert sorted(st.get_boundaries([2, 3, 4])) == [([2, 3], 1.0), ([2, 4], 2.0), ([3, 4], 2.0)]
    assert list(st.get_boundaries([2])) == []
    for bad in ([], [0, 4], [6]):
        with pytest.raises(RuntimeError):
            list(st.get_boundaries(bad))


def test_equality_operator():
    # test_simplex_tree.py::test_equality_operator
    st1, st2 = SimplexTree(), SimplexTree()
    assert st1 == st2
    st1.insert([1, 2, 3], 4.0)
    assert st1 != st2
    st2.insert([1, 2, 3], 4.0)
    assert st1 == st2


def test_insert_batch_keeps_the_smallest_value():
    # test_simplex_tree.py::test_insert_batch (GUDHI >= 3.5): a simplex given twice keeps its smallest value
    st = SimplexTree()
    st.insert_batch(np.array([[6, 1, 5], [7, 5, 6]]), np.array([4.0, 2.0, 3.0]))
    assert st.num_simplices() == 7  # the vertices 1, 5, 6, 7 and three edges
    assert st.filtration([5]) == 2.0 and st.filtration([6]) == 3.0 and st.filtration([5, 6]) == 3.0
    st.insert_batch(np.array([[5], [6]]), np.array([1.0]))
    assert st.filtration([5, 6]) == 1.0 and st.filtration([5]) == 1.0
    st.insert_batch(np.array([[5, 5], [6, 6]]), np.array([9.0, 0.5]))
    assert st.filtration([5, 6]) == 0.5


def test_persistence_pairs_and_cycles():
    # test_simplex_tree.py::test_persistence_pairs (our wording): the simplices of a hollow triangle's pairs
    st = SimplexTree()
    st.insert([0, 1], 1.0)
    st.insert([1, 2], 2.0)
    st.insert([0, 2], 3.0)
    st.insert([0], 0.0)
    st.insert([1], 0.5)
    st.insert([2], 0.7)
    st.persistence(persistence_dim_max=True)
    pairs = sorted(st.persistence_pairs())
    assert pairs == [([0], []), ([0, 2], []), ([1], [0, 1]), ([2], [1, 2])]
    cycles = st.cycles_of_persistence_pairs()
    (one,) = [c for c in cycles if c[0][0] == 1]
    assert one[0] == (1, (3.0, INF)) and sorted(one[1]) == [[0, 1], [0, 2], [1, 2]]


def test_lower_star_as_gudhi_users_write_it():
    # GUDHI's lower-star recipe (the tutorials' "lower star filtration" of a function on vertices):
    # insert the complex, assign each vertex its value, make the filtration non-decreasing
    st = SimplexTree()
    for t in ([0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]):
        st.insert(t)
    height = {0: 5.0, 1: 1.0, 2: 2.0, 3: 3.0, 4: 4.0}
    for v, h in height.items():
        st.assign_filtration([v], h)
    st.make_filtration_non_decreasing()
    assert st.persistence() == [(1, (4.0, 5.0)), (0, (1.0, INF))]
    # the same as gmap's own lower-star call
    faces = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    ours = gmap.persistence(faces, vertex_values=height, field=11)
    assert sorted(map(tuple, ours.tolist())) == [(0.0, 1.0, INF), (1.0, 4.0, 5.0)]


def test_integer_homology_with_torsion():
    # not in GUDHI: the homology over Z of a SimplexTree (the projective plane's Z/2 torsion)
    rp2 = [[1, 2, 3], [1, 2, 4], [1, 3, 5], [1, 4, 6], [1, 5, 6], [2, 3, 6], [2, 4, 5], [2, 5, 6], [3, 4, 5], [3, 4, 6]]
    st = SimplexTree()
    for t in rp2:
        st.insert(t)
    h = st.integer_homology()
    assert h.betti[:2] == [1, 0]
    assert list(h.torsion[1]) == [2]


def test_expansion_to_a_huge_dimension_ends_at_once():
    # a hostile max_dim (issue 47's hostile run): the flag complex of a triangle and a
    # pendant edge has dimension 2 whatever the bound
    st = SimplexTree()
    for s in ([0, 1], [1, 2], [0, 2], [2, 3]):
        st.insert(s)
    st.expansion(2**63)
    assert st.dimension() == 2
    assert st.num_simplices() == 9
