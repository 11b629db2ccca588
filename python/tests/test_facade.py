"""One door: what the package does is what the facade (and so the command) does. Images
open as their own class with the command's groups, `save` refuses what `gmap convert`
refuses without --lossy, and errors carry the file, the line and the offending item."""

import json
import subprocess

import numpy as np
import pytest

import gmap
from conftest import DATA


def cli(binary, *args):
    return subprocess.run([binary, *map(str, args)], capture_output=True, text=True)


# ---------------------------------------------------------------- images


@pytest.fixture
def grey(tmp_path):
    """A 2-D grey image with a ring of high values around a low hole, as .npy."""
    a = np.zeros((9, 11), dtype=np.float32)
    a[2:7, 2:9] = 3.0
    a[4, 5] = 0.0
    p = tmp_path / "ring.npy"
    np.save(p, a)
    return p, a


def test_an_npy_file_opens_as_an_image_with_the_commands_groups(gmap_bin, grey):
    p, a = grey
    img = gmap.open(p)
    assert isinstance(img, gmap.Image)
    assert img.dim == 2 and img.shape == [9, 11] and len(img) == a.size
    assert repr(img) == "<gmap.Image dim=2 shape=[9, 11]>"
    for kw, flags in [({}, []), ({"field": 3}, ["--field", "3"]), ({"level": 0.0}, ["--level", "0"]),
                      ({"generators": True}, ["--generators"])]:
        r = cli(gmap_bin, "homology", p, "--json", *flags)
        assert r.returncode == 0, r.stderr
        assert gmap.homology(img, **kw).to_dict() == json.loads(r.stdout), kw
        assert gmap.homology(p, **kw).to_dict() == json.loads(r.stdout), kw
    # the nonzero values are a ring (b1 = 1); at level 0 the zeros are the frame around it
    # (a ring too) and the pixel in its hole
    assert gmap.homology(img).betti == [1, 1, 0]
    assert gmap.homology(img, level=0.0).betti == [2, 1, 0]
    # level applies to images only, as --level does
    with pytest.raises(gmap.InputError, match="--level applies to images"):
        gmap.homology(gmap.SimplicialComplex([[0, 1]]), level=1.0)


def test_an_image_has_its_diagram_its_page_and_its_files(grey, tmp_path):
    p, a = grey
    img = gmap.open(p)
    assert np.array_equal(gmap.persistence(img), gmap.persistence(p))
    assert np.array_equal(gmap.persistence(img), gmap.persistence(a.astype(np.float64)))
    page = img.view()
    assert page.startswith("<!DOCTYPE html>")
    assert img._repr_html_().startswith("<iframe srcdoc=")
    out = tmp_path / "copy.npy"
    img.save(out)
    assert np.array_equal(np.load(out), a)
    dipha = tmp_path / "copy.complex"
    img.save(dipha)
    assert np.array_equal(gmap.persistence(dipha), gmap.persistence(img))
    with pytest.raises(gmap.InputError, match="an image is written as .npy or .complex"):
        img.save(tmp_path / "copy.gmap")


@pytest.mark.parametrize("name", ["images/camera.pgm", "images/camera.npy", "cubical/ring.cub", "cubical/cube_faces.cel",
                                  "cubical/annulus_p1.pbm", "rp2.facets", "labelled_segment.gmap", "arch/court.json"])
def test_every_kind_opens_as_the_class_the_registry_names(name):
    x = gmap.open(DATA / name)
    expected = {
        ".pgm": gmap.Image, ".npy": gmap.Image, ".cub": gmap.CubicalSet, ".cel": gmap.CubicalSet,
        ".pbm": gmap.CubicalSet, ".facets": gmap.SimplicialComplex, ".gmap": gmap.GMap, ".json": gmap.ArchComplex,
    }["." + name.rsplit(".", 1)[1]]
    assert type(x) is expected
    assert gmap.homology(x) == gmap.homology(DATA / name)


# ---------------------------------------------------------------- save and lossy


def test_save_refuses_what_convert_refuses_without_lossy(gmap_bin, tmp_path):
    src = DATA / "labelled_segment.gmap"
    out = tmp_path / "cli.moka"
    r = cli(gmap_bin, "convert", src, out)
    assert r.returncode == 1 and "drops the labels" in r.stderr and not out.exists()
    m = gmap.open(src)
    mine = tmp_path / "py.moka"
    with pytest.raises(gmap.InputError, match="drops the labels") as e:
        m.save(mine)
    assert e.value.path == str(mine)
    assert not mine.exists()
    # with lossy: the same file the command writes with --lossy
    m.save(mine, lossy=True)
    assert cli(gmap_bin, "convert", "--lossy", src, out).returncode == 0
    assert mine.read_text() == out.read_text()
    # a format that keeps everything needs no lossy, and reads back the same
    again = tmp_path / "again.gmap"
    m.save(again)
    assert gmap.open(again).to_text() == m.to_text()
    # an architectural complex: refused or written in each format as the command does
    arch = DATA / "arch" / "rooms_door_window.json"
    x = gmap.open(arch)
    for ext in ("gmap", "moka", "off", "facets", "json", "dot"):
        cmd = cli(gmap_bin, "convert", arch, tmp_path / f"cli.{ext}")
        try:
            x.save(tmp_path / f"py.{ext}")
        except gmap.GmapError:
            written = False
        else:
            written = True
        assert written == (cmd.returncode == 0), (ext, cmd.stderr)


