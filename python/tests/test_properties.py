"""Properties over random inputs (hypothesis): the same groups through every door,
round trips of maps through numpy and files, and errors rather than crashes on hostile
input."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import gmap

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])


@st.composite
def facet_lists(draw):
    """Random simplicial complexes: up to 12 facets of 1 to 4 distinct labels out of a few
    (labels spread over a wide range)."""
    n = draw(st.integers(4, 9))
    scale = draw(st.sampled_from([1, 1000, 2**40]))
    facets = draw(
        st.lists(
            st.lists(st.integers(0, n - 1), min_size=1, max_size=4, unique=True),
            min_size=1,
            max_size=12,
            unique_by=frozenset,
        )
    )
    return [[v * scale for v in f] for f in facets]


@SETTINGS
@given(facet_lists())
def test_same_groups_through_path_list_and_array(tmp_path, facets):
    h = gmap.homology(facets)
    # Euler–Poincaré on the faces
    faces = {frozenset(s) for f in facets for k in range(1, len(f) + 1) for s in _subsets(f, k)}
    chi = sum((-1) ** (len(s) - 1) for s in faces)
    assert h.euler_characteristic == chi
    p = tmp_path / "x.facets"
    p.write_text("".join(" ".join(map(str, f)) + "\n" for f in facets))
    assert gmap.homology(str(p)) == h
    assert gmap.homology(gmap.SimplicialComplex(facets)) == h
    widths = {len(f) for f in facets}
    if len(widths) == 1:  # a rectangular array: one facet a row
        assert gmap.homology(np.array(facets, dtype=np.int64)) == h
        assert gmap.homology(np.array(facets, dtype=np.uint64)) == h
    if all(f == sorted(f) for f in facets):
        assert gmap.homology(tuple(tuple(f) for f in facets)) == h


def _subsets(f, k):
    import itertools

    return itertools.combinations(f, k)


@SETTINGS
@given(facet_lists(), st.sampled_from([2, 3, 5]))
def test_field_betti_bounds(facets, p):
    hz = gmap.homology(facets)
    hp = gmap.homology(facets, field=p)
    # universal coefficients: b_k(Z/p) = b_k + #(p | t in T_k) + #(p | t in T_{k-1})
    for k in range(len(hz.betti)):
        div = sum(1 for t in hz.torsion[k] if t % p == 0)
        below = sum(1 for t in hz.torsion[k - 1] if t % p == 0) if k else 0
        assert hp.betti[k] == hz.betti[k] + div + below


@SETTINGS
@given(arrays(np.bool_, st.tuples(st.integers(1, 6), st.integers(1, 6), st.integers(1, 4))), st.booleans())
def test_cubical_array_layouts_and_files(tmp_path, a, periodic):
    h = gmap.homology(a, periodic=periodic)
    assert gmap.homology(np.asfortranarray(a), periodic=periodic) == h
    assert gmap.homology(a.astype(np.int32), periodic=periodic) == h
    assert gmap.homology(gmap.CubicalSet(a), periodic=periodic) == h
    if a.any() and not periodic:
        c = gmap.CubicalSet(a)
        p = tmp_path / "a.cub"
        c.save(p)
        assert gmap.homology(str(p)) == h
        # the G-map of the cubes has the same groups, or is refused where cubes meet at a
        # cell without a shared facet there
        try:
            m = c.to_gmap()
        except Exception as e:  # noqa: BLE001 - the refusal's type is the package's error
            assert "share no facet there" in str(e)
        else:
            assert gmap.homology(m) == h


@SETTINGS
@given(st.sampled_from(["grid", "simplex", "cube", "lens", "torus"]), st.integers(1, 4))
def test_gmap_numpy_file_round_trip(tmp_path, kind, k):
    m = {
        "grid": lambda: gmap.build.grid((k, k + 1), periodic=[k % 2 == 0, False]),
        "simplex": lambda: gmap.build.simplex(k),
        "cube": lambda: gmap.build.cube(min(k, 3)),
        "lens": lambda: gmap.build.lens_space(k + 1, 1),
        "torus": lambda: gmap.build.surface("a b a^-1 b^-1"),
    }[kind]()
    a = m.alphas
    back = gmap.GMap.from_alphas(a.astype(np.int64))
    assert np.array_equal(back.alphas, a)
    p = tmp_path / "m.gmap"
    m.save(p)
    f = gmap.open(p)
    assert np.array_equal(f.alphas, a)
    assert f.cell_counts() == m.cell_counts()
    assert gmap.homology(f) == gmap.homology(m)
    assert gmap.GMap.from_text(m.to_text()).cell_counts() == m.cell_counts()
    # Euler–Poincaré on the map
    assert gmap.homology(m).euler_characteristic == m.euler_characteristic()


@SETTINGS
@given(arrays(np.int64, st.tuples(st.integers(1, 4), st.integers(0, 8)), elements=st.integers(-3, 10)))
def test_hostile_alphas_raise(a):
    try:
        m = gmap.GMap.from_alphas(a)
    except gmap.GmapError:
        return
    m.check()
    assert np.array_equal(m.alphas, a)


@pytest.mark.parametrize(
    "bad",
    [
        np.zeros((2, 3), dtype=np.complex128),  # wrong dtype
        np.array(["a", "b"]),  # strings
        np.zeros((0, 3), dtype=bool),  # an empty axis
        np.zeros((1,) * 9, dtype=bool),  # nine axes
        np.zeros((), dtype=bool),  # no axis
        [[0, 1, -2]],  # a negative label
        np.array([[0, 1, -2]]),  # a negative label in an array
        [[0, 1, 2**64]],  # past u64
        [[0, 1, "x"]],  # not an int
        [[0, 0, 1]],  # a repeated vertex
        [],  # no facet
        3,  # not a sequence
    ],
)
def test_hostile_inputs_raise(bad):
    with pytest.raises((gmap.GmapError, TypeError, ValueError)):
        gmap.homology(bad)


def test_huge_sizes_refused_under_the_memory_policy():
    # a box of 2^40 cubes is refused before anything is allocated (a broadcast view: no memory)
    huge = np.broadcast_to(np.ones(1, dtype=bool), (1 << 20, 1 << 20))
    with pytest.raises(gmap.GmapError):
        gmap.homology(huge)
    # a 40-vertex facet has 2^40 faces: refused on the count
    with pytest.raises(gmap.LimitError):
        gmap.homology([list(range(40))])
    with pytest.raises(gmap.GmapError):
        gmap.GMap(3, 2**40)
    with pytest.raises(gmap.GmapError):
        gmap.build.grid((1 << 20, 1 << 20, 1 << 20))
