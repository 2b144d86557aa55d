"""The tables of the theory modules: one row per case, for ``chainbench theory``."""

from __future__ import annotations

from collections.abc import Mapping, Sequence


def rows(columns: Mapping[str, Sequence]) -> list[dict]:
    """The rows of a table given by its `columns` (name -> values, all of one length).

    Examples
    --------
    >>> rows({"z": [6, 8], "N_u2": [3257.0, 2723.0]})
    [{'z': 6, 'N_u2': 3257.0}, {'z': 8, 'N_u2': 2723.0}]
    """
    return [dict(zip(columns, row, strict=True)) for row in zip(*columns.values(), strict=True)]
