"""Fixtures of the reader tests: tiny files written on the fly, a corpus of every layout.

The corpus (:func:`corpus`) holds an engagement log (time, force, angle) in
every delimited layout, dialect, encoding and line end, with the defects the
readers handle (blank lines, comment lines, quoted cells and a trailing delimiter, a sentinel,
a NaN run, a time gap, a truncated last line, a decimal comma that is also the
delimiter), an MTS export, a workbook and a TDMS file; the buffer and row-range
tests compare each reader with ``read_table`` on all of them.
"""

from __future__ import annotations

import datetime
import io
from pathlib import Path

import numpy as np
import openpyxl
import pytest
from nptdms import ChannelObject, GroupObject, TdmsWriter

#: Data rows of each delimited log of the corpus.
ROWS = 37


@pytest.fixture
def write(tmp_path):
    """Write text (in an encoding) or bytes to a file in a temporary folder; return its path."""

    def _write(name: str, content: str | bytes, encoding: str = "utf-8") -> Path:
        path = tmp_path / name
        path.write_bytes(content if isinstance(content, bytes) else content.encode(encoding))
        return path

    return _write


def _cells(rows: int, gaps: bool) -> list[tuple[str, str, str]]:
    """Time [s], force [kN] and angle [deg] cells: a time gap after row 20, a sentinel in
    row 11 and, with `gaps`, no force in rows 5 to 7."""
    cells = []
    for row in range(rows):
        force = f"{1.5 + row % 7 * 0.25:.2f}"
        if row == 11:
            force = "-1000000.0"
        elif gaps and 5 <= row < 8:
            force = ""
        cells.append((f"{row * 0.005 + (0.5 if row > 20 else 0.0):.3f}", force, f"{row * 1.5:.1f}"))
    return cells


def _delimited(
    *,
    delimiter: str = ",",
    decimal: str = ".",
    newline: str = "\n",
    names: tuple[str, ...] = ("time [s]", "force [kN]", "angle [deg]"),
    above: tuple[str, ...] = (),
    units_row: str | None = None,
    quote: bool = False,
    row_end: str = "",
    blank_every: int = 0,
    comment_every: int = 0,
    gaps: bool = True,
    tail: str = "",
) -> str:
    """An engagement log in one delimited dialect: `above` are the lines above the names
    row, `units_row` the line below it, `row_end` ends each data row (a trailing
    delimiter), `tail` follows the last line; a blank line or a logger's comment line
    follows every `blank_every`-th or `comment_every`-th row (and a comment opens the
    rows)."""
    lines = [*above, delimiter.join(names), *([units_row] if units_row is not None else [])]
    if comment_every:
        lines.append("# missing reply")
    for row, cells in enumerate(_cells(ROWS, gaps)):
        cells = [cell.replace(".", decimal) for cell in cells]
        lines.append(delimiter.join(f'"{cell}"' if quote else cell for cell in cells) + row_end)
        if blank_every and row % blank_every == blank_every - 1:
            lines.append("")
        if comment_every and row % comment_every == comment_every - 1:
            lines.append("# Skipped 1 cycles")
    return newline.join(lines) + newline + tail


POLISH = ("czas [s]", "siła [kN]", "kąt [deg]")
#: The headers of a LabVIEW measurement file above its names row (tab-separated).
LABVIEW_HEADERS = (
    "LabVIEW Measurement\t", "Writer_Version\t2", "Separator\tTab", "Decimal_Separator\t.",
    "X_Columns\tOne", "***End_of_Header***\t", "", "Channels\t2\t",
    "Y_Unit_Label\tkN\tdeg\t", "X_Dimension\tTime\tTime\t", "***End_of_Header***\t")
LABVIEW_NAMES = ("X_Value", "Force", "Angle", "Comment")

