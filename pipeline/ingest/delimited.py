"""Delimited text tables, in the layouts machines and lab PCs write, declared as data.

One reader (:func:`read_contiguous`) reads every delimited layout; a layout
(:class:`TextLayout`) only says how it is recognised from the sniffed head of
the file and whether its preamble is kept. :data:`LAYOUTS` are tried in order.

``machine_export``: a free-text preamble, a names row, a separate units row
(Instron Bluehill ``RawData``)::

    Text Inputs : Specimen label,"22L.3"
    General : Start Date,13/11/2018 5:14 PM

    Time,Extension,Load,Segment ID,Total Cycle Count
    (sec),(mm),(N),,
    0.00000,-2.04726,-4.31900,22476,0

``european_csv``: ``;`` or tab delimiter and a decimal comma, as Polish and
German lab PCs write (often cp1250), or ``;`` and a decimal point::

    czas [s];siła [kN];wydłużenie [mm]
    0,00;0,012;0,000

``plain_csv``: one names row with units in brackets, ``,`` delimiter, ``.``
decimal mark::

    time [s],force [kN],gauge1 [mm],gauge2 [mm]
    0.00,0.012,0.000,0.001

File defects handled in every layout
------------------------------------
* units in ``[...]`` or ``(...)`` after the name, in their own row
  (``(sec),(mm),(N),,``, ``Sec  mm  kgf``; empty for counters and IDs), or
  none (then from the run sheet);
* a UTF-8 BOM, UTF-16 with BOM, cp1250 or latin-1 text;
* CRLF, LF or CR line ends; blank lines inside the table;
* quoted cells (``"1.5"``, ``"0,892"``), blanks and ``NaN``/``N/A`` cells
  (missing values); a trailing delimiter on data rows (an extra empty column,
  dropped);
* a decimal comma (``0,892``, parsed by pyarrow with ``decimal_point=","``),
  also where the comma is the delimiter too: read if quoted, or if every value
  splits unambiguously into an integer and a fraction field (``0,5,1,25``
  under ``time,force``), else an error with a hint;
* a mixed decimal mark (a ``0.5`` in a decimal-comma file), a non-numeric
  cell, a row with too many or too few fields: an error naming line and column;
* text lines after the last data row (``Results``, ``Test ended``): left
  out with a warning;
* a half-written last line (no line end after it): too few fields, or a last
  number that stops short of the decimals its column always has (``0,`` or
  ``0,0`` where the column writes ``0,000``): dropped with a warning; a
  complete last line without a line end is kept;
* a time column of clock readings (``14:03:27.125``, ``2024-03-05 14:03:27``):
  seconds after the first row's (:mod:`pipeline.ingest.clock`);
* the machine's cycle counter (``Total Cycle Count``) kept as ``cycle_count``;
  columns nobody maps (``Segment ID``) kept out of the table;
* German, Polish, Spanish and English column names (:mod:`pipeline.ingest.names`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import pyarrow as pa

from pipeline.errors import EmptyFileError, IngestError, LayoutError
from pipeline.ingest import waveforms
from pipeline.ingest.clock import (
    MINUTE_READINGS,
    READ_FORMS,
    ClockColumn,
    declare_seconds,
    is_unread_clock,
    stops_at_minute,
)
from pipeline.ingest.names import (
    fold,
    header_text,
    is_clock_part,
    is_unmeasured,
    match_role,
    split_name_unit,
)
from pipeline.ingest.preamble import parse_preamble
from pipeline.ingest.raw import RawColumns, RawTable
from pipeline.ingest.roles import Candidates, display_name, find_candidates
from pipeline.ingest.sniff import Head, TableSpec, is_number, require_names, split_fields
from pipeline.ingest.table import TableMetadata
from pipeline.ingest.textbody import (
    Region,
    comment_warning,
    float_arrays,
    join_comma_pairs,
    parse_body,
    split_table,
    trim_trailer,
    trim_truncated_tail,
    truncated_warning,
    without_events,
)
from pipeline.ingest.unitparse import (
    is_micro_alone,
    is_quantity_unit,
    is_strain_unit,
    spellings,
    unit_fits,
)

#: The preamble settings an oscilloscope gives its time axis's unit under (Tektronix; Rohde
#: & Schwarz's RTH writes the singular).
HORIZONTAL_UNITS = ("Horizontal Units", "Horizontal Unit")
#: ... and its channels' unit, when it writes one for all.
VERTICAL_UNITS = ("Vertical Units", "Vertical Unit")
#: The keys of a preamble row that gives each channel's unit, folded (a DTS SLICE export's
#: ``Engineering Unit``, a Kyowa PCD-400A's ``単位``, a Rohde & Schwarz RTH oscilloscope's
#: ``Vertical Unit``).
UNITS_ROW_KEYS = frozenset({"engineering unit", "engineering units", "unit", "units", "eu",
                            "vertical unit", "vertical units",
                            "einheit", "einheiten", "unite", "unites", "unidad", "unidades",
                            "unidade", "単位"})
#: Column names that are a unit of time, folded: the column holds the time in that unit
#: (not ``s``, which a German export gives a displacement, nor ``min``, a minimum, nor
#: ``ms``, which a KEYENCE logger gives the milliseconds of its date-time column).
TIME_UNIT_NAMES = frozenset({"sec", "secs", "seconds", "minutes", "mins", "hours", "hrs"})
#: Words before a unit of time that name a machine's running time (``Operating hours``,
#: ``Run hours``): the column holds that time in the unit.
RUNNING_WORDS = frozenset({"operating", "run", "running", "test"})
#: Column names of a microcontroller's clock call, folded, and the unit it counts in:
#: Arduino's ``millis()`` and ``micros()``, an HX711 logger's first column.
CLOCK_CALL_UNITS = {"millis": "ms", "micros": "µs"}
#: Column names that are a unit of force, folded: the column holds the force in that unit (a
#: pull tester's ``Distance, Newtons``). Not ``N`` alone, which may number the samples.
FORCE_UNIT_NAMES = frozenset({"newton", "newtons", "kilonewton", "kilonewtons", "lbf", "kgf",
                              "gf", "gmf"})
#: Units of time a name gives beside ``elapsed`` only (``elapsed_ms``, ``s_elapsed``).
ELAPSED_UNITS = frozenset({"ms", "s", "min", "h"})
#: The warning of a file whose decimal comma is also its delimiter.
PAIRS_WARNING = "the decimal comma is also the delimiter: values were rejoined in pairs"


def header_columns(spec: TableSpec) -> tuple[list[str], list[str | None]]:
    """Column names and units from the names row (``name [unit]``, or ``name unit`` in
    every cell) and the units row.

    A unit in the names row other than the units row's stays in the name: Bluehill's
    ``"Tensile strain (Extension)"`` over ``"(mm/mm)"`` names the channel the strain
    was computed from (see :func:`~pipeline.ingest.names.gauge_kind`).
    """
    split = [split_name_unit(cell) for cell in spec.names]
    if spec.units_index is None and not any(unit for _, unit in split):
        trailing = _trailing_unit_words(spec.names)
        if trailing is not None:
            return [name for name, _ in trailing], [unit for _, unit in trailing]
    names, units = [], []
    for cell, (name, unit), row_unit in zip(spec.names, split, spec.units, strict=True):
        if row_unit and unit is not None and unit != row_unit:
            name = header_text(cell)
        names.append(name)
        units.append(row_unit or unit)
    return names, units


def _trailing_unit_words(cells: list[str]) -> list[tuple[str, str | None]] | None:
    """Names and units of a names row whose cells end in a unit word.

    Bluehill's ``.raw.csv`` writes ``Time sec;Extension mm;Strain 1 %;Load N``: when
    every named cell ends in a word pint reads, each is a unit (after ``in``, which
    is left out of the name: ``in s,C1 in V``). Otherwise a last word
    is a unit only where it is a unit of the role the rest of the name gives
    (a Japanese logger's ``荷重 kN`` beside ``名前`` and ``測定日時``, or a script's
    ``time_s,force_kN``): ``"Weg 1"`` or ``"Channel A"`` end in a word pint reads
    (``1``, amperes) without being units.
    None when no cell has a unit.
    """
    # a comma before the unit (Russian software's "Время, с") is no part of the name
    split = [(name.rstrip().removesuffix(","), blank, unit)
             for name, blank, unit in (cell.strip().rpartition(" ") for cell in cells)]
    named = [(name.strip(), unit) for name, _, unit in split if unit]
    if len(named) >= 2 and all(
            name and not unit.isdigit() and spellings(unit) for name, unit in named):
        return [(_without_in(name), unit or None) for name, _, unit in split]
    fitting = [(name.strip().removesuffix(","), unit)
               if _unit_after_its_name(name.strip(), unit, blank)
               else (cell.strip(), None)
               for cell, (name, blank, unit) in zip(cells, map(_last_word, cells), strict=True)]
    return fitting if any(unit for _, unit in fitting) else None


def _last_word(cell: str) -> tuple[str, str, str]:
    """`cell` split before its last word: after its last blank, or in a name without one,
    after its last underscore (a script's ``time_s``, ``force_kN``), a prefix written out
    before it joined to it (``load_micro_N``: ``load`` in µN, never in N)."""
    text = cell.strip()
    name, separator, unit = text.rpartition(" " if " " in text else "_")
    stem, _, prefix = name.rpartition("_")
    if separator == "_" and stem and prefix.casefold() in _PREFIXES:
        return stem, separator, _PREFIXES[prefix.casefold()] + unit
    return name, separator, unit


#: SI prefixes a script writes out before a unit's symbol (``load_micro_N``).
_PREFIXES = {"nano": "n", "micro": "µ", "milli": "m", "kilo": "k", "mega": "M"}


def _time_unit_of_the_scope(names: list[str], units: list[str | None],
                            preamble: dict[str, str], warnings: list[str]) -> list[str | None]:
    """`units`, a time column without one given the preamble's :data:`HORIZONTAL_UNITS`
    (a Tektronix oscilloscope's ``TIME,CH1`` under its settings), and the channels without
    one its single :data:`VERTICAL_UNITS` (``Vertical Units,V``: a force channel in volts
    is then told as such), with a note."""
    key = next((key for key in HORIZONTAL_UNITS if preamble.get(key, "").strip()), None)
    if key is None:
        return units
    axis = preamble[key].strip()
    vertical = next((key for key in VERTICAL_UNITS if preamble.get(key, "").strip()), None)
    level = preamble[vertical].strip() if vertical else ""
    given = [axis if unit is None and match_role(name) == "time"
             else level if unit is None and name.strip() and len(level.split()) == 1
             else unit for name, unit in zip(names, units, strict=True)]
    warnings += [f"column {name!r}: unit {new!r} from the preamble's "
                 f"{key if new == axis else vertical}"
                 for name, unit, new in zip(names, units, given, strict=True) if unit != new]
    return given


def _unit_of_its_name(names: list[str], units: list[str | None],
                      warnings: list[str]) -> list[str | None]:
    """`units`, a column without one whose name is a unit of time (:data:`TIME_UNIT_NAMES`: a
    logger's ``seconds``, an oscilloscope's ``sec`` beside ``Volt1``), alone or with
    ``elapsed`` (a phone logger's ``seconds_elapsed``), or a unit of force
    (:data:`FORCE_UNIT_NAMES`: ``Newtons``), given that unit, with a note."""
    given = [(time_unit_named(name)
              or (name.strip() if fold(name.strip()) in FORCE_UNIT_NAMES else None))
             if unit is None else unit
             for name, unit in zip(names, units, strict=True)]
    warnings += [f"column {name!r}: unit {new!r} from its name"
                 for name, unit, new in zip(names, units, given, strict=True) if unit != new]
    return given


def time_unit_named(name: str) -> str | None:
    """The unit of time `name` names, as written, or None.

    A name that is a unit of time (:data:`TIME_UNIT_NAMES`), alone or beside
    ``elapsed`` (a phone logger's ``seconds_elapsed``; beside ``elapsed``, ``ms``,
    ``s``, ``min`` and ``h`` are units too): the column holds the time in it. So does
    a microcontroller's clock call (:data:`CLOCK_CALL_UNITS`), in its unit, and a
    machine's running time in a unit of time (:data:`RUNNING_WORDS`).

    >>> time_unit_named("seconds_elapsed"), time_unit_named("elapsed_ms"), time_unit_named("ms")
    ('seconds', 'ms', None)
    >>> time_unit_named("Operating hours"), time_unit_named("Cycle hours")
    ('hours', None)
    >>> time_unit_named("millis()")
    'ms'
    """
    words = re.findall(r"[^\W_]+", name)
    if len(words) == 1 and fold(words[0]) in CLOCK_CALL_UNITS:
        return CLOCK_CALL_UNITS[fold(words[0])]
    unit = [word for word in words if fold(word) != "elapsed"]
    units = TIME_UNIT_NAMES | (ELAPSED_UNITS if len(unit) < len(words) else frozenset())
    if len(unit) == 1 and fold(unit[0]) in units and len(words) <= 2:
        return unit[0]
    if (len(words) == 2 and fold(words[0]) in RUNNING_WORDS
            and fold(words[1]) in TIME_UNIT_NAMES):  # a wear rig's "Operating hours"
        return words[1]
    return None


def _units_of_a_preamble_row(spec: TableSpec, names: list[str], units: list[str | None],
                             warnings: list[str]) -> list[str | None]:
    """`units`, with those a row of the preamble gives the channels (a DTS SLICE export's
    ``Engineering Unit,deg/sec,g,...`` above ``Time,Chan 0,...``), with a note.

    The row is a settings row: its key (:data:`UNITS_ROW_KEYS`) over the first column,
    a unit over two channels at least, nothing but units; a single ``Units,mm`` setting
    names no column. It may lie in a table of settings passed over above the data (a
    Kyowa PCD-400A's ``"単位","g","g"`` under its calibration factors).
    """
    for line in (*spec.preamble, *spec.passed):
        key, *cells = (cell.strip() for cell in split_fields(line, spec.delimiter))
        given = [cell or None for cell in cells[: len(units) - 1]]
        if (fold(key) not in UNITS_ROW_KEYS or len(cells) > len(units)
                or sum(cell is not None for cell in given) < 2
                or not all(cell is None or spellings(cell) for cell in given)):
            continue
        filled, changed = list(units), []
        for index, unit in enumerate(given, start=1):
            if filled[index] is None and unit is not None:
                filled[index] = unit
                changed.append(display_name(names, index))
        if changed:
            warnings.append(f"units of {', '.join(map(repr, changed))} from the preamble's "
                            f"{key!r} row")
        return filled
    return units


def _units_of_unit_columns(head: Head, spec: TableSpec, names: list[str],
                           units: list[str | None], warnings: list[str]) -> list[str | None]:
    """`units`, with the unit a column named as such (:data:`UNITS_ROW_KEYS`) gives the
    column before it, as a force gauge writes it beside each value (Imada:
    ``Force,Unit,Displacement,Unit`` over ``0.0,gf,0.000,mm``), with a note.

    Only a column of text holding one unit in every row of the file's head, beside a
    column that has no unit of its own.
    """
    unit_columns = [index for index in range(1, len(names))
                    if fold(names[index]) in UNITS_ROW_KEYS and index in spec.texts
                    and units[index - 1] is None]
    if not unit_columns:  # the head's rows are split only for a file that has such columns
        return units
    rows = [split_fields(line, spec.delimiter) for line in head.lines[spec.data_index:]
            if line.strip()]
    filled = list(units)
    for index in unit_columns:
        found = sorted({row[index].strip() for row in rows if len(row) > index})
        column, beside = display_name(names, index - 1), display_name(names, index)
        if len(found) == 1 and spellings(found[0]):
            filled[index - 1] = found[0]
            warnings.append(f"unit of {column!r} ({found[0]}) from the column {beside!r} "
                            "beside it")
        elif len(found) > 1 and all(map(spellings, found)):
            warnings.append(f"the column {beside!r} beside {column!r} holds several units "
                            f"({', '.join(found)}): none is taken as its unit")
    return filled


def _without_in(name: str) -> str:
    """A name without the ``in`` before its unit word (Rohde & Schwarz: ``C1 in V``)."""
    words = name.split()
    return " ".join(words[:-1] if words[-1:] == ["in"] else words)


def _unit_after_its_name(name: str, unit: str, separator: str) -> bool:
    """Whether `unit`, after `name` and `separator`, is a unit of the role `name` gives
    (``荷重`` and ``kN``: force; a strain's ratio for a gauge), or of another quantity, two
    letters or more and no word (``Load psi``, ``Velocidad_RPM``: the column then refuses it,
    where the file was said to give no unit); or, after a name that gives
    no role, a strain's ratio or a micro sign alone after a blank (a Japanese logger's
    ``表-縦 με``, ``表-横 μ``: such a column is warned of), or a unit of force of two
    letters or more after an underscore (a load logger's ``current_kN``, ``peak_kN``), or
    of length (a nanoindenter's ``depth_nm``; not ``in``): ``N`` alone may be a number's
    mark (``Sample_N``), ``m`` a minute's; or of the quantity of a symbol (``t_sec``, ``F_N``:
    :data:`_SYMBOLS`). A word that names a role is part of the name
    (``Ext Strain``: a strain, its unit unknown, not a ratio)."""
    if not (name and unit) or unit.isdigit() or match_role(unit) is not None:
        return False  # a number ends a name (Weg 1, gauge_1); a role word names
    role = match_role(name)
    if role is not None:  # a unit of another quantity is the column's, to be refused
        return (unit_fits(unit, role) or (role == "gauge" and is_strain_unit(unit))
                or (len(unit) > 1 and unit[0].isalpha()  # a label: Strain_1a, no 1 a
                    and unit.casefold() not in _WORDS_AS_UNITS and is_quantity_unit(unit)))
    return ((separator == "_" and len(unit) > 1 and unit != "in"
             and (unit_fits(unit, "force") or unit_fits(unit, "length")))
            or (separator == "_" and unit_fits(unit, _SYMBOLS.get(name, "")))
            or (separator == " " and (is_strain_unit(unit) or is_micro_alone(unit))))


#: A quantity's symbol before an underscore and its unit (a script's ``t_sec``, ``F_N``).
_SYMBOLS = {"t": "time", "F": "force"}


#: Words pint reads as units that end a name as words (``Force at``, ``Time AM``) or as
#: an axis (a force plate's centre of pressure, ``ground_force1_px``: no pixels), folded.
_WORDS_AS_UNITS = frozenset({"in", "at", "am", "pm", "px"})


def metadata(head: Head, spec: TableSpec, layout: str, preamble: dict[str, str]) -> TableMetadata:
    """The metadata every text layout reports."""
    return TableMetadata(
        file=head.name,
        layout=layout,
        encoding=head.encoding,
        delimiter=spec.delimiter,
        decimal=spec.decimal,
        preamble=preamble,
        header_line=names_line(spec),
        first_data_line=spec.data_index + 1,
        warnings=spec.results_warning(),
        specimens=list(spec.specimens),
    )


def names_line(spec: TableSpec) -> int | None:
    """The 1-based line of the names row; None when the file has none."""
    return None if spec.header_index is None else spec.header_index + 1


def units_line(spec: TableSpec) -> int | None:
    """The line to point at for a unit problem: the units row, else the names row."""
    return spec.units_index + 1 if spec.units_index is not None else names_line(spec)


def text_header(
    head: Head, spec: TableSpec, layout: str, preamble: dict[str, str], columns: Mapping | None
) -> RawColumns:
    """What the header of a text table says: names, units, role candidates, metadata.

    Parameters
    ----------
    head, spec
        The sniffed head and table.
    layout : str
        The layout's name, for the metadata.
    preamble : dict
        The parsed preamble, for the metadata.
    columns : mapping, optional
        Run-sheet ``columns`` (see :func:`~pipeline.ingest.roles.find_candidates`).
    """
    require_names(spec, head.name, columns)
    names, units = header_columns(spec)
    meta = metadata(head, spec, layout, preamble)
    names, units = waveforms.time_columns(head, spec, names, units, meta.warnings)
    units = _time_unit_of_the_scope(names, units, preamble, meta.warnings)
    units = _unit_of_its_name(names, units, meta.warnings)
    if spec.units_index is None:
        units = _units_of_a_preamble_row(spec, names, units, meta.warnings)
    units = _units_of_unit_columns(head, spec, names, units, meta.warnings)
    candidates, set_aside = numeric_candidates(
        spec, find_candidates(names, units, columns, file=head.name,
                              header_line=names_line(spec)),
        names, split_fields(head.lines[spec.data_index], spec.delimiter), meta.warnings)
    candidates = _clock_as_time(spec, names, candidates, meta.warnings)
    clocks = time_clocks(spec, candidates, names, units, meta.warnings)
    return RawColumns(names=names, units=units, candidates=candidates, metadata=meta,
                      units_line=units_line(spec), clocks=clocks, set_aside=set_aside)


def numeric_candidates(spec: TableSpec, candidates: Candidates, names: list[str],
                       first: list[str], warnings: list[str]
                       ) -> tuple[Candidates, tuple[tuple[str, str], ...]]:
    """`candidates` without the columns that hold text, the clock readings of any role but
    the time, and the fractions of a second beside a clock; the roles those columns would
    have taken, each with why (:attr:`~pipeline.ingest.raw.RawColumns.set_aside`), also
    told in `warnings`. `first` is the first data row's cells."""
    candidates, texts = candidates.without(spec.texts)
    candidates, stamps = candidates.without(frozenset(spec.clocks), but="time")
    candidates, _ = candidates.without(spec.fractions)
    set_aside = tuple((role, _why_set_aside(display_name(names, index), first[index].strip(),
                                            what))
                      for found, what in ((texts, "text"), (stamps, "clock readings"))
                      for index, role in found.items())
    warnings += [f"{why}: not used as the {role}" for role, why in set_aside]
    return candidates, set_aside


def _why_set_aside(name: str, cell: str, what: str) -> str:
    """Why column `name`, whose first cell is `cell`, takes no role: it holds `what`."""
    if what == "text" and is_unread_clock(cell):
        if stops_at_minute(cell):
            return (f"column {name!r} holds clock readings to the minute ({cell!r}...): "
                    f"{MINUTE_READINGS}")
        return (f"column {name!r} holds clock readings in a form the reader does not guess "
                f"({cell!r}...; it reads {READ_FORMS}), to be exported as seconds")
    return f"column {name!r} holds {what} ({cell!r}...), not numbers"


def _clock_as_time(spec: TableSpec, names: list[str], candidates: Candidates,
                   warnings: list[str]) -> Candidates:
    """`candidates`, and where no column may be the time, the one column whose cells are
    clock readings and whose name gives it no role as the time, with a note: one without a
    name (PicoLog writes ``""`` over its time stamps), one named as a part of a clock whose
    cells hold the whole reading (a Spanish logger's ``Hora``, ``19:22:30,584``, beside
    its ``Fecha``), one whose name the readers do not know (``Uhrzeit``, ``Clock``). A
    name of another quantity (``last_changed``) keeps it from the role."""
    clocks = [index for index in spec.clocks if index not in candidates.indexes()
              and match_role(names[index]) is None
              and (is_clock_part(names[index]) or not is_unmeasured(names[index]))]
    if "time" in candidates.roles or "time" in candidates.explicit or len(clocks) != 1:
        return candidates
    said = ("whose name the readers do not take for a time" if names[clocks[0]].strip()
            else "which has no name")
    warnings.append(f"column {display_name(names, clocks[0])!r}, {said}, holds clock "
                    "readings: taken as the time")
    return Candidates(candidates.roles | {"time": clocks}, candidates.explicit)


def time_clocks(spec: TableSpec, candidates: Candidates, names: list[str],
                units: list[str | None], warnings: list[str]) -> dict[int, ClockColumn]:
    """The time columns whose cells are clock readings (:attr:`TableSpec.clocks`).

    Their unit in `units` becomes ``"s"`` (the reader turns them into
    seconds), and a note for each goes into `warnings`.
    """
    clocks = {index: spec.clocks[index] for index in candidates.roles.get("time", [])
              if index in spec.clocks}
    declare_seconds(clocks, names, units, warnings)
    return clocks


def raw_table(
    parsed: tuple[dict[int, pa.ChunkedArray], int, set[int]],
    region: Region,
    header: RawColumns,
    first_row: int = 0,
) -> RawTable:
    """Wrap a parsed body as a :class:`RawTable` (float candidates, empty others).

    Parameters
    ----------
    parsed : tuple
        :func:`~pipeline.ingest.textbody.split_table` of the parsed body; the
        caller holds no other reference to the table, so that its columns are
        freed as they are converted.
    region : Region
        Where the rows are in the file.
    header : RawColumns
        The table's header.
    first_row : int
        The file's 0-based row number of the region's first row.

    Raises
    ------
    EmptyFileError
        If the body holds no row.
    """
    chunks, rows, empty = parsed
    require_rows(rows, region)
    return header.table(arrays=float_arrays(chunks), rows=rows, line_of=region.line_of,
                        empty=empty, first_row=first_row)


def require_rows(rows: int, region: Region) -> None:
    """Raise :class:`~pipeline.errors.EmptyFileError` if `region` holds no data row."""
    if rows == 0:
        raise EmptyFileError(
            "the file has a header but no data rows",
            file=region.name, row=region.first_line,
            hint="the machine wrote no measurements: export the test again",
        )


def body(head: Head, spec: TableSpec, warnings: list[str]) -> Region:
    """The region from the first data row to the end of the table.

    Text lines after the last data row (a results block, an end-of-test line)
    are left out, with a warning appended to `warnings`
    (:func:`~pipeline.ingest.textbody.trim_trailer`).
    """
    whole = Region(head.source, head.offsets[spec.data_index], head.size, spec.data_index + 1,
                   head.codec)
    region, trailer = trim_trailer(whole, spec.width, spec.delimiter, spec.decimal)
    if trailer is not None:
        warnings.append(trailer)
    return region


def parse_rows(
    region: Region, spec: TableSpec, header: RawColumns, body: Region | None = None
) -> tuple[tuple[dict[int, pa.ChunkedArray], int, set[int]], int]:
    """Parse the rows of `region` with pyarrow (values split by a decimal comma rejoined,
    clock readings turned into seconds, comment lines passed over); of `body` if given
    (the rows of `region` without the lines it leaves out).

    Returns
    -------
    parsed : tuple
        :func:`~pipeline.ingest.textbody.split_table` of the parsed rows.
    comments : int
        Comment lines passed over.
    """
    names, found = header.names, header.candidates
    try:
        table, comments = parse_body(
            body or region,
            region,
            names=names,
            width=spec.width,
            delimiter=spec.delimiter,
            decimal=spec.decimal,
            float_columns=found.indexes(),
            clocks=header.clocks,
            as_text=spec.pairs,
        )
    except LayoutError as error:
        if not spec.pairs:
            raise
        raise LayoutError(
            error.message, file=error.file, row=error.row, column=error.column,
            hint="the decimal comma is also the delimiter, so a value written without "
            "decimals (or left empty) shifts the fields: export with ';' or tab as "
            "delimiter, or with quoted numbers",
        ) from error
    if spec.pairs:
        table = join_comma_pairs(table, region, names)
    return split_table(table, found.indexes(), len(names), header.clocks), comments


def read_contiguous(head: Head, spec: TableSpec, header: RawColumns) -> RawTable:
    """Read a table whose data rows run from the first data row to the end of the file.

    A truncated last line is dropped with a warning (see
    :func:`~pipeline.ingest.textbody.trim_truncated_tail`).
    """
    whole = body(head, spec, header.metadata.warnings)
    region, truncated = trim_truncated_tail(whole, spec.width, spec.delimiter, spec.decimal)
    try:
        parsed, comments = parse_rows(region, spec, header)
    except IngestError as error:
        found = without_events(region, spec.delimiter, spec.decimal)
        if found is None or error.row not in {number for number, _ in found[2]}:
            raise
        rows, region, events = found
        parsed, comments = parse_rows(region, spec, header, rows)
        header.metadata.warnings.append(
            f"{len(events)} line(s) among the data rows hold a text, not readings (events "
            f"the machine logged), left out; the first at line {events[0][0]}: "
            f"{events[0][1][:60]!r}")
    if comments:
        header.metadata.warnings.append(comment_warning(region, comments))
    if spec.pairs:
        header.metadata.warnings.append(PAIRS_WARNING)
    if truncated:
        header.metadata.warnings.append(truncated_warning(whole.line_of(parsed[1])))
    return raw_table(parsed, region, header)


def _settings(lines: list[str], spec: TableSpec) -> list[str]:
    """The lines of a table passed over above the data that each give a setting: a name,
    then one value over every channel (Kistler BioWare's ``Samples (#):``, ``59118`` in
    each column); not a batch's results, one row a specimen."""
    found = []
    for line in lines:
        name, *cells = (cell.strip() for cell in split_fields(line, spec.delimiter))
        values = {cell for cell in cells if cell}
        if name and not is_number(name, spec.decimal) and len(values) == 1:
            found.append(line)
    return found


@dataclass(frozen=True)
class TextLayout:
    """A delimited-text layout: its name, how it is recognised, whether it has a preamble."""

    name: str
    #: True when the sniffed head and table are of this layout
    matches: Callable[[Head, TableSpec], bool]
    #: the free-text lines above the table, and the settings of a table passed over there
    #: (:func:`_settings`), are parsed into the metadata's preamble
    preamble: bool = False

    def header(self, head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawColumns:
        """The header of a file sniffed as `head` / `spec` in this layout (see
        :func:`text_header`)."""
        preamble = (parse_preamble([*spec.preamble, *_settings(spec.passed, spec)],
                                   spec.delimiter) if self.preamble else {})
        return text_header(head, spec, self.name, preamble, columns)

    def read(self, head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
        """Read a file sniffed as `head` / `spec` in this layout (see the module docstring)."""
        return read_contiguous(head, spec, self.header(head, spec, columns))


#: The delimited layouts, in the order they are tried; the last one matches any table.
LAYOUTS = (
    TextLayout("machine_export", preamble=True,
               matches=lambda head, spec: bool(spec.preamble) or spec.units_index is not None),
    TextLayout("european_csv",
               matches=lambda head, spec: spec.decimal == "," or spec.delimiter == ";"),
    TextLayout("plain_csv", matches=lambda head, spec: True),
)
