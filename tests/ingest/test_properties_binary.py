"""Property-based tests of read_table on the binary layouts, ``.xlsx`` and TDMS.

The text layouts are covered by ``test_properties.py``; here:

* random valid-but-odd workbooks (sheet name, table placed anywhere after a
  preamble, units in brackets or in a units row, numbers stored as numbers or
  as text with either decimal mark, empty cells, any supported unit) come back
  in SI units to float precision;
* broken workbooks (mangled zip bytes, mangled XML inside a sound zip, an empty
  workbook, a sheet of text only, a header only): only
  :class:`~pipeline.errors.IngestError` escapes;
* random TDMS files (group and channel names, channel named as
  ``"Group/Channel"`` or ``"Channel"``, waveform properties or not, float32,
  float64 or integer data, data split over segments, a named channel absent)
  give their values and time back, or a typed error naming what is missing;
* truncated or mangled TDMS bytes: only :class:`IngestError` escapes.
"""

from __future__ import annotations

import io
import zipfile

import numpy as np
import openpyxl
import pytest
from hypothesis import HealthCheck, assume, event, given, settings
from hypothesis import strategies as st
from nptdms import ChannelObject, GroupObject, RootObject, TdmsWriter

from pipeline.errors import ColumnError, IngestError, UnitError
from pipeline.ingest import read_table
from pipeline.ingest.canonical import SENTINELS
from pipeline.ingest.names import is_unmeasured, match_role
from pipeline.units import to_si

BOUNDED = settings(max_examples=60, deadline=None,
                   suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                          HealthCheck.function_scoped_fixture])

#: Column names by role (English, German, Polish, Spanish), as machines write them.
NAMES = {
    "time": ["time", "Time", "Zeit", "czas", "Tiempo"],
    "force": ["force", "Load", "Kraft", "Standardkraft", "siła", "Fuerza"],
    "gauge": ["gauge", "Extension", "Weg", "wydłużenie", "Desplazamiento"],
}
#: Units read_table converts, per role.
UNITS = {
    "time": ["s", "ms", "min", "sec"],
    "force": ["N", "kN", "daN", "kgf", "kG", "tf", "lbf"],
    "gauge": ["mm", "µm", "um", "m", "in"],
}
VALUES = st.floats(-1e5, 1e5, allow_nan=False, allow_infinity=False)
#: Characters of sheet, group and channel names (no ``/``: it separates group and channel).
NAME_TEXT = st.text(st.characters(codec="utf-8", exclude_categories=("C",),
                                  exclude_characters="/[]:*?\\'"), min_size=1, max_size=20)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("binary")


def read_or_typed_error(path, **options):
    """Read `path`; a typed ingest error naming the file is acceptable, anything else fails."""
    try:
        result = read_table(path, **options)
    except IngestError as error:
        assert error.file == str(path)
        event(type(error).__name__)
        return None
    event("read")
    return result


def save(book: openpyxl.Workbook) -> bytes:
    """The bytes of a saved workbook."""
    stream = io.BytesIO()
    book.save(stream)
    return stream.getvalue()


def edit(content: bytes, edits) -> bytes:
    """`content` with each ``(position, "put" | "drop", data)`` edit applied in turn."""
    content = bytearray(content)
    for position, action, data in edits:
        position = min(position, len(content))
        if action == "put":
            content[position:position] = data
        else:
            del content[position : position + len(data)]
    return bytes(content)


EDITS = st.lists(st.tuples(st.integers(0, 20_000), st.sampled_from(["put", "drop"]),
                           st.binary(min_size=1, max_size=4)), min_size=1, max_size=5)


# --- .xlsx ----------------------------------------------------------------------------------

