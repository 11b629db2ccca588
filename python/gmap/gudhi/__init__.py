"""GUDHI's persistence classes under GUDHI's names and conventions, over gmap's engine.

``import gmap.gudhi as gudhi`` runs a script written for GUDHI's ``CubicalComplex``,
``PeriodicCubicalComplex`` and ``SimplexTree``: the same constructors, the same default
field (Z/11), the same output (lists of ``(dimension, (birth, death))`` sorted by
dimension then length, both from the longest), the same flat indices (Fortran order over
the array's shape, as GUDHI counts cells). The layer is thin: every diagram comes from
``gmap`` (its native API keeps its own names: ``gmap.persistence(x, field=2, ...)``).

What GUDHI lacks, added here: ``cycles_of_persistence_pairs()`` (a representative cycle
per pair, cells as GUDHI's flat indices into ``all_cells()`` or as simplices) and
``integer_homology()`` (the homology over Z, torsion included, from ``gmap.homology``).

Where GUDHI's result depends on its tie-breaking (which of two equal cells is "the" birth
cell), the cells given here are valid for the same diagram but may be other cells of the
same value: GUDHI's documentation calls the choice arbitrary.
"""

from __future__ import annotations

import math
import os
from typing import Any, Dict, Iterable, Iterator, List, Optional, Sequence, Tuple

import numpy as np

from .. import _gmap

__all__ = ["CubicalComplex", "PeriodicCubicalComplex", "SimplexTree", "sklearn"]

Interval = Tuple[int, Tuple[float, float]]


def _gudhi_order(pairs: np.ndarray) -> List[Interval]:
    """(k, 3) pairs as GUDHI lists them: dimension down, then the longest first."""
    out = [(int(d), (float(b), float(e))) for d, b, e in pairs.tolist()]
    out.sort(key=lambda p: (-p[0], -(p[1][1] - p[1][0]), p[1][0]))
    return out


class _Diagram:
    """What GUDHI's persistence interface answers once ``persistence()`` has run."""

    def __init__(self, pairs: np.ndarray, top: int):
        self.pairs = pairs
        self.top = top

    def intervals(self, dim: int) -> np.ndarray:
        p = self.pairs[self.pairs[:, 0] == dim][:, 1:]
        if len(p) == 0:
            return np.empty(shape=[0, 2])
        return p[np.lexsort((p[:, 1], p[:, 0]))]

    def betti(self) -> List[int]:
        b = [0] * (self.top + 1)
        for d, _, e in self.pairs.tolist():
            if math.isinf(e) and int(d) <= self.top:
                b[int(d)] += 1
        return b

    def persistent_betti(self, from_value: float, to_value: float) -> List[int]:
        b = [0] * (self.top + 1)
        for d, s, e in self.pairs.tolist():
            if s <= from_value and e > to_value and int(d) <= self.top:
                b[int(d)] += 1
        return b


def _grouped(rows: List[Tuple[int, Any]], width: int) -> List[np.ndarray]:
    """GUDHI's grouping of cells by dimension: a list indexed by dimension, up to the
    largest dimension present, of int arrays (n, width) (width 1: shape (n,))."""
    if not rows:
        return []
    top = max(d for d, _ in rows) + 1
    out = []
    for h in range(top):
        cells = [c for d, c in rows if d == h]
        if width == 1:
            out.append(np.array(cells, dtype=np.int64).reshape(len(cells)))
        else:
            out.append(np.array(cells, dtype=np.int64).reshape(len(cells), width))
    return out


def _flat_f(coords: Sequence[int], shape: Sequence[int]) -> int:
    """The Fortran-order flat index of ``coords`` in an array of ``shape`` (GUDHI's)."""
    i, m = 0, 1
    for c, s in zip(coords, shape):
        i += int(c) * m
        m *= int(s)
    return i


