"""The package under hostile calls (issue 47): no panic and no abort anywhere. Every public
function and method is driven with hostile values (huge and negative ints, floats, NaN,
wrong types, empty arrays, float16, masked arrays, 2**70 labels); each call returns or
raises an ordinary exception — a gmap error for what the library refuses, TypeError /
OverflowError / ValueError for an argument Python itself cannot convert — never
pyo3's PanicException (a BaseException). Builders estimate their memory under the policy
first. One GMap read from many threads at once, and written while read, raises gmap errors
only."""

import os
import subprocess
import sys
import threading

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import gmap

# what an argument conversion of Python itself may raise; everything the library refuses is
# a GmapError
ORDINARY = (gmap.GmapError, TypeError, OverflowError, ValueError)

HOSTILE_INTS = [2**70, 2**64, 2**64 - 1, 2**63, 2**32, 10**12, 10**9, 10**8, -1, -(2**63), 0, 1, 2]
HOSTILE = HOSTILE_INTS + [
    float("nan"),
    float("inf"),
    -0.0,
    1.5,
    "x",
    None,
    [],
    (),
    b"",
    [[]],
    [[0, 2**70]],
    [[-1, 0]],
    [[0, 1], [1]],
    True,
]


def hostile_arrays():
    return [
        np.zeros(0),
        np.zeros((0, 3)),
        np.zeros((3, 0, 2)),
        np.ones((2, 2), np.float16),
        np.ma.masked_array(np.ones((3, 3)), mask=np.eye(3)),
        np.array([[0, 2**63]], dtype=np.uint64),
        np.full((2, 2), np.nan),
        np.ones((1,) * 9, bool),
        np.ones((2, 2), complex),
        np.array(["a", "b"]),
        np.array([[0, 1, 2]], dtype=object),
        np.ones((2,) * 8, bool),
    ]


def calls_ok(f, *a, **k):
    """Calls f; an exception must be an ordinary one (a PanicException is a BaseException
    and is not caught here: the test fails with it)."""
    try:
        f(*a, **k)
    except ORDINARY:
        pass


@pytest.fixture(autouse=True)
def small_memory_limit():
    gmap.set_max_memory(1_000_000_000)
    yield
    gmap.set_max_memory(None)


VALUES = st.one_of(st.sampled_from(HOSTILE), st.integers(-(2**80), 2**80), st.floats(allow_nan=True))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(v=VALUES, w=VALUES)
def test_builders_and_constructors_refuse_hostile_values(v, w):
    b = gmap.build
    for f in (b.simplex, b.cube, b.polygon, b.solid_torus, b.surface, b.from_facets):
        calls_ok(f, v)
    calls_ok(b.lens_space, v, w)
    calls_ok(b.grid, (v, w))
    calls_ok(b.grid, (2, 2), (v, w))
    calls_ok(gmap.GMap, v, w)
    calls_ok(gmap.CubicalSet, np.ones((2, 2), bool), [v, w])
    for f in (gmap.SimplicialComplex, gmap.CubicalSet, gmap.ArchComplex, gmap.GMap.from_alphas, gmap.GMap.from_text):
        calls_ok(f, v)
    for kw in ("field", "level", "method", "generators", "periodic"):
        calls_ok(gmap.homology, [[0, 1, 2]], **{kw: v})
        calls_ok(gmap.homology, np.ones((3, 3), bool), **{kw: v})
    for kw in ("field", "superlevel", "construction", "cycles", "periodic"):
        calls_ok(gmap.persistence, np.arange(16.0).reshape(4, 4), **{kw: v})


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(v=VALUES, pos=st.integers(0, 2))
def test_gmap_methods_refuse_hostile_values(v, pos):
    methods = [
        ("alpha", 2), ("is_free", 2), ("unsew", 2), ("cells", 1), ("labels", 1), ("remove_cell", 2),
        ("contract_cell", 2), ("is_removable", 2), ("is_contractible", 2), ("insert_barycenter_in_cell", 2),
        ("add_darts", 1), ("insert_cell_0_in_cell_1", 1), ("insert_cell_0_in_cell_2", 1),
        ("insert_cell_1_in_cell_2", 2), ("insert_dangling_cell_1_in_cell_2", 1),
        ("insert_cell_1_between_two_cells_2", 2), ("sew", 3), ("is_sewable", 3),
    ]  # fmt: skip
    for name, n in methods:
        args = [0] * n
        args[min(pos, n - 1)] = v
        calls_ok(getattr(gmap.build.grid((3, 3)), name), *args)
    m = gmap.build.grid((2, 2))
    calls_ok(m.set_label, 0, 0, "a", v)
    calls_ok(m.set_label, v, 0, "a", 1)
    calls_ok(m.insert_point_in_cell, 0, [v, 0, 0], 2)
    calls_ok(m.orbit, 0, [v])
    calls_ok(setattr, m, "points", v)


