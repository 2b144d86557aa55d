"""One ``chainbench run`` per output folder at a time.

Two runs on one campaign at once would interleave their writes; the second
one stops at once with a clear message instead. The lock is a
:class:`filelock.FileLock` on ``<output>/.lock`` (``flock`` on POSIX, a
byte-range lock on Windows): the operating system releases it when the holding
process ends, however it ends, so a killed run never blocks the next.

The holder writes its process id to ``<output>/.lock.pid`` beside the lock
(Windows does not let other processes read a locked file), so that a refused
run can say which process holds the folder.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from pathlib import Path

from filelock import FileLock, Timeout

from pipeline.errors import ChainbenchError
from pipeline.store import layout

#: The file holding the lock holder's process id, while it holds the lock.
PID_NAME = layout.LOCK + ".pid"


class CampaignBusyError(ChainbenchError):
    """Another process is writing the same campaign's outputs."""


@contextmanager
def campaign_lock(output: Path) -> Iterator[None]:
    """Hold the output folder's lock for the duration of the block.

    Not reentrant: a second ``campaign_lock`` on the same folder is refused,
    from another process or from this one.

    Raises
    ------
    CampaignBusyError
        When it is held already (the message names the holder's process id
        when known).
    """
    output = Path(output)
    output.mkdir(parents=True, exist_ok=True)
    # A lock object of our own (not a shared singleton), not tied to a thread:
    # two calls make two OS locks, which conflict even within one process.
    lock = FileLock(output / layout.LOCK, timeout=0, thread_local=False)
    try:
        lock.acquire()
    except Timeout:
        holder = _holder(output)
        who = f" (process {holder})" if holder is not None else ""
        raise CampaignBusyError(
            f"another chainbench run{who} is writing this campaign's outputs",
            file=output, hint="wait for it to finish, then run again",
        ) from None
    pid_file = output / PID_NAME
    try:
        with suppress(OSError):  # the id only improves the message a refused run gives
            pid_file.write_text(str(os.getpid()), encoding="ascii")
        yield
    finally:
        with suppress(OSError):  # still under the lock: never the next holder's file
            pid_file.unlink(missing_ok=True)
        lock.release()


def _holder(output: Path) -> int | None:
    """The process id the lock's holder wrote, or None when unknown."""
    try:
        return int((output / PID_NAME).read_text(encoding="ascii").strip())
    except (OSError, ValueError):
        return None


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
