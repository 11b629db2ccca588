"""Values given per facet, per vertex and per simplex on lists of facets of mixed sizes,
against GUDHI's SimplexTree (issue 46: values followed the facets' reordering)."""

import itertools

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import gmap

gudhi = pytest.importorskip("gudhi")


def triples(pairs):
    return sorted((int(d), float(b), float(e)) for d, b, e in np.asarray(pairs).tolist())


def gudhi_triples(tree, field=2):
    tree.compute_persistence(homology_coeff_field=field, persistence_dim_max=True)
    return sorted((d, float(b), float(e)) for d, (b, e) in tree.persistence(homology_coeff_field=field, persistence_dim_max=True))


facet_lists = st.lists(
    st.frozensets(st.integers(0, 6), min_size=1, max_size=4), min_size=1, max_size=7, unique=True
).map(lambda fs: [sorted(f) for f in fs])


def test_the_smallest_case_of_the_issue():
    # [[0, 1], [2, 4], [0, 2, 3]] with [0, 0, 1]: two components at 0, joined at 1
    got = triples(gmap.persistence([[0, 1], [2, 4], [0, 2, 3]], facet_values=[0, 0, 1]))
    assert got == [(0, 0.0, 1.0), (0, 0.0, float("inf"))]


@settings(max_examples=200, deadline=None)
@given(facet_lists, st.data())
def test_values_per_facet_as_gudhi(facets, data):
    values = data.draw(st.lists(st.integers(0, 4), min_size=len(facets), max_size=len(facets)))
    tree = gudhi.SimplexTree()
    for f, v in zip(facets, values):
        tree.insert(f, float(v))
    assert triples(gmap.persistence(facets, facet_values=values)) == gudhi_triples(tree)
    # the same through a tuple of tuples
    assert triples(gmap.persistence(tuple(map(tuple, facets)), facet_values=values)) == gudhi_triples(tree)


@settings(max_examples=100, deadline=None)
@given(facet_lists, st.data())
def test_values_per_vertex_as_gudhi(facets, data):
    labels = sorted({v for f in facets for v in f})
    vals = data.draw(st.lists(st.integers(0, 4), min_size=len(labels), max_size=len(labels)))
    by_label = dict(zip(labels, map(float, vals)))
    tree = gudhi.SimplexTree()
    for f in facets:
        tree.insert(f)
    for s, _ in list(tree.get_simplices()):
        tree.assign_filtration(s, max(by_label[v] for v in s))
    assert triples(gmap.persistence(facets, vertex_values=by_label)) == gudhi_triples(tree)


@settings(max_examples=100, deadline=None)
@given(facet_lists, st.data())
def test_values_per_simplex_as_gudhi(facets, data):
    # every simplex listed with a value of its own, in a drawn order
    simplices = sorted({tuple(c) for f in facets for k in range(1, len(f) + 1) for c in itertools.combinations(f, k)})
    simplices = data.draw(st.permutations(simplices))
    values = data.draw(st.lists(st.integers(0, 5), min_size=len(simplices), max_size=len(simplices)))
    tree = gudhi.SimplexTree()
    for s, v in zip(simplices, values):
        tree.insert(list(s), float(v))
    got = gmap.persistence([list(s) for s in simplices], facet_values=values, field=3)
    assert triples(got) == gudhi_triples(tree, field=3)