def test_hostile_arrays_everywhere(tmp_path):
    for a in hostile_arrays():
        for f in (gmap.homology, gmap.persistence, gmap.CubicalSet, gmap.SimplicialComplex, gmap.build.from_facets):
            calls_ok(f, a)
        calls_ok(gmap.GMap.from_alphas, a)
        calls_ok(setattr, gmap.build.grid((1, 1)), "points", a)


def test_huge_builders_are_refused_by_estimate_before_allocating():
    # issue 47: L(10^9, 1) was a PanicException after taking the machine's memory
    for f, args in [
        (gmap.build.lens_space, (10**9, 1)),
        (gmap.build.lens_space, (10**8, 1)),
        (gmap.build.grid, ((10**5, 10**5),)),
        (gmap.build.solid_torus, (2**32,)),
        (gmap.build.polygon, (2**31,)),
        (gmap.GMap, (0, 10**8)),
        (gmap.GMap, (3, 2**31)),
    ]:
        with pytest.raises(gmap.LimitError, match="memory limit|2\\^32 - 2|at most"):
            f(*args)
    m = gmap.GMap(2, 1)
    with pytest.raises(gmap.LimitError):
        m.add_darts(10**8)
    with pytest.raises(gmap.LimitError):
        m.add_darts(2**64 - 1)
    # the cube's dimension is refused before a list of its sides is made
    for n in (2**32, 2**63, 10**12):
        with pytest.raises(gmap.InputError, match="dimension from 0 to"):
            gmap.build.cube(n)
    with pytest.raises(gmap.LimitError):
        gmap.build.simplex(2**64 - 1)


