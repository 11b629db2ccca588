"""Builders of classic G-maps: grids, simplices, cubes, polygons, lens spaces, surfaces,
solid tori, and the map of a pure pseudo-manifold given by its facets.

>>> import gmap
>>> gmap.build.grid((3, 3), periodic=True).euler_characteristic()
0
"""

from __future__ import annotations

from typing import Any, Sequence, Union

from ._gmap import (
    GMap,
    _build_cube,
    _build_from_facets,
    _build_grid,
    _build_lens_space,
    _build_polygon,
    _build_simplex,
    _build_solid_torus,
    _build_surface,
)

__all__ = ["grid", "simplex", "cube", "polygon", "lens_space", "solid_torus", "surface", "from_facets"]


def grid(shape: Sequence[int], periodic: Union[bool, Sequence[bool]] = False) -> GMap:
    """The cubical grid of ``shape`` (cubes per axis) as a d-map; ``periodic``: one bool for
    every axis or one per axis (opposite faces identified along those axes: a torus)."""
    return _build_grid(list(shape), periodic)


def simplex(n: int) -> GMap:
    """The n-simplex (a ball) as an n-map."""
    return _build_simplex(n)


def cube(n: int) -> GMap:
    """The n-cube (a ball) as an n-map."""
    return _build_cube(n)


def polygon(k: int) -> GMap:
    """A k-gon (a disc) as a 2-map."""
    return _build_polygon(k)


def lens_space(p: int, q: int) -> GMap:
    """The lens space L(p, q) as a closed 3-map (H_1 = Z/p)."""
    return _build_lens_space(p, q)


def solid_torus(k: int) -> GMap:
    """A solid torus: a ring of k cubes as a 3-map."""
    return _build_solid_torus(k)


def surface(word: str) -> GMap:
    """The surface of a polygon schema, e.g. ``"a b a^-1 b^-1"`` (a torus)."""
    return _build_surface(word)


def from_facets(facets: Any) -> GMap:
    """The G-map of a pure pseudo-manifold (every ridge in at most two facets) given by its
    facets (a sequence of sequences of non-negative ints or a 2-D integer array). The map
    keeps the complex while its darts are not edited: the generators of
    ``gmap.homology(m, generators=True)`` are then named by the facets' vertex labels (tuples,
    as for the facet list itself); after ``sew``, ``unsew`` or an Euler operator, by darts."""
    return _build_from_facets(facets)
