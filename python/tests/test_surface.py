"""The whole surface of the package under hostile calls, hypothesis-driven (issue 47).

Every function of the compiled module ``gmap._gmap`` and of ``gmap``, ``gmap.build`` and
``gmap.gudhi``, every constructor, and every public method, property and pickling method
(``__setstate__``, ``__getitem__``, …) of their classes is called on fresh small objects
with arguments drawn from hostile values (huge and negative ints, NaN, wrong types, empty,
float16, masked and 9-axis arrays, paths of empty, truncated and garbage files, a sparse
``.npy`` declaring 10^12 voxels, a folder) mixed with plausible ones (small ints, shapes,
facets, small arrays, copies of files of tests/data, the package's own objects), so that
calls get past the argument checks. Each call must return or raise an ``Exception``:
pyo3's ``PanicException`` (a ``BaseException``) fails the test; an abort would end the
interpreter. Calls from the compiled module may raise only a ``GmapError``, what Python's
own argument conversion raises (``TypeError``, ``ValueError``, ``OverflowError``) or, for a
file that cannot be opened, read or written, an ``OSError`` (as ``open`` raises).

Every file the calls may write lands in a temporary folder (the current folder during the
test). ``GMAP_SURFACE_EXAMPLES`` is the number of examples per callable (default 6: the
CI's short run); ``GMAP_SURFACE_REPORT=FILE`` writes the counts of calls and outcomes as
JSON at the end (the long run's figures are in fuzz/README.md)."""

import atexit
import collections
import inspect
import json
import os
import shutil
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import gmap
import gmap.gudhi

from conftest import DATA

EXAMPLES = int(os.environ.get("GMAP_SURFACE_EXAMPLES", "6"))
ORDINARY = (gmap.GmapError, TypeError, OverflowError, ValueError, OSError)
# the limit every call runs under: builders past it are refused by their estimate
LIMIT = 300_000_000

# --- the files: copies of test data (never the originals: calls may write to them) and
# hostile ones, in a folder of their own that is also the current folder of the calls
FILES = Path(tempfile.mkdtemp(prefix="gmap-surface-"))
atexit.register(shutil.rmtree, FILES, True)


def _npy_header(shape):
    d = f"{{'descr': '|u1', 'fortran_order': False, 'shape': {shape}, }}".encode()
    d += b" " * ((64 - (10 + len(d) + 1) % 64) % 64) + b"\n"
    return b"\x93NUMPY\x01\x00" + len(d).to_bytes(2, "little") + d


