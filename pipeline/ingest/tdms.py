"""NI TDMS files (npTDMS), as written by LabVIEW / DAQmx on engagement rigs.

The file (or a buffer holding one) is opened in streaming mode
(:meth:`nptdms.TdmsFile.open`): only its metadata is read (:func:`describe`),
then only the channels that take a role, and only the samples asked for
(:meth:`Layout.read`), so a 10^7-sample log with many channels costs the
memory of the channels and samples used.

Channels are named ``"Group/Channel"``; the run sheet may name them so or by
``"Channel"`` alone. Without a time channel, time comes from the waveform
properties of the force channel: ``wf_start_offset + wf_increment * i``.
Units come from the ``unit_string`` channel property, else the run sheet.

File defects handled
--------------------
* a channel named in the run sheet that is not in the file (error listing the
  channels it has);
* no time channel and no ``wf_increment`` (time absent; an engagement run then
  fails with a message saying so);
* channels of unequal length (cut to the shortest, with a warning);
* empty channels (dropped, noted), sentinel values (NaN);
* a time channel of timestamps (LabVIEW's ``Get Date/Time``): seconds after its
  first sample, with a note (:mod:`pipeline.ingest.clock`);
* a non-numeric channel given a role (error);
* a file that is not valid TDMS, or holds no channel or no sample (error);
* a truncated file (a copy or an acquisition stopped early), found by walking
  the segments' lead-ins (see :func:`truncation`): what precedes the cut is
  read, with a warning saying where the file stops; if nothing does, an error;
* npTDMS's own warnings (logged, printed on stderr by default): collected
  into the table's warnings, prefixed ``npTDMS:``.
"""

from __future__ import annotations

import struct
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np
import pyarrow as pa
from nptdms import TdmsFile

from pipeline.errors import ColumnError, EmptyFileError, LayoutError
from pipeline.ingest.clock import ClockColumn, declare_seconds
from pipeline.ingest.librarylogs import collected_logs
from pipeline.ingest.raw import RawColumns, RawTable
from pipeline.ingest.roles import Candidates, find_candidates
from pipeline.ingest.source import Source
from pipeline.ingest.table import TableMetadata

LAYOUT = "tdms"

#: The channel property holding the unit (NI convention).
UNIT_PROPERTY = "unit_string"
#: The name of npTDMS's loggers, whose warnings become the table's.
NPTDMS_LOGGER = "nptdms"

#: Bytes of a segment's lead-in: tag, table of contents, version, two lengths.
LEAD_IN = 28
_TAG = b"TDSm"
_BIG_ENDIAN = 1 << 6  # table-of-contents flag of a big-endian segment
_VERSIONS = (4712, 4713)
_LENGTH_NOT_WRITTEN = 0xFFFF_FFFF_FFFF_FFFF  # the length a writer that stopped leaves
_COPY_AGAIN = ("copy the file again from the machine; if the copy is as short, the "
               "acquisition stopped early: record the run again")


def truncation(source: Source) -> str | None:
    """Where a TDMS file stops short of what its segments declare; None if it does not.

    Each segment starts with a lead-in giving its length. The file is
    truncated if a lead-in is cut, a segment runs past the end of the file, or
    a segment's length was never written (the writer stopped while writing it).
    Bytes that are not a lead-in end the walk: npTDMS reports them.

    Parameters
    ----------
    source : Source
        The ``.tdms`` file or buffer.

    Returns
    -------
    str or None
        E.g. ``"5000 of 5545 bytes, segment 3 incomplete"``.
    """
    size = source.size
    position = segment = 0
    while position < size:
        segment += 1
        lead_in = source.read(position, position + LEAD_IN)
        end = position + LEAD_IN
        if len(lead_in) == LEAD_IN:
            if not _is_lead_in(lead_in):
                return None
            length = _segment_length(lead_in)
            if length == _LENGTH_NOT_WRITTEN:
                return f"segment {segment} incomplete, its length never written"
            end += length
        elif not _TAG.startswith(lead_in[: len(_TAG)]):
            return None
        if end > size:
            return f"{size} of {end} bytes, segment {segment} incomplete"
        position = end
    return None


def _is_lead_in(lead_in: bytes) -> bool:
    """True if 28 bytes start a TDMS segment (its tag and a known version)."""
    version = struct.unpack(_order(lead_in) + "I", lead_in[8:12])[0]
    return lead_in.startswith(_TAG) and version in _VERSIONS


def _segment_length(lead_in: bytes) -> int:
    """Bytes of a segment after its lead-in (metadata and data)."""
    return struct.unpack(_order(lead_in) + "Q", lead_in[12:20])[0]


def _order(lead_in: bytes) -> str:
    """The :mod:`struct` byte order of a segment (its table of contents is little-endian)."""
    return ">" if struct.unpack("<I", lead_in[4:8])[0] & _BIG_ENDIAN else "<"