def _expand(a: np.ndarray, axis: int, periodic: bool, vertices: bool) -> np.ndarray:
    """Along one axis, the doubled grid of ``a``: from top cells (odd places, even ones the
    minimum of their neighbours) or from vertices (even places, odd ones the maximum)."""
    a = np.moveaxis(a, axis, 0)
    n = a.shape[0]
    if vertices:
        m = 2 * n if periodic else 2 * n - 1
        out = np.empty((m,) + a.shape[1:], dtype=a.dtype)
        out[0::2] = a
        nxt = np.roll(a, -1, axis=0) if periodic else a[1:]
        out[1::2] = np.maximum(a[: len(nxt)], nxt)
    else:
        m = 2 * n if periodic else 2 * n + 1
        out = np.empty((m,) + a.shape[1:], dtype=a.dtype)
        out[1::2] = a
        if periodic:
            out[0::2] = np.minimum(np.roll(a, 1, axis=0), a)
        else:
            out[0] = a[0]
            out[-1] = a[-1]
            out[2:-1:2] = np.minimum(a[:-1], a[1:])
    return np.moveaxis(out, 0, axis)


def _read_perseus_cubical(path: str) -> Tuple[np.ndarray, List[bool]]:
    """A Perseus cubical file through gmap's reader: the top cells (numpy axis order) and
    the periodic flag of each axis."""
    values, shape, periodic = _gmap._perseus_cubical(os.fspath(path))
    return np.asarray(values, dtype=np.float64).reshape(shape, order="F"), list(periodic)


class _Queries:
    """What GUDHI's complexes answer from their last diagram, shared by the cubical
    complexes and the simplex tree."""

    _diagram: Optional[_Diagram]

    def _need(self, what: str) -> _Diagram:
        if self._diagram is None:
            raise RuntimeError(f"compute_persistence() must be called before {what}()")
        return self._diagram

    def betti_numbers(self) -> List[int]:
        """The number of essential classes per dimension, 0 to the number of axes."""
        return self._need("betti_numbers").betti()

    def persistent_betti_numbers(self, from_value: float, to_value: float) -> List[int]:
        """Per dimension, the pairs born at or before from_value that die after to_value."""
        return self._need("persistent_betti_numbers").persistent_betti(from_value, to_value)

    def persistence_intervals_in_dimension(self, dimension: int) -> np.ndarray:
        """The (n, 2) array of (birth, death) of dimension ``dimension``."""
        return self._need("persistence_intervals_in_dimension").intervals(dimension)


