"""Type stubs of the compiled module gmap._gmap (re-exported by gmap)."""

import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

PathLike = Union[str, "os.PathLike[str]"]
Facets = Union[Sequence[Sequence[int]], npt.NDArray[np.integer]]
LabelValue = Union[int, float, str]

Item = Union[int, str, Tuple[int, ...]]

class GmapError(Exception):
    """Base class of every error raised by gmap: the message the command prints, the file
    (`path`, also `file`) and line it concerns, and the item it is about (`item`: a dart
    number as the GMap numbers its darts, a cell `(dim, dart)`, a simplex's vertex labels,
    a region's id, a facet's index; `item_kind` says which: 'dart', 'cell', 'simplex',
    'region', 'facet'), each None when it does not apply."""

    message: str
    path: Optional[str]
    file: Optional[str]
    line: Optional[int]
    item: Optional[Item]
    item_kind: Optional[str]

class ParseError(GmapError):
    """A file that does not fit its format; `.path` and `.line` (or None) say where."""

class LimitError(GmapError):
    """An input refused for its size: over the dart, face or work limit, or the memory policy."""

class PreconditionError(GmapError):
    """A method that does not apply to this input (conditions C1/C2, an Euler operator's precondition)."""

class InputError(GmapError):
    """An argument that is not a valid input (bad facets, shapes, options)."""

class ValidityError(GmapError):
    """A map that breaks the G-map axioms (`GMap.check`)."""

class ComputationError(GmapError):
    """A computation that could not finish (overflow, internal check)."""

class Generator:
    """One summand's representative cycle, in the input's own terms (its arrays are made
    when first read, then kept)."""

    dim: int
    order: int
    cells: Any
    extents: Optional[npt.NDArray[np.uint8]]
    coefficients: npt.NDArray[np.int64]

class Homology:
    """The homology groups of an input: H_k = Z^betti[k] + sum of Z/t for t in torsion[k]."""

    @property
    def betti(self) -> List[int]: ...
    @property
    def torsion(self) -> List[List[int]]: ...
    @property
    def dimension(self) -> int: ...
    @property
    def method(self) -> str: ...
    @property
    def route(self) -> Optional[str]: ...
    @property
    def coefficients(self) -> str: ...
    @property
    def euler_characteristic(self) -> int: ...
    @property
    def generators(self) -> Optional[List[Generator]]: ...
    def group(self, k: int) -> str:
        """The text of H_k: 'Z^2 + Z/2'."""
    def to_dict(self) -> Dict[str, Any]:
        """The object `gmap homology --json` prints."""
    def to_json(self) -> str:
        """The JSON text `gmap homology --json` prints."""
    @staticmethod
    def from_json(text: str) -> "Homology":
        """The result whose `to_json()` is `text`."""

