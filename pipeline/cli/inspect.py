"""``chainbench inspect FILE``: what the readers detect in a raw file, processing nothing.

Prints the layout, encoding, delimiter and decimal mark, the number of rows,
each column with the role and unit found, the number of load cycles and the
warnings. Role and unit problems are shown as warnings (a file without units
shows ``unit: null``); a file that cannot be read at all gives its typed error
on one line and a non-zero exit status (``--debug`` shows the traceback).

Cycles are counted by :func:`pipeline.condition.segmentation.count_cycles` on
the force column; the cycles of the machine's own counter that the file holds,
when it has one, are shown beside them as ``machine_cycles``, with a warning
when the counter skips cycles (a fatigue machine logging some cycles only).
"""

from __future__ import annotations

import json
from enum import StrEnum
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import numpy as np
import typer
from rich.markup import escape
from rich.table import Table

from pipeline.cli._output import console, json_ready
from pipeline.errors import ChainbenchError

if TYPE_CHECKING:
    import pandas as pd

    from pipeline.condition.channels import Copy
    from pipeline.ingest.table import TableMetadata

# The readers and the segmentation are imported inside the functions that use them,
# so that every other command starts without loading them.

#: Counter units that count half cycles (two segments per load cycle).
SEGMENT_UNITS = ("segment", "segments")


class Kind(StrEnum):
    """Run kinds ``inspect`` can check a file for."""

    tensile = "tensile"
    engagement = "engagement"
    wear = "wear"
    segment_load = "segment-load"
    #: Read as an engagement log (time and branch tension), as ``chainbench run`` reads it.
    roller_engagement = "roller-engagement"


def counted_cycles(table: pd.DataFrame, metadata: TableMetadata) -> np.ndarray | None:
    """The load cycles of the machine's counter the file holds (segments, by the counter's
    unit or name, counted two per cycle), sorted, or None without a counter."""
    from pipeline.ingest.names import tokens

    if "cycle_count" not in table:
        return None
    counts = table["cycle_count"].to_numpy()
    counts = counts[np.isfinite(counts)]
    counter = next(column for column in metadata.columns if column.role == "cycle_count")
    segments = ((counter.unit or "").strip().lower() in SEGMENT_UNITS
                or "segment" in tokens(counter.name))
    per_cycle = 2 if segments else 1
    return np.unique(np.floor(counts / per_cycle)) if counts.size else None


def derived(table: pd.DataFrame, metadata: TableMetadata
            ) -> tuple[dict[str, str], dict[str, Copy]]:
    """The gauge and strain columns that measure nothing of their own
    (:func:`~pipeline.condition.channels.find_derived`), by their names in the file: length
    column -> the column it repeats, and strain column -> how it was worked out from a
    length column (:class:`~pipeline.condition.channels.Copy`)."""
    from pipeline.condition.channels import find_derived

    names = {column.role: column.name for column in metadata.columns
             if column.role and column.role.startswith(("gauge_", "strain_"))
             and column.role in table}
    kinds = {column.role: column.kind for column in metadata.columns if column.role in names}
    duplicates, copies = find_derived(
        {role: table[role].to_numpy(dtype=float) for role in names}, kinds)
    return ({names[name]: names[source] for name, source in duplicates.items()},
            {names[strain]: copy._replace(source=names[copy.source])
             for strain, copy in copies.items()})


def sample_rate(table: pd.DataFrame) -> float | None:
    """The log's sampling rate [Hz]: one over its mean time step, the gaps left out
    (steps over :data:`~pipeline.ingest.table.GAP_FACTOR` times the median), or None
    without time (or steps). Stamps rounded coarser than the steps (whole milliseconds,
    one and two apart) give the rate of the rows, not of their median step. Stamps that
    repeat with other readings (a clock to the second at two rows a second, ten rows a
    millisecond) count each row as a step: the rows between the first and the last change
    of stamp, over the time between them. Rows repeated whole, every one (a logger writing
    each sample thrice), are no samples; some repeated whole among others are a coarse
    reading's (an oscilloscope's stamps to three digits, twelve rows a stamp, beside an
    8-bit channel that rests on a value for rows on end)."""
    steps = _steps(table)
    if steps is None:
        return None
    every = np.diff(table["time"].to_numpy(dtype=float))
    repeats = np.flatnonzero(every == 0) + 1
    values = table.to_numpy(dtype=float) if repeats.size else None  # only then: rows whole
    if repeats.size and not np.all(values[repeats] == values[repeats - 1]):
        changes = np.flatnonzero(every > 0)
        between = every[changes[0] + 1:changes[-1] + 1]
        if np.any(between > 0):
            steps = between[between >= 0]
    return 1.0 / _mean_step(steps)


