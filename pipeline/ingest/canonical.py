"""From a reader's raw columns to the canonical table (roles, SI units, checks).

Every layout reader ends here, so the file defects that do not depend on the
layout are handled once:

* sentinel values of unused channels (:data:`SENTINELS`) become NaN;
* all-empty channels are dropped, with a note in the warnings;
* two candidates for one role (two force columns, a duplicated ``Load``) are an
  error unless the run sheet says which to take;
* a missing, unknown or wrong-dimension unit is an error naming the column and
  the run-sheet key to set (``units = {force = "kN"}``);
* a gauge column whose unit is a ratio (``%``, ``mm/mm``, ``µm/m``) is a strain
  channel, ``strain_1``...; each gauge or strain column is given the kind its
  name says (:func:`~pipeline.ingest.names.gauge_kind`: crosshead, extensometer
  or plain gauge), so that later stages never mix channels of different kinds;
* NaN stretches are kept as NaN and reported with their count and longest run;
* values a power of ten off their neighbours and back (decimal marks a spreadsheet
  mangled: :mod:`~pipeline.ingest.decimalshift`) are reported;
* time stepping backwards, repeated time stamps and time gaps are *reported* (warnings and
  :attr:`TableMetadata.time_monotonic` / ``time_gaps``), never repaired: the
  conditioning stage decides what to do with them.

With ``strict=False`` (``chainbench inspect``) role and unit problems become
warnings and the table holds only the columns that could be converted.

Roles and units are settled once per file (:func:`settle`, a
:class:`Conversion`), then applied to the whole file (:func:`build`, for
``read_table``) or to some of its rows (:func:`convert_rows`, for the
row-range reader of :mod:`pipeline.ingest.stream`): the same values either way.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from pipeline.errors import (
    ChainbenchError,
    ColumnError,
    LayoutError,
    UnitError,
)
from pipeline.ingest.decimalshift import decimal_shifts, step_blocks
from pipeline.ingest.names import (
    fold,
    gauge_kind,
    is_auxiliary,
    is_cycle_statistic,
    is_held_peak,
    is_humidity,
    is_unmeasured,
    match_role,
    peak_partner,
    repeats,
    run_labels,
    says_part,
    says_sign_convention,
    says_total,
    says_weight,
    tokens,
)
from pipeline.ingest.raw import RawColumns, RawTable
from pipeline.ingest.roles import SHEET_KEY, display_name, role_of_key
from pipeline.ingest.specimens import choose
from pipeline.ingest.statedrate import built_note, stated_rate, unread_rate
from pipeline.ingest.table import GAP_FACTOR, ROLES, ColumnInfo, TableMetadata
from pipeline.ingest.unitparse import (
    FORCE_ROLES,
    MICRO_ALONE,
    ROLE_SI_UNIT,
    is_counter_unit,
    is_mass_unit,
    is_micro_alone,
    is_strain_unit,
    is_voltage_unit,
    si_factor,
    unit_fits,
    unit_misfits,
)

#: Values some machines write for a channel that records nothing.
SENTINELS = {
    -1_000_000.0: "MTS / Instron unused-channel marker",
    -999_999.0: "unused-channel marker",
    9.9e37: "NI / Agilent overflow marker",
    999_999_999.0: "Yokogawa recorder over-range marker",
    -999_999_999.0: "Yokogawa recorder under-range marker",
}

# Values beyond these may be sentinels: the arrays are scanned for them only then.
_LOWEST_NEGATIVE = max(value for value in SENTINELS if value < 0)
_LOWEST_POSITIVE = min(value for value in SENTINELS if value > 0)

#: Seconds of a day: the step back of a time of day passing midnight.
DAY = 86_400.0

#: Roles a run of each kind must have: one role of each group (a wear log counts running
#: time or cycles, and logs a section length or an elongation, a gauge).
REQUIRED = {"tensile": (("force",), ("gauge",)), "engagement": (("time",), ("force",)),
            "wear": (("time", "cycle_count"), ("length", "gauge")),
            "segment-load": (("time",), ("force",), ("segment_force_1",), ("segment_force_2",))}

_SINGLE = ("time", "force", "angle", "cycle_count", "length", "speed", "segment_force_1",
           "segment_force_2", "side_force")
#: The roles each kind of run uses: a tensile run's stiffness needs force and gauges; an
#: engagement run the time, force and the wheel's angle when logged; a wear run its running
#: time or cycles and length or elongation; a segment-load run the time and its forces.
#: A wear run's force and speed are only shown beside its results (the load and speed
#: logged), so it does without them.
USED = {"tensile": frozenset({"force", "gauge"}),
        "engagement": frozenset({"time", "force", "angle"}),
        "wear": frozenset({"time", "cycle_count", "length", "gauge"}),
        "segment-load": frozenset({"time", "force", "segment_force_1", "segment_force_2",
                                   "side_force"})}
#: Roles a kind of run does without: when several columns could take one, none does, or
#: when its column has no unit, it is not used, with a warning, rather than the run being
#: refused (a drive rig's motor speed beside an engagement log's force and time).
DISPENSABLE = {kind: frozenset(ROLES) - used for kind, used in USED.items()}


#: Words that make a gauge column a strain by its name (English, German).
STRAIN_WORDS = frozenset({"strain", "dehnung"})

#: A unit cell that writes a dimensionless quantity as engineers do (``Dehnung [-]``).
DIMENSIONLESS = "-"

#: The hint for a strain column that has no unit: a ratio and a percentage cannot be told
#: apart from the values, and one unit for all gauges would turn the others into strains.
STRAIN_WITHOUT_UNIT_HINT = (
    'a strain may be a ratio or in %: give each gauge its unit in the run sheet, '
    'units = {gauges = ["mm", "1", ...]} ("1" for mm/mm), or keep only the gauges to use, '
    'columns = {gauges = ["..."]}'
)


class _Problems:
    """Raises in strict mode; collects warnings otherwise."""

    def __init__(self, strict: bool, warnings: list[str]) -> None:
        self.strict = strict
        self.warnings = warnings

    def report(self, error: ChainbenchError) -> None:
        if self.strict:
            raise error
        where = f"column {error.column!r}: " if error.column else ""
        self.warnings.append(where + error.message + (f" ({error.hint})" if error.hint else ""))


def _run_sheet_units(units: Mapping | None, file: str) -> dict[str, list[str]]:
    resolved = {}
    for key, value in (units or {}).items():
        role = role_of_key(key, file=file, what="units")
        resolved[role] = [value] if isinstance(value, str) else [str(item) for item in value]
    return resolved


@dataclass(frozen=True)
class Conversion:
    """How a file's raw columns become its canonical table: settled once for the whole file.

    Attributes
    ----------
    columns : tuple of (int, str, float)
        Raw column index, canonical name and SI factor of each column of the
        table, in table order.
    infos : tuple of ColumnInfo
        Every raw column and what it became (:attr:`TableMetadata.columns`).
    unitless_time : int or None
        Raw column index of a time column left out of the table for want of a
        unit: its steps are still checked (a step back, such as specimens stacked
        one below the other, needs no unit to be seen).
    interval : float or None
        Time between rows [s] that the header states, for a file without a time
        column (:mod:`pipeline.ingest.statedrate`): the table's time is built
        from it, counted from the file's first data row.
    """

    columns: tuple[tuple[int, str, float], ...]
    infos: tuple[ColumnInfo, ...]
    unitless_time: int | None = None
    interval: float | None = None

    def table(self, raw: RawTable) -> pd.DataFrame:
        """The canonical table of `raw` (its arrays converted in place), indexed by file row."""
        data = {}
        if self.interval is not None:
            data["time"] = np.arange(raw.first_row, raw.first_row + raw.rows) * self.interval
        for index, name, factor in self.columns:
            array = raw.arrays[index]
            if factor != 1.0:
                np.multiply(array, factor, out=array)
            data[name] = array
        rows = pd.RangeIndex(raw.first_row, raw.first_row + raw.rows)
        return pd.DataFrame(data, index=rows, copy=False)

    def checked_rows(self, table: pd.DataFrame, raw: RawTable, warnings: list[str]
                     ) -> tuple[bool | None, int]:
        """:func:`_check_rows` of `table`, with the time column left out for want of a unit
        (:attr:`unitless_time`) checked as read."""
        if self.unitless_time is not None:
            table = table.assign(time=raw.arrays[self.unitless_time])
            return _check_rows(table, raw, warnings, time_unit=" (no unit given)")
        return _check_rows(table, raw, warnings)


def settle(
    raw: RawColumns, empty: set[int], *, kind: str, units: Mapping | None = None,
    strict: bool = True, specimen: str | int | None = None,
    sample_rate_hz: float | None = None,
) -> Conversion:
    """Settle the roles and SI units of a file's columns.

    Parameters
    ----------
    raw : RawColumns
        The file's header; warnings go to its metadata.
    empty : set of int
        Columns holding no value in the whole file (they take no role).
    kind : {"tensile", "engagement", "wear", "segment-load"}
        The run kind: tensile runs need force and a gauge, engagement runs
        time and force, wear runs time or cycles and a length or a gauge,
        segment-load runs time, force and both segment forces.
    units : mapping, optional
        Run-sheet ``units``: role -> unit (a list for several gauges). It
        overrides the file's unit, with a warning when they differ.
    strict : bool
        Raise on role and unit problems (True) or turn them into warnings.
    specimen : str or int, optional
        Run-sheet ``specimen_in_file``: of several specimens side by side, the one
        read (its label, or its place from 1 at the left); the other specimens'
        columns take no role.
    sample_rate_hz : float, optional
        Run-sheet ``sample_rate_hz`` [Hz]: the rows' sampling, for a file with no time
        column (over the header's, :func:`_stated_interval`).

    Raises
    ------
    LayoutError
        When the columns repeat one group of names side by side (several
        specimens in one file: :func:`~pipeline.ingest.names.repeats`) and
        `specimen` does not say which to read, or says it of a file of one; when
        every force column is a cycle's maximum or minimum (a table of peaks).
    ColumnError, UnitError
        In strict mode, as listed in the module docstring.
    """
    meta = raw.metadata
    others = _other_specimens(raw, specimen)
    mine = [index for index in range(len(raw.names)) if index not in others]
    if others and all(index in empty for index in mine):
        raise LayoutError(
            f"specimen {meta.specimen!r} holds no readings: its columns "
            f"({', '.join(display_name(raw.names, index) for index in mine)}) are empty, or "
            "hold one value, in the whole file",
            file=meta.file, row=meta.header_line,
            hint="read another specimen (specimen_in_file in the run sheet)")
    empty = empty | others
    _refuse_a_table_of_peaks(raw, kind)
    problems = _Problems(strict, meta.warnings)
    sheet_units = _run_sheet_units(units, meta.file)
    ambiguous: set[str] = set()
    assigned = _settle_roles(raw, empty, set(sheet_units), problems, kind, ambiguous)
    interval = _stated_interval(raw, ambiguous, sample_rate_hz, problems)
    rejected: dict[str, UnitError] = {}
    factors, found_units, strains = _settle_units(raw, assigned, sheet_units, problems, kind,
                                                  rejected)
    needs = " and ".join(" or ".join(group) for group in REQUIRED[kind])
    for group in REQUIRED[kind]:
        if any(assigned.get(role) or role in ambiguous for role in group) or (
                interval is not None and "time" in group):
            continue
        keys = " or ".join(f"columns = {{{SHEET_KEY[role]} = \"...\"}}" for role in group)
        if "time" in group:
            keys += " (or, for rows sampled at a steady rate, the rate: sample_rate_hz = ...)"
        why = "".join(f"{reason}; " for role, reason in raw.set_aside if role in group)
        why += _spectrum_note(raw) + unread_rate(meta.preamble) if "time" in group else ""
        why += _load_note(raw, empty) if "force" in group else ""
        problems.report(next((rejected[role] for role in group if role in rejected), None)
                        or ColumnError(
            f"no {' or '.join(group)} column found ({kind} runs need {needs})",
            file=meta.file, row=raw.units_line,
            hint=f"name it in the run sheet, {keys}; {why}"
            "the file has: " + ", ".join(display_name(raw.names, i)  # not the empty ones
                                          for i in range(len(raw.names)) if i not in empty),
        ))
    if kind == "tensile":
        _warn_unnamed_strains(raw, empty)
    if kind in ("tensile", "wear"):  # the runs whose gauges are measured
        _warn_by_unit_alone(raw, "gauge", assigned.get("gauge", []))
    _warn_by_unit_alone(raw, "force", assigned.get("force", []))
    canonical = _canonical_names(assigned, strains)
    columns = tuple((index, canonical[index], factors[index]) for role in ROLES
                    for index in assigned.get(role, []) if index in factors)
    kept = {index for index, _, _ in columns}
    infos = tuple(
        ColumnInfo(
            name=display_name(raw.names, index),
            role=canonical.get(index),
            unit=found_units.get(index, raw.units[index]),
            si_unit=_si_unit(canonical[index]) if index in kept else None,
            kind=gauge_kind(raw.names[index]) if canonical.get(index, "").startswith(
                ("gauge_", "strain_")) else None,
        )
        for index in range(len(raw.names)) if index not in others
    )
    if interval is not None:
        infos = (ColumnInfo(name=STATED_TIME, role="time", unit="s", si_unit="s"), *infos)
    unitless_time = next((index for index in assigned.get("time", []) if index not in factors),
                         None)
    return Conversion(columns, infos, unitless_time, interval)


#: The name :attr:`TableMetadata.columns` gives a time built from the stated sample rate.
STATED_TIME = "time (from the stated sample rate)"


def _stated_interval(raw: RawColumns, ambiguous: set[str], sample_rate_hz: float | None,
                     problems: _Problems) -> float | None:
    """The time between rows [s] for a file with no time column (none by name, unit or run
    sheet, none set aside, none of several left undecided): the run sheet's
    `sample_rate_hz`'s, or the header's (:func:`~pipeline.ingest.statedrate.stated_rate`);
    None otherwise. Noted in the warnings, as are a header stating rates that disagree and
    a run sheet's rate unlike the header's. A run sheet's rate for a file with a time column
    is reported (a :class:`~pipeline.errors.ColumnError`)."""
    meta = raw.metadata
    timed = ("time" in raw.candidates.roles or "time" in ambiguous
             or any(role == "time" for role, _ in raw.set_aside))
    if timed:
        if sample_rate_hz is not None:
            problems.report(ColumnError(
                f"the run sheet gives sample_rate_hz = {sample_rate_hz:g}, but the file has "
                "a time column", file=meta.file, row=raw.units_line,
                hint="sample_rate_hz is for a file with no time column: leave it out"))
        return None
    stated = stated_rate(meta.preamble, meta.decimal)
    if sample_rate_hz is not None:
        interval = 1.0 / sample_rate_hz
        unlike = (f"; the header states {stated.said}, which is not used"
                  if stated is not None and not (stated.interval and math.isclose(
                      stated.interval, interval, rel_tol=1e-6)) else "")
        meta.warnings.append(built_note(f"the run sheet's sample_rate_hz = {sample_rate_hz:g}",
                                        interval) + unlike)
        return interval
    if stated is None:
        return None
    meta.warnings.append(stated.note() if stated.interval is not None else
                         f"the header states its sample rate twice, and not alike "
                         f"({stated.said}): no time is built from it")
    return stated.interval


def _warn_unnamed_strains(raw: RawColumns, empty: set[int]) -> None:
    """Warn of each column in a strain unit (or a micro sign alone, which may be one) whose
    name gives it no role: an extensometer named in a language the readers do not know
    (``Rek 1``, ``Töjning 1``, a Japanese logger's ``表-縦 μ``) would be passed over for the
    crosshead without a word."""
    candidates = raw.candidates.indexes()
    for index, name in enumerate(raw.names):
        unit = raw.units[index]
        micro = is_micro_alone(unit)
        if (index not in candidates and index not in empty
                and (micro or is_strain_unit(unit))
                and not (is_unmeasured(name) or is_humidity(name))):
            shown = display_name(raw.names, index)
            said = f"{MICRO_ALONE}" if micro else "a strain's unit"
            given = ', units = {gauges = ["µε"]}' if micro else ""
            raw.metadata.warnings.append(
                f"column {shown!r} reads in {unit!r}, {said}, but its name is not one the "
                "readers know: not used (if it is an extensometer's strain, name it in the "
                f"run sheet, columns = {{gauges = [\"{shown}\"]}}{given})")


#: What a column taken for `role` by its unit alone may be instead, and the run-sheet key
#: that names the right one (:func:`_warn_by_unit_alone`).
_BY_UNIT_ALONE = {
    "gauge": ("a gauge", "no length along the specimen (a position, a level, a feedback)",
              "gauges = [...]"),
    "force": ("the force", "not the load on the specimen (a reaction, a second load cell)",
              'force = "..."'),
}


def _warn_by_unit_alone(raw: RawColumns, role: str, columns: list[int]) -> None:
    """Warn of each of `columns` taken for `role` (a gauge, the force) by its unit alone,
    its name not one the readers know (a logger's ``Ch 2 (mm)``, but also a force plate's
    centre of pressure ``Ax (m)``, a rig's ``DilaFBK (in)``; a nanoindenter's ``Zzz
    (µN)``): unless the run sheet names the role's columns."""
    if role in raw.candidates.explicit:
        return
    taken, instead, key = _BY_UNIT_ALONE[role]
    for index in columns:
        if match_role(raw.names[index]) is None:
            shown = display_name(raw.names, index)
            raw.metadata.warnings.append(
                f"column {shown!r} is read as {taken} by its unit {raw.units[index]!r} alone, "
                f"its name not one the readers know: if it is {instead}, name "
                f"{'the gauges' if role == 'gauge' else 'the force'} in the run sheet, "
                f"columns = {{{key}}}")


def _refuse_a_table_of_peaks(raw: RawColumns, kind: str) -> None:
    """Refuse a table of one row per cycle: its force columns, or its gauge columns, are
    each cycle's peaks and valleys (and amplitudes, means); or, beside a count of cycles,
    each a maximum alone (``Cycles,Max Load,Max Position``). Unless the run sheet names
    the force or the gauges. A wear run, which does without the force, may read such a
    table (a WaveMatrix trends export: the elongation one row per cycle) once the run sheet
    names which of its gauge columns is the elongation: its hint says so."""
    roles = raw.candidates.roles
    counted = bool(roles.get("cycle_count"))
    if {"force", "gauge"} & set(raw.candidates.explicit):  # the run sheet says
        return
    for role in ("gauge",) if kind == "wear" else ("force", "gauge"):
        measured = roles.get(role, [])
        if not measured:
            continue
        if all(is_cycle_statistic(raw.names, index) for index in measured):
            first = next(index for index in measured
                         if peak_partner(raw.names, index) is not None)
            said = (f"the {role} columns {raw.names[first]!r} and "
                    f"{peak_partner(raw.names, first)!r} are a cycle's extremes")
        elif counted and all(is_held_peak(raw.names, index) for index in measured):
            shown = ", ".join(repr(raw.names[index]) for index in measured)
            said = f"the {role} column(s) {shown} hold a maximum, beside a count of cycles"
        else:
            continue
        raise LayoutError(
            f"{said}: the file is a table of one row per cycle"
            + ("" if kind == "wear" else ", not the samples of a log"),
            file=raw.metadata.file, row=raw.metadata.header_line,
            hint="a wear run reads one row per cycle: name the column that is the "
                 "elongation, the cycle's maximum or minimum as the lab measures it, "
                 'columns = {gauges = "..."}' if kind == "wear" else
                 "export the test's raw data (every sample) rather than its trends or peaks "
                 f"table; only if those columns are sampled readings, name the {role} column "
                 f"in the run sheet, columns = {{{SHEET_KEY[role]} = \"...\"}}",
        )


def _other_specimens(raw: RawColumns, specimen: str | int | None) -> set[int]:
    """The columns of the specimens other than `specimen` where the columns repeat one
    group of names side by side (:func:`~pipeline.ingest.names.repeats`); `specimen` is a
    label of :attr:`TableMetadata.specimens` or a place from 1. Records the one read in
    the metadata. A reader that chose the specimen itself (of specimens one below the
    other) has recorded it already."""
    meta = raw.metadata
    count = repeats(raw.names)
    if count == 1 and meta.specimen is not None:
        return set()
    named = len(raw.names)
    while named and not raw.names[named - 1].strip():  # trailing unnamed columns: no group's
        named -= 1
    labels = (meta.specimens if len(meta.specimens) == count
              else run_labels(raw.names[:named], count) if count > 1 else [])
    size = named // count
    group = raw.names[:size]
    said = (f"the columns {', '.join(name for name in group if name)} repeat {count} times "
            f"side by side: the file holds {count} specimens or tests")
    chosen = choose(labels, count, specimen, said, "from the left", file=meta.file,
                    row=meta.header_line)
    if count == 1:
        return set()
    meta.specimen = labels[chosen] if labels else str(chosen + 1)
    return set(range(len(raw.names))) - set(range(chosen * size, (chosen + 1) * size))


def build(
    raw: RawTable, *, kind: str, units: Mapping | None = None, strict: bool = True,
    specimen: str | int | None = None, sample_rate_hz: float | None = None,
) -> tuple[pd.DataFrame, TableMetadata]:
    """Settle roles and units of `raw` and return the canonical table.

    Parameters
    ----------
    raw : RawTable
        What the layout reader found: the whole file.
    kind, units, strict, specimen, sample_rate_hz
        See :func:`settle`. The rows past the last of a `specimen` shorter than the
        file's longest, empty in its columns, are left out with a note.

    Returns
    -------
    table : pandas.DataFrame
        Canonical columns in SI units (see :mod:`pipeline.ingest.table`).
    metadata : TableMetadata
        The reader's metadata with ``columns``, ``rows`` and the checks filled in.

    Raises
    ------
    LayoutError
        When the columns repeat one group of names side by side (several
        specimens in one file: :func:`~pipeline.ingest.names.repeats`), or when
        every force column is a cycle's maximum or minimum (a table of peaks).
    ColumnError, UnitError
        In strict mode, as listed in the module docstring.
    """
    meta = raw.metadata
    empty = raw.empty | clean(raw, meta.warnings)
    if empty:
        meta.warnings.append(empty_warning(raw.names, empty))
    lone = _lone_values(raw, empty, meta.warnings)
    conversion = settle(raw, empty | lone, kind=kind, units=units, strict=strict,
                        specimen=specimen, sample_rate_hz=sample_rate_hz)
    table = conversion.table(raw)
    if meta.specimen is not None:
        table = _without_padding(table, raw, meta)
    table = _without_end_mark(table, raw, meta)
    meta.time_monotonic, meta.time_gaps = conversion.checked_rows(table, raw, meta.warnings)
    meta.rows = len(table)
    meta.columns = list(conversion.infos)
    meta.warnings += unlike_stated(meta.preamble, meta.rows)
    return table, meta


#: Keys of a header that state how many rows the file holds, folded (IMADA's ``Data
#: Quantity`` and ``DATA COUNT``, an oscilloscope's ``Record Length``, Kistler BioWare's
#: ``Samples (#)``, once over each channel; a Kyowa recorder's ``集録データ数/CH``, rows
#: recorded a channel).
STATED_ROWS_KEYS = frozenset({"data quantity", "data count", "record length",
                              "number of points", "number of samples", "number of rows",
                              "samples (#)", fold("集録データ数/CH")})


def _stated_rows(preamble: Mapping[str, str]) -> tuple[str, int] | None:
    """The key and the number of rows the header states (:data:`STATED_ROWS_KEYS`)."""
    for key, value in preamble.items():
        counts = set(value.replace(",", " ").split())  # one, or the same over each channel
        text = counts.pop() if len(counts) == 1 else ""
        if fold(key.strip()) in STATED_ROWS_KEYS and text.isdigit():
            return key.strip(), int(text)
    return None


def unlike_stated(preamble: Mapping[str, str], rows: int) -> list[str]:
    """A warning when the header states (:data:`STATED_ROWS_KEYS`) more rows than the
    `rows` read (a file cut short at a line end shows no other sign), or fewer (a row
    past them is read as a sample)."""
    stated = _stated_rows(preamble)
    if stated is None or stated[1] == rows:
        return []
    said = f"the header says {stated[0]} = {stated[1]}, the file holds {rows} rows"
    if stated[1] > rows:
        return [f"{said}: it may be cut short (copy it again from the machine)"]
    return [f"{said}: the rows past the stated ones are read as samples (an end mark, "
            "or another test's rows): check the last rows"]


def _without_end_mark(table: pd.DataFrame, raw: RawTable, meta: TableMetadata
                      ) -> pd.DataFrame:
    """`table` without its last row when that is the one past the rows the header states
    and holds nothing but zeros: the software's end mark (a Deben tester's
    ``0,0,0,0,1,0,"0"``, read as a sample, made a stopped test's fracture at its end)."""
    stated = _stated_rows(meta.preamble)
    if stated is None or len(table) != stated[1] + 1:
        return table
    last = table.iloc[-1].to_numpy(dtype=float)
    if not np.all((last == 0.0) | np.isnan(last)):
        return table
    meta.warnings.append(f"the row at {raw.where(len(table) - 1)}, past the {stated[1]} the "
                         f"header states ({stated[0]}), holds only zeros: an end mark, left out")
    return table.iloc[:-1]


def _without_padding(table: pd.DataFrame, raw: RawTable, meta: TableMetadata) -> pd.DataFrame:
    """`table` (one specimen's of several side by side) without its last rows where they
    are empty in every column: the specimen ended before the file's longest did."""
    filled = np.flatnonzero(table.notna().any(axis=1).to_numpy())
    stop = int(filled[-1]) + 1 if filled.size else len(table)
    if stop < len(table):
        meta.warnings.append(
            f"specimen {meta.specimen!r} ends at {raw.where(stop - 1)}: the "
            f"{len(table) - stop} row(s) below, empty in its columns, were left out")
    return table.iloc[:stop]


def convert_rows(raw: RawTable, conversion: Conversion) -> tuple[pd.DataFrame, list[str]]:
    """The canonical table of some rows of a file, converted as settled for the whole file.

    Parameters
    ----------
    raw : RawTable
        The rows, as read (:attr:`RawTable.first_row` says where they start).
    conversion : Conversion
        The file's :func:`settle`.

    Returns
    -------
    table : pandas.DataFrame
        As :func:`build` would give these rows, indexed by file row.
    warnings : list of str
        What these rows gave: sentinels, missing values, time steps back and
        gaps, each counted within the rows.
    """
    warnings: list[str] = []
    clean(raw, warnings)
    table = conversion.table(raw)
    conversion.checked_rows(table, raw, warnings)
    return table, warnings


def _canonical_names(assigned: dict[str, list[int]], strains: set[int]) -> dict[int, str]:
    """Column index -> canonical name: gauges ``gauge_1``..., strains ``strain_1``..., in file
    order within each."""
    names: dict[int, str] = {}
    counts = {"gauge": 0, "strain": 0}
    for role in ROLES:
        for index in assigned.get(role, []):
            if role != "gauge":
                names[index] = role
                continue
            prefix = "strain" if index in strains else "gauge"
            counts[prefix] += 1
            names[index] = f"{prefix}_{counts[prefix]}"
    return names


#: Units of a frequency axis (a spectrum's, a sweep's), folded.
_FREQUENCY_UNITS = frozenset({"hz", "khz", "mhz"})


def _spectrum_note(raw: RawColumns) -> str:
    """What the hint of a missing time says of a column of frequencies (``Frequency [Hz]``,
    a spectrum's or a frequency sweep's axis), or ""."""
    found = next((index for index, unit in enumerate(raw.units)
                  if (unit or "").strip().casefold() in _FREQUENCY_UNITS), None)
    if found is None:
        return ""
    return (f"column {display_name(raw.names, found)!r} is in {raw.units[found]}: a spectrum "
            "or a frequency sweep, whose rows are frequencies, has no time and is no test "
            "record; ")


#: An accelerometer's axis (a drop-test logger's ``ax``, ``AccY``), whose ``g`` is gravity's,
#: no gram: never offered as a load in grams.
_ACCELEROMETER_AXIS = re.compile(r"(?:a|acc|accel)[\s_.-]?[xyz]", re.IGNORECASE)


def _load_note(raw: RawColumns, empty: set[int]) -> str:
    """What the hint of a missing force says of the columns in a unit of mass whose name
    gives no role (a load cell's ``Value [kg]``), and of those named as a weight without a
    unit (a load-cell logger's ``weight``): a mass alone makes no force, but such a column
    may be the load, as the weight of that mass; and of those in volts (a logger's input
    ``(1)HA-V01``), a sensor's signal that no reader turns into a force; or ""."""
    notes = []
    for index, unit in enumerate(raw.units):
        name = raw.names[index]
        if index in empty or match_role(name) is not None or is_unmeasured(name):
            continue
        shown = display_name(raw.names, index)
        if is_mass_unit(unit) and not _ACCELEROMETER_AXIS.fullmatch(name.strip()):
            notes.append(f"column {shown!r} is in {unit}, a mass: if it is the load, name it "
                         "as the force (read as the weight of that mass); ")
        elif is_voltage_unit(unit):
            notes.append(f"column {shown!r} is in {unit}, a sensor's signal: if it is the "
                         "load, convert it to a force with the sensor's calibration first "
                         "(the readers apply none); ")
        elif unit is None and says_weight(name):
            notes.append(f"column {shown!r} is named as a weight, with no unit: if it is the "
                         "load, name it as the force with its unit (a mass's, kg or g, is read "
                         "as the weight of that mass); ")
    return "".join(notes)


def _si_unit(name: str) -> str:
    return ROLE_SI_UNIT[name.partition("_")[0] if name.startswith(("gauge_", "strain_"))
                        else name]


def clean(raw: RawTable, warnings: list[str]) -> set[int]:
    """Sentinels to NaN (noted in `warnings`); returns the arrays left without a value."""
    empty = set()
    for index, array in raw.arrays.items():
        low = np.fmin.reduce(array) if array.size else np.nan
        if low <= _LOWEST_NEGATIVE or (array.size and np.fmax.reduce(array) >= _LOWEST_POSITIVE):
            mask = np.isin(array, list(SENTINELS))
            count = int(np.count_nonzero(mask))
            if count:
                found = "; ".join(f"{value:g}, {SENTINELS[value]}"
                                  for value in sorted(set(array[mask].tolist())))
                array[mask] = np.nan
                warnings.append(f"column {display_name(raw.names, index)!r}: {count} sentinel "
                                f"values ({found}) set to NaN")
                low = np.fmin.reduce(array)
        if np.isnan(low):
            empty.add(index)
    return empty


def first_values(raw: RawTable, columns: set[int]) -> dict[int, tuple[int, float, str]]:
    """Of each of `columns` of `raw`: how many values it holds (two at most are counted),
    and the first, with where it stands when it is the only one (NaN and "" without)."""
    found = {}
    for index in columns:
        array = raw.arrays[index]
        finite = np.isfinite(array[:2])
        if not finite.all():  # a value missing from the first two rows: look further
            finite = np.isfinite(array)
        count = min(2, int(np.count_nonzero(finite)))
        at = int(np.argmax(finite))
        found[index] = (count, float(array[at]) if count else math.nan,
                        raw.where(at) if count == 1 else "")
    return found


def lone_warning(names: list[str], index: int, value: float, line: str, rows: int) -> str:
    """What to say of a column holding one value (`value`, on `line`) over `rows` rows: a
    specimen's diameter written beside its first sample, no channel."""
    return (f"column {display_name(names, index)!r} holds one value ({value:g}, {line}) over "
            f"{rows} rows: a specimen's dimension or a setting, no channel: not used")


def _lone_values(raw: RawTable, empty: set[int], warnings: list[str]) -> set[int]:
    """The columns (not `empty`) holding one value among :data:`LONE_ROWS` rows or more,
    told in `warnings` (:func:`lone_warning`)."""
    if raw.rows < LONE_ROWS:
        return set()
    lone = {index: (value, line) for index, (count, value, line)
            in first_values(raw, set(raw.arrays) - empty).items() if count == 1}
    warnings += [lone_warning(raw.names, index, value, line, raw.rows)
                 for index, (value, line) in lone.items()]
    return set(lone)


#: Rows a column of one value must stand beside to be no channel.
LONE_ROWS = 10


def empty_warning(names: list[str], empty: set[int]) -> str:
    """The warning listing the empty columns, dropped."""
    return (f"{len(empty)} empty column(s) dropped: "
            + ", ".join(display_name(names, index) for index in sorted(empty)))


def _settle_roles(raw: RawColumns, empty: set[int], sheet_units: set[str], problems: _Problems,
                  kind: str, ambiguous: set[str]) -> dict[str, list[int]]:
    """The columns of each role: the candidates with values, and of a role that takes one
    column, the only one (else an ambiguity is reported, and no column takes the role: it is
    added to `ambiguous`; for a role the `kind` of run does without, :data:`DISPENSABLE`, a
    warning only). Of several
    candidates matched by name, those whose unit in the file is not one of the role (a
    stress in MPa named after its load channel) are left out, with a warning, when some
    others fit or the run does without the role (a drive's speeds in rpm are no chain
    speed); so are those :data:`_PREFERRED` passes over (:func:`_preferred`)."""
    file = raw.metadata.file
    assigned: dict[str, list[int]] = {}
    for role, indexes in raw.candidates.roles.items():
        live = [index for index in indexes if index not in empty]
        if (role in _SINGLE and len(live) > 1 and role not in raw.candidates.explicit
                and role not in sheet_units):
            misfits = [index for index in live if unit_misfits(raw.units[index], role)]
            if len(misfits) < len(live) or role in DISPENSABLE.get(kind, ()):
                for index in misfits:
                    _warn_misfit(raw, index, role)
                live = [index for index in live if index not in misfits]
        if role in _SINGLE and len(live) > 1 and role not in raw.candidates.explicit:
            live = _without_copies(raw, _preferred(raw, live, role, kind, role in sheet_units),
                                   role)
        if role in raw.candidates.explicit and len(live) < len(indexes):
            dead = next(index for index in indexes if index in empty)
            problems.report(ColumnError(
                f"the column given for {role} in the run sheet is empty",
                file=file, column=display_name(raw.names, dead),
                hint="check the run sheet's columns, or the export",
            ))
        if role in _SINGLE and len(live) > 1:
            shown = [display_name(raw.names, index) for index in live]
            same = len(set(shown)) == 1
            ambiguity = ColumnError(
                f"column {shown[0]!r} is duplicated" if same else
                f"{len(live)} columns could be the {role}: " + ", ".join(map(repr, shown)),
                file=file, row=raw.units_line, column=shown[0],
                hint=f"say which in the run sheet, columns = {{{SHEET_KEY[role]} = \"...\"}}"
                + (", after renaming the duplicates in the export" if same else ""),
            )
            if role in DISPENSABLE.get(kind, ()) and role not in raw.candidates.explicit:
                raw.metadata.warnings.append(
                    f"{ambiguity.message}: none is used as the {role}, which {kind} runs do "
                    f"without ({ambiguity.hint})")
                continue
            problems.report(ambiguity)  # not strict: no column is taken for a guess
            ambiguous.add(role)
            continue
        if live:
            assigned[role] = live
    return assigned


#: The rules that go by the file's units: not for a role whose unit the run sheet gives.
_UNITED = ((frozenset({"force"}), lambda raw, at: unit_fits(raw.units[at], "force"),
            "has no unit of force beside one that has"),
           (frozenset({"time"}), lambda raw, at: unit_fits(raw.units[at], "time"),
            "has no unit of time beside one that has"))
#: The time's symbol as a column's whole name: a time when its unit is one (a rig's
#: ``t [ms]``, its controller's clock, beside the PC's ``Timestamp``), never by itself.
TIME_SYMBOL = "t"
#: A column that moves over one holding a value (:func:`_constant`).
_MOVING = (frozenset({"force", "time"}), lambda raw, at: not _constant(raw, at),
           "holds one value in every row of the file: no signal, beside one that moves")


#: Of several candidates for a role, the columns preferred, with why the others are not
#: used: for a force or a time a run uses, one that moves over one holding a value
#: throughout (a net load never worked out, all zeros; a count may rest at one cycle, a
#: tribometer's normal load at its setting); the testing machine's over a second
#: instrument's; for a force or a time, one in a unit of the role over one without (a
#: test stand's English ``temps``, its temperatures, beside ``elapsed (s)``; an insole's
#: clock beside its steps' ``Contact_time``); for a time, one named so (or ``t``, the time's
#: symbol) over one of a time unit only (a thrust stand's ``ESC signal (µs)``, a pulse
#: width), and a time
#: counted over clock readings (PASCO's ``Date and Time``, to the second); for a time or
#: a count, the whole test's over one that starts again (a step's, a cycle's, one since a
#: counter's reset); for a force, the measured load over one turned to a kind of test's
#: sign, the reading over a peak held.
_PREFERRED = (
    _MOVING,
    (None, lambda raw, at: not is_auxiliary(raw.names[at]),
     "is a second instrument's {role} beside the machine's"),
    *_UNITED,
    (frozenset({"time"}), lambda raw, at: (match_role(raw.names[at]) == "time"
                                           or fold(raw.names[at]).strip() == TIME_SYMBOL),
     "has a unit of time but no name of one, beside a column named as the time"),
    (frozenset({"time"}), lambda raw, at: at not in raw.clocks,
     "holds clock readings beside a time counted in seconds"),
    (frozenset({"time", "cycle_count"}), lambda raw, at: says_total(raw.names[at]),
     "is named as one that starts again (a step's, a cycle's, since a reset) beside the "
     "whole test's"),
    (frozenset({"time"}), lambda raw, at: not says_part(raw.names[at]),
     "is named as a part's of the test (a scan's, a step's), which starts again with each, "
     "beside one that is not"),
    (frozenset({"force"}), lambda raw, at: not says_sign_convention(raw.names[at]),
     "is named as the load in one kind of test's sign, worked out from the measured one"),
    (frozenset({"force"}), lambda raw, at: not is_held_peak(raw.names, at),
     "is a peak held beside the reading itself"),
)


def _constant(raw: RawColumns, index: int) -> bool:
    """Whether column `index` holds one value in each of :data:`LONE_ROWS` rows or more of
    the whole file; False when its readings are not at hand (a log read by ranges)."""
    if not isinstance(raw, RawTable) or raw.rows < LONE_ROWS:
        return False
    array = raw.arrays[index]
    return bool(np.fmin.reduce(array) == np.fmax.reduce(array))


def _preferred(raw: RawColumns, live: list[int], role: str, kind: str, sheet_unit: bool
               ) -> list[int]:
    """Of the columns `live` that could take a `role` one column takes, those of
    :data:`_PREFERRED` when some are and some are not; each column passed over is warned
    of. A column holding one value is passed over only for a role the `kind` of run uses
    (a tribometer's normal load is one value, the friction force beside it no load); the
    file's units do not choose when the run sheet gives the role's (`sheet_unit`)."""
    for rule in _PREFERRED:
        roles, keeps, why = rule
        if (roles is not None and role not in roles
                or rule is _MOVING and role not in USED[kind]
                or rule in _UNITED and sheet_unit):
            continue
        kept = [index for index in live if keeps(raw, index)]
        if not kept or len(kept) == len(live):
            continue
        shown = ", ".join(repr(display_name(raw.names, index)) for index in kept)
        raw.metadata.warnings += [
            f"column {display_name(raw.names, index)!r} {why.format(role=role)} ({shown}): "
            f"not used (say otherwise in the run sheet, columns = "
            f"{{{SHEET_KEY[role]} = \"...\"}})" for index in live if index not in kept]
        live = kept
    return live


def _without_copies(raw: RawColumns, live: list[int], role: str) -> list[int]:
    """The columns `live` but those holding the values of one before them row for row, in
    the same unit (any count, for a counter), each warned of: one channel written twice (MTS
    TestSuite's ``_Cycle`` index beside the ``Cycle Channel`` it copies) takes the role once.
    All kept when the readings are not at hand (a log read by ranges), or are too few to
    tell a copy from a coincidence (under :data:`LONE_ROWS` rows, or one value throughout:
    a table of results)."""
    if not isinstance(raw, RawTable) or raw.rows < LONE_ROWS:
        return live
    kept: list[int] = []
    for index in live:
        copied = next((first for first in kept if _same_unit(raw, first, index, role)
                       and not _constant(raw, first)
                       and np.array_equal(raw.arrays[first], raw.arrays[index], equal_nan=True)),
                      None)
        if copied is None:
            kept.append(index)
            continue
        raw.metadata.warnings.append(
            f"column {display_name(raw.names, index)!r} holds the values of "
            f"{display_name(raw.names, copied)!r} row for row: one channel written twice, "
            f"{display_name(raw.names, copied)!r} is the {role}")
    return kept


def _same_unit(raw: RawColumns, first: int, second: int, role: str) -> bool:
    """Whether two columns are in one unit as written (any count, for a counter)."""
    if role == "cycle_count":
        return is_counter_unit(raw.units[first]) and is_counter_unit(raw.units[second])
    first_unit, second_unit = ((raw.units[index] or "").strip().casefold()
                               for index in (first, second))
    return first_unit == second_unit


#: The readings of a spreadsheet's date serials: days since 1899-12-30, from 1954 to 2119.
_DATE_SERIALS = (20_000.0, 80_000.0)
_DATE_SERIALS_HINT = (" (its numbers look like a spreadsheet's dates and times, days since "
                      '1899: units = {time = "d"})')


def _date_serials(raw: RawColumns, index: int) -> bool:
    """Whether column `index` reads as a spreadsheet's date serials, rising by fractions of
    a day (``45352,4166666667``: a time saved through a spreadsheet as a number); False
    when its readings are not at hand (a log read by ranges)."""
    if not isinstance(raw, RawTable) or index not in raw.arrays:
        return False
    values = raw.arrays[index][np.isfinite(raw.arrays[index])]
    steps = np.diff(values)
    return bool(values.size > 2 and _DATE_SERIALS[0] <= values.min()
                and values.max() <= _DATE_SERIALS[1] and np.all(steps >= 0)
                and 0 < values[-1] - values[0] < 30)


def _says_strain(name: str) -> bool:
    """Whether a gauge column's name makes it a strain (:data:`STRAIN_WORDS`)."""
    return not STRAIN_WORDS.isdisjoint(tokens(name))


def _warn_misfit(raw: RawColumns, index: int, role: str) -> None:
    si = "" if role == "cycle_count" else f" ({ROLE_SI_UNIT[role]})"  # a count has none
    raw.metadata.warnings.append(f"column {display_name(raw.names, index)!r}: unit "
                                 f"{raw.units[index]!r} is not a unit of {role}{si}: column "
                                 "not used")


def _settle_units(
    raw: RawColumns,
    assigned: dict[str, list[int]],
    sheet_units: dict[str, list[str]],
    problems: _Problems,
    kind: str,
    rejected: dict[str, UnitError],
) -> tuple[dict[int, float], dict[int, str | None], set[int]]:
    """SI factors of the columns that can be converted, each column's unit text, and the
    gauge columns that hold a strain (a ratio unit).

    A column matched by name whose unit is of another dimension (``Kraft
    [mm]``) is not used, with a warning; its error is kept in `rejected` in
    case its role ends up missing.
    """
    file = raw.metadata.file
    factors: dict[int, float] = {}
    found: dict[int, str | None] = {}
    strains: set[int] = set()
    for role in list(assigned):
        for position, index in enumerate(list(assigned[role])):
            name = display_name(raw.names, index)
            text, source = raw.units[index], "the file"
            given = sheet_units.get(role)
            sheet_text = given[min(position, len(given) - 1)] if given else text
            if index in raw.clocks and sheet_text != text:  # clock readings: seconds already
                raw.metadata.warnings.append(
                    f"column {name!r}: unit {sheet_text!r} from the run sheet not used: the "
                    "column holds clock readings, read as seconds")
            elif given and index not in raw.clocks:
                if text and sheet_text != text and is_voltage_unit(text):
                    raw.metadata.warnings.append(
                        f"column {name!r}: the file gives it in {text!r}, a sensor's signal, "
                        f"no {role}; read in {sheet_text!r} as the run sheet says: right only "
                        f"if its amplifier was scaled to give {sheet_text!r} (1 {text} = 1 "
                        f"{sheet_text}); else convert it with the sensor's calibration first "
                        "(the readers apply none)")
                elif text and sheet_text != text and unit_misfits(text, role):
                    raw.metadata.warnings.append(
                        f"column {name!r}: the file gives it in {text!r}, no unit of {role}; "
                        f"read in {sheet_text!r} as the run sheet says: check that it is the "
                        f"{role} column (columns = ...) and that its numbers are in "
                        f"{sheet_text!r}")
                elif text and sheet_text != text:
                    raw.metadata.warnings.append(
                        f"column {name!r}: unit {sheet_text!r} from the run sheet replaces "
                        f"{text!r} from the file"
                    )
                text, source = sheet_text, "the run sheet"
            found[index] = text
            if role == "cycle_count":
                factors[index] = 1.0
                continue
            if text is None:
                missing = UnitError(
                    f"no unit for the {role} column",
                    file=file, row=raw.units_line, column=name,
                    hint=STRAIN_WITHOUT_UNIT_HINT if role == "gauge" and _says_strain(name)
                    else f'the file gives none: set it in the run sheet, units = '
                         f'{{{SHEET_KEY[role]} = "..."}}'
                         + (_DATE_SERIALS_HINT if role == "time" and _date_serials(raw, index)
                            else ""),
                )
                if role in DISPENSABLE.get(kind, ()) and role not in raw.candidates.explicit:
                    raw.metadata.warnings.append(
                        f"column {name!r}: {missing.message}, which {kind} runs do without: "
                        f"not used ({missing.hint})")
                else:
                    problems.report(missing)
                continue
            if (role == "gauge" and text.strip().strip("()[]").strip() == DIMENSIONLESS
                    and _says_strain(name)):  # "strain [-]": a ratio, written dimensionless
                raw.metadata.warnings.append(
                    f"column {name!r}: unit {text!r} read as a ratio (mm/mm): a strain "
                    "written dimensionless")
                text = "1"
            if role == "gauge" and is_strain_unit(text):
                strains.add(index)
                factors[index] = si_factor(text, "strain", file=file, row=raw.units_line,
                                           column=name, source=source)
                continue
            explicit = role in raw.candidates.explicit or source == "the run sheet"
            if unit_misfits(text, role) and not explicit:
                _warn_misfit(raw, index, role)
                rejected[role] = UnitError(
                    f"unit {text!r} is not a unit of {role} ({ROLE_SI_UNIT[role]})",
                    file=file, row=raw.units_line, column=name,
                    hint="correct the unit, or name the columns in the run sheet (columns = ...)",
                )
                assigned[role].remove(index)
                found.pop(index)
                continue
            try:
                factors[index] = si_factor(
                    text, role, file=file, row=raw.units_line, column=name, source=source
                )
            except UnitError as error:
                problems.report(error)
                continue
            if role in FORCE_ROLES and is_mass_unit(text):
                raw.metadata.warnings.append(
                    f"column {name!r}: unit {text!r} is a mass: read as the force of its "
                    f"weight ({text} x standard gravity, {factors[index]:.6g} N)")
        if not assigned[role]:
            del assigned[role]
    return factors, found, strains


def _report_missing(table: pd.DataFrame, raw: RawTable, warnings: list[str]) -> None:
    for name in table.columns:
        values = table[name].to_numpy()
        with np.errstate(invalid="ignore"):  # inf - inf is NaN: no warning to print
            if not values.size or np.isfinite(np.add.reduce(values)):  # no NaN, Inf: one pass
                continue
        infinite = np.flatnonzero(np.isinf(values))
        if infinite.size:
            warnings.append(f"{name}: {infinite.size} infinite values (Inf or -Inf, a script's "
                            f"overflow or division by zero), the first at "
                            f"{raw.where(int(infinite[0]))}")
        if not np.isnan(values.min()):  # the minimum is NaN if any value is
            continue
        missing = np.isnan(values)
        count = int(np.count_nonzero(missing))
        edges = np.diff(np.concatenate(([0], missing.view(np.int8), [0])))
        starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
        longest = int(np.argmax(ends - starts))
        warnings.append(
            f"{name}: {count} missing values kept as NaN; longest run "
            f"{ends[longest] - starts[longest]} rows from {raw.where(int(starts[longest]))}"
        )


def _report_decimal_shifts(table: pd.DataFrame, raw: RawTable, warnings: list[str]) -> None:
    for name in table.columns:
        count, first = decimal_shifts(table[name].to_numpy())
        if count:
            warnings.append(
                f"{name}: {count} values jump tenfold (or more) from the one before and back, "
                f"first at {raw.where(first)}, as when a spreadsheet took the decimal mark for "
                "a thousands separator: compare the file with the machine's own export"
            )


#: Rows below the first that tell what the first should look like.
FIRST_ROW_PEERS = 50


def _report_first_row(raw: RawTable, warnings: list[str]) -> bool:
    """Tell (and return whether there is) a first data row whose values lie outside the
    range of the next :data:`FIRST_ROW_PEERS` rows, by over ten times that range, in most
    of the columns but the time's (two at least): a row of settings written above the
    samples (a script's ``150,75,500`` of sampling rate, samples per channel and timer over
    forces of a few newtons). A time far from the next is a gap, told as such."""
    if raw.first_row or raw.rows <= FIRST_ROW_PEERS // 5:
        return False
    told = unlike = 0
    times = set(raw.candidates.roles.get("time", ()))
    for values in (values for index, values in raw.arrays.items() if index not in times):
        first, peers = values[0], values[1:FIRST_ROW_PEERS + 1]
        peers = peers[np.isfinite(peers)]
        if not np.isfinite(first) or peers.size < FIRST_ROW_PEERS // 5:
            continue
        told += 1
        low, high = float(peers.min()), float(peers.max())
        unlike += bool(min(abs(first - low), abs(first - high)) > 10 * (high - low))
    if not (told >= 2 and 2 * unlike > told):
        return False
    warnings.append(
        f"{raw.where(0)}, the first data row, is unlike the rows below it: in {unlike} of "
        f"{told} columns its value lies outside their range by over ten times it. A row "
        "of settings (a rate, a count) written above the samples? It is read as the first "
        "sample: delete it from a copy of the file if it is none")
    return True


#: Steps a gauge may take over half its range before its jumps are no longer told (a
#: fatigue log of peaks and valleys takes one each row).
JUMPS_TOLD = 3
#: Rows before a jump whose way it goes against to step back.
JUMP_TREND = 20


def _report_jump(table: pd.DataFrame, raw: RawTable, warnings: list[str], start: int = 0
                 ) -> None:
    """Tell a gauge or length (of a table without time) that steps back, against its way
    over the :data:`JUMP_TREND` rows before, over half its range in one step, no more than
    :data:`JUMPS_TOLD` steps crossing so much, while its median step is under a hundredth of
    the range and the range over a tenth of its largest value: a second test appended below
    the first (the displacement back at its start after the fracture), or a gauge taken off
    or reset, that no time shows. The rows before `start` are left out (a first row told
    unlike the others)."""
    for name in table.columns:
        if not name.startswith(("gauge_", "strain_", "length")):
            continue
        values = table[name].to_numpy()[start:]
        steps = np.abs(np.diff(values))
        finite = steps[np.isfinite(steps)]
        if finite.size < 10:
            continue
        span = float(np.nanmax(values) - np.nanmin(values))
        jumps = steps > span / 2
        if not (1 <= np.count_nonzero(jumps) <= JUMPS_TOLD and np.median(finite) < span / 100
                and span > np.nanmax(np.abs(values)) / 10):
            continue
        back = [at for at in np.flatnonzero(jumps) + 1 if (values[at] - values[at - 1]) * (
            values[at - 1] - values[max(0, at - 1 - JUMP_TREND)]) < 0]
        if not back:
            continue
        at = back[0]
        line = raw.where(start + at)
        unit = "" if _si_unit(name) == "1" else " " + _si_unit(name)
        warnings.append(
            f"{name}: crosses {steps[at - 1] / span:.0%} of its range in one step, from "
            f"{values[at - 1]:.4g}{unit} to {values[at]:.4g}{unit} at {line}, where its "
            f"median step is {np.median(finite) / span:.2%} of it: a second test appended "
            "below the first, or a gauge taken off or reset? The file has no time to tell; "
            "give each test its own file")
        return


def _step_extremes(time: np.ndarray, block: int = 1 << 16) -> tuple[float, float]:
    """Smallest and largest step of `time` (NaN when a step is NaN), a block at a time, so
    that no array of every step is made for a log whose steps are all in order."""
    smallest, largest = math.inf, -math.inf
    for _, steps in step_blocks(time, block):
        low, high = float(steps.min()), float(steps.max())
        if math.isnan(low):
            return math.nan, math.nan
        smallest, largest = min(smallest, low), max(largest, high)
    return smallest, largest


def _past_midnight(raw: RawTable, step: float) -> str:
    """What a step back of `step` [s] in a time of day means when it is about a day: the
    clock passed midnight, and the log's date (if any) is elsewhere."""
    if not (any(clock.kind == "time of day" for clock in raw.clocks.values())
            and -DAY <= step < -DAY + 3600):
        return ""
    return (" (the time of day passes midnight; a date in the column before or after it is joined "
            "only when it can be read one way: year first, dotted, or of slashes whose "
            "dates follow one another day by day read day first or month first; export the "
            "date and time in one column, year first, or the time in seconds)")


def _no_time(count: int, steps: int) -> str:
    """What steps back, three or more, in a quarter of the `steps` or more mean: no time (a
    request's latency, a reading named after the time)."""
    if count < 3 or 4 * count < steps:
        return ""
    return (f" (in {count} of {steps} steps: a time runs forward, so the column may be no "
            "time; name the time in the run sheet, columns = {time = \"...\"})")


def _starts_again(time: np.ndarray, backwards: np.ndarray) -> str:
    """What a step back to the first sample's time (within two of its first steps) means:
    tests one after another."""
    first_step = float(time[1] - time[0])
    landed = time[1:][backwards]
    if not (first_step > 0 and np.any(np.abs(landed - time[0]) <= 2 * first_step)):
        return ""
    return (" (back to the first sample's time: the time starts again, as a cycle's or a "
            "step's own time does, or as the next test's in a file of tests one after "
            "another)")


def _check_rows(table: pd.DataFrame, raw: RawTable, warnings: list[str],
                time_unit: str = " s") -> tuple[bool | None, int]:
    """Report missing values and time problems of `table` in `warnings`, its time steps
    told in `time_unit` (the seconds of the canonical table, or a file's time as read).

    Returns
    -------
    time_monotonic : bool or None
        False if time steps back, None without time (or with one row).
    time_gaps : int
        Time steps longer than :data:`GAP_FACTOR` x the median step.
    """
    _report_missing(table, raw, warnings)
    _report_decimal_shifts(table, raw, warnings)
    unlike_first = _report_first_row(raw, warnings)
    if "time" not in table or len(table) < 2:
        _report_jump(table, raw, warnings, start=int(unlike_first))
        return None, 0
    time = table["time"].to_numpy()
    smallest, largest = _step_extremes(time)
    count, steps = 0, None  # every step, made only for a log whose extremes show a problem
    if not smallest > 0:  # a step back, a repeat or a missing time: find which
        steps = np.diff(time)
        backwards = steps < 0
        count = int(np.count_nonzero(backwards))
        if count:
            first = int(np.argmax(backwards)) + 1
            warnings.append(f"time: steps back {count} times, first at {raw.where(first)}"
                            + (_no_time(count, steps.size) or _past_midnight(raw, steps[first - 1])
                               or _starts_again(time, backwards)))
        repeated = steps == 0
        if repeated.any():
            first = int(np.argmax(repeated)) + 1
            warnings.append(
                f"time: {int(np.count_nonzero(repeated))} repeated time stamp(s), first at "
                f"{raw.where(first)}"
            )
    every = max(1, (time.size - 1) // 100_000)
    sample = time[1::every] - time[:-1:every]  # every n-th step
    sample = sample[sample > 0]
    if not sample.size:
        return count == 0, 0
    median = float(np.median(sample))
    if largest <= GAP_FACTOR * median:
        return count == 0, 0
    steps = np.diff(time) if steps is None else steps
    gaps = steps > GAP_FACTOR * median  # a gap, or a missing time: count the gaps
    count_gaps = int(np.count_nonzero(gaps))
    if count_gaps:
        first = int(np.argmax(gaps)) + 1
        warnings.append(
            f"time: {count_gaps} gap(s) longer than {GAP_FACTOR:g} x the median step "
            f"({median:.3g}{time_unit}), the longest {float(steps[gaps].max()):.3g}{time_unit}, "
            f"first before {raw.where(first)}")
    return count == 0, count_gaps