#: file name -> (text, encoding) of the delimited logs of the corpus.
TEXT_LOGS = {
    "plain_lf.csv": (_delimited(), "utf-8"),
    "plain_crlf.csv": (_delimited(newline="\r\n"), "utf-8"),
    "plain_cr.csv": (_delimited(newline="\r"), "utf-8"),
    "blank_lines.csv": (_delimited(newline="\r\n", blank_every=4), "utf-8"),
    "quoted_trailing_delimiter.csv": (_delimited(quote=True, row_end=","), "utf-8"),
    "truncated.csv": (_delimited(tail="9.999,1.2"), "utf-8"),
    "european.csv": (_delimited(delimiter=";", decimal=",", newline="\r\n", names=POLISH),
                     "cp1250"),
    "european_truncated.csv": (_delimited(delimiter=";", decimal=",", names=POLISH,
                                          tail="9,999;1,25;0,"), "cp1250"),
    "tab_utf16.txt": (_delimited(delimiter="\t", decimal=",", newline="\r\n",
                                 names=("Zeit [s]", "Kraft [kN]", "Winkel [deg]")), "utf-16"),
    "utf16_be_blank_lines.txt": (_delimited(delimiter=";", decimal=",", blank_every=5),
                                 "utf-16-be"),
    "bom.csv": (_delimited(delimiter=";", decimal=","), "utf-8-sig"),
    "comment_lines.csv": (_delimited(comment_every=5, blank_every=7), "utf-8"),
    "utf16_comment_lines.txt": (_delimited(delimiter="\t", decimal=",", newline="\r\n",
                                           comment_every=3), "utf-16-le"),
    "comma_pairs.csv": (_delimited(decimal=",", gaps=False), "utf-8"),
    "machine_export.csv": (_delimited(above=('Machine : Rig 2,"E-7"', ""),
                                      names=("Time", "Load", "Angle", ""),
                                      units_row="(sec),(kN),(deg),", row_end=",",
                                      newline="\r\n"), "latin-1"),
    # read by row range as delimited text, and (a comment on every row) read whole
    "labview.lvm": (_delimited(delimiter="\t", above=LABVIEW_HEADERS, names=LABVIEW_NAMES,
                               newline="\r\n"), "utf-8"),
    "labview_comments.lvm": (_delimited(delimiter="\t", above=LABVIEW_HEADERS,
                                        names=LABVIEW_NAMES, row_end="\tStandby"), "utf-8"),
}
#: read_table options beyond the run kind, by file name.
OPTIONS = {name: {"columns": {"force": "CH1", "angle": "CH2"}}
           for name in ("graphtec.csv", "graphtec_split_date.csv")}


#: The first stamp of :func:`graphtec`'s log: 2 s before midnight.
GRAPHTEC_START = datetime.datetime(2026, 3, 5, 23, 59, 58)



def graphtec(step_ms: int = 250, split_date: bool = False) -> str:
    """A Graphtec midi logger's export (GL840 form, CRLF): a settings block, the names row,
    a units row with ``NO.`` over the sample number, ``Time`` over the clock and the
    alarms' states over the alarm columns, the clock to the whole second and the
    milliseconds within it in column ``ms``; a row every `step_ms` from
    :data:`GRAPHTEC_START`, force [kN] in CH1 and angle [deg] in CH2 (:func:`_cells`).
    With `split_date`, the date (day first) and the time of day in columns of their own,
    as a GL980 writes them, from 8 days later (the 13th: the day says the date's order)."""
    start = GRAPHTEC_START + datetime.timedelta(days=8 if split_date else 0)
    clock = "Date,Time" if split_date else "Date&Time"
    lines = ["Vendor,GRAPHTEC Corporation", "Model,GL840", f"Sampling,{step_ms}ms",
             "AMP Settings", "CH,Signal name,Input,Range,Filter,Span",
             'CH1, "Load",DC,10V,Off,5.000000,0.000000,kN',
             'CH2, "Angle",DC,10V,Off,360.000000,0.000000,deg', "Logic/Pulse,Off", "Data",
             f"No.,{clock},ms,CH1,CH2,Alarm1-10,AlarmOut",
             f"NO.,{'Date,' if split_date else ''}Time,ms,kN,deg,A1234567890,A1234"]
    for row, (_, force, angle) in enumerate(_cells(ROWS, gaps=True)):
        stamp = start + datetime.timedelta(milliseconds=row * step_ms)
        signed = [cell if not cell or cell.startswith("-") else f"+{cell}"
                  for cell in (force, angle)]
        written = f"{stamp:%d/%m/%Y,%H:%M:%S}" if split_date else f"{stamp:%Y/%m/%d %H:%M:%S}"
        lines.append(f"{row + 1},{written},{stamp.microsecond // 1000},"
                     f"{','.join(signed)},LLLLLLLLLL,LLLL")
    return "\r\n".join(lines) + "\r\n"


def elapsed_clock_log() -> str:
    """A rig's log whose time is its test clock in ``H:MM:SS.fff``, passing 24 hours
    (time of :func:`_cells` from 23:59:59.900), force [kN] and angle [deg]."""
    lines = ["Test time,Force (kN),Angle (deg)"]
    for time, force, angle in _cells(ROWS, gaps=True):
        hours, rest = divmod(round((86_399.9 + float(time)) * 1000), 3_600_000)
        minutes, milliseconds = divmod(rest, 60_000)
        lines.append(f"{hours}:{minutes:02d}:{milliseconds / 1000:06.3f},{force},{angle}")
    return "\n".join(lines) + "\n"


