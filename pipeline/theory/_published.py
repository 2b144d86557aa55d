"""The papers' published numbers as data, and the one rule for comparing a model with them.

Each paper's numbers are in ``pipeline/data/published/paper_<paper>.csv``, one
number a row, with the columns of :data:`CSV_COLUMNS`:

``quantity``
    A stable id, e.g. ``E0_theory_13x50``. Its leading part names the model
    call that gives the number (see :func:`compare`).
``inputs``
    The model's inputs, ``name=value unit`` separated by ``"; "``; a value may
    be a comma-separated list; no unit means dimensionless
    (see :func:`parse_inputs`).
``published``
    The number as printed, in ``unit``.
``unit``
    The paper's unit of the number (``-`` for a pure number).
``source``
    Where the paper prints it (table, figure, equation).
``tolerance``
    The relative tolerance [-] within which the model reproduces the number:
    the rounding of its printed digits unless the note says otherwise.
``reproduced``
    ``yes`` or ``no``: whether the corrected model reproduces it, as declared
    (and checked by the tests). A ``no`` is a finding: the note says why.
``note``
    Why not, or how close the model comes.

The one tolerance rule (:func:`within_tolerance`):
|model - published| <= tolerance * |published|.
"""

from __future__ import annotations

import io
from collections.abc import Callable, Mapping
from importlib.resources import files

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pipeline.units import to_si

#: The columns of a paper's CSV, in order.
CSV_COLUMNS = (
    "quantity", "inputs", "published", "unit", "source", "tolerance", "reproduced", "note",
)  # fmt: skip

#: The columns of :func:`compare`'s table, in order.
COLUMNS = (
    "quantity", "inputs", "published", "model", "unit", "rel_diff", "tolerance",
    "within_tolerance", "reproduced", "source", "note",
)  # fmt: skip

#: A model call: the row's inputs (SI, :func:`parse_inputs`) -> the value in the row's unit.
Model = Callable[[dict[str, float | np.ndarray]], float]


def within_tolerance(model: ArrayLike, published: ArrayLike, tolerance: ArrayLike):
    """Whether the model reproduces the published number: |model - published| <= tol |published|.

    Parameters
    ----------
    model : float or array_like
        The model's value(s), in the unit of `published`.
    published : float or array_like
        The published value(s).
    tolerance : float or array_like
        Relative tolerance [-], >= 0.

    Returns
    -------
    bool or numpy.ndarray of bool
        Element-wise verdict (a NaN model is never within tolerance).

    Examples
    --------
    >>> within_tolerance(2379.0, 2300.0, 0.04), within_tolerance(2379.0, 2300.0, 0.005)
    (True, False)
    """
    model, published = np.asarray(model, dtype=float), np.asarray(published, dtype=float)
    verdict = np.abs(model - published) <= np.asarray(tolerance, dtype=float) * np.abs(published)
    return bool(verdict) if verdict.ndim == 0 else verdict


def parse_inputs(text: str) -> dict[str, float | np.ndarray]:
    """The inputs of a CSV row as SI values.

    Parameters
    ----------
    text : str
        ``name=value unit`` entries separated by ``"; "``, e.g.
        ``"z=6,8,10; psi=20 deg; E0=2.26e7 N"``; a comma-separated value gives
        an array; empty text gives no inputs.

    Returns
    -------
    dict
        name -> value in SI units (float, or numpy.ndarray for a list).

    Examples
    --------
    >>> parse_inputs("t=64 mm; z=6,8; k=2")
    {'t': 0.064, 'z': array([6., 8.]), 'k': 2.0}
    """
    inputs: dict[str, float | np.ndarray] = {}
    for entry in filter(None, (part.strip() for part in text.split(";"))):
        name, equals, value = entry.partition("=")
        if not equals:
            raise ValueError(f"input {entry!r} is not name=value [unit]")
        number, _, unit = value.strip().partition(" ")
        numbers = [float(item) for item in number.split(",")]
        inputs[name.strip()] = to_si(numbers if len(numbers) > 1 else numbers[0], unit.strip())
    return inputs


def read_published(paper: str) -> pd.DataFrame:
    """The published numbers of one paper, as its CSV holds them.

    Parameters
    ----------
    paper : str
        The paper's number, ``"000"`` to ``"004"``.

    Returns
    -------
    pandas.DataFrame
        The columns of :data:`CSV_COLUMNS`; ``published`` and ``tolerance`` as
        float, ``reproduced`` as bool.

    Raises
    ------
    ValueError
        If the columns differ from :data:`CSV_COLUMNS`, a quantity repeats or
        ``reproduced`` is not ``yes`` or ``no``.
    """
    name = f"paper_{paper}.csv"
    text = files("pipeline.data").joinpath("published", name).read_text(encoding="utf-8")
    table = pd.read_csv(io.StringIO(text), dtype=str, keep_default_na=False)
    if tuple(table.columns) != CSV_COLUMNS:
        raise ValueError(f"{name}: columns must be {', '.join(CSV_COLUMNS)}")
    if table["quantity"].duplicated().any():
        raise ValueError(f"{name}: a quantity repeats")
    if not table["reproduced"].isin(["yes", "no"]).all():
        raise ValueError(f"{name}: reproduced must be yes or no")
    return table.astype({"published": float, "tolerance": float}).assign(
        reproduced=table["reproduced"] == "yes"
    )


def compare(paper: str, models: Mapping[str, Model]) -> pd.DataFrame:
    """Each published number of `paper` with the model's value beside it.

    Parameters
    ----------
    paper : str
        The paper's number, ``"000"`` to ``"004"`` (:func:`read_published`).
    models : mapping
        Model call by quantity: a row's call is the one whose key is its
        ``quantity`` or, failing that, the longest key that with ``"_"`` begins it
        (``"E0_theory"`` serves ``E0_theory_13x50``). Each call takes the row's
        parsed inputs and returns the value in the row's unit.

    Returns
    -------
    pandas.DataFrame
        One row per CSV row, the columns of :data:`COLUMNS`: ``model`` [the
        row's unit], ``rel_diff`` (model / published - 1), ``within_tolerance``
        (:func:`within_tolerance`) and ``reproduced`` (as declared).

    Raises
    ------
    KeyError
        If a row has no model call.
    """
    table = read_published(paper)
    table["model"] = [
        float(_model_of(quantity, models)(parse_inputs(inputs)))
        for quantity, inputs in zip(table["quantity"], table["inputs"], strict=True)
    ]
    table["rel_diff"] = table["model"] / table["published"] - 1
    table["within_tolerance"] = within_tolerance(
        table["model"], table["published"], table["tolerance"]
    )
    return table[list(COLUMNS)]


def _model_of(quantity: str, models: Mapping[str, Model]) -> Model:
    """The model call of `quantity` (see :func:`compare`)."""
    if quantity in models:
        return models[quantity]
    keys = [key for key in models if quantity.startswith(f"{key}_")]
    if not keys:
        raise KeyError(f"no model gives the published quantity {quantity!r}")
    return models[max(keys, key=len)]
