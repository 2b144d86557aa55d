"""One ``chainbench run`` per output folder at a time.

Two runs on one campaign at once would interleave their writes; the second
one stops at once with a clear message instead. The lock is an advisory
``flock`` on ``<output>/.lock``: the operating system releases it when the
holding process ends, however it ends, so a killed run never blocks the next.
"""

from __future__ import annotations

import fcntl
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from pipeline.errors import ChainbenchError

LOCK_NAME = ".lock"


class CampaignBusyError(ChainbenchError):
    """Another process is writing the same campaign's outputs."""


@contextmanager
def campaign_lock(output: Path) -> Iterator[None]:
    """Hold the output folder's lock for the duration of the block.

    Raises
    ------
    CampaignBusyError
        When another process holds it (the message names its process id).
    """
    output.mkdir(parents=True, exist_ok=True)
    path = output / LOCK_NAME
    descriptor = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        try:
            fcntl.flock(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.pread(descriptor, 32, 0).decode(errors="replace").strip() or "unknown"
            raise CampaignBusyError(
                f"another chainbench run (process {holder}) is writing this campaign's outputs",
                file=output, hint="wait for it to finish, then run again",
            ) from None
        os.ftruncate(descriptor, 0)
        os.pwrite(descriptor, str(os.getpid()).encode(), 0)
        yield
    finally:
        os.close(descriptor)  # closing releases the lock


def remove_stale_temporaries(output: Path) -> list[Path]:
    """Delete the temporary files an interrupted run left behind (call under the lock).

    Outputs are written as ``.<name>.<random>.tmp`` and renamed into place
    (:func:`pipeline.store.netcdf.write_atomic`); a run killed mid-write leaves
    such a file, never a half-written result.
    """
    stale = sorted(output.glob(".*.tmp"))
    for path in stale:
        path.unlink(missing_ok=True)
    return stale
