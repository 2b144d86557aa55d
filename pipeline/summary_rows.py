"""A table of the campaign summary from its rows: one row per run, texts, numbers, checks.

The per-kind tables of ``summary.nc`` (``wear_run``, ``sprocket_point``,
``segment_point``) are built the same way from a row per run (a mapping of
variable name -> value, SI): :func:`table_dataset` turns the rows into the
table's variables with their units, long names and, for interval limits, the
confidence level (:func:`pipeline.results.tensile.variable_attrs`).
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from typing import Any

import numpy as np
import xarray as xr

from pipeline.results.tensile import variable_attrs

#: Flag values and meanings of a check that may not have been evaluated.
EVALUATED_FLAGS = {-1: "not_evaluated", 0: "no", 1: "yes"}
#: Flag values and meanings of a check that is always evaluated.
YES_NO_FLAGS = {0: "no", 1: "yes"}


def table_dataset(dim: str, rows: Mapping[str, Mapping[str, Any]], texts: Mapping[str, str],
                  numbers: Mapping[str, tuple[str, str]], checks: Collection[str],
                  confidence: float, flags: Mapping[int, str] = EVALUATED_FLAGS
                  ) -> xr.Dataset:
    """One table of the summary, on dimension `dim`, from a row per label.

    Parameters
    ----------
    dim : str
        The table's dimension (``"segment_point"``).
    rows : mapping
        Label (run id) -> its row: variable name -> value (SI), in table order.
    texts : mapping
        Text variables -> long name; every row has them.
    numbers : mapping
        Numeric variables -> (UDUNITS units, long name), in the order of the
        table; a row without one gets NaN. The names in `checks` among them are
        verdicts, which every row must have.
    checks : collection of str
        The names of `numbers` that are verdicts: stored as int8 with `flags`.
    confidence : float
        Level of the intervals [1], recorded on every interval limit.
    flags : mapping of int to str, optional
        The verdicts' values and meanings (default :data:`EVALUATED_FLAGS`).

    Returns
    -------
    xarray.Dataset
        The texts, then the numbers (float) and verdicts (int8), labelled by
        the rows' keys.
    """
    ids = list(rows)
    data = {name: (dim, [str(rows[i][name]) for i in ids], {"long_name": text})
            for name, text in texts.items()}
    for name, (units, text) in numbers.items():
        if name in checks:
            data[name] = (dim, np.array([rows[i][name] for i in ids], dtype="int8"), {
                "long_name": text, "flag_values": np.array(list(flags), dtype="int8"),
                "flag_meanings": " ".join(flags.values())})
        else:
            values = np.array([rows[i].get(name, math.nan) for i in ids], dtype=float)
            data[name] = (dim, values, variable_attrs(units, text, name, confidence))
    return xr.Dataset(data, coords={dim: ids})