def test_every_class_saves_through_the_registry(tmp_path):
    sc = gmap.SimplicialComplex([[0, 1, 2], [0, 2, 3], [0, 1, 3], [1, 2, 3]])
    sc.save(tmp_path / "s.facets")
    assert (tmp_path / "s.facets").read_text() == "0 1 2\n0 2 3\n0 1 3\n1 2 3\n"
    sc.save(tmp_path / "s.gmap")
    assert gmap.homology(gmap.open(tmp_path / "s.gmap")) == gmap.homology(sc)
    cs = gmap.CubicalSet(np.array([[1, 1, 1], [1, 0, 1], [1, 1, 1]], dtype=bool), min=[2, -1])
    cs.save(tmp_path / "c.cub")
    back = gmap.open(tmp_path / "c.cub")
    assert back.min == [2, -1] and np.array_equal(back.array, cs.array)
    cs.save(tmp_path / "c.vtk")
    assert (tmp_path / "c.vtk").read_text().startswith("# vtk DataFile")
    with pytest.raises(gmap.InputError, match="holds cubical sets"):
        gmap.build.polygon(3).save(tmp_path / "p.cub")


def test_a_c_ordered_array_keeps_its_axes_in_the_set():
    a = np.zeros((2, 5), dtype=bool)
    a[0, 4] = a[1, 0] = True
    c = gmap.CubicalSet(a)
    assert c.shape == [2, 5] and np.array_equal(c.array, a)
    assert np.array_equal(gmap.CubicalSet(np.asfortranarray(a)).array, a)
    assert np.array_equal(gmap.CubicalSet(a.astype(np.float32) * 0.5).array, a)
    h = gmap.homology(c, generators=True)
    # the two cubes are components: each generator's vertex is a corner of one of them
    corners = {tuple(g.cells[0]) for g in h.generators if g.dim == 0}
    assert len(corners) == 2 and all(0 <= x <= 2 and 0 <= y <= 5 for x, y in corners)


# ---------------------------------------------------------------- errors carry what they are about


def test_a_parse_error_carries_path_line_and_the_offending_ridge(tmp_path):
    p = tmp_path / "ridge.facets"
    p.write_text("1 2 3\n1 2 4\n1 2 5\n")
    # the direct route takes any complex; the G-map needs a pseudo-manifold
    assert gmap.homology(p).betti == [1, 0, 0]
    with pytest.raises(gmap.ParseError) as e:
        gmap.homology(p, method="gmap")
    assert e.value.path == str(p) and e.value.file == str(p)
    assert e.value.line == 1
    assert e.value.item == (1, 2) and e.value.item_kind == "simplex"
    bad = tmp_path / "word.facets"
    bad.write_text("1 2 3\n4 x 6\n")
    with pytest.raises(gmap.ParseError) as e:
        gmap.open(bad)
    assert (e.value.path, e.value.line, e.value.item) == (str(bad), 2, None)


def test_an_edit_names_the_users_darts():
    m = gmap.GMap(1, 4)
    m.sew(0, 1, 0)
    with pytest.raises(gmap.PreconditionError) as e:
        m.sew(0, 2, 0)
    assert e.value.item in (0, 1) and e.value.item_kind == "dart"
    assert f"dart {e.value.item}" in str(e.value)
    assert "DartId" not in str(e.value) and "v1" not in str(e.value)
    sq = gmap.build.polygon(4)
    with pytest.raises(gmap.PreconditionError) as e:
        sq.remove_cell_keeping_homology(0, 2)
    assert "DartId" not in str(e.value)
    # an Euler operator refused on a boundary: the dart named is one of the map's
    with pytest.raises(gmap.PreconditionError) as e:
        sq.contract_cell_keeping_homology(0, 1)
    assert "DartId" not in str(e.value)
    assert e.value.item is None or 0 <= e.value.item < len(sq)


def test_a_broken_map_and_a_failed_condition_name_their_dart_and_cell():
    # alpha_0 of dart 2 is 0, which is sent to 1: not an involution
    a = np.array([[1, 0, 0], [0, 1, 2]])
    with pytest.raises(gmap.ValidityError) as e:
        gmap.GMap.from_alphas(a)
    assert e.value.item_kind == "dart" and e.value.item in (0, 1, 2)
    assert f"dart {e.value.item}" in str(e.value)
    # a segment with an open end: the cellular method's C1 fails at the edge, 1-cell of dart 0
    seg = gmap.GMap(1, 2)
    seg.sew(0, 1, 1)
    with pytest.raises(gmap.PreconditionError) as e:
        gmap.homology(seg)
    assert e.value.item_kind == "cell" and e.value.item == (1, 0)
    # the refused facet of a list is its index
    with pytest.raises(gmap.InputError) as e:
        gmap.homology([[0, 1], [2, -1]])
    assert (e.value.item, e.value.item_kind) == (1, "facet")


def test_a_missing_file_is_an_oserror_with_its_path(tmp_path):
    p = tmp_path / "missing.gmap"
    with pytest.raises(OSError) as e:
        gmap.open(p)
    assert e.value.path == str(p)
