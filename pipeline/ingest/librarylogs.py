"""What a reading library logs about a file, collected for the table instead of printed.

npTDMS reports what it finds odd in a file (a segment shorter than declared, a
last chunk cut short) through :mod:`logging`, on one logger per module
(``nptdms.reader``, ``nptdms.tdms_segment``...), each with its own stderr
handler. :func:`collected_logs` takes those records while a file is read, so
that the reader can hand them on as the table's warnings.
"""

from __future__ import annotations

import logging
import threading
from collections.abc import Iterator
from contextlib import contextmanager


class _Collector(logging.Filter):
    """Takes the warnings logged by the thread that made it; lets every other record through."""

    def __init__(self) -> None:
        super().__init__()
        self.thread = threading.get_ident()
        self.messages: list[str] = []

    def filter(self, record: logging.LogRecord) -> bool:
        """False (record dropped) for a warning of the collecting thread, kept in `messages`."""
        if record.levelno < logging.WARNING or threading.get_ident() != self.thread:
            return True
        message = record.getMessage()
        if message not in self.messages:
            self.messages.append(message)
        return False


def _loggers(prefix: str) -> list[logging.Logger]:
    """The loggers that exist under the name `prefix` or ``prefix.<module>``."""
    return [
        logger for name, logger in list(logging.root.manager.loggerDict.items())
        if (name == prefix or name.startswith(prefix + ".")) and isinstance(logger, logging.Logger)
    ]


@contextmanager
def collected_logs(prefix: str) -> Iterator[list[str]]:
    """Collect the warnings this thread logs on the `prefix` loggers while the block runs.

    A filter is added to every existing logger named `prefix` or
    ``prefix.<module>`` (a library creates them when it is imported) and
    removed when the block ends, even on an error. Warnings logged by this
    thread are kept, each once, and go neither to the loggers' handlers
    (stderr) nor to their parents; records of other threads, and records below
    WARNING, go on as before, so that concurrent reads each collect their own.

    Parameters
    ----------
    prefix : str
        The library's logger name (``"nptdms"``).

    Yields
    ------
    list of str
        The messages, in the order first logged; filled as the block runs.
    """
    collector = _Collector()
    loggers = _loggers(prefix)
    for logger in loggers:
        logger.addFilter(collector)
    try:
        yield collector.messages
    finally:
        for logger in loggers:
            logger.removeFilter(collector)