class GMap:
    """An editable generalized map: darts 0..len-1, involutions alpha_0..alpha_dim, points, labels."""

    def __init__(self, dim: int, darts: int = 0) -> None: ...
    @staticmethod
    def from_alphas(a: npt.ArrayLike) -> "GMap":
        """The map whose involutions are the rows of `a`, shape (dim + 1, darts)."""
    @staticmethod
    def from_text(text: str) -> "GMap":
        """The map of a `.gmap` text."""
    def to_text(self) -> str:
        """The map in the `.gmap` format."""
    @property
    def dim(self) -> int: ...
    def __len__(self) -> int: ...
    @property
    def alphas(self) -> npt.NDArray[np.uint32]: ...
    def alpha(self, d: int, i: int) -> int: ...
    def is_free(self, d: int, i: int) -> bool: ...
    def add_darts(self, k: int = 1) -> int: ...
    def is_sewable(self, d: int, e: int, i: int) -> bool: ...
    def sew(self, d: int, e: int, i: int) -> None: ...
    def unsew(self, d: int, i: int) -> None: ...
    def cell_counts(self) -> List[int]: ...
    def cells(self, i: int) -> npt.NDArray[np.uint32]: ...
    def components(self) -> npt.NDArray[np.uint32]: ...
    def orbit(self, d: int, dims: Sequence[int]) -> npt.NDArray[np.uint32]: ...
    def is_orientable(self) -> bool: ...
    def euler_characteristic(self) -> int: ...
    def check(self) -> None: ...
    def is_valid(self) -> bool: ...
    @property
    def points(self) -> npt.NDArray[np.float64]: ...
    @points.setter
    def points(self, p: npt.ArrayLike) -> None: ...
    def labels(self, i: int) -> List[Dict[str, LabelValue]]: ...
    def set_label(self, i: int, d: int, name: str, value: LabelValue) -> None: ...
    def copy(self) -> "GMap": ...
    def view(self, path: Optional[PathLike] = None, *, generators: bool = False, color_by: Optional[str] = None) -> str:
        """The page of `gmap view` (one self-contained HTML file) written to `path` (the path
        is returned as a str), or its HTML text when path is None."""
    def _repr_html_(self) -> str:
        """The page in an iframe for Jupyter, or a note when it is too big to embed."""
    def save(self, path: PathLike, lossy: bool = False) -> None:
        """Writes the map by extension (the writers of `gmap convert`); refuses a format that
        would drop its labels or points unless lossy=True."""
    def incidences(self) -> List[Tuple[Tuple[int, int], Tuple[int, int]]]: ...
    def incidence_graph(self) -> Any:
        """The incidence graph as a networkx.Graph (needs networkx)."""
    def insert_cell_0_in_cell_1(self, d: int) -> int: ...
    def is_insertable_cell_0_in_cell_1(self, d: int) -> bool: ...
    def insert_cell_0_in_cell_2(self, d: int, point: Optional[Sequence[float]] = None) -> int: ...
    def is_insertable_cell_0_in_cell_2(self, d: int) -> bool: ...
    def insert_cell_1_in_cell_2(self, d1: int, d2: int) -> int: ...
    def is_insertable_cell_1_in_cell_2(self, d1: int, d2: int) -> bool: ...
    def insert_dangling_cell_1_in_cell_2(self, d: int, point: Optional[Sequence[float]] = None) -> int: ...
    def is_insertable_dangling_cell_1_in_cell_2(self, d: int) -> bool: ...
    def insert_cell_1_between_two_cells_2(self, d1: int, d2: int) -> int: ...
    def is_insertable_cell_1_between_two_cells_2(self, d1: int, d2: int) -> bool: ...
    def insert_cell_2_in_cell_3(self, path: Sequence[int]) -> int: ...
    def is_insertable_cell_2_in_cell_3(self, path: Sequence[int]) -> bool: ...
    def insert_barycenter_in_cell(self, d: int, i: int) -> int: ...
    def is_insertable_barycenter_in_cell(self, d: int, i: int) -> bool: ...
    def insert_point_in_cell(self, d: int, point: Sequence[float], i: int) -> int: ...
    def remove_cell(self, d: int, i: int) -> int: ...
    def is_removable(self, d: int, i: int) -> bool: ...
    def contract_cell(self, d: int, i: int) -> int: ...
    def is_contractible(self, d: int, i: int) -> bool: ...
    def make_combinatorial_tetrahedron(self) -> int: ...
    def make_combinatorial_hexahedron(self) -> int: ...

class SimplicialComplex:
    """A finite simplicial complex given by its facets."""

    def __init__(self, facets: Facets) -> None: ...
    @property
    def dim(self) -> int: ...
    @property
    def facets(self) -> List[List[int]]: ...
    def __len__(self) -> int: ...
    def is_pure(self) -> bool: ...
    def to_gmap(self) -> GMap: ...
    def save(self, path: PathLike, lossy: bool = False) -> None: ...
    def view(self, path: Optional[PathLike] = None, *, generators: bool = False, color_by: Optional[str] = None) -> str:
        """The page of `gmap view` (one self-contained HTML file) written to `path` (the path
        is returned as a str), or its HTML text when path is None."""
    def _repr_html_(self) -> str:
        """The page in an iframe for Jupyter, or a note when it is too big to embed."""

