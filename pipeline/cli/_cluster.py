"""The command line's dask cluster: starting it, and driving a campaign from a worker.

``chainbench run --workers N`` starts a local cluster (:func:`dask_client`) and
hands each campaign to it whole (:func:`drive_on_cluster`): one task, the
driver, plans the runs, submits them and the report's pages as tasks of their
own, builds the summary and renders what the command prints, in a worker that
has the stages loaded already. The command's own process only starts the
cluster, forwards the driver's progress to the screen and prints its text: it
never imports the stages or the numerical libraries, whose import (about 1.5 s
of CPU) would otherwise compete with the workers' on a two-core machine. The
dask scheduler runs in the command's process too; every task sent to it is a
pickled call (:func:`pipeline.tasks.submit`), so that it does not import them
either.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any
from uuid import uuid4

import typer

if TYPE_CHECKING:
    from distributed import Client

#: The environment of a local cluster's worker processes, set before each one starts (as
#: dask's ``distributed.nanny.pre-spawn-environ``): one thread for the numerical libraries
#: (BLAS, OpenMP, pyarrow), the workers being the parallelism, and no
#: ``MALLOC_TRIM_THRESHOLD_``: dask's default sets it, which turns off glibc's adaptive
#: mmap threshold, so that every array over 128 KiB is mapped and zeroed afresh, and a run
#: takes twice its serial time (docs/quality.md, scale-out).
WORKER_ENVIRONMENT = {"OMP_NUM_THREADS": 1, "OPENBLAS_NUM_THREADS": 1, "MKL_NUM_THREADS": 1}
#: dask settings of a local cluster: its workers' environment (above), and no statistical
#: profiler in the workers (it samples every running task's stack every 10 ms, 3 to 4 % of
#: a run's CPU time, for a dashboard the command line does not serve).
CLUSTER_CONFIG = {"distributed.nanny.pre-spawn-environ": WORKER_ENVIRONMENT,
                  "distributed.worker.profile.enabled": False}
#: What each worker sets as it starts: a dask computation inside a task runs in the task's
#: thread. xarray writing a run file then takes this process's netCDF lock, as in a serial
#: run, and not a lock on the cluster (two round trips to the scheduler per variable).
WORKER_SETTINGS = {"DASK_SCHEDULER": "synchronous"}
#: What each worker of a local cluster imports once, as it starts: the stages of a run,
#: moved out of the garbage collector's scans (:mod:`pipeline.cli._worker`).
WORKER_PRELOAD = ["pipeline.cli._worker"]


@contextmanager
def dask_client(workers: int | None, scheduler: str | None) -> Iterator[Client | None]:
    """A dask.distributed client: a local cluster of `workers` processes, or `scheduler`'s.

    The local cluster's workers start in the background, importing the stages
    (:data:`WORKER_PRELOAD`); the driver submitted meanwhile waits for the first.
    The client is not made dask's default. None when neither is given.
    """
    if workers is None and scheduler is None:
        yield None
        return
    if workers is not None and scheduler is not None:
        raise typer.BadParameter("give --workers or --scheduler, not both")
    import dask
    from distributed import Client, LocalCluster

    if scheduler is not None:
        with Client(scheduler, set_as_default=False) as client:
            yield client
        return
    with (dask.config.set(CLUSTER_CONFIG),
          LocalCluster(n_workers=0, threads_per_worker=1, processes=True,
                       # no dashboard; the scheduler's own HTTP server on a free port, so
                       # that a dask dashboard already on 8787 gives no warning
                       dashboard_address=":0", scheduler_kwargs={"dashboard": False},
                       preload=WORKER_PRELOAD, env=WORKER_SETTINGS) as cluster,
          Client(cluster, set_as_default=False) as client):
        cluster.scale(workers)  # returns at once: the workers start in the background
        yield client


def drive_on_cluster(client: Client, function: Callable[..., Any], *args: Any,
                     listener: Any) -> Any:
    """``function(*args, listener=..., client=...)`` as one task on `client`; its result.

    The task (the driver) gets a client of its own to submit further tasks with,
    and leaves its worker's thread to them while it waits
    (:func:`distributed.secede`). What it calls on its `listener` (a method name
    and plain arguments: strings and numbers) is called on `listener` here, in
    the order called, as dask events; the last arrive before the result.

    Parameters
    ----------
    client : distributed.Client
        The cluster.
    function : callable
        A module-level function taking ``listener`` and ``client`` keywords.
    *args
        Its other arguments.
    listener : object
        Receives the driver's calls here (e.g. a progress display).
    """
    topic = f"chainbench-{uuid4().hex}"
    client.subscribe_topic(topic, lambda event: _deliver(listener, event[1]))
    try:
        return client.submit(_drive, function, args, topic, pure=False,
                             key=f"{function.__name__}-{uuid4().hex}").result()
    finally:
        client.unsubscribe_topic(topic)


def _deliver(listener: Any, message: list) -> None:
    """Call on `listener` what the driver called on its stand-in (:class:`_Relay`)."""
    method, *args = message
    getattr(listener, method)(*args)


class _Relay:
    """The driver's stand-in for the listener of :func:`drive_on_cluster`: each method
    called on it is sent, with its arguments, as an event under `topic`."""

    def __init__(self, worker: Any, topic: str) -> None:
        self._worker, self._topic = worker, topic

    def __getattr__(self, method: str) -> Callable[..., None]:
        if method.startswith("_"):
            raise AttributeError(method)
        return lambda *args: self._worker.log_event(self._topic, [method, *args])


def _drive(function: Callable[..., Any], args: tuple, topic: str) -> Any:
    """The driver task: `function` with a client of its own, out of the worker's pool.

    Not the worker's own client (:func:`distributed.worker_client`): that one
    becomes dask's default in the whole worker, and xarray in the other tasks
    there would then write their files under a lock on the cluster.
    """
    from distributed import Client, get_worker, rejoin, secede

    worker = get_worker()
    secede()
    try:
        with Client(worker.scheduler.address, security=worker.security,
                    set_as_default=False) as client:
            return function(*args, listener=_Relay(worker, topic), client=client)
    finally:
        rejoin()