def _steps(table: pd.DataFrame) -> np.ndarray | None:
    """The log's positive time steps [s], None without time or steps."""
    if "time" not in table:
        return None
    steps = np.diff(table["time"].to_numpy(dtype=float))
    steps = steps[steps > 0]
    return steps if steps.size else None


def _mean_step(steps: np.ndarray) -> float:
    """The mean of time `steps` [s], the gaps the reader reports (over its factor times the
    median positive step) left out."""
    from pipeline.ingest.table import GAP_FACTOR

    return float(np.mean(steps[steps <= GAP_FACTOR * np.median(steps[steps > 0])]))


#: How far the mean time step (gaps left out) may lie from the median one before the rate
#: shown, the mean's, is said to be one of bursts or pauses.
UNEVEN_STEPS = 1.5


def uneven_steps(table: pd.DataFrame) -> str | None:
    """A warning when the log's time steps (the gaps the reader reports left out) average
    far from their median: rows sent in bursts (a logger's three readings a millisecond
    apart, then a pause) make the rate shown (:func:`sample_rate`, the mean step's) no
    steady rate of the log."""
    steps = _steps(table)
    if steps is None or steps.size < 2:
        return None
    median, mean = float(np.median(steps)), _mean_step(steps)
    if 1 / UNEVEN_STEPS <= mean / median <= UNEVEN_STEPS:
        return None
    return (f"the time steps are uneven: the median step gives {1 / median:.4g} Hz, their "
            f"mean {1 / mean:.4g} Hz (steps from {steps.min():.3g} s to {steps.max():.3g} s): "
            "the rows come in bursts or at irregular times, and the sample rate shown is the "
            "mean step's")


def slow_for_impacts(rate: float | None) -> str | None:
    """A warning when an engagement log's sampling rate `rate` [Hz] is below the advised
    one (:data:`~pipeline.condition.engagement.ADVISED_SAMPLE_RATE`), else None."""
    from pipeline.condition.engagement import ADVISED_SAMPLE_RATE

    if rate is None or rate >= ADVISED_SAMPLE_RATE:
        return None
    return (f"sampled at {rate:.4g} Hz: an engagement run needs the ringing of the chain "
            f"branch after each strike, {ADVISED_SAMPLE_RATE / 1e3:g} kHz or more; processed "
            "at this rate it is likely refused")


def summary(table: pd.DataFrame, metadata: TableMetadata) -> dict:
    """What ``inspect`` prints, as a JSON-ready mapping."""
    from pipeline.condition.segmentation import count_cycles
    from pipeline.ingest.unitparse import is_counter_unit

    cycles = count_cycles(table["force"].to_numpy()) if "force" in table else None
    held = counted_cycles(table, metadata)
    counted = None if held is None else held.size
    warnings = list(metadata.warnings)
    if held is not None and held[-1] - held[0] + 1 > held.size:
        warnings.append(
            f"the machine's counter runs from {held[0]:g} to {held[-1]:g}, and the file "
            f"holds {held.size} of those cycles: the machine logged some cycles only"
        )
    warnings += [f"the cycle counter {column.name!r} has the unit {column.unit!r}, which "
                 "chainbench cannot scale: a run refuses it (log the cycles as a plain count)"
                 for column in metadata.columns
                 if column.role == "cycle_count" and not is_counter_unit(column.unit)]
    if cycles is not None and counted is not None and cycles != counted:
        warnings.append(
            f"the force signal shows {cycles} load cycle(s), the machine's counter {counted}"
        )
    duplicates, copies = derived(table, metadata)
    kinds = {column.name: column.kind for column in metadata.columns if column.role}
    rate = sample_rate(table)
    warnings += filter(None, [uneven_steps(table)])
    sources = {name: copy.source for name, copy in copies.items()} | duplicates
    return {
        "file": metadata.file,
        "layout": metadata.layout,
        "encoding": metadata.encoding,
        "delimiter": metadata.delimiter,
        "decimal": metadata.decimal,
        "sheet": metadata.sheet,
        "specimen": metadata.specimen,
        "rows": metadata.rows,
        "sample_rate_hz": rate,
        "columns": [
            {"name": column.name, "role": column.role, "unit": column.unit,
             "si_unit": column.si_unit,
             "kind": kinds[sources[column.name]] if column.name in sources else column.kind}
            for column in metadata.columns
        ],
        "copies": {name: list(copy) for name, copy in copies.items()},
        "duplicates": duplicates,
        "cycles": cycles if cycles is not None else counted,
        "machine_cycles": counted,
        "preamble": metadata.preamble,
        "warnings": warnings,
    }


