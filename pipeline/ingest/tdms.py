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
* a file that is not valid TDMS, or holds no channel or no sample (error).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import numpy as np
from nptdms import TdmsFile

from pipeline.errors import ColumnError, EmptyFileError, LayoutError
from pipeline.ingest.raw import RawTable
from pipeline.ingest.roles import Candidates, find_candidates
from pipeline.ingest.table import TableMetadata

LAYOUT = "tdms"

#: The channel property holding the unit (NI convention).
UNIT_PROPERTY = "unit_string"


def _open(path: Path) -> TdmsFile:
    try:
        return TdmsFile.open(path)
    except Exception as error:  # npTDMS raises many kinds of error on a broken file
        raise LayoutError(
            f"not a readable TDMS file ({type(error).__name__}: {error})",
            file=path, hint="check the file; give its format in the run sheet if it is not TDMS",
        ) from error


def _numeric(channel, path: Path, name: str) -> np.ndarray:
    try:
        data = channel[:]
    except Exception as error:  # a truncated segment makes npTDMS fail in many ways
        raise LayoutError(
            f"channel data cannot be read ({type(error).__name__}: {error})",
            file=path, column=name, hint="the file may be truncated: copy it from the rig again",
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
    """
    with _open(path) as tdms:
        channels = [channel for group in tdms.groups() for channel in group.channels()]
        names = [f"{channel.group_name}/{channel.name}" for channel in channels]
        units = [str(channel.properties.get(UNIT_PROPERTY, "")).strip() or None
                 for channel in channels]
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
        arrays = {index: _numeric(channels[index], path, names[index])
                  for index in sorted(found.indexes())}
        meta = TableMetadata(
            file=str(path),
            layout=LAYOUT,
            preamble={str(key): str(value) for key, value in tdms.properties.items()},
        )
        empty = {index for index, channel in enumerate(channels)
                 if index not in arrays and len(channel) == 0}
        rows = _common_length(arrays, names, meta.warnings)
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