def _truncated(name: str, cut: str, detail: str, column: str | None = None) -> LayoutError:
    """The error of a truncated file that leaves nothing usable."""
    return LayoutError(f"the TDMS file is truncated ({cut}): {detail}", file=name,
                       column=column, hint=_COPY_AGAIN)


def _open(source: Source, cut: str | None) -> TdmsFile:
    """Open a TDMS file or buffer in streaming mode (metadata read, data left to read).

    Parameters
    ----------
    source : Source
        The file or buffer.
    cut : str or None
        Its :func:`truncation`.

    Raises
    ------
    LayoutError
        If npTDMS cannot read it.
    """
    try:
        return TdmsFile.open(source.file())
    except Exception as error:  # npTDMS raises many kinds of error on a broken file
        detail = f"{type(error).__name__}: {error}"
        if cut is not None:
            raise _truncated(source.name, cut, f"it cannot be opened ({detail})") from error
        raise LayoutError(
            f"not a readable TDMS file ({detail})",
            file=source.name,
            hint="check the file; give its format in the run sheet if it is not TDMS",
        ) from error


def _numeric(channel, file: str, name: str, cut: str | None, rows: slice,
             clock: ClockColumn | None = None) -> np.ndarray:
    """Samples of a channel as float64 (a timestamp channel's as seconds after `clock`'s
    first).

    Parameters
    ----------
    channel : nptdms.TdmsChannel
        The channel, its file open.
    file : str
        The file's name, for messages.
    name : str
        The channel's ``"Group/Channel"``, for messages.
    cut : str or None
        The file's :func:`truncation`.
    rows : slice
        The samples to read.
    clock : ClockColumn, optional
        For a time channel of timestamps: its first sample.

    Raises
    ------
    LayoutError
        If the samples cannot be read.
    ColumnError
        If the channel does not hold numbers.
    """
    try:
        data = channel[rows]
    except Exception as error:  # a truncated segment makes npTDMS fail in many ways
        detail = f"channel data cannot be read ({type(error).__name__}: {error})"
        if cut is not None:
            raise _truncated(file, cut, detail, column=name) from error
        raise LayoutError(
            detail, file=file, column=name,
            hint="the file may be truncated: copy it from the rig again",
        ) from error
    if clock is not None and data.dtype.kind == "M":
        return clock.seconds(pa.chunked_array([pa.array(data)])).to_numpy()
    if data.dtype.kind not in "iuf":
        raise ColumnError(
            f"channel holds {data.dtype} values, not numbers",
            file=file, column=name, hint="name the numeric channel in the run sheet's columns",
        )
    return np.array(data, dtype=np.float64)


def _channels(tdms: TdmsFile) -> list:
    """The channels of every group, in file order."""
    return [channel for group in tdms.groups() for channel in group.channels()]


@dataclass(frozen=True)
class Waveform:
    """Time built from a channel's waveform properties: ``start + increment * i`` [s]."""

    column: int  #: index of the time column (after the file's channels)
    start: float  #: ``wf_start_offset`` [s]
    increment: float  #: ``wf_increment`` [s]

    def times(self, start: int, stop: int) -> np.ndarray:
        """The times of samples `start` to `stop` (0-based, `stop` excluded) [s]."""
        return self.start + self.increment * np.arange(start, stop)


@dataclass
class Layout:
    """What a TDMS file's metadata says, before its samples are read.

    Attributes
    ----------
    header : RawColumns
        Channel names (``"Group/Channel"``, then the waveform time if any),
        units, role candidates and metadata (with the whole file's warnings).
    rows : int
        Samples of the shortest channel that takes a role.
    channels : list of int
        The channels read (the candidates, without the waveform time).
    waveform : Waveform or None
        The time column built from waveform properties, if any.
    empty : set of int
        Channels that take no role and hold no sample.
    cut : str or None
        The file's :func:`truncation`.
    """

    header: RawColumns
    rows: int
    channels: list[int]
    waveform: Waveform | None
    empty: set[int]
    cut: str | None

    def read(self, tdms: TdmsFile, start: int, stop: int) -> RawTable:
        """Samples `start` to `stop` (0-based, `stop` excluded) of the channels that take a role.

        Parameters
        ----------
        tdms : TdmsFile
            The file, open (:func:`reading`).
        start, stop : int
            The rows, within ``[0, rows]``.
        """
        channels = _channels(tdms)
        names, file = self.header.names, self.header.metadata.file
        arrays = {index: _numeric(channels[index], file, names[index], self.cut,
                                  slice(start, stop), self.header.clocks.get(index))
                  for index in self.channels}
        if self.waveform is not None:
            arrays[self.waveform.column] = self.waveform.times(start, stop)
        return self.header.table(arrays=arrays, rows=stop - start, line_of=lambda row: None,
                                 empty=self.empty, first_row=start)


