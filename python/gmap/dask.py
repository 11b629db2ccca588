"""Homology of a corpus on a Dask ``distributed`` cluster.

:func:`homology_many` sends one task per input to the workers of a cluster and gathers the
results in input order; each task is the serial ``gmap.homology`` call, so the results are
those of the serial run. Without a client it starts a :class:`distributed.LocalCluster` on
this machine (one single-threaded worker process per core) and closes it afterwards.

Pointing it at a real cluster: start a scheduler and workers where the package is installed
(``pip install ./python`` on every machine, the same version)::

    dask scheduler                        # on the head node: prints tcp://HOST:8786
    dask worker tcp://HOST:8786 --nthreads 1 --nworkers 8   # on each compute node

then pass a client connected to it::

    from distributed import Client
    import gmap.dask
    client = Client("tcp://HOST:8786")
    results = gmap.dask.homology_many(paths, client=client)

Paths are opened by the workers, so they must name the same files there (a shared file
system); objects (``GMap``, ``SimplicialComplex``, ``CubicalSet``, ``ArchComplex``, lists of
facets, numpy arrays) travel with the task, pickled.
"""

from __future__ import annotations

import os
from typing import Any, List, Optional, Sequence

from . import Homology, homology

__all__ = ["homology_many"]


def _one(x: Any, options: dict) -> str:
    """One task: the homology of ``x`` as JSON text (a Homology crosses back pickled as
    that text)."""
    return homology(x, **options).to_json()


def homology_many(
    paths_or_objects: Sequence[Any],
    client: Optional[Any] = None,
    *,
    field: Optional[int] = None,
    generators: bool = False,
    method: Optional[str] = None,
    periodic: bool = False,
    n_workers: Optional[int] = None,
) -> List[Homology]:
    """The homology of every input on a Dask cluster, as a list of :class:`gmap.Homology` in
    input order, equal to ``[gmap.homology(x, ...) for x in paths_or_objects]``.

    ``client``: a ``distributed.Client``; None starts a ``LocalCluster`` of ``n_workers``
    single-threaded worker processes (default: the number of cores) for this call. The first
    error raised by an input is raised here (the other tasks are cancelled).
    """
    from distributed import Client, LocalCluster

    items = [os.fspath(x) if isinstance(x, os.PathLike) else x for x in paths_or_objects]
    options = dict(field=field, generators=generators, method=method, periodic=periodic)
    own_cluster = None
    if client is None:
        own_cluster = LocalCluster(
            n_workers=n_workers or os.cpu_count() or 1,
            threads_per_worker=1,
            processes=True,
            dashboard_address=None,
        )
        client = Client(own_cluster)
    try:
        futures = client.map(_one, items, options=options, pure=False)
        texts = client.gather(futures)
    finally:
        if own_cluster is not None:
            client.close()
            own_cluster.close()
    return [Homology.from_json(t) for t in texts]