def _show(report: dict) -> None:
    shown = {"\t": "tab", " ": "space"}
    console.print(f"[bold]{escape(str(report['file']))}[/bold]", highlight=False)
    for key in ("layout", "encoding", "delimiter", "decimal", "sheet", "specimen", "rows",
                "sample_rate_hz", "cycles", "machine_cycles"):
        value = report[key]
        if value is not None:
            if key == "delimiter":
                value = shown.get(value, value)
            elif key == "sample_rate_hz":
                value = f"{value:.4g}"
            console.print(f"  {key:<15}{value}",
                          markup=False, highlight=False)
    table = Table(title="columns")
    for heading in ("name", "role", "unit", "si_unit", "kind"):
        table.add_column(heading)
    for column in report["columns"]:
        table.add_row(*(escape(str(column[key])) if column[key] is not None else "-"
                        for key in ("name", "role", "unit", "si_unit", "kind")))
    console.print(table)
    from pipeline.condition.channels import Copy

    for name, listed in report["copies"].items():
        copy = Copy(*listed)
        console.print(f"note: {escape(repr(name))} is {escape(copy.formula(repr(copy.source)))}"
                      " to the last digit: a strain worked out from it, counted as its kind",
                      highlight=False)
    for name, source in report["duplicates"].items():
        console.print(f"note: {escape(repr(name))} moves with {escape(repr(source))} to the "
                      "last digit, its zero and sign aside: one transducer written twice, "
                      "counted as its kind",
                      highlight=False)
    for warning in report["warnings"]:
        console.print(f"[yellow]warning:[/yellow] {escape(warning)}", highlight=False)


def command(
    file: Annotated[Path, typer.Argument(
        help="Raw file: CSV, machine export, .lvm, .xlsx, .ods, .xls or .tdms.")],
    kind: Annotated[Kind, typer.Option("--kind", help="Run kind the file is checked for.")] = (
        Kind.tensile
    ),
    specimen: Annotated[str | None, typer.Option(
        "--specimen", help="Of several specimens side by side in FILE, the one shown: its "
                           "label or its place from 1 (the run sheet's specimen_in_file).")
    ] = None,
    sample_rate_hz: Annotated[float | None, typer.Option(
        "--sample-rate-hz",
        help="For FILE with no time column, the rate its rows were sampled at [Hz] (the "
             "run sheet's sample_rate_hz).")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON (for programs).")] = False,
    debug: Annotated[bool, typer.Option("--debug", help="Show the traceback of an error.")] = False,
) -> None:
    """Show what the readers detect in FILE (layout, columns, units, cycles), processing nothing."""
    if sample_rate_hz is not None and not sample_rate_hz > 0:
        raise typer.BadParameter("give a rate above 0", param_hint="--sample-rate-hz")
    try:
        from pipeline.ingest import read_table
        from pipeline.runs import READ_AS

        table, metadata = read_table(file, kind=READ_AS.get(kind.value, kind.value),
                                     specimen=specimen, sample_rate_hz=sample_rate_hz,
                                     strict=False)
        report = summary(table, metadata)
        if kind in (Kind.engagement, Kind.roller_engagement) and (
                slow := slow_for_impacts(report["sample_rate_hz"])):
            report["warnings"].append(slow)
    except ChainbenchError as error:
        if debug:
            raise
        typer.echo("error: " + " ".join(str(error).split()), err=True)
        raise typer.Exit(1) from error
    except Exception as error:
        if debug:
            raise
        typer.echo(
            f"error: {file}: unexpected failure ({type(error).__name__}: "
            + " ".join(str(error).split()) + "); rerun with --debug and report it",
            err=True,
        )
        raise typer.Exit(2) from error
    if as_json:
        print(json.dumps(json_ready(report), indent=2))
    else:
        _show(report)