class CubicalSet:
    """A full cubical set: the unit cubes of a box that belong to the set."""

    def __init__(self, array: npt.ArrayLike, min: Optional[Sequence[int]] = None) -> None: ...
    @property
    def dim(self) -> int: ...
    @property
    def shape(self) -> List[int]: ...
    @property
    def min(self) -> List[int]: ...
    @property
    def array(self) -> npt.NDArray[np.bool_]: ...
    def __len__(self) -> int: ...
    def to_gmap(self, periodic: bool = False) -> GMap: ...
    def save(self, path: PathLike, lossy: bool = False) -> None: ...
    def view(self, path: Optional[PathLike] = None, *, generators: bool = False, color_by: Optional[str] = None) -> str:
        """The page of `gmap view` (one self-contained HTML file) written to `path` (the path
        is returned as a str), or its HTML text when path is None."""
    def _repr_html_(self) -> str:
        """The page in an iframe for Jupyter, or a note when it is too big to embed."""

class ArchComplex:
    """An architectural complex (an incidence graph of regions, `.json`)."""

    def __init__(self, text: str) -> None: ...
    @property
    def dim(self) -> int: ...
    def __len__(self) -> int: ...
    def to_json(self) -> str: ...
    def save(self, path: PathLike, lossy: bool = False) -> None: ...
    def view(self, path: Optional[PathLike] = None, *, generators: bool = False, color_by: Optional[str] = None) -> str:
        """The page of `gmap view` (one self-contained HTML file) written to `path` (the path
        is returned as a str), or its HTML text when path is None."""
    def _repr_html_(self) -> str:
        """The page in an iframe for Jupyter, or a note when it is too big to embed."""

class Image:
    """A grey-value image (`.npy`, `.complex`, `.pgm`, `.png`): a cubical set at a level
    for homology (the nonzero values, or `level=`), a filtration for persistence."""

    @property
    def dim(self) -> int: ...
    @property
    def shape(self) -> List[int]: ...
    def __len__(self) -> int: ...
    def save(self, path: PathLike, lossy: bool = False) -> None:
        """Writes the image as it is, `.npy` or `.complex`."""
    def view(self, path: Optional[PathLike] = None, *, generators: bool = False, color_by: Optional[str] = None) -> str:
        """The page of `gmap view` (the image's cubes at its default level)."""
    def _repr_html_(self) -> str:
        """The page in an iframe for Jupyter, or a note when it is too big to embed."""

Input = Union[PathLike, GMap, SimplicialComplex, CubicalSet, Image, ArchComplex, Facets, npt.NDArray[Any]]

def homology(
    x: Input,
    *,
    field: Optional[int] = None,
    generators: Union[bool, str] = False,
    method: Optional[str] = None,
    periodic: bool = False,
    level: Optional[float] = None,
) -> Homology:
    """The homology groups of `x` over Z (or Z/field); `level`: an image's cubes are its
    values <= level (default: the nonzero values); `generators="shortest"` (with field=2):
    the generators of H_1 a shortest basis over Z/2."""

def shortest_non_contractible_cycle(
    x: Union[GMap, str, "os.PathLike[str]"],
    *,
    weights: Union[None, str, Sequence[float]] = None,
    through: Optional[int] = None,
) -> Optional[Dict[str, Any]]:
    """The shortest non-contractible cycle of a surface (through the vertex of dart
    `through`): `length`, `darts`, `edge_darts`, `vertex_darts`; None if there is none."""

def edge_width(x: Union[GMap, str, "os.PathLike[str]"]) -> Optional[Dict[str, Any]]:
    """A non-contractible cycle of the fewest edges, as shortest_non_contractible_cycle."""

def face_width(x: Union[GMap, str, "os.PathLike[str]"]) -> Optional[Dict[str, Any]]:
    """The face width of a closed surface: `width`, `face_darts`, `vertex_darts`."""

def is_contractible(x: Union[GMap, str, "os.PathLike[str]"], path: Sequence[int], *, vertices: bool = False) -> bool:
    """Whether a closed path (darts, or vertices with vertices=True) is contractible."""

def are_freely_homotopic(
    x: Union[GMap, str, "os.PathLike[str]"], p: Sequence[int], q: Sequence[int], *, vertices: bool = False
) -> bool:
    """Whether two closed paths are freely homotopic (PreconditionError where undecided)."""

