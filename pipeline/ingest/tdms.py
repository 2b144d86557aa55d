"""NI TDMS files (npTDMS), as written by LabVIEW / DAQmx on engagement rigs.

The file is opened in streaming mode (:meth:`nptdms.TdmsFile.open`): only its
metadata is read, then only the channels that take a role, so a 10^7-sample
log with many channels costs the memory of the channels used.

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
from collections.abc import Mapping
from pathlib import Path

import numpy as np
from nptdms import TdmsFile

from pipeline.errors import ColumnError, EmptyFileError, LayoutError
from pipeline.ingest.librarylogs import collected_logs
from pipeline.ingest.raw import RawTable
from pipeline.ingest.roles import Candidates, find_candidates
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


def truncation(path: Path) -> str | None:
    """Where a TDMS file stops short of what its segments declare; None if it does not.

    Each segment starts with a lead-in giving its length. The file is
    truncated if a lead-in is cut, a segment runs past the end of the file, or
    a segment's length was never written (the writer stopped while writing it).
    Bytes that are not a lead-in end the walk: npTDMS reports them.

    Parameters
    ----------
    path : Path
        The ``.tdms`` file.

    Returns
    -------
    str or None
        E.g. ``"5000 of 5545 bytes, segment 3 incomplete"``.
    """
    size = path.stat().st_size
    position = segment = 0
    with path.open("rb") as stream:
        while position < size:
            segment += 1
            stream.seek(position)
            lead_in = stream.read(LEAD_IN)
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


def _truncated(path: Path, cut: str, detail: str, column: str | None = None) -> LayoutError:
    """The error of a truncated file that leaves nothing usable."""
    return LayoutError(f"the TDMS file is truncated ({cut}): {detail}", file=path,
                       column=column, hint=_COPY_AGAIN)


def _open(path: Path, cut: str | None) -> TdmsFile:
    try:
        return TdmsFile.open(path)
    except Exception as error:  # npTDMS raises many kinds of error on a broken file
        detail = f"{type(error).__name__}: {error}"
        if cut is not None:
            raise _truncated(path, cut, f"it cannot be opened ({detail})") from error
        raise LayoutError(
            f"not a readable TDMS file ({detail})",
            file=path, hint="check the file; give its format in the run sheet if it is not TDMS",
        ) from error


def _numeric(channel, path: Path, name: str, cut: str | None) -> np.ndarray:
    try:
        data = channel[:]
    except Exception as error:  # a truncated segment makes npTDMS fail in many ways
        detail = f"channel data cannot be read ({type(error).__name__}: {error})"
        if cut is not None:
            raise _truncated(path, cut, detail, column=name) from error
        raise LayoutError(
            detail, file=path, column=name,
            hint="the file may be truncated: copy it from the rig again",
        ) from error
    if data.dtype.kind not in "iuf":
        raise ColumnError(
            f"channel holds {data.dtype} values, not numbers",
            file=path, column=name, hint="name the numeric channel in the run sheet's columns",
        )
    return np.array(data, dtype=np.float64)


def read(path: Path, columns: Mapping | None = None) -> RawTable:
    """Read the channels of a TDMS file that take a role.

    Parameters
    ----------
    path : Path
        The ``.tdms`` file.
    columns : mapping, optional
        Run-sheet ``columns``: role -> ``"Channel"`` or ``"Group/Channel"``.

    Returns
    -------
    RawTable
        Its warnings include npTDMS's own, prefixed ``npTDMS:``.
    """
    cut = truncation(path)
    with collected_logs(NPTDMS_LOGGER) as logged:
        raw = _read(path, columns, cut)
    raw.metadata.warnings.extend(f"npTDMS: {message}" for message in logged)
    return raw


def _read(path: Path, columns: Mapping | None, cut: str | None) -> RawTable:
    """:func:`read` of a file whose :func:`truncation` is `cut`."""
    with _open(path, cut) as tdms:
        channels = [channel for group in tdms.groups() for channel in group.channels()]
        names = [f"{channel.group_name}/{channel.name}" for channel in channels]
        units = [str(channel.properties.get(UNIT_PROPERTY, "")).strip() or None
                 for channel in channels]
        if cut is not None and not any(len(channel) for channel in channels):
            raise _truncated(path, cut, "no sample is left before the cut")
        if not channels:
            raise LayoutError(
                "no channels in the TDMS file", file=path,
                hint="the file may be truncated or not a TDMS file: copy it from the rig again",
            )
        if not any(len(channel) for channel in channels):
            raise EmptyFileError(
                "the TDMS file holds no samples", file=path,
                hint="the acquisition wrote no data: record the run again",
            )
        found = find_candidates(names, units, columns, file=path, header_line=None)
        arrays = {index: _numeric(channels[index], path, names[index], cut)
                  for index in sorted(found.indexes())}
        meta = TableMetadata(
            file=str(path),
            layout=LAYOUT,
            preamble={str(key): str(value) for key, value in tdms.properties.items()},
        )
        empty = {index for index, channel in enumerate(channels)
                 if index not in arrays and len(channel) == 0}
        rows = _common_length(arrays, names, meta.warnings)
        if cut is not None:
            if rows == 0 and arrays:
                raise _truncated(path, cut, "a channel it reads has no sample before the cut")
            meta.warnings.append(
                f"the file is truncated ({cut}): the {rows} samples before the cut were read")
        roles = dict(found.roles)
        source = (roles.get("force") or sorted(arrays) or [None])[0]
        if "time" not in roles and source is not None:
            properties = channels[source].properties
            if "wf_increment" in properties:
                start = float(properties.get("wf_start_offset", 0.0))
                names.append(f"time (waveform of {names[source]})")
                units.append("s")
                arrays[len(names) - 1] = start + float(properties["wf_increment"]) * np.arange(rows)
                roles["time"] = [len(names) - 1]
    return RawTable(
        names=names,
        units=units,
        arrays=arrays,
        rows=rows,
        candidates=Candidates(roles, found.explicit),
        metadata=meta,
        line_of=lambda row: None,
        empty=empty,
    )


def _common_length(arrays: dict[int, np.ndarray], names: list[str], warnings: list[str]) -> int:
    """Cut the channels to the shortest one (warned); returns the length."""
    lengths = {index: array.size for index, array in arrays.items()}
    rows = min(lengths.values(), default=0)
    if any(length != rows for length in lengths.values()):
        warnings.append(
            "channels of unequal length cut to the shortest (" + ", ".join(
                f"{names[index]}: {length}" for index, length in lengths.items()) + ")"
        )
        for index in arrays:
            arrays[index] = arrays[index][:rows].copy()
    return rows