def describe(tdms: TdmsFile, file: str, columns: Mapping | None, cut: str | None) -> Layout:
    """Read the channels, roles, units and length of an open TDMS file (no sample read).

    Parameters
    ----------
    tdms : TdmsFile
        The file, open (:func:`reading`).
    file : str
        Its name, for messages.
    columns : mapping, optional
        Run-sheet ``columns``: role -> ``"Channel"`` or ``"Group/Channel"``.
    cut : str or None
        Its :func:`truncation`.

    Raises
    ------
    LayoutError, EmptyFileError, ColumnError
        As listed in the module docstring.
    """
    channels = _channels(tdms)
    names = [f"{channel.group_name}/{channel.name}" for channel in channels]
    units = [str(channel.properties.get(UNIT_PROPERTY, "")).strip() or None
             for channel in channels]
    if cut is not None and not any(len(channel) for channel in channels):
        raise _truncated(file, cut, "no sample is left before the cut")
    if not channels:
        raise LayoutError(
            "no channels in the TDMS file", file=file,
            hint="the file may be truncated or not a TDMS file: copy it from the rig again",
        )
    if not any(len(channel) for channel in channels):
        raise EmptyFileError(
            "the TDMS file holds no samples", file=file,
            hint="the acquisition wrote no data: record the run again",
        )
    found = find_candidates(names, units, columns, file=file, header_line=None)
    read = sorted(found.indexes())
    meta = TableMetadata(
        file=file,
        layout=LAYOUT,
        preamble={str(key): str(value) for key, value in tdms.properties.items()},
    )
    rows = _common_length({index: len(channels[index]) for index in read}, names,
                          meta.warnings)
    if cut is not None:
        if rows == 0 and read:
            raise _truncated(file, cut, "a channel it reads has no sample before the cut")
        meta.warnings.append(
            f"the file is truncated ({cut}): the {rows} samples before the cut were read")
    roles = dict(found.roles)
    source = (roles.get("force") or read or [None])[0]
    waveform = None
    if "time" not in roles and source is not None:
        properties = channels[source].properties
        if "wf_increment" in properties:
            names.append(f"time (waveform of {names[source]})")
            units.append("s")
            waveform = Waveform(len(names) - 1, float(properties.get("wf_start_offset", 0.0)),
                                float(properties["wf_increment"]))
            roles["time"] = [waveform.column]
    clocks = _timestamp_clocks(channels, roles.get("time", []), rows)
    declare_seconds(clocks, names, units, meta.warnings)
    header = RawColumns(names=names, units=units, candidates=Candidates(roles, found.explicit),
                        metadata=meta, clocks=clocks)
    empty = {index for index, channel in enumerate(channels)
             if index not in read and len(channel) == 0}
    return Layout(header, rows, read, waveform, empty, cut)


def _timestamp_clocks(channels: list, times: list[int], rows: int) -> dict[int, ClockColumn]:
    """The time channels that hold timestamps, each with its first sample."""
    return {index: ClockColumn("date and time", str(channels[index][0:1][0]))
            for index in times
            if index < len(channels) and rows and channels[index].dtype.kind == "M"}


def parse(source: Source, columns: Mapping | None = None) -> RawTable:
    """Read the channels of a TDMS file or buffer that take a role.

    Parameters
    ----------
    source : Source
        The ``.tdms`` file or buffer.
    columns : mapping, optional
        Run-sheet ``columns``: role -> ``"Channel"`` or ``"Group/Channel"``.

    Returns
    -------
    RawTable
        Its warnings include npTDMS's own, prefixed ``npTDMS:``.
    """
    cut = truncation(source)
    with reading(source, cut) as (tdms, logged):
        layout = describe(tdms, source.name, columns, cut)
        raw = layout.read(tdms, 0, layout.rows)
    raw.metadata.warnings.extend(logged)
    return raw


@contextmanager
def reading(source: Source, cut: str | None) -> Iterator[tuple[TdmsFile, list[str]]]:
    """The file open in streaming mode for the ``with`` block, and npTDMS's warnings.

    Parameters
    ----------
    source : Source
        The ``.tdms`` file or buffer.
    cut : str or None
        Its :func:`truncation`.

    Yields
    ------
    tdms : TdmsFile
        The open file, closed at the block's end.
    warnings : list of str
        What npTDMS logs in the block, prefixed ``npTDMS:``, filled at its end.
    """
    warnings: list[str] = []
    with collected_logs(NPTDMS_LOGGER) as logged:
        try:
            with _open(source, cut) as tdms:
                yield tdms, warnings
        finally:
            warnings.extend(f"npTDMS: {message}" for message in logged)


def _common_length(lengths: dict[int, int], names: list[str], warnings: list[str]) -> int:
    """The length of the shortest channel; channels of unequal length are warned about."""
    rows = min(lengths.values(), default=0)
    if any(length != rows for length in lengths.values()):
        warnings.append(
            "channels of unequal length cut to the shortest (" + ", ".join(
                f"{names[index]}: {length}" for index, length in lengths.items()) + ")"
        )
    return rows