@st.composite
def workbooks(draw):
    """A valid odd workbook: what to write (see :func:`write_workbook`), the sheet to ask
    for, and the columns written as ``(role, name, unit, values)``, NaN for empty cells."""
    rows = draw(st.integers(1, 15))
    roles = draw(st.permutations((["time"] if draw(st.booleans()) else []) + ["force"]
                                 + ["gauge"] * draw(st.integers(1, 2))))
    columns = []
    for number, role in enumerate(roles):
        name = draw(st.sampled_from(NAMES[role])) + (f" {number}" if role == "gauge" else "")
        values = draw(st.lists(VALUES, min_size=rows, max_size=rows))
        missing = draw(st.lists(st.booleans(), min_size=rows, max_size=rows))
        for kept in draw(st.lists(st.integers(0, rows - 1), min_size=min(rows, 2),
                                  max_size=min(rows, 2), unique=True)):
            missing[kept] = False  # two values at least: one alone is no channel
        values = [np.nan if gone else value for value, gone in zip(values, missing, strict=True)]
        columns.append((role, name, draw(st.sampled_from(UNITS[role])), values))
    storage = [draw(st.sampled_from(["number", "text", "comma text", "mixed"])) for _ in columns]

    def cell(value, how):
        if np.isnan(value):
            return draw(st.sampled_from([None, "", "NaN"]))
        if how == "mixed":
            how = draw(st.sampled_from(["number", "text", "comma text"]))
        if how == "number":
            return value
        return repr(value).replace(".", "," if how == "comma text" else ".")

    style = draw(st.sampled_from(["[]", "()", "units row", "bracketed units row"]))
    if style in ("[]", "()"):
        header = [[f"{name} {style[0]}{unit}{style[1]}" for _, name, unit, _ in columns]]
    else:
        wrap = "({})" if style == "bracketed units row" else "{}"
        header = [[name for _, name, _, _ in columns],
                  [wrap.format(unit) for _, _, unit, _ in columns]]
    preamble = draw(st.lists(st.tuples(st.sampled_from(["Operator", "Specimen", "Machine"]),
                                       st.sampled_from(["J. Nowak", "18-A", "Amsler 50 t"])),
                             max_size=3))
    cells = [list(pair) for pair in preamble] + ([[]] if preamble else []) + header + [
        [cell(values[row], how) for (_, _, _, values), how in zip(columns, storage, strict=True)]
        for row in range(rows)
    ]
    title = draw(NAME_TEXT.map(str.strip).filter(bool))
    cover = draw(st.booleans())  # a cover sheet first: the data must then be asked for
    wanted = draw(st.sampled_from([1, title] if cover else [None, 0, title]))
    layout = {"title": title, "cells": cells, "origin": (draw(st.integers(1, 4)),
                                                          draw(st.integers(1, 3))),
              "cover": cover}
    return layout, wanted, columns


def write_workbook(path, title: str, cells: list[list], origin: tuple[int, int], cover: bool):
    """Write `cells` (None: left empty) from `origin` on sheet `title`, after a cover sheet."""
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.title = title
    for r, row in enumerate(cells):
        for c, value in enumerate(row):
            if value is not None:
                sheet.cell(origin[0] + r, origin[1] + c, value)
    if cover:
        book.create_sheet("Cover", 0)["A1"] = "see the next sheet"
    book.save(path)


@BOUNDED
@given(case=workbooks())
def test_odd_workbooks_round_trip_to_si(folder, case):
    layout, wanted, columns = case
    path = folder / "odd.xlsx"
    write_workbook(path, **layout)
    table, meta = read_table(path, sheet=wanted)
    kept = ~np.all(np.isnan([values for _, _, _, values in columns]), axis=0)  # empty rows go
    gauges = 0
    for role, name, unit, values in columns:
        if role == "gauge":
            gauges += 1
            role = f"gauge_{gauges}"
        expected = np.asarray(values)[kept] * to_si(1.0, unit)
        np.testing.assert_allclose(table[role].to_numpy(), expected, rtol=1e-12, atol=0,
                                   err_msg=f"{role} ({name} [{unit}])")
    assert meta.layout == "xlsx" and meta.rows == int(kept.sum())


VALID_BOOK = [["time [s]", "force [kN]", "gauge [mm]"], [0.0, 1.5, 0.1], [0.1, "2,5", 0.2],
              [0.2, 3.5, None]]


def zip_entries(content: bytes) -> dict[str, bytes]:
    """The entries of a zip archive, by name."""
    with zipfile.ZipFile(io.BytesIO(content)) as archive:
        return {name: archive.read(name) for name in archive.namelist()}


