"""A GUDHI tutorial-style script (python/examples/gudhi_tutorial.py) runs unchanged but for
its import on gmap.gudhi, with GUDHI's results when GUDHI is installed."""

from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[1] / "examples" / "gudhi_tutorial.py"


def run(import_line):
    text = SCRIPT.read_text()
    assert "import gudhi\n" in text
    scope = {"__name__": "tutorial"}
    exec(compile(text.replace("import gudhi\n", import_line + "\n", 1), str(SCRIPT), "exec"), scope)
    return scope["results"]


def test_the_tutorial_runs_on_gmap():
    r = run("import gmap.gudhi as gudhi")
    assert r["cubical_betti"] == [1, 0, 0]
    assert r["periodic_betti"] == [1, 2, 1]
    assert r["simplicial_betti"] == [1, 0, 1]
    assert r["num_simplices"] == 14 + 2 + 2
    assert r["simplicial_h2"] == [[4.0, float("inf")]]
    assert r["flag_betti"] == [1, 0, 0]


def test_the_tutorial_gives_gudhis_results():
    pytest.importorskip("gudhi")
    ours = run("import gmap.gudhi as gudhi")
    theirs = run("import gudhi")
    assert ours.keys() == theirs.keys()
    for k in ours:
        assert ours[k] == theirs[k], k