class CubicalComplex(_Queries):
    """GUDHI's ``CubicalComplex``: values on the top-dimensional cells (a face takes the
    minimum of its cofaces') or on the vertices (a cell takes the maximum of its
    vertices'), from an array, from a flat list with ``dimensions`` (Fortran order), or
    from a Perseus file."""

    _periodic_class = False

    def __init__(
        self,
        *,
        top_dimensional_cells: Any = None,
        vertices: Any = None,
        dimensions: Optional[Iterable[int]] = None,
        perseus_file: str = "",
        periodic_dimensions: Optional[Iterable[bool]] = None,
    ):
        self._diagram: Optional[_Diagram] = None
        self._last: Tuple[int, float] = (11, 0.0)
        self._from_vertices = False
        if perseus_file:
            if top_dimensional_cells is not None or vertices is not None or dimensions is not None:
                raise ValueError("The Perseus file contains all the information, do not specify anything else")
            if self._periodic_class and periodic_dimensions is not None:
                raise ValueError("The Perseus file contains all the information, do not specify anything else")
            if not os.path.exists(os.fspath(perseus_file)):
                raise FileNotFoundError(f"no such file: {perseus_file}")
            self._array, periodic = _read_perseus_cubical(perseus_file)
            self._periodic = periodic if self._periodic_class else [False] * len(periodic)
            return
        if top_dimensional_cells is not None:
            if vertices is not None:
                raise ValueError("Can only specify the top dimensional cells OR the vertices, not both")
            array = top_dimensional_cells
        elif vertices is not None:
            array = vertices
            self._from_vertices = True
        else:
            raise ValueError("Must specify one of top_dimensional_cells, vertices, or perseus_file")
        if dimensions is not None:
            array = np.asarray(array, dtype=np.float64).reshape(list(dimensions), order="F")
        else:
            array = np.asarray(array, dtype=np.float64)
        if array.ndim == 0 or array.size == 0:
            raise ValueError("an empty array of cells")
        self._array = array
        if self._periodic_class:
            if periodic_dimensions is None:
                raise ValueError("periodic_dimensions: one flag per axis")
            flags = [bool(p) for p in periodic_dimensions]
            if len(flags) != array.ndim:
                raise ValueError(f"{len(flags)} periodic flags for {array.ndim} axes")
            self._periodic = flags
        else:
            self._periodic = [False] * array.ndim

    # the arrays
    def _is_defined(self) -> bool:
        return True

    def _is_persistence_defined(self) -> bool:
        return self._diagram is not None

    def dimension(self) -> int:
        """The number of axes."""
        return self._array.ndim

    def num_simplices(self) -> int:
        """The number of cells of every dimension."""
        return int(np.prod(self.all_cells().shape))

    def all_cells(self) -> np.ndarray:
        """The value of every cell, on the doubled grid (numpy's axis order)."""
        a = self._array
        for k in range(a.ndim):
            a = _expand(a, k, self._periodic[k], self._from_vertices)
        return a

    def top_dimensional_cells(self) -> np.ndarray:
        """The values of the top-dimensional cells (the array given, for a complex made of them)."""
        if not self._from_vertices:
            return self._array
        return self.all_cells()[(slice(1, None, 2),) * self._array.ndim]

    def vertices(self) -> np.ndarray:
        """The values of the vertices (the array given, for a complex made of them)."""
        if self._from_vertices:
            return self._array
        return self.all_cells()[(slice(0, None, 2),) * self._array.ndim]

    # persistence
    def _pairs(self, field: int, min_persistence: float, cells: bool) -> Tuple[np.ndarray, list, list, list]:
        values = np.ascontiguousarray(self._array, dtype=np.float64)
        construction = "V" if self._from_vertices else "T"
        return _gmap._image_pairs(values, construction, self._periodic, field, False, float(min_persistence), cells)

    def compute_persistence(self, homology_coeff_field: int = 11, min_persistence: float = 0) -> None:
        """The diagram over Z/homology_coeff_field, pairs living more than min_persistence."""
        pairs = self._pairs(homology_coeff_field, min_persistence, False)[0]
        self._diagram = _Diagram(pairs, self._array.ndim)
        self._last = (homology_coeff_field, float(min_persistence))

    def persistence(self, homology_coeff_field: int = 11, min_persistence: float = 0) -> List[Interval]:
        """``[(dimension, (birth, death)), ...]``, dimension down, then the longest first."""
        self.compute_persistence(homology_coeff_field, min_persistence)
        assert self._diagram is not None
        return _gudhi_order(self._diagram.pairs)

    def _pair_cells(self, what: str) -> Tuple[np.ndarray, list, list, list]:
        self._need(what)
        field, minp = self._last
        return self._pairs(field, minp, True)

    def _owner(self, cell: Sequence[int], value: float) -> Tuple[int, ...]:
        """The top cell (T) or vertex (V) of the same value that gives ``cell`` its value."""
        options = []
        for k, c in enumerate(cell):
            n = self._array.shape[k]
            if self._from_vertices:
                near = [c // 2] if c % 2 == 0 else [c // 2, (c // 2 + 1) % n if self._periodic[k] else c // 2 + 1]
            else:
                near = [c // 2] if c % 2 == 1 else [(c // 2 - 1) % n if self._periodic[k] else c // 2 - 1, c // 2]
            options.append([i for i in near if 0 <= i < n])
        for idx in np.ndindex(*[len(o) for o in options]):
            at = tuple(options[k][i] for k, i in enumerate(idx))
            if self._array[at] == value:
                return at
        raise RuntimeError(f"no neighbour of cell {tuple(cell)} has its value {value}")

    def _cells_of_pairs(self, what: str) -> List[List[np.ndarray]]:
        pairs, births, deaths, _ = self._pair_cells(what)
        cells = self.all_cells()
        shape = self._array.shape
        regular, essential = [], []
        for (d, _, _), b, e in zip(pairs.tolist(), births, deaths):
            pb = _flat_f(self._owner(b, cells[tuple(b)]), shape)
            if e is None:
                essential.append((int(d), pb))
            else:
                regular.append((int(d), [pb, _flat_f(self._owner(e, cells[tuple(e)]), shape)]))
        return [_grouped(regular, 2), _grouped(essential, 1)]

    def cofaces_of_persistence_pairs(self) -> List[List[np.ndarray]]:
        """GUDHI's ``[regular, essential]``: per dimension, the (n, 2) int arrays of the top
        cells that give each finite pair its birth and death, and the (n,) arrays of the top
        cells of the essential pairs; flat indices in Fortran order over the array."""
        if self._from_vertices:
            raise RuntimeError(
                "cofaces_of_persistence_pairs() only makes sense for a complex initialized from the values of the top-dimensional cells"
            )
        return self._cells_of_pairs("cofaces_of_persistence_pairs")

    def vertices_of_persistence_pairs(self) -> List[List[np.ndarray]]:
        """As :meth:`cofaces_of_persistence_pairs`, with vertices, for a complex made of them."""
        if not self._from_vertices:
            raise RuntimeError(
                "vertices_of_persistence_pairs() only makes sense for a complex initialized from the values of the vertices"
            )
        return self._cells_of_pairs("vertices_of_persistence_pairs")

    def cycles_of_persistence_pairs(self) -> List[Tuple[Interval, np.ndarray, np.ndarray]]:
        """Not in GUDHI: a representative cycle of each pair, as ``(interval, cells,
        coefficients)``, cells as flat indices into :meth:`all_cells` (Fortran order, GUDHI's
        indexing of every cell), coefficients in 1..p-1; in the order of :meth:`persistence`."""
        pairs, _, _, cycles = self._pair_cells("cycles_of_persistence_pairs")
        shape = self.all_cells().shape
        out = []
        for (dim, b, e), chain in zip(pairs.tolist(), cycles):
            flat = np.array([_flat_f(c, shape) for c, _ in chain], dtype=np.int64)
            coef = np.array([k for _, k in chain], dtype=np.int64)
            out.append(((int(dim), (float(b), float(e))), flat, coef))
        out.sort(key=lambda t: (-t[0][0], -(t[0][1][1] - t[0][1][0]), t[0][1][0]))
        return out


class PeriodicCubicalComplex(CubicalComplex):
    """GUDHI's ``PeriodicCubicalComplex``: a :class:`CubicalComplex` whose axis k wraps
    when ``periodic_dimensions[k]`` (a Perseus file says so by a negative size)."""

    _periodic_class = True


class SimplexTree(_Queries):
    """GUDHI's ``SimplexTree``: simplices with a filtration value each, a face never above
    its cofaces (``insert`` lowers faces, ``make_filtration_non_decreasing`` raises
    cofaces). Persistence goes to gmap with every simplex and its value."""

    def __init__(self) -> None:
        self._f: Dict[Tuple[int, ...], float] = {}
        self._diagram: Optional[_Diagram] = None
        self._cells: Optional[Tuple[np.ndarray, list, list]] = None
        self._last: Tuple[int, float, bool] = (11, 0.0, False)
        self._dim_bound = -1

    def _is_defined(self) -> bool:
        return True

    def _is_persistence_defined(self) -> bool:
        return self._diagram is not None

    def __eq__(self, other: object) -> bool:
        return isinstance(other, SimplexTree) and self._f == other._f

    @staticmethod
    def _key(simplex: Iterable[int]) -> Tuple[int, ...]:
        return tuple(sorted(int(v) for v in simplex))

    def _changed(self) -> None:
        self._diagram = None
        self._cells = None

    # building
    def insert(self, simplex: Iterable[int], filtration: float = 0.0) -> bool:
        """Inserts the simplex and its faces at ``filtration``; a face already there with a
        larger value is lowered to it. True if the simplex was not there."""
        s = self._key(simplex)
        if not s:
            return False
        new = s not in self._f
        f = float(filtration)
        n = len(s)
        for mask in range(1, 1 << n):
            face = tuple(s[i] for i in range(n) if mask >> i & 1)
            old = self._f.get(face)
            if old is None or old > f:
                self._f[face] = f
        self._dim_bound = max(self._dim_bound, n - 1)
        self._changed()
        return new

    def insert_batch(self, vertex_array: Any, filtrations: Any) -> "SimplexTree":
        """Inserts the simplices that are the columns of ``vertex_array`` (k, n) with the
        values ``filtrations`` (n,); a simplex given twice keeps the smallest value."""
        va = np.asarray(vertex_array)
        fs = np.asarray(filtrations, dtype=np.float64)
        if va.ndim != 2 or va.shape[1] != len(fs):
            raise ValueError("vertex_array: (k, n) with n the number of filtration values")
        for j in range(va.shape[1]):
            self.insert(va[:, j].tolist(), float(fs[j]))
        return self

    def assign_filtration(self, simplex: Iterable[int], filtration: float) -> None:
        """Sets the value of a simplex that is there (faces and cofaces unchanged)."""
        s = self._key(simplex)
        if s in self._f:
            self._f[s] = float(filtration)
            self._changed()

    def make_filtration_non_decreasing(self) -> bool:
        """Raises each simplex to the largest value of its faces; True if one changed."""
        changed = False
        for s in sorted(self._f, key=len):
            if len(s) < 2:
                continue
            top = max(self._f[s[:i] + s[i + 1 :]] for i in range(len(s)))
            if top > self._f[s]:
                self._f[s] = top
                changed = True
        if changed:
            self._changed()
        return changed

    def remove_maximal_simplex(self, simplex: Iterable[int]) -> None:
        """Removes a simplex that is the face of no other."""
        s = self._key(simplex)
        if self.get_cofaces(s, 1):
            raise ValueError(f"{list(s)} is not maximal")
        self._f.pop(s, None)
        self._changed()

    def prune_above_filtration(self, filtration: float) -> bool:
        """Removes the simplices of value above ``filtration``; True if one was."""
        gone = [s for s, f in self._f.items() if f > filtration]
        for s in gone:
            del self._f[s]
        if gone:
            self._changed()
        return bool(gone)

    def expansion(self, max_dim: int) -> None:
        """Adds every simplex up to dimension max_dim whose edges are all there (the flag
        complex), at the largest value of its faces."""
        adj: Dict[int, set] = {}
        for s in self._f:
            if len(s) == 2:
                adj.setdefault(s[0], set()).add(s[1])
                adj.setdefault(s[1], set()).add(s[0])

        # dimension by dimension: every clique's faces are there before it
        level = [s for s in self._f if len(s) == 2]
        # a clique has at most one vertex per vertex of the graph: past that, or once a
        # dimension adds nothing, no larger simplex can come (a huge max_dim ends at once)
        for _ in range(2, min(max_dim, len(adj)) + 1):
            if not level:
                break
            nxt = []
            for s in sorted(level):
                common = set.intersection(*(adj.get(v, set()) for v in s))
                for v in sorted(x for x in common if x > s[-1]):
                    c = s + (v,)
                    if c not in self._f:
                        self._f[c] = max(self._f[c[:i] + c[i + 1 :]] for i in range(len(c)))
                    nxt.append(c)
            level = nxt
        self._dim_bound = max(self._dim_bound, min(max_dim, self.dimension()))
        self._changed()

    # reading
    def find(self, simplex: Iterable[int]) -> bool:
        return self._key(simplex) in self._f

    def filtration(self, simplex: Iterable[int]) -> float:
        return self._f.get(self._key(simplex), math.inf)

    def num_vertices(self) -> int:
        return sum(1 for s in self._f if len(s) == 1)

    def num_simplices(self) -> int:
        return len(self._f)

    def dimension(self) -> int:
        return max((len(s) - 1 for s in self._f), default=-1)

    def upper_bound_dimension(self) -> int:
        self._dim_bound = self.dimension()
        return self._dim_bound

    def _tree_order(self, simplices: Iterable[Tuple[int, ...]]) -> List[Tuple[int, ...]]:
        # GUDHI's tree walk: a simplex after the simplices it is a prefix of
        return sorted(simplices, key=lambda s: s + (math.inf,))

    def get_simplices(self) -> Iterator[Tuple[List[int], float]]:
        for s in self._tree_order(self._f):
            yield list(s), self._f[s]

    def get_skeleton(self, dimension: int) -> Iterator[Tuple[List[int], float]]:
        for s in self._tree_order(s for s in self._f if len(s) - 1 <= dimension):
            yield list(s), self._f[s]

    def get_filtration(self) -> Iterator[Tuple[List[int], float]]:
        """The simplices by value, then by their vertices read from the last (GUDHI's
        reverse lexicographic order: a face before its cofaces)."""
        for s in sorted(self._f, key=lambda s: (self._f[s], s[::-1])):
            yield list(s), self._f[s]

    def get_star(self, simplex: Iterable[int]) -> List[Tuple[List[int], float]]:
        s = set(self._key(simplex))
        return [(list(t), self._f[t]) for t in self._tree_order(t for t in self._f if s <= set(t))]

    def get_cofaces(self, simplex: Iterable[int], codimension: int) -> List[Tuple[List[int], float]]:
        s = self._key(simplex)
        want = set(s)
        return [
            (list(t), self._f[t])
            for t in self._tree_order(self._f)
            if want <= set(t) and (len(t) > len(s) if codimension == 0 else len(t) == len(s) + codimension)
        ]

    def get_boundaries(self, simplex: Iterable[int]) -> Iterator[Tuple[List[int], float]]:
        s = self._key(simplex)
        if not s or s not in self._f:
            raise RuntimeError(f"{list(s)} is not in the complex")
        if len(s) == 1:
            return
        for i in range(len(s) - 1, -1, -1):
            f = s[:i] + s[i + 1 :]
            yield list(f), self._f[f]

    def reset_filtration(self, filtration: float, min_dim: int = 0) -> None:
        for s in self._f:
            if len(s) - 1 >= min_dim:
                self._f[s] = float(filtration)
        self._changed()

    # persistence
    def _pairs(self, field: int, min_persistence: float, cells: bool) -> Tuple[np.ndarray, list, list, list]:
        simplices = list(self._f)
        values = [self._f[s] for s in simplices]
        if not simplices:
            return np.empty((0, 3)), [], [], []
        return _gmap._simplex_pairs([list(s) for s in simplices], values, field, float(min_persistence), cells)

    def compute_persistence(
        self, homology_coeff_field: int = 11, min_persistence: float = 0, persistence_dim_max: bool = False
    ) -> None:
        """The diagram over Z/homology_coeff_field; without persistence_dim_max the classes
        of the complex's top dimension are left out (GUDHI's default)."""
        pairs = self._pairs(homology_coeff_field, min_persistence, False)[0]
        top = self.dimension()
        if not persistence_dim_max and top > 0:
            pairs = pairs[pairs[:, 0] < top]
        self._diagram = _Diagram(pairs, max(top, 0) if persistence_dim_max else max(top - 1, 0))
        self._last = (homology_coeff_field, float(min_persistence), persistence_dim_max)
        self._cells = None

    def persistence(
        self, homology_coeff_field: int = 11, min_persistence: float = 0, persistence_dim_max: bool = False
    ) -> List[Interval]:
        """``[(dimension, (birth, death)), ...]``, dimension down, then the longest first."""
        self.compute_persistence(homology_coeff_field, min_persistence, persistence_dim_max)
        assert self._diagram is not None
        return _gudhi_order(self._diagram.pairs)

    def _with_cells(self) -> Tuple[np.ndarray, list, list]:
        self._need("persistence_pairs")
        if self._cells is None:
            field, minp, dim_max = self._last
            pairs, births, deaths, _ = self._pairs(field, minp, True)
            top = self.dimension()
            keep = [dim_max or top <= 0 or int(d) < top for d in pairs[:, 0].tolist()]
            self._cells = (pairs[np.array(keep, dtype=bool)] if len(keep) else pairs,
                           [b for b, k in zip(births, keep) if k], [e for e, k in zip(deaths, keep) if k])
        return self._cells

    def persistence_pairs(self) -> List[Tuple[List[int], List[int]]]:
        """The (birth simplex, death simplex) of each pair, [] as the death of an essential one."""
        _, births, deaths = self._with_cells()
        return [(list(b), [] if e is None else list(e)) for b, e in zip(births, deaths)]

    def lower_star_persistence_generators(self) -> Tuple[List[np.ndarray], List[np.ndarray]]:
        """GUDHI's generators of a lower-star filtration: per dimension, the (n, 2) arrays of
        the vertices that give each finite pair its birth and death (the vertex of largest
        value of its birth and death simplices), and the (n,) arrays of the essential pairs'."""
        pairs, births, deaths = self._with_cells()

        def top(s: Sequence[int]) -> int:
            return max(s, key=lambda v: (self._f[(v,)], v))

        regular, essential = [], []
        for d, b, e in zip(pairs[:, 0].tolist(), births, deaths):
            if e is None:
                essential.append((int(d), top(b)))
            else:
                regular.append((int(d), [top(b), top(e)]))
        return _grouped(regular, 2), _grouped(essential, 1)

    def cycles_of_persistence_pairs(self) -> List[Tuple[Interval, List[List[int]], np.ndarray]]:
        """Not in GUDHI: a representative cycle of each pair as ``(interval, simplices,
        coefficients)``, in the order of :meth:`persistence`."""
        self._need("cycles_of_persistence_pairs")
        field, minp, dim_max = self._last
        simplices = list(self._f)
        pairs, cycles = _gmap.persistence(
            [list(s) for s in simplices],
            facet_values=[self._f[s] for s in simplices],
            field=field,
            cycles=True,
            min_persistence=minp,
        )
        top = self.dimension()
        out = []
        for (d, b, e), (cells, coef) in zip(pairs.tolist(), cycles):
            if dim_max or top <= 0 or int(d) < top:
                out.append(((int(d), (float(b), float(e))), [list(c) for c in cells], np.asarray(coef, dtype=np.int64)))
        out.sort(key=lambda t: (-t[0][0], -(t[0][1][1] - t[0][1][0]), t[0][1][0]))
        return out

    def integer_homology(self) -> Any:
        """Not in GUDHI: the homology over Z of the whole complex (``gmap.Homology``: betti
        and torsion per dimension)."""
        faces = {t[:i] + t[i + 1 :] for t in self._f for i in range(len(t)) if len(t) > 1}
        return _gmap.homology([list(s) for s in self._f if s not in faces])


from . import sklearn  # noqa: E402  (gudhi.sklearn's CubicalPersistence)
