"""How the report writes values, and the jinja2 environment of its pages.

Numbers are shown to a few significant digits with thin-space thousands; a
missing value (NaN) as :data:`MISSING`. Every page is a jinja2 template of
``pipeline/report/templates`` with autoescape on.
"""

from __future__ import annotations

import math
import re
from datetime import UTC, datetime
from functools import cache

import jinja2

#: Shown where a value is missing (NaN).
MISSING = "–"


def number(value: float, digits: int = 4) -> str:
    """`value` to `digits` significant digits, thin-space thousands; :data:`MISSING` for NaN."""
    value = float(value)
    if not math.isfinite(value):
        return MISSING
    if value == 0:
        return "0"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
    return f"{value:,.{decimals}f}".replace(",", "\u2009")


def plain_number(value: float) -> str:
    """`value` in the shortest form (``6``, ``20``, ``2.54``); :data:`MISSING` for NaN."""
    value = float(value)
    return f"{value:.6g}" if math.isfinite(value) else MISSING


def percent(value: float, decimals: int = 2) -> str:
    """A ratio as a percentage with `decimals` decimals (``0.0586`` -> ``"5.86 %"``)."""
    value = float(value)
    return f"{100 * value:.{decimals}f} %" if math.isfinite(value) else MISSING


def interval(low: float, high: float, format_value=number) -> str:
    """``low … high`` (or :data:`MISSING`)."""
    if not (math.isfinite(float(low)) and math.isfinite(float(high))):
        return MISSING
    return f"{format_value(low)} … {format_value(high)}"


def kilonewtons(value: float) -> str:
    """A force [N] in kN, 5 significant digits."""
    return number(float(value) / 1e3, 5)


def kilonewton_interval(low: float, high: float) -> str:
    """An interval of forces [N] in kN, 5 significant digits."""
    return interval(float(low) / 1e3, float(high) / 1e3, lambda value: number(value, 5))


def timestamp(created: datetime) -> str:
    """ISO 8601 UTC stamp of `created` (a naive time is taken as UTC)."""
    if created.tzinfo is None:
        created = created.replace(tzinfo=UTC)
    return created.astimezone(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")


def natural_key(text: str) -> list[int | str]:
    """Sort key putting ``E8-20`` before ``E10-20``: digit runs compare as numbers."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def first_rows(summary, dim: str, key: str) -> list:
    """The first row of every group of a summary table, in the order the groups appear.

    The fit of a drum or a sprocket is repeated on each of its runs' rows, so
    its first row stands for the group.

    Parameters
    ----------
    summary : xarray.Dataset
        A campaign summary.
    dim : str
        The table's dimension, e.g. ``"segment_point"`` or ``"sprocket_point"``.
    key : str
        The text variable naming each row's group, e.g. ``"segment_drum"``.

    Returns
    -------
    list of xarray.Dataset
        One row per group.
    """
    keys = list(summary[key].values.astype(str))
    return [summary.isel({dim: keys.index(group)}) for group in dict.fromkeys(keys)]


def verdict_class(passed: bool | None) -> str:
    """The CSS class of a verdict: ``pass``, ``fail``, or ``info`` (None: no verdict)."""
    return {True: "pass", False: "fail", None: "info"}[passed]


@cache
def environment() -> jinja2.Environment:
    """The jinja2 environment of the report's pages: package templates, autoescape on
    (one per process: its templates are compiled once)."""
    return jinja2.Environment(
        loader=jinja2.PackageLoader("pipeline.report", "templates"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
    )
