"""Printing tables for people (rich) or for programs (``--json``)."""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence

import numpy as np
from rich.console import Console
from rich.table import Table

console = Console()


def _plain(value):
    """A JSON-friendly copy of `value` (numpy scalars and arrays become Python)."""
    if isinstance(value, Mapping):
        return {str(key): _plain(item) for key, item in value.items()}
    if isinstance(value, (list, tuple, np.ndarray)):
        return [_plain(item) for item in value]
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _cell(value, digits: int) -> str:
    if isinstance(value, (float, np.floating)):
        return f"{value:.{digits}g}"
    return str(value)


def emit(
    rows: Sequence[Mapping],
    *,
    title: str,
    as_json: bool,
    extra: Mapping | None = None,
    digits: int = 5,
    notes: Sequence[str] = (),
) -> None:
    """Print `rows` (one mapping per table row) as a rich table or as JSON.

    Parameters
    ----------
    rows : sequence of mapping
        Table rows; the keys of the first row are the columns.
    title : str
        Table title (also stored under ``"title"`` in the JSON).
    as_json : bool
        Print ``{"title", "rows", **extra, "notes"}`` as JSON instead of a table.
    extra : mapping, optional
        Further top-level JSON members (inputs, scalars).
    digits : int
        Significant digits of floats in the table.
    notes : sequence of str
        Remarks printed under the table (warnings, non-reproduced values).
    """
    if as_json:
        document = {"title": title, **(extra or {}), "rows": list(rows), "notes": list(notes)}
        print(json.dumps(_plain(document), indent=2))
        return
    table = Table(title=title)
    columns = list(rows[0]) if rows else []
    for column in columns:
        table.add_column(column, justify="right")
    for row in rows:
        table.add_row(*(_cell(row[column], digits) for column in columns))
    console.print(table)
    for note in notes:
        console.print(f"[yellow]note:[/yellow] {note}")
