"""The dataset of one engagement run, built from the stages' outputs.

Layout (``docs/outputs.md``): the conditioned signal ``time(sample)``,
``force(sample)`` [N] (full rate up to :data:`MAX_STORED_SAMPLES`, else
decimated by an integer stride recorded in the ``signal_decimation``
attribute); per detected engagement event ``event_time``, ``impact2_time``,
``tau`` [s], ``baseline``, ``N_u1``, ``N_u2`` (strike amplitudes A), their
standard errors, ``peak1``, ``peak2`` (first-peak heights) [N] and ``status``;
run-level statistics (``N_u1_median``, ``N_u1_iqr``, ...) and the branch's
fitted natural frequency and damping as scalars.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import pandas as pd
import xarray as xr

from pipeline.condition.engagement import EngagementEvents
from pipeline.fit.impact import ImpactResult

#: Largest number of signal samples stored in a run file; longer logs are decimated.
MAX_STORED_SAMPLES = 200_000

#: units and long names of the per-event columns of :class:`ImpactResult`
EVENT_VARIABLES = {
    "event_time": ("s", "onset of impact 1 (idle flank)"),
    "impact2_time": ("s", "onset of impact 2 (working flank)"),
    "tau": ("s", "time between impact 1 and impact 2"),
    "baseline": ("N", "slow branch tension at impact 1"),
    "N_u1": ("N", "impact tension 1: strike amplitude A"),
    "N_u1_stderr": ("N", "standard error of N_u1"),
    "N_u2": ("N", "impact tension 2: strike amplitude A"),
    "N_u2_stderr": ("N", "standard error of N_u2"),
    "peak1": ("N", "first-peak height of strike 1's own response"),
    "peak2": ("N", "first-peak height of strike 2's own response"),
    "residual_rms": ("N", "root-mean-square residual of the event's fit"),
}

_STATISTIC_UNITS = {"count": "1", "tau": "s"}


def _signal(table: pd.DataFrame) -> tuple[xr.Dataset, int]:
    stride = max(1, math.ceil(len(table) / MAX_STORED_SAMPLES))
    kept = table.iloc[::stride]
    signal = xr.Dataset({
        "time": ("sample", kept["time"].to_numpy(), {"units": "s", "long_name": "time"}),
        "force": ("sample", kept["force"].to_numpy(),
                  {"units": "N", "long_name": "branch tension"}),
    })
    return signal, stride


def _events(result: ImpactResult) -> xr.Dataset:
    events = result.events.reset_index(drop=True)
    variables = {
        name: ("event", events[name].to_numpy(dtype=float), {"units": units, "long_name": text})
        for name, (units, text) in EVENT_VARIABLES.items()
    }
    variables["status"] = ("event", events["status"].astype(str).to_numpy(),
                           {"long_name": "ok, or why the event was excluded"})
    return xr.Dataset(variables)


def _statistics(result: ImpactResult) -> dict[str, tuple]:
    scalars = {}
    for name, value in result.summary().items():
        if isinstance(value, str):
            continue
        quantity, _, statistic = name.rpartition("_")
        units = _STATISTIC_UNITS.get(statistic) or _STATISTIC_UNITS.get(quantity, "N")
        if name.startswith(("excluded_", "events_")):
            units = "1"
        elif name.startswith("omega_n"):
            units = "rad s-1"
        elif name.startswith("zeta"):
            units = "1"
        scalars[name] = ((), float(value), {"units": units})
    return scalars


def engagement_dataset(
    table: pd.DataFrame,
    events: EngagementEvents,
    result: ImpactResult,
    attrs: Mapping[str, str],
) -> xr.Dataset:
    """Assemble the dataset of one engagement run.

    Parameters
    ----------
    table : pandas.DataFrame
        The canonical table (``time``, ``force``).
    events : EngagementEvents
        The detected seatings.
    result : ImpactResult
        The impact extraction.
    attrs : mapping
        Global attributes (provenance, run identity).

    Returns
    -------
    xarray.Dataset
        Signal on ``sample``, events on ``event``, run statistics as scalars.
    """
    signal, stride = _signal(table)
    dataset = xr.merge([signal, _events(result)])
    for name, variable in _statistics(result).items():
        dataset[name] = variable
    dataset["seating_period"] = ((), events.seating_period,
                                 {"units": "s", "long_name": "measured seating period"})
    dataset["omega_measured"] = ((), events.omega,
                                 {"units": "s-1", "long_name": "wheel speed measured in the log"})
    dataset.attrs.update(attrs)
    dataset.attrs.update(
        signal_decimation=stride, event_source=events.source, comparison=result.comparison,
        messages="; ".join(result.messages),
    )
    return dataset


def measured_point(dataset: Mapping) -> dict[str, float]:
    """The run's measured impact tensions, as stored by :func:`engagement_dataset`.

    `dataset` is the run's dataset or any mapping of its scalar variables
    (:func:`pipeline.store.netcdf.read_scalars`).

    Keys: ``N_u1_meas``, ``N_u1_iqr``, ``N_u1_stderr``, ``N_u1_count`` (and the
    same for ``N_u2``) and ``omega_measured``: one row of the campaign's
    operating points.
    """
    row = {}
    for impact in ("N_u1", "N_u2"):
        row[f"{impact}_meas"] = float(dataset[f"{impact}_median"])
        for statistic in ("iqr", "stderr", "count"):
            row[f"{impact}_{statistic}"] = float(dataset[f"{impact}_{statistic}"])
    row["omega_measured"] = float(dataset["omega_measured"])
    return row