def _make_files():
    good = [
        "tetrahedron.facets",
        "rp2.facets",
        "labelled_segment.gmap",
        "images/text.npy",
        "images/text.pgm",
        "persistence/torus.txt",
        "persistence/hollow_triangle.txt",
    ]
    good += [str(p.relative_to(DATA)) for p in sorted((DATA / "cubical").glob("*.c[ue][bl]"))[:3]]
    good += [str(p.relative_to(DATA)) for p in sorted((DATA / "mesh").glob("*.vt[ku]"))[:2]]
    good += [str(p.relative_to(DATA)) for p in sorted((DATA / "mesh").glob("*.msh"))[:2]]
    good += [str(p.relative_to(DATA)) for p in sorted((DATA / "arch").glob("*.json"))[:2]]
    paths = []
    for rel in good:
        src = DATA / rel
        if not src.is_file():
            continue
        dst = FILES / src.name
        shutil.copyfile(src, dst)
        paths.append(str(dst))
        # the same file cut in half
        cut = FILES / f"cut_{src.name}"
        cut.write_bytes(src.read_bytes()[: src.stat().st_size // 2])
        paths.append(str(cut))
    for ext in ["gmap", "moka", "off", "vtk", "vtu", "msh", "facets", "lex", "json", "cub", "cel", "pbm",
                "npy", "complex", "pgm", "png", "txt", "lar.json", "dot", "graphml", "xyz"]:  # fmt: skip
        (FILES / f"empty.{ext}").write_bytes(b"")
        (FILES / f"garbage.{ext}").write_bytes(bytes(range(256)) * 3)
        paths += [str(FILES / f"empty.{ext}"), str(FILES / f"garbage.{ext}")]
    (FILES / "bowtie.facets").write_text("0 1 2\n0 3 4\n")
    # a sparse .npy declaring 10^12 voxels (a header, then a hole of 1 TB)
    with open(FILES / "huge.npy", "wb") as f:
        f.write(_npy_header("(10000, 10000, 10000)"))
        f.truncate(f.tell() + 10**12)
    (FILES / "folder").mkdir()
    paths += [str(FILES / "bowtie.facets"), str(FILES / "huge.npy"), str(FILES / "folder"), str(FILES / "missing.gmap")]
    return paths


PATHS = _make_files()

HOSTILE = [2**70, 2**64, 2**63, 2**32, 10**12, 10**9, -1, -(2**63), float("nan"), float("inf"), -0.0, 1.5, "",
           "x", None, [], (), b"", [[]], [[0, 2**70]], [[-1, 0]], [[0, 1], [1]], True, {}, object()]  # fmt: skip


def _arrays():
    return [
        np.zeros(0),
        np.zeros((0, 3)),
        np.ones((2, 2), np.float16),
        np.ma.masked_array(np.ones((3, 3)), mask=np.eye(3)),
        np.array([[0, 2**63]], dtype=np.uint64),
        np.full((2, 2), np.nan),
        np.ones((1,) * 9, bool),
        np.ones((2, 2), complex),
        np.array(["a", "b"]),
        np.ones((3, 3), bool),
        np.arange(16.0).reshape(4, 4),
        np.arange(27.0).reshape(3, 3, 3)[:, ::2],
        np.array([[0, 1, 2], [0, 2, 3]]),
        np.array([[1, 0, 2], [0, 3, 0]], dtype=np.int32),
        np.array([[0, 0.0, 1.0], [1, 0.5, np.inf]]),
    ]


def _objects():
    """Fresh small objects of every class, by name (a call may change the one it gets)."""
    arch = next(p for p in PATHS if p.endswith(".json") and "/cut_" not in p and "garbage" not in p and "empty" not in p)
    return {
        "GMap": lambda: gmap.build.grid((2, 2)),
        "GMap3": lambda: gmap.build.cube(3),
        "SimplicialComplex": lambda: gmap.SimplicialComplex([[0, 1, 2], [0, 2, 3], [1, 2, 3]]),
        "CubicalSet": lambda: gmap.CubicalSet(np.array([[1, 1], [1, 0]], bool)),
        "Image": lambda: gmap.open(str(FILES / "text.npy")),
        "ArchComplex": lambda: gmap.open(arch),
        "Homology": lambda: gmap.homology([[0, 1, 2]]),
        "Generator": lambda: gmap.homology(gmap.build.grid((2, 2), True), generators=True).generators[0],
        "SimplexTree": lambda: _simplex_tree(),
        "CubicalComplex": lambda: gmap.gudhi.CubicalComplex(top_dimensional_cells=np.arange(9.0).reshape(3, 3)),
        "PeriodicCubicalComplex": lambda: gmap.gudhi.PeriodicCubicalComplex(
            top_dimensional_cells=np.arange(9.0).reshape(3, 3), periodic_dimensions=[True, False]
        ),
    }


def _simplex_tree():
    t = gmap.gudhi.SimplexTree()
    t.insert([0, 1, 2], 1.0)
    t.insert([2, 3], 2.0)
    return t


OBJECTS = _objects()

SMALL = st.integers(-2, 5)
VALUES = st.deferred(
    lambda: st.one_of(
        st.sampled_from(HOSTILE),
        SMALL,
        st.integers(-(2**80), 2**80),
        st.floats(allow_nan=True),
        st.booleans(),
        st.text(alphabet="abcxyz.#_-ZQ0123456789", max_size=10),
        st.sampled_from(["direct", "gmap", "cellular", "simplicial", "rips", "alpha", "auto", "faces", "png", "svg"]),
        st.sampled_from(PATHS),
        st.sampled_from(PATHS).map(lambda p: f"{p}.out{p[p.rfind('.'):] if '.' in p else ''}"),
        st.builds(lambda i: _arrays()[i], st.integers(0, len(_arrays()) - 1)),
        st.lists(st.lists(st.integers(-1, 6), max_size=4), max_size=4),
        st.tuples(SMALL, SMALL),
        st.lists(VALUES, max_size=3),
        st.builds(lambda k: OBJECTS[k](), st.sampled_from(sorted(OBJECTS))),
    )
)


def _module_functions(mod, prefix):
    out = []
    for name in sorted(dir(mod)):
        f = getattr(mod, name)
        if name.startswith("__") or inspect.isclass(f) or inspect.ismodule(f) or not callable(f):
            continue
        out.append((f"{prefix}.{name}", None, name))
    return out


def _targets():
    """(id, object name or None, attribute): a module function, a class (its constructor)
    or a method or property of a fresh object."""
    t = _module_functions(gmap._gmap, "gmap._gmap")
    # the Python layer's public functions (its private helpers take what the package hands
    # them: `_gudhi_time` passes facets to GUDHI itself, which crashes on a negative vertex)
    t += [x for x in _module_functions(gmap, "gmap") if not hasattr(gmap._gmap, x[2]) and not x[2].startswith("_")]
    t += _module_functions(gmap.build, "gmap.build")
    t += [x for x in _module_functions(gmap.gudhi, "gmap.gudhi") if not x[2].startswith("_")]
    # the calls below are the classes' constructors
    for mod, prefix in [(gmap._gmap, "gmap._gmap"), (gmap.gudhi, "gmap.gudhi")]:
        for name in sorted(dir(mod)):
            c = getattr(mod, name)
            if inspect.isclass(c) and not issubclass(c, BaseException) and not name.startswith("_"):
                t.append((f"{prefix}.{name}()", None, ("class", mod, name)))
    extra = {"__setstate__", "__getitem__", "__contains__", "__eq__", "__reduce__", "__getstate__", "__len__", "__iter__"}
    for obj in sorted(OBJECTS):
        o = OBJECTS[obj]()
        for name in sorted(dir(o)):
            if (name.startswith("_") and name not in extra) or name in {"incidence_graph"}:
                continue
            t.append((f"{obj}.{name}", obj, name))
    return t


TARGETS = _targets()
# callables that take only small values (none today: SimplexTree.expansion(2**63) ends at
# once, its loop bounded by the vertex count)
SMALL_ONLY: set = set()
# what the run met: calls, and each outcome's count (returned, or the exception's type)
COUNTS = collections.Counter()
PER_TARGET = collections.Counter()


def _write_report():
    path = os.environ.get("GMAP_SURFACE_REPORT")
    if path:
        report = {
            "targets": len(TARGETS),
            "examples_per_target": EXAMPLES,
            "calls": sum(PER_TARGET.values()),
            "outcomes": dict(COUNTS.most_common()),
            "panics": COUNTS.get("PanicException", 0),
        }
        Path(path).write_text(json.dumps(report, indent=1) + "\n")


atexit.register(_write_report)


def _call(tid, compiled, f, args, kwargs, also=()):
    """Calls f; a panic or an exception the library should have turned into a GmapError
    fails with the call written out."""
    PER_TARGET[tid] += 1
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            f(*args, **kwargs)
        COUNTS["returned"] += 1
    except KeyboardInterrupt:
        raise
    except BaseException as e:  # noqa: BLE001 - a PanicException is a BaseException
        kind = type(e).__name__
        COUNTS[kind] += 1
        call = f"{tid}(*{args!r:.300}, **{kwargs!r:.300})"
        if kind == "PanicException" or not isinstance(e, Exception):
            raise AssertionError(f"{call} panicked or escaped: {kind}: {e}") from None
        if compiled and not isinstance(e, ORDINARY + also):
            raise AssertionError(f"{call} raised {kind}: {e} (not a GmapError)") from None
    finally:
        gmap.set_max_memory(LIMIT)


def _parameters(f):
    try:
        return [
            p
            for p in inspect.signature(f).parameters.values()
            if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and p.name != "self"
        ]
    except (TypeError, ValueError):
        return None


@pytest.fixture(autouse=True)
def in_the_files_folder():
    old = os.getcwd()
    os.chdir(FILES)
    gmap.set_max_memory(LIMIT)
    yield
    gmap.set_max_memory(None)
    os.chdir(old)


@pytest.mark.parametrize("target", TARGETS, ids=[t[0] for t in TARGETS])
@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=list(HealthCheck), database=None)
@given(data=st.data())
def test_every_callable_survives_hostile_arguments(target, data):
    tid, obj, attr = target
    compiled = tid.startswith("gmap._gmap") or (obj is not None and obj not in {"SimplexTree", "CubicalComplex", "PeriodicCubicalComplex"})
    if isinstance(attr, tuple):
        _, mod, name = attr
        f = getattr(mod, name)
        compiled = mod is gmap._gmap
    elif obj is None:
        mod = {"gmap._gmap": gmap._gmap, "gmap.build": gmap.build, "gmap.gudhi": gmap.gudhi, "gmap": gmap}[tid.rsplit(".", 1)[0]]
        f = getattr(mod, attr)
    else:
        o = OBJECTS[obj]()
        a = inspect.getattr_static(o, attr, None)
        if isinstance(a, property) or (a is not None and type(a).__name__ == "getset_descriptor"):
            # a property: read it, and set it to a hostile value
            _call(tid, compiled, lambda: getattr(o, attr), (), {})
            if data.draw(st.booleans(), label="set"):
                # a property without a setter: Python's AttributeError
                _call(tid, compiled, setattr, (o, attr, data.draw(VALUES, label="value")), {}, (AttributeError,))
            return
        f = getattr(o, attr)
        if not callable(f):
            return
        # a method the Python layer adds (view, from_meshio, to_pyvista, …) is not compiled
        compiled = compiled and not (inspect.ismethod(f) or inspect.isfunction(f))
    params = _parameters(f)
    n = len(params) if params is not None else 3
    k = data.draw(st.integers(0, n + 1), label="positional")
    values = SMALL if tid in SMALL_ONLY else VALUES
    args = tuple(data.draw(values, label=f"arg{i}") for i in range(k))
    kwargs = {}
    for p in (params or [])[k:]:
        if data.draw(st.booleans(), label=f"give {p.name}"):
            kwargs[p.name] = data.draw(values, label=p.name)
    _call(tid, compiled, f, args, kwargs)
    if obj is not None:
        # the object after the call is still one the package can read, or refuses with an
        # ordinary error
        for g in ("__len__", "to_text", "cell_counts", "is_valid"):
            if hasattr(o, g):
                _call(f"{tid} then {g}", compiled, getattr(o, g), (), {})


def test_the_surface_is_all_there():
    """The targets cover the compiled module's every function and class and the classes'
    methods: a new function cannot be left out of the hostile run."""
    ids = {t[0] for t in TARGETS}
    for name in dir(gmap._gmap):
        f = getattr(gmap._gmap, name)
        if name.startswith("__") or inspect.ismodule(f) or (inspect.isclass(f) and issubclass(f, BaseException)):
            continue
        assert (f"gmap._gmap.{name}" in ids) or (f"gmap._gmap.{name}()" in ids), name
    for method in ("GMap.sew", "GMap.remove_cell", "GMap.save", "GMap.__reduce__", "GMap.points", "Image.save",
                   "SimplicialComplex.save", "CubicalSet.to_gmap", "SimplexTree.persistence", "ArchComplex.to_json"):  # fmt: skip
        assert method in ids, method
    assert len(TARGETS) > 150
