"""GUDHI's scikit-learn wrapper of cubical persistence (``gudhi.sklearn.CubicalPersistence``)
over gmap: ``from gmap.gudhi.sklearn import CubicalPersistence``."""

from __future__ import annotations

from typing import Any, Iterable, List, Union

import numpy as np

from . import CubicalComplex

__all__ = ["CubicalPersistence"]


class CubicalPersistence:
    """Transforms a list of arrays into their persistence diagrams: for an int
    ``homology_dimensions`` one (n, 2) array of (birth, death) per input, for a list of
    them a list of such arrays, one per dimension asked for. ``input_type`` is
    ``"top_dimensional_cells"`` or ``"vertices"``; ``n_jobs`` is accepted and ignored (the
    engine uses every core already). A float32 input gives float32 diagrams."""

    def __init__(
        self,
        homology_dimensions: Union[int, Iterable[int]] = 0,
        input_type: str = "top_dimensional_cells",
        homology_coeff_field: int = 11,
        min_persistence: float = 0.0,
        n_jobs: Any = None,
    ):
        if input_type not in ("top_dimensional_cells", "vertices"):
            raise ValueError(f"input_type {input_type!r}: 'top_dimensional_cells' or 'vertices'")
        self.homology_dimensions = homology_dimensions
        self.input_type = input_type
        self.homology_coeff_field = homology_coeff_field
        self.min_persistence = min_persistence
        self.n_jobs = n_jobs

    def fit(self, X: Any, Y: Any = None) -> "CubicalPersistence":
        return self

    def _one(self, a: Any) -> Union[np.ndarray, List[np.ndarray]]:
        arr = np.asarray(a)
        dtype = np.float32 if arr.dtype == np.float32 else np.float64
        kw = {self.input_type: arr}
        cc = CubicalComplex(**kw)
        cc.compute_persistence(homology_coeff_field=self.homology_coeff_field, min_persistence=self.min_persistence)
        if isinstance(self.homology_dimensions, (int, np.integer)):
            return cc.persistence_intervals_in_dimension(int(self.homology_dimensions)).astype(dtype)
        return [cc.persistence_intervals_in_dimension(int(d)).astype(dtype) for d in self.homology_dimensions]

    def transform(self, X: Iterable[Any]) -> List[Any]:
        return [self._one(a) for a in X]

    def fit_transform(self, X: Iterable[Any], Y: Any = None) -> List[Any]:
        return self.fit(X, Y).transform(X)
