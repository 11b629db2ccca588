"""The package gives the command line's results: on every file in tests/data,
``gmap.homology(path, ...).to_dict()`` equals ``gmap homology PATH --json ...``, and an
input the command refuses raises a GmapError with the command's message."""

import json
import subprocess

import pytest

import gmap
from conftest import DATA, data_files

FILES = data_files()

# (keyword arguments, command-line flags)
OPTIONS = [
    ({}, []),
    ({"field": 2}, ["--field", "2"]),
    ({"field": 3}, ["--field", "3"]),
]
SIMPLICIAL = [({"method": "gmap"}, ["--via", "gmap"]), ({"method": "simplicial"}, ["--method", "simplicial"])]
GENERATORS = [({"generators": True}, ["--generators"])]


def cases():
    for f in FILES:
        opts = list(OPTIONS)
        big = f.stat().st_size > 60_000
        if f.suffix in (".facets", ".lex") and not big:
            opts += SIMPLICIAL
        if not big:
            opts += GENERATORS
        for kw, flags in opts:
            yield pytest.param(f, kw, flags, id=f"{f.relative_to(DATA)}{''.join(flags)}")


def run_cli(binary, path, flags):
    r = subprocess.run([binary, "homology", str(path), "--json", *flags], capture_output=True, text=True)
    return r


def test_there_are_files():
    assert len(FILES) >= 50


@pytest.mark.parametrize("path,kw,flags", list(cases()))
def test_same_as_cli(gmap_bin, path, kw, flags):
    r = run_cli(gmap_bin, path, flags)
    if r.returncode == 0:
        expected = json.loads(r.stdout)
        got = gmap.homology(str(path), **kw).to_dict()
        assert got == expected
    else:
        assert r.returncode == 1, r.stderr
        with pytest.raises(gmap.GmapError) as e:
            gmap.homology(str(path), **kw)
        assert r.stderr.strip() == "error: " + str(e.value)


def test_refusals_as_cli(gmap_bin, tmp_path):
    bad = tmp_path / "bad.facets"
    bad.write_text("1 2 3\n1 2 x\n")
    r = run_cli(gmap_bin, bad, [])
    assert r.returncode == 1
    with pytest.raises(gmap.ParseError) as e:
        gmap.homology(str(bad))
    assert r.stderr.strip() == "error: " + str(e.value)
    assert e.value.file == str(bad)
    assert e.value.line == 2
