"""Printing tables for people (rich) or for programs (``--json``).

Every text that comes from the user's inputs (file names, run-sheet keys, error
messages quoting them) may hold square brackets, which rich would read as
markup: it is escaped before it is printed (:func:`say`, :func:`emit`). Nor are
emoji codes read (a units cell ``H:M:S`` would show ``HⓂS``).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from numbers import Integral, Real

from rich.console import Console
from rich.markup import escape
from rich.table import Table

console = Console(emoji=False)
#: Messages of commands whose standard output is a JSON document go here.
error_console = Console(stderr=True, emoji=False)


def say(tag: str, style: str, text: str, *, stderr: bool = False,
        to: Console | None = None) -> None:
    """Print `text` after a coloured `tag` (``error``, ``warning``, ``note``...).

    Parameters
    ----------
    tag : str
        The word leading the line, printed in `style`.
    style : str
        A rich style (``"red"``, ``"yellow"``).
    text : str
        The message, printed verbatim (never read as markup) on one line, which
        the terminal wraps.
    stderr : bool
        Print to standard error (beside a JSON document on standard output).
    to : rich.console.Console, optional
        Print there instead (e.g. a console recording the text).
    """
    target = to or (error_console if stderr else console)
    target.print(f"[{style}]{tag}[/{style}] {escape(text)}", highlight=False, soft_wrap=True)


def json_ready(value):
    """A JSON-friendly copy of `value` (numpy scalars and arrays become Python)."""
    import numpy as np  # here: printing a stored re-run must not load numpy

    if isinstance(value, Mapping):
        return {str(key): json_ready(item) for key, item in value.items()}
    if isinstance(value, (list, tuple, np.ndarray)):
        return [json_ready(item) for item in value]
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _cell(value, digits: int) -> str:
    if isinstance(value, Real) and not isinstance(value, Integral):  # numpy's floats too
        return f"{value:.{digits}g}"
    return str(value)


def _heading(column: str, unit: str | None) -> str:
    """A table heading: `column` over its unit (``"N_u1\\n[N]"``).

    The unit goes on a line of its own, so that it does not widen the column. A
    column without a unit, dimensionless (``"1"``) or whose name ends with its
    unit (``psi_deg``) is left as it is.
    """
    if unit in (None, "", "1") or column.endswith(f"_{unit}"):
        return column
    return f"{column}\n[{unit}]"


def emit(
    rows: Sequence[Mapping],
    *,
    title: str,
    as_json: bool,
    extra: Mapping | None = None,
    digits: int = 5,
    notes: Sequence[str] = (),
    units: Mapping[str, str] | None = None,
) -> None:
    """Print `rows` (one mapping per table row) as a rich table or as JSON.

    Parameters
    ----------
    rows : sequence of mapping
        Table rows; the keys of the first row are the columns.
    title : str
        Table title (also stored under ``"title"`` in the JSON).
    as_json : bool
        Print ``{"title", "units", **extra, "rows", "notes"}`` as JSON instead of a
        table.
    extra : mapping, optional
        Further top-level JSON members (inputs, scalars).
    digits : int
        Significant digits of floats in the table.
    notes : sequence of str
        Remarks printed under the table (warnings, non-reproduced values).
    units : mapping, optional
        Column -> unit, for columns whose name does not say it: shown in the
        table headings (:func:`_heading`) and stored under ``"units"`` in the JSON.
    """
    if as_json:
        document = {"title": title, **({"units": dict(units)} if units else {}),
                    **(extra or {}), "rows": list(rows), "notes": list(notes)}
        print(json.dumps(json_ready(document), indent=2))
        return
    table = Table(title=escape(title))
    columns = list(rows[0]) if rows else []
    for column in columns:
        table.add_column(escape(_heading(column, (units or {}).get(column))), justify="right")
    for row in rows:
        table.add_row(*(escape(_cell(row[column], digits)) for column in columns))
    console.print(table)
    for note in notes:
        say("note:", "yellow", note)
