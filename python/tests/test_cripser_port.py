"""Our port of CubicalRipser's tests (shizuo-kaji/CubicalRipser_3dim, tests/) to gmap's
native API: each test names the peer test it follows."""

import numpy as np
import pytest

import gmap


def shell(n, d):
    """CubicalRipser's thin sphere (tests/test_3d_hole.py::create_3d_sphere), in d axes:
    0 on the shell, 1 elsewhere."""
    c = (n - 1) / 2.0
    grids = np.meshgrid(*[np.arange(n, dtype=float)] * d, indexing="ij")
    dist = np.sqrt(sum((g - c) ** 2 for g in grids))
    return np.where(np.abs(dist - c) <= 0.85, 0.0, 1.0)


def finite(d, dim):
    p = d[(d[:, 0] == dim) & np.isfinite(d[:, 1]) & np.isfinite(d[:, 2])]
    return sorted(map(tuple, p[:, 1:].tolist()))


@pytest.mark.parametrize("construction", ["V", "T"])
def test_cripser_module_on_3d_hole(construction):
    # tests/test_3d_hole.py::test_cripser_module_on_3d_hole (and its tcripser twin, the T-construction):
    # a 2-sphere of voxels: one component, one cavity filled at 1
    d = gmap.persistence(shell(5, 3), construction=construction)
    assert set(d[:, 0].astype(int)) >= {0, 2}
    assert finite(d, 2) == [(0.0, 1.0)]
    assert int(((d[:, 0] == 0) & np.isinf(d[:, 2])).sum()) == 1


@pytest.mark.parametrize("construction", ["V", "T"])
def test_4d_sphere_ph(construction):
    # tests/test_4d_sphere.py::test_4d_sphere_ph, on our own 4-D hollow ball (the peer's
    # sample/4d_hole.npy is its data): one essential H0 born at 0, one H3 bar (0, 1)
    d = gmap.persistence(shell(9, 4), construction=construction)
    h0 = d[(d[:, 0] == 0) & np.isinf(d[:, 2])]
    assert len(h0) == 1 and h0[0, 1] == 0.0
    assert [tuple(r) for r in d[d[:, 0] == 3][:, 1:].tolist()] == [(0.0, 1.0)]


@pytest.mark.parametrize("dim", [1, 2, 3])
@pytest.mark.parametrize("construction", ["V", "T"])
def test_cripser_vs_gudhi(dim, construction):
    # tests/test_compare_gudhi.py::test_cripser_vs_gudhi: the intervals of every dimension below
    # the top against GUDHI's CubicalComplex over Z/2 (when GUDHI is installed)
    gudhi = pytest.importorskip("gudhi")
    arr = np.random.default_rng(dim).random([10] * dim)
    d = gmap.persistence(arr, construction=construction, field=2)
    kw = {"vertices": arr} if construction == "V" else {"top_dimensional_cells": arr}
    cc = gudhi.CubicalComplex(**kw)
    cc.persistence(homology_coeff_field=2, min_persistence=0)
    for k in range(dim):
        ours = sorted(map(tuple, d[d[:, 0] == k][:, 1:].tolist()))
        theirs = sorted(map(tuple, np.asarray(cc.persistence_intervals_in_dimension(k)).tolist()))
        assert ours == theirs, (dim, construction, k)


@pytest.mark.parametrize("dim", [2, 3, 4])
def test_alexander(dim):
    # tests/test_alexander.py::test_alexander: Alexander duality between the T-construction of an
    # image and the V-construction of its negation framed by -inf (the outside of the box is in the
    # complement from the start, as cripser's embedded=True frames it); a finite bar (b, d) of
    # dimension i is a finite bar (-d, -b) of dimension dim-1-i
    img = np.random.default_rng(0).random((6,) * dim)
    t = gmap.persistence(img, construction="T")
    v = gmap.persistence(np.pad(-img, 1, constant_values=-np.inf), construction="V")
    for i in range(dim):
        assert finite(t, i) == sorted((-e, -b) for b, e in finite(v, dim - 1 - i)), i