def test_builders_do_not_abort_under_an_address_space_limit():
    # issue 47: under ulimit -v 8000000, lens_space(10^8, 1) ended the interpreter (SIGABRT)
    code = (
        "import resource, gmap\n"
        "resource.setrlimit(resource.RLIMIT_AS, (8_000_000_000, 8_000_000_000))\n"
        "for p in (10**8, 10**9):\n"
        "    try:\n"
        "        gmap.build.lens_space(p, 1)\n"
        "    except gmap.LimitError as e:\n"
        "        print('refused', p)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split("\n")[:2] == ["refused 100000000", "refused 1000000000"]


def test_a_label_past_64_bits_is_refused_not_stored_as_a_float():
    m = gmap.build.grid((1, 1))
    for v in (2**70, 2**63, -(2**63) - 1, np.uint64(2**64 - 1)):
        with pytest.raises(gmap.InputError, match="64 bits"):
            m.set_label(0, 0, "big", v)
    assert m.labels(0)[0] == {}
    m.set_label(0, 0, "big", 2**63 - 1)
    m.set_label(0, 1, "small", np.int64(-5))
    assert m.labels(0)[0]["big"] == 2**63 - 1 and isinstance(m.labels(0)[0]["big"], int)


def test_float16_is_refused_as_the_command_refuses_it(tmp_path, gmap_bin):
    a = np.ones((3, 3), np.float16)
    path = tmp_path / "half.npy"
    np.save(path, a)
    cli = subprocess.run([gmap_bin, "homology", str(path)], capture_output=True, text=True)
    assert cli.returncode != 0
    rule = "dtype '<f2' is not read: bool, integers (i1–i8, u1–u8) and floats (f4, f8) are"
    assert rule in cli.stderr
    for f in (gmap.homology, gmap.persistence, gmap.CubicalSet):
        with pytest.raises(gmap.GmapError) as e:
            f(a)
        assert rule in str(e.value), f
    # and through the file, the same rule
    with pytest.raises(gmap.GmapError, match="is not read"):
        gmap.homology(str(path))


def test_a_masked_array_is_refused_naming_the_choices():
    a = np.ma.masked_array(np.ones((3, 3)), mask=np.eye(3))
    for f in (gmap.homology, gmap.persistence, gmap.CubicalSet):
        with pytest.raises(gmap.InputError, match="masked array is refused.*a.filled\\(0\\).*a.data"):
            f(a)
    # the choices it names work
    assert gmap.homology(a.filled(0)).betti == [1, 1, 0]
    assert gmap.homology(a.data).betti == [1, 0, 0]


def test_a_4_map_saved_as_moka_is_a_gmap_error(tmp_path):
    m = gmap.build.grid((1, 1, 1, 1))
    out = tmp_path / "m.moka"
    with pytest.raises(gmap.GmapError, match="dimension at most 3") as e:
        m.save(out)
    assert not isinstance(e.value, OSError)
    assert not out.exists()


def test_a_bowtie_save_keeps_the_space_or_refuses(tmp_path):
    s = gmap.SimplicialComplex([[0, 1, 2], [0, 3, 4]])
    out = tmp_path / "b.gmap"
    with pytest.raises(gmap.GmapError, match="the vertex 0 becomes 2 cells") as e:
        s.save(out)
    assert e.value.item == (0,)
    assert ".facets, .json, .dot, .graphml keep it" in str(e.value)
    assert not out.exists()
    with pytest.warns(UserWarning, match="another space"):
        s.save(out, lossy=True)
    assert gmap.homology(str(out)).betti == [2, 0, 0]
    s.save(tmp_path / "b.facets")
    assert gmap.homology(str(tmp_path / "b.facets")).betti == [1, 0, 0]


def test_many_threads_read_one_map_at_once():
    m = gmap.build.grid((12, 12, 12))
    want = gmap.homology(m).betti
    errors, results = [], []

    def homology():
        try:
            results.append(gmap.homology(m).betti)
        except BaseException as e:  # noqa: BLE001 - a panic is what is looked for
            errors.append(repr(e))

    def reads():
        try:
            for _ in range(3):
                m.incidences()
                m.is_orientable()
                m.cells(1)
                m.components()
        except BaseException as e:  # noqa: BLE001
            errors.append(repr(e))

    threads = [threading.Thread(target=homology) for _ in range(12)]
    threads += [threading.Thread(target=reads) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    assert results == [want] * 12


def test_a_write_racing_a_read_is_a_gmap_error_at_most():
    m = gmap.build.grid((14, 14, 14))
    errors = []
    stop = threading.Event()

    def reads():
        while not stop.is_set():
            try:
                m.incidences()
                # free darts added meanwhile: the cellular method refuses the map (a gmap
                # error); what must not happen is a panic or a Python error
                gmap.homology(m)
            except gmap.GmapError:
                pass
            except BaseException as e:  # noqa: BLE001
                errors.append(repr(e))
                return

    readers = [threading.Thread(target=reads) for _ in range(3)]
    for t in readers:
        t.start()
    base, written = len(m), 0
    try:
        for _ in range(40):
            try:
                m.add_darts(2)
                written += 1
            except gmap.GmapError:
                pass
    finally:
        stop.set()
        for t in readers:
            t.join()
    assert errors == []
    assert len(m) == base + 2 * written


def test_a_sparse_terabyte_npy_is_refused_as_the_command_refuses_it(tmp_path, gmap_bin):
    """A header declaring 10000**3 = 10**12 voxels, then a 1 TB hole: gmap.homology(path)
    refuses it at once with the estimate and message of `gmap homology`, gmap.open(path)
    opens it (memory-mapped, nothing read) and its homology is refused the same way."""
    d = b"{'descr': '|u1', 'fortran_order': False, 'shape': (10000, 10000, 10000), }"
    d += b" " * ((64 - (10 + len(d) + 1) % 64) % 64) + b"\n"
    path = tmp_path / "huge.npy"
    with open(path, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + len(d).to_bytes(2, "little") + d)
        f.truncate(f.tell() + 10**12)
    cli = subprocess.run([gmap_bin, "homology", str(path), "--max-memory", "8G"], capture_output=True, text=True)
    assert cli.returncode == 1
    message = cli.stderr.strip().removeprefix("error: ")
    assert "the layers of the one-pass cubical homology would take an estimated 14405760576 bytes" in message
    gmap.set_max_memory(8 * 2**30)
    with pytest.raises(gmap.LimitError) as e:
        gmap.homology(str(path))
    assert str(e.value) == message
    img = gmap.open(str(path))
    assert img.shape == [10000, 10000, 10000]
    with pytest.raises(gmap.LimitError) as e:
        gmap.homology(img)
    assert "would take an estimated 14405760576 bytes" in str(e.value)


def test_homology_through_the_gmap_of_a_bowtie_is_refused_naming_the_vertex():
    """Two triangles sharing the vertex 0 only: H_0 = Z directly; through the G-map (which
    splits the vertex) a PreconditionError naming it, not the groups of another space."""
    bowtie = [[0, 1, 2], [0, 3, 4]]
    assert gmap.homology(bowtie).betti == [1, 0, 0]
    for method in ("gmap", "simplicial"):
        with pytest.raises(gmap.PreconditionError) as e:
            gmap.homology(bowtie, method=method)
        assert "the facets around the vertex 0 fall into 2 groups" in str(e.value)
        assert "so the vertex 0 becomes 2 cells" in str(e.value)