def rezip(entries: dict[str, bytes]) -> bytes:
    """A sound zip archive of `entries`."""
    stream = io.BytesIO()
    with zipfile.ZipFile(stream, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in entries.items():
            archive.writestr(name, data)
    return stream.getvalue()


def valid_workbook() -> bytes:
    """A small valid workbook (a preamble line, the table, a number stored as text)."""
    book = openpyxl.Workbook()
    book.active.append(["Machine", "Amsler 50 t"])
    book.active.append([])
    for row in VALID_BOOK:
        book.active.append(row)
    return save(book)


VALID_XLSX = valid_workbook()
XLSX_ENTRIES = zip_entries(VALID_XLSX)


@BOUNDED
@given(how=st.sampled_from(["bytes", "truncate", "xml", "drop entry"]), edits=EDITS,
       cut=st.integers(0, len(VALID_XLSX)), entry=st.sampled_from(sorted(XLSX_ENTRIES)))
def test_broken_workbooks_give_typed_errors(folder, how, edits, cut, entry):
    if how == "bytes":
        content = edit(VALID_XLSX, edits)
    elif how == "truncate":
        content = VALID_XLSX[:cut]
    else:
        entries = dict(XLSX_ENTRIES)
        if how == "xml":
            entries[entry] = edit(entries[entry], [(p % (len(entries[entry]) + 1), a, d)
                                                   for p, a, d in edits])
        else:
            del entries[entry]
        content = rezip(entries)
    path = folder / "broken.xlsx"
    path.write_bytes(content)
    read_or_typed_error(path)


@BOUNDED
@given(texts=st.lists(st.lists(st.one_of(st.none(), st.text(
           st.characters(exclude_categories=("C",)), max_size=12)), max_size=5), max_size=8),
       title=NAME_TEXT.map(str.strip).filter(bool))
def test_workbooks_without_numbers_give_typed_errors(folder, texts, title):
    book = openpyxl.Workbook()
    book.active.title = title
    for row in texts:  # text cells only (openpyxl keeps strings as strings): no table
        book.active.append([value if value is None else f"x{value}" for value in row])
    path = folder / "text.xlsx"
    path.write_bytes(save(book))
    with pytest.raises(IngestError) as caught:
        read_table(path)
    assert caught.value.file == str(path)


# --- TDMS -----------------------------------------------------------------------------------

DTYPES = ["float64", "float32", "int16", "int32", "int64", "uint16"]


def neutral(name: str) -> bool:
    """Whether the reader's roles ignore name `name`: it names no role, and does not keep
    a column from the role of its unit (a transverse width, a setpoint, a clock's part, a
    test's result: ``MODUL 1``, German for a modulus)."""
    name = name.strip()
    return match_role(name) is None and not is_unmeasured(name)


def channel_names(draw, count: int) -> list[str]:
    """`count` random channel names, distinct, none that the roles do not ignore."""
    return [draw(NAME_TEXT.map(lambda name, n=number: f"{name} {n}").filter(neutral))
            for number in range(count)]


@st.composite
def tdms_files(draw):
    """A TDMS engagement log: its groups, how the run sheet names channels, what to expect.

    Returns ``(groups, columns, units, segments, expected)``: ``groups`` maps
    group -> channel -> (data, properties); ``expected`` holds the SI force
    (sentinel values as NaN) and time the reader must return (time None when
    the file has none).
    """
    rows = draw(st.integers(1, 40))
    dtype = np.dtype(draw(st.sampled_from(DTYPES)))
    info = np.iinfo(dtype) if dtype.kind in "iu" else None
    values = st.integers(int(info.min), int(info.max)) if info else VALUES
    force = np.array(draw(st.lists(values, min_size=rows, max_size=rows)), dtype=dtype)
    # a group's name is part of its channels' ("group/channel"): none is a role word either
    group_names = draw(st.lists(NAME_TEXT.map(str.strip).filter(bool).filter(
        lambda name: match_role(name) is None), min_size=1, max_size=2, unique=True))
    force_name, time_name, other_name = channel_names(draw, 3)
    force_group = draw(st.sampled_from(group_names))
    properties = {}
    unit = draw(st.sampled_from([None, *UNITS["force"]]))
    if unit is not None:
        properties["unit_string"] = unit
    time_source = draw(st.sampled_from(["waveform", "waveform, no offset", "channel", "none"]))
    increment = draw(st.floats(1e-6, 10.0))
    offset = draw(st.floats(-1e3, 1e3)) if time_source == "waveform" else 0.0
    if time_source.startswith("waveform"):
        properties["wf_increment"] = increment
        if time_source == "waveform":
            properties["wf_start_offset"] = offset
        if draw(st.booleans()):
            properties["wf_samples"] = rows
    groups = {name: {} for name in group_names}
    groups[force_group][force_name] = (force, properties)
    time = offset + increment * np.arange(rows)
    if time_source == "channel":
        time_unit = draw(st.sampled_from(UNITS["time"]))
        groups[draw(st.sampled_from(group_names))][time_name] = (
            time / to_si(1.0, time_unit), {"unit_string": time_unit})
    if draw(st.booleans()):  # a channel that takes no role
        groups[draw(st.sampled_from(group_names))][other_name] = (
            np.zeros(rows), {"unit_string": "V"})
    named = draw(st.sampled_from(["channel", "group/channel", "absent"]))
    wanted = {"channel": force_name, "group/channel": f"{force_group}/{force_name}",
              "absent": f"{force_name} missing"}[named]
    columns = {"force": wanted}
    if time_source == "channel" and draw(st.booleans()):
        columns["time"] = time_name
    sheet_unit = draw(st.sampled_from([None, *UNITS["force"]]))
    units = {"force": sheet_unit} if sheet_unit else None
    segments = draw(st.integers(1, 3))
    raw = force.astype(np.float64)
    raw[np.isin(raw, list(SENTINELS))] = np.nan  # unused-channel markers read as missing
    expected = {
        "force": raw * to_si(1.0, sheet_unit or unit or "N"),
        "empty": bool(np.isnan(raw).all()),
        "time": None if time_source == "none" else time,
        "absent": wanted if named == "absent" else None,
        "unit": sheet_unit or unit,
    }
    return groups, columns, units, segments, expected


def write_tdms(path, groups, segments: int) -> None:
    """Write `groups` to `path`, the data split over `segments` segments."""
    with TdmsWriter(path) as writer:
        for number in range(segments):
            objects = [RootObject({"title": "fuzz"})] if number == 0 else []
            for group, channels in groups.items():
                objects.append(GroupObject(group))
                for channel, (data, properties) in channels.items():
                    part = np.array_split(data, segments)[number]
                    objects.append(ChannelObject(group, channel, part,
                                                 properties=properties if number == 0 else {}))
            writer.write_segment(objects)


@BOUNDED
@given(case=tdms_files())
def test_tdms_channels_round_trip(folder, case):
    groups, columns, units, segments, expected = case
    path = folder / "odd.tdms"
    write_tdms(path, groups, segments)
    try:
        table, meta = read_table(path, kind="engagement", columns=columns, units=units)
    except ColumnError as error:
        event("ColumnError")
        assert error.file == str(path)
        channels = [f"{group}/{name}" for group, names in groups.items() for name in names]
        if expected["absent"] is not None:
            assert error.column == expected["absent"]
        elif expected["empty"]:
            assert "empty" in error.message
            return
        else:  # the file gives no time: the error says which roles the run needs
            assert expected["time"] is None and "no time column" in error.message
        assert all(channel in error.hint for channel in channels), error.hint
        return
    except UnitError as error:
        event("UnitError")
        assert expected["unit"] is None and error.column is not None
        return
    event("read")
    assert expected["absent"] is None and expected["time"] is not None and not expected["empty"]
    assert meta.layout == "tdms" and meta.rows == expected["force"].size
    np.testing.assert_allclose(table["force"].to_numpy(), expected["force"], rtol=1e-12)
    np.testing.assert_allclose(table["time"].to_numpy(), expected["time"], rtol=1e-9,
                               atol=1e-12 * max(1.0, np.abs(expected["time"]).max()))


def valid_tdms(path) -> bytes:
    """The bytes of a small valid engagement log in two segments."""
    force = np.linspace(0.0, 5.0, 64)
    write_tdms(path, {"Rig": {"Branch tension": (force, {"unit_string": "kN",
                                                          "wf_increment": 1e-3}),
                              "Wheel angle": (force / 5, {"unit_string": "rad"})}}, 2)
    return path.read_bytes()


@BOUNDED
@given(cut=st.floats(0.0, 1.0, exclude_max=True), edits=st.one_of(st.just([]), EDITS))
def test_truncated_or_mangled_tdms_gives_typed_errors(folder, cut, edits):
    content = valid_tdms(folder / "valid.tdms")
    assume(cut > 0 or edits)
    content = edit(content[: max(1, int(len(content) * (1 - cut)))], edits)
    path = folder / "broken.tdms"
    path.write_bytes(content)
    read_or_typed_error(path, kind="engagement")
    read_or_typed_error(path, kind="engagement", columns={"force": "Branch tension"})
