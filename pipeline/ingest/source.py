"""Where a reader's bytes come from: a file, or a buffer already in memory.

Every reader reads through a :class:`Source`, so that one code path serves
:func:`~pipeline.ingest.read_table` (a :class:`FileSource`: the file is read
in blocks as the parsers ask, never read whole nor mapped, so that its pages
do not add to the reader's memory) and :func:`~pipeline.ingest.parse_table`
(a :class:`BufferSource` over bytes in memory, read without a copy). Messages
name the source by :attr:`Source.name`: the file's path, or the name given
with the buffer.
"""

from __future__ import annotations

import io
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import BinaryIO, Protocol

import pyarrow as pa

from pipeline.errors import IngestError

#: Bytes read at a time when a source is scanned in Python or numpy (small enough to stay
#: in the processor's cache: numpy scans 1 MiB blocks faster than 16 MiB ones).
BLOCK = 1 << 20


class Source(Protocol):
    """Random access to the bytes of one file or buffer."""

    name: str  #: the file's path, or the buffer's name, as messages show it
    size: int  #: length [bytes]

    def read(self, start: int, stop: int) -> bytes:
        """The bytes from offset `start` to `stop` (fewer past the end)."""

    def stream(self, start: int, stop: int) -> pa.NativeFile:
        """A pyarrow input stream of the bytes from `start` to `stop`, for the body parser."""

    def file(self) -> BinaryIO:
        """A seekable binary file object of the whole content at its start (for npTDMS and
        openpyxl)."""


class BufferSource:
    """A bytes-like object (``bytes``, ``bytearray``, ``memoryview``, ``mmap``) as a source.

    The buffer is read without a copy and never changed; it is viewed only
    while a read or a stream is under way, so that an ``mmap`` handed in can
    be closed once the reader has returned.

    Parameters
    ----------
    buffer : bytes-like
        The content.
    name : str
        The name messages give it.
    """

    def __init__(self, buffer: bytes | bytearray | memoryview, name: str) -> None:
        self.name = name
        self._buffer = buffer
        with memoryview(buffer) as view:
            self.size = view.nbytes

    def read(self, start: int, stop: int) -> bytes:
        """The bytes from offset `start` to `stop`."""
        with memoryview(self._buffer) as view, view.cast("B") as data:
            return bytes(data[start:stop])

    def stream(self, start: int, stop: int) -> pa.NativeFile:
        """A pyarrow stream over the bytes from `start` to `stop` (no copy)."""
        return pa.BufferReader(pa.py_buffer(self._buffer)[start:stop])

    def file(self) -> BinaryIO:
        """The content as a seekable file object at its start (no copy)."""
        return pa.BufferReader(pa.py_buffer(self._buffer))


class FileSource:
    """A file as a source, open from creation until :meth:`close` (or the ``with`` block's end).

    Two handles are open: a Python file for the reads made in Python, and a
    pyarrow file for the body streams, read at explicit offsets (so that
    pyarrow's reading threads and Python never move one another's position).

    Parameters
    ----------
    path : Path
        The file.

    Raises
    ------
    OSError
        If the file cannot be opened.
    """

    def __init__(self, path: Path) -> None:
        self.name = str(path)
        self._file = path.open("rb")
        status = os.fstat(self._file.fileno())
        self.size = status.st_size
        self.modified = status.st_mtime_ns  #: modification time [ns]
        try:
            self._arrow = pa.OSFile(self.name)
        except OSError:
            self._file.close()
            raise

    def __enter__(self) -> FileSource:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    def close(self) -> None:
        """Close the file."""
        self._arrow.close()
        self._file.close()

    def read(self, start: int, stop: int) -> bytes:
        """The bytes from offset `start` to `stop`."""
        self._file.seek(start)
        return self._file.read(max(stop - start, 0))

    def stream(self, start: int, stop: int) -> pa.NativeFile:
        """A pyarrow stream of the bytes from `start` to `stop`, read in blocks as parsed."""
        return self._arrow.get_stream(start, stop - start)

    def file(self) -> BinaryIO:
        """The open file, at its start (its position is then the caller's to move)."""
        self._file.seek(0)
        return self._file


class _Range(io.RawIOBase):
    """The bytes from `start` to `stop` of a source as a raw binary stream."""

    def __init__(self, source: Source, start: int, stop: int) -> None:
        super().__init__()
        self._source = source
        self._position = start
        self._stop = stop

    def readable(self) -> bool:
        return True

    def readinto(self, buffer: memoryview) -> int:
        data = self._source.read(self._position, min(self._position + len(buffer), self._stop))
        buffer[: len(data)] = data
        self._position += len(data)
        return len(data)


def text_lines(source: Source, start: int, stop: int, codec: str) -> Iterator[str]:
    """The lines between two offsets of a source, decoded, without their line ends.

    Lines end with CRLF, LF or CR; undecodable bytes are replaced. The text is
    read and decoded in blocks (Python speed: for error messages).

    Parameters
    ----------
    source : Source
        The bytes.
    start, stop : int
        Offsets [bytes] of a line start and of the end of the text.
    codec : str
        The text's codec.
    """
    raw = io.BufferedReader(_Range(source, start, stop), buffer_size=BLOCK)
    with io.TextIOWrapper(raw, encoding=codec, errors="replace", newline="") as text:
        for line in text:
            yield line.rstrip("\r\n")


def contains(source: Source, patterns: tuple[bytes, ...], start: int, stop: int) -> bool:
    """True if one of `patterns` occurs between offsets `start` and `stop` of `source`.

    The bytes are read in blocks of :data:`BLOCK`, overlapping by the longest
    pattern so that none is missed across a block's end.
    """
    overlap = max(len(pattern) for pattern in patterns) - 1
    position = start
    while position < stop:
        end = min(position + BLOCK, stop)
        block = source.read(position, min(end + overlap, stop))
        if any(pattern in block for pattern in patterns):
            return True
        position = end
    return False


@contextmanager
def opened(path: Path) -> Iterator[FileSource]:
    """The file at `path` as a source for the ``with`` block, closed at its end.

    Raises
    ------
    IngestError
        If the file cannot be opened or read (an :class:`OSError`), naming it.
    """
    try:
        with FileSource(path) as source:
            yield source
    except OSError as error:
        raise IngestError(
            f"cannot read the file: {error.strerror or error}",
            file=path, hint="check the run sheet's file entry and the file's permissions",
        ) from error
