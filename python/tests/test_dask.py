"""The Lutz corpus on a 2-worker LocalCluster gives the serial results, in input order."""

import pytest

import gmap
from conftest import DATA

distributed = pytest.importorskip("distributed")
import gmap.dask  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_lutz_corpus_equals_serial(client):
    files = sorted(str(p) for p in (DATA / "lutz").glob("*.facets"))
    assert len(files) >= 40
    serial = [gmap.homology(f) for f in files]
    parallel = gmap.dask.homology_many(files, client=client)
    assert [h.to_dict() for h in parallel] == [h.to_dict() for h in serial]


def test_objects_and_options_travel(client):
    xs = [gmap.build.lens_space(5, 2), [[0, 1, 2], [0, 2, 3], [0, 1, 3], [1, 2, 3]], gmap.build.grid((2, 3))]
    got = gmap.dask.homology_many(xs, client=client, field=5, generators=True)
    assert [h.to_dict() for h in got] == [gmap.homology(x, field=5, generators=True).to_dict() for x in xs]


def test_errors_come_back(client):
    with pytest.raises(gmap.GmapError):
        gmap.dask.homology_many([[[0, 1]], [[0, 0]]], client=client)


def test_local_cluster_by_default():
    got = gmap.dask.homology_many([[[0, 1], [1, 2], [2, 0]]], n_workers=1)
    assert got[0].betti == [1, 1]