def are_homotopic_with_fixed_endpoints(
    x: Union[GMap, str, "os.PathLike[str]"], p: Sequence[int], q: Sequence[int], *, vertices: bool = False
) -> bool:
    """Whether two paths with the same ends are homotopic with their ends fixed."""

def is_homotopic_to_simple_cycle(
    x: Union[GMap, str, "os.PathLike[str]"], path: Sequence[int], *, vertices: bool = False
) -> bool:
    """Whether a closed path is homotopic to a simple closed curve (PreconditionError where undecided)."""

Cycle = Tuple[Union[npt.NDArray[np.int64], List[Tuple[int, ...]]], npt.NDArray[np.int64]]

def persistence(
    x: Union[PathLike, GMap, CubicalSet, Image, SimplicialComplex, ArchComplex, Sequence[Sequence[int]], npt.NDArray[Any]],
    *,
    field: int = 2,
    construction: str = "T",
    superlevel: bool = False,
    periodic: bool = False,
    cycles: bool = False,
    label: str = "value",
    vertex_values: Union[None, Mapping[int, float], Sequence[float], npt.NDArray[Any]] = None,
    facet_values: Optional[Sequence[float]] = None,
    min_persistence: float = 0.0,
) -> Union[npt.NDArray[np.float64], Tuple[npt.NDArray[np.float64], List[Cycle]]]:
    """The persistence diagram of `x` over Z/field: a (k, 3) float64 array of (dimension,
    birth, death), inf for essential classes; with cycles=True also a representative cycle
    per pair, (cells, coefficients) in the input's terms. A simplicial complex takes
    vertex_values (the lower-star filtration: {label: value} or a sequence indexed by label)
    or facet_values (one per facet, in the order given for a list of facets, in the order of
    its facets for a SimplicialComplex; a face takes the minimum). Pairs living min_persistence or
    less are left out; a float32 array gives float32 pairs.
    An image past the memory limit (set_max_memory) is computed from its lower stars, read
    in place (1 to 4 axes, neither periodic nor with cycles)."""

def set_max_memory(nbytes: Optional[int]) -> None:
    """The memory limit of the calls that follow (the command's --max-memory): work whose
    estimate passes it is refused with LimitError, and a grey array past it takes the Morse
    route of persistence (its lower stars, read in place). None restores the default."""

def max_memory() -> int:
    """The memory limit in force, in bytes."""

def open(path: PathLike) -> Union[GMap, SimplicialComplex, CubicalSet, Image, ArchComplex]:
    """What the file holds, in the class the format registry names for its kind."""

def _bench_json(paths: Sequence[PathLike]) -> str: ...
def _page(x: Any, path: Optional[PathLike] = None, generators: bool = False, color_by: Optional[str] = None) -> str: ...
def _page_frame(x: Any) -> str: ...
def _build_grid(shape: Sequence[int], periodic: Union[None, bool, Sequence[bool]] = None) -> GMap: ...
def _build_simplex(n: int) -> GMap: ...
def _build_cube(n: int) -> GMap: ...
def _build_polygon(k: int) -> GMap: ...
def _build_lens_space(p: int, q: int) -> GMap: ...
def _build_solid_torus(k: int) -> GMap: ...
def _build_surface(word: str) -> GMap: ...
def _build_from_facets(facets: Facets) -> GMap: ...
def _image_pairs(
    values: npt.NDArray[np.float64], construction: str, periodic: Sequence[bool], field: int,
    superlevel: bool, min_persistence: float, cells: bool,
) -> Tuple[npt.NDArray[np.float64], List[Tuple[int, ...]], List[Optional[Tuple[int, ...]]]]: ...
def _simplex_pairs(
    simplices: Sequence[Sequence[int]], values: Sequence[float], field: int, min_persistence: float, cells: bool,
) -> Tuple[npt.NDArray[np.float64], List[Tuple[int, ...]], List[Optional[Tuple[int, ...]]]]: ...
def _perseus_cubical(path: PathLike) -> Tuple[npt.NDArray[np.float64], Tuple[int, ...], Tuple[bool, ...]]: ...
