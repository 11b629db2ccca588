"""The Lutz library (tests/data/lutz) on a Dask cluster, checked against the serial run.

    python python/examples/corpus_dask.py                       # a LocalCluster of 2 workers
    python python/examples/corpus_dask.py tcp://HOST:8786       # a running scheduler

Prints one line per file (its groups) and the serial and cluster times.
"""

import sys
import time
from pathlib import Path

from distributed import Client, LocalCluster

import gmap
import gmap.dask

LUTZ = Path(__file__).resolve().parents[2] / "tests" / "data" / "lutz"


def main() -> int:
    files = sorted(str(p) for p in LUTZ.glob("*.facets"))
    if len(sys.argv) > 1:
        client, cluster = Client(sys.argv[1]), None
    else:
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    try:
        client.run(lambda: __import__("gmap"))  # workers import the package before timing
        t = time.perf_counter()
        serial = [gmap.homology(f) for f in files]
        t_serial = time.perf_counter() - t
        t = time.perf_counter()
        remote = gmap.dask.homology_many(files, client=client)
        t_cluster = time.perf_counter() - t
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    for f, h in zip(files, remote):
        print(f"{Path(f).name:45s} {h}")
    same = [h.to_dict() for h in remote] == [h.to_dict() for h in serial]
    print(f"{len(files)} files: serial {t_serial:.2f} s, cluster {t_cluster:.2f} s, same results: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
