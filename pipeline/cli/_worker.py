"""What each worker of the command line's local dask cluster runs as it starts and stops.

A dask preload (``LocalCluster(preload=...)``): importing this module loads the
stages once per worker, before its first task, with the garbage collector
paused and what they created frozen out of its reach
(:func:`pipeline.cli._stages.load_stages`). As the worker stops, everything
left is frozen too: the process then exits without the collector's final pass
over every object (about 0.3 s with the numerical libraries loaded), which the
cluster's shutdown waits for.

A task's error goes to the command, which reports it itself (a run's failure
in the campaign's summary, a campaign's error on one line, the traceback with
``--debug``): the worker does not also log it, with its traceback, over the
command's output.
"""

from __future__ import annotations

import gc
import logging
from typing import Any

from pipeline.cli._stages import load_stages

load_stages()


class _TaskErrorsToTheCommand(logging.Filter):
    """Drops the worker's record of a task that failed (``Compute Failed``)."""

    def filter(self, record: logging.LogRecord) -> bool:
        return not str(record.msg).startswith("Compute Failed")


logging.getLogger("distributed.worker").addFilter(_TaskErrorsToTheCommand())


def dask_teardown(worker: Any) -> None:
    """Freeze everything left, so the worker process exits without a full collection."""
    gc.freeze()