def spreadsheet_clock_log() -> str:
    """A log saved from a US spreadsheet: each time a date of slashes and a 12-hour clock
    in one cell (time of :func:`_cells` from 11:59:59.900 AM: past noon), force [kN] and
    angle [deg]."""
    start = datetime.datetime(2026, 3, 5, 11, 59, 59, 900_000)
    lines = ["Date Time,Force (kN),Angle (deg)"]
    for time, force, angle in _cells(ROWS, gaps=True):
        stamp = start + datetime.timedelta(seconds=float(time))
        lines.append(f"{stamp.month}/{stamp.day}/{stamp.year} {int(stamp.strftime('%I'))}:"
                     f"{stamp:%M:%S}.{stamp.microsecond // 1000:03d} {stamp:%p},{force},{angle}")
    return "\n".join(lines) + "\n"


@pytest.fixture
def graphtec_export():
    """:func:`graphtec`: ``graphtec_export(step_ms)`` is a Graphtec logger's export (text)."""
    return graphtec


def _mts(blocks: int = 3, points: int = 9) -> str:
    """An MTS TestWare cyclic-acquisition export (Spanish, tab, decimal comma, CRLF)."""
    lines = ["MTS***|MPT|**|*|*", ""]
    for block in range(blocks):
        lines += [f"Adquisición cíclica\t\t\tTiempo\t{10 * block},0\tSec",
                  f"Puntos: \t{points}", "Tiempo\tFuerza\tÁngulo", "Sec\tkgf\tdeg"]
        lines += [f"{10 * block + point / 100:.2f}\t{point},5\t{point * 3},0".replace(".", ",")
                  for point in range(points)]
        lines.append("")
    return "\r\n".join(lines[:-1])


def _workbook() -> bytes:
    """An engagement log as a workbook: a preamble, a units row, empty cells."""
    book = openpyxl.Workbook()
    sheet = book.active
    for row in (["Rig", "E-7"], [], ["Time", "Force", "Angle"], ["s", "kN", "deg"]):
        sheet.append(row)
    for time, force, angle in _cells(ROWS, gaps=True):
        sheet.append([float(time), float(force) if force else None, float(angle)])
    stream = io.BytesIO()
    book.save(stream)
    return stream.getvalue()


def _write_tdms(path: Path, channels: dict[str, tuple[np.ndarray, dict]], segments: int = 1
                ) -> Path:
    """Write channels (name -> (data, properties)) of group ``Rig`` in `segments` segments."""
    with TdmsWriter(path) as writer:
        for part in range(segments):
            writer.write_segment([GroupObject("Rig")] + [
                ChannelObject("Rig", name, np.array_split(data, segments)[part],
                              properties=properties)
                for name, (data, properties) in channels.items()
            ])
    return path


#: Waveform properties of a TDMS force channel in kN (time from them).
WAVE = {"wf_increment": 5e-5, "wf_start_offset": 0.25, "unit_string": "kN"}


@pytest.fixture
def tdms_writer():
    """``write(path, {name: (data, properties)}, segments=1)``: a TDMS file of group ``Rig``."""
    return _write_tdms


def _engagement_tdms(path: Path) -> Path:
    """A TDMS engagement log of 1000 samples in 4 segments: force (a sentinel at sample 17,
    time from its waveform properties) and wheel angle."""
    force = 1.5 + 0.25 * np.sin(np.arange(1000) / 7.0)
    force[17] = -1e6
    return _write_tdms(path, {"Branch tension": (force, WAVE),
                              "Wheel angle": (np.arange(1000) * 0.01, {"unit_string": "rad"})},
                       segments=4)


@pytest.fixture(scope="session")
def corpus(tmp_path_factory) -> dict[Path, dict]:
    """Every log of the corpus, written once: path -> ``read_table`` options."""
    folder = tmp_path_factory.mktemp("corpus")
    for name, (text, encoding) in TEXT_LOGS.items():
        (folder / name).write_bytes(text.encode(encoding))
    (folder / "cyclic.dat").write_bytes(_mts().encode("latin-1"))
    (folder / "book.xlsx").write_bytes(_workbook())
    _engagement_tdms(folder / "rig.tdms")
    (folder / "graphtec.csv").write_bytes(graphtec().encode("ascii"))
    (folder / "graphtec_split_date.csv").write_bytes(graphtec(split_date=True).encode("ascii"))
    (folder / "elapsed_clock.csv").write_bytes(elapsed_clock_log().encode("ascii"))
    (folder / "spreadsheet_clock.csv").write_bytes(spreadsheet_clock_log().encode("ascii"))
    return {path: {"kind": "engagement", **OPTIONS.get(path.name, {})}
            for path in sorted(folder.iterdir())}
