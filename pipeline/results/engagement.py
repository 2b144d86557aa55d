"""The result of one engagement run, and its dataset: the run file ``<run id>.nc``.

Layout (``docs/outputs.md``): the conditioned signal ``time(sample)``,
``force(sample)`` [N] (full rate up to :data:`MAX_STORED_SAMPLES`, else
decimated by an integer stride recorded in the ``signal_decimation``
attribute); per detected engagement event ``event_time``, ``impact2_time``,
``tau`` [s], ``baseline``, ``N_u1``, ``N_u2`` (strike amplitudes A), their
standard errors (``N_u1_event_stderr``, ``N_u2_event_stderr``: ``N_u1_stderr``
is the run's), ``peak1``, ``peak2`` (first-peak heights) [N] and ``status``;
run-level statistics (``N_u1_median``, ``N_u1_iqr``, ...), the branch's
fitted natural frequency and damping and the clipping levels as scalars; the
settings of the extraction (:func:`pipeline.fit.impact.extraction_settings`) as attributes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.condition.engagement import EngagementEvents
from pipeline.fit.impact import ImpactResult, extraction_settings
from pipeline.fit.windows import Ringing
from pipeline.results.notes import joined, lines
from pipeline.statistics import MedianStatistics

#: Largest number of signal samples stored in a run file; longer logs are decimated.
MAX_STORED_SAMPLES = 200_000

#: units and long names of the per-event columns of :class:`ImpactResult` (stored under
#: the names of :data:`EVENT_NAMES` where a run statistic has theirs)
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

#: Per-event columns stored under another name: ``N_u1_stderr`` is the run statistic's.
EVENT_NAMES = {"N_u1_stderr": "N_u1_event_stderr", "N_u2_stderr": "N_u2_event_stderr"}

#: The statistics of each quantity (:class:`MedianStatistics`), stored as ``<quantity>_<name>``.
STATISTICS = ("median", "iqr", "mad", "stderr", "count", "stderr_events", "stderr_ringing")

#: Global attributes written from the result's fields (the others are its :attr:`attrs`).
DERIVED_ATTRS = ("ingest_warnings", "signal_decimation", "event_source", "comparison",
                 "messages")

_STATISTIC_UNITS = {"count": "1", "tau": "s"}


@dataclass(frozen=True, eq=False)
class EngagementResult:
    """What one engagement run gave, as its run file holds it (SI units).

    Attributes
    ----------
    attrs : dict
        Global attributes: provenance (:func:`pipeline.store.netcdf.provenance_attrs`),
        the run's identity (``campaign``, ``run_id``, ``kind``, ``chain``,
        ``wheel``, ``layout``) and the extraction's settings
        (:func:`pipeline.fit.impact.extraction_settings`).
    time : numpy.ndarray
        Times of the stored signal [s].
    force : numpy.ndarray
        Branch tension of the stored signal [N].
    signal_decimation : int
        Stride of the stored signal over the log [1] (1: full rate).
    impact : ImpactResult
        Per-event impact tensions, run statistics, ringing, exclusions and
        clipping levels, from the full-rate log.
    seating_period : float
        Seating period measured in the log [s].
    omega_measured : float
        Wheel speed measured in the log [1/s].
    event_source : str
        Where the seatings were found: ``"angle"`` or ``"force"``.
    ingest_warnings : tuple of str
        What the reader decided or repaired.
    """

    attrs: dict[str, Any]
    time: np.ndarray
    force: np.ndarray
    signal_decimation: int
    impact: ImpactResult
    seating_period: float
    omega_measured: float
    event_source: str
    ingest_warnings: tuple[str, ...] = ()

    @classmethod
    def of(cls, events: EngagementEvents, impact: ImpactResult,
           signal: tuple[np.ndarray, np.ndarray, int], attrs: dict[str, Any],
           ingest_warnings: list[str]) -> EngagementResult:
        """The result of the stages' outputs, with the extraction's settings in its attributes.

        Parameters
        ----------
        events : EngagementEvents
            The detected seatings.
        impact : ImpactResult
            The impact extraction.
        signal : (numpy.ndarray, numpy.ndarray, int)
            Time [s], force [N] and stride [1] of the stored signal: every
            stride-th sample of the log, at most :data:`MAX_STORED_SAMPLES`.
        attrs : dict
            Provenance and identity (see :attr:`attrs`).
        ingest_warnings : list of str
            The reader's warnings.
        """
        time, force, stride = signal
        return cls(attrs={**attrs, **extraction_settings()}, time=time, force=force,
                   signal_decimation=int(stride), impact=impact,
                   seating_period=float(events.seating_period),
                   omega_measured=float(events.omega), event_source=events.source,
                   ingest_warnings=tuple(ingest_warnings))

    def global_attrs(self) -> dict[str, Any]:
        """The run file's global attributes: :attr:`attrs` and those of the fields."""
        return {**self.attrs, "ingest_warnings": joined(self.ingest_warnings),
                "signal_decimation": self.signal_decimation, "event_source": self.event_source,
                "comparison": self.impact.comparison, "messages": joined(self.impact.messages)}

    def to_dataset(self) -> xr.Dataset:
        """The run file (layout in the module docstring and ``docs/outputs.md``)."""
        signal = xr.Dataset({
            "time": ("sample", self.time, {"units": "s", "long_name": "time"}),
            "force": ("sample", self.force, {"units": "N", "long_name": "branch tension"}),
        })
        dataset = xr.merge([signal, _events(self.impact)])
        for name, variable in _statistics(self.impact).items():
            dataset[name] = variable
        ringing, (low, high) = self.impact.ringing, self.impact.clip_levels
        dataset["ringing_correlation"] = ((), float(ringing.correlation), {
            "units": "1", "long_name": "correlation of the fitted omega_n and zeta"})
        dataset["ringing_events"] = ((), float(ringing.n_events), {
            "units": "1", "long_name": "events omega_n and zeta were fitted on (0: given)"})
        for name, level in (("clip_level_low", low), ("clip_level_high", high)):
            dataset[name] = ((), math.nan if level is None else float(level), {
                "units": "N", "long_name": f"{name.split('_')[-1]} clipping level of the "
                                           "force channel used (NaN: none)"})
        dataset["seating_period"] = ((), self.seating_period,
                                     {"units": "s", "long_name": "measured seating period"})
        dataset["omega_measured"] = ((), self.omega_measured,
                                     {"units": "s-1", "long_name": "wheel speed measured in "
                                                                   "the log"})
        dataset.attrs.update(self.global_attrs())
        return dataset

    @classmethod
    def from_dataset(cls, dataset: xr.Dataset) -> EngagementResult:
        """The result a run file holds (the inverse of :meth:`to_dataset`).

        Parameters
        ----------
        dataset : xarray.Dataset
            An engagement run file, loaded (:func:`pipeline.store.netcdf.read_dataset`).
        """
        attrs = {key: value for key, value in dataset.attrs.items() if key not in DERIVED_ATTRS}
        return cls(attrs=attrs, time=dataset["time"].values, force=dataset["force"].values,
                   signal_decimation=int(dataset.attrs["signal_decimation"]),
                   impact=_impact_of(dataset),
                   seating_period=float(dataset["seating_period"]),
                   omega_measured=float(dataset["omega_measured"]),
                   event_source=str(dataset.attrs["event_source"]),
                   ingest_warnings=lines(dataset.attrs["ingest_warnings"]))


def _events(result: ImpactResult) -> xr.Dataset:
    events = result.events.reset_index(drop=True)
    variables = {
        EVENT_NAMES.get(name, name): ("event", events[name].to_numpy(dtype=float),
                                      {"units": units, "long_name": text})
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


def _impact_of(dataset: xr.Dataset) -> ImpactResult:
    """The :class:`ImpactResult` of an engagement run file."""
    names = list(dataset.data_vars)
    quantities = [name.removesuffix("_median") for name in names if name.endswith("_median")]
    statistics = {
        quantity: MedianStatistics(**{
            statistic: (int if statistic == "count" else float)(
                dataset[f"{quantity}_{statistic}"]) for statistic in STATISTICS})
        for quantity in quantities}
    excluded = {name.removeprefix("excluded_"): int(dataset[name]) for name in names
                if name.startswith("excluded_")}
    ringing = Ringing(omega_n=float(dataset["omega_n"]), zeta=float(dataset["zeta"]),
                      omega_n_stderr=float(dataset["omega_n_stderr"]),
                      zeta_stderr=float(dataset["zeta_stderr"]),
                      correlation=float(dataset["ringing_correlation"]),
                      n_events=int(dataset["ringing_events"]))
    events = pd.DataFrame({name: dataset[EVENT_NAMES.get(name, name)].values
                           for name in EVENT_VARIABLES})
    events["status"] = dataset["status"].values.astype(str)
    clip = tuple(None if math.isnan(level) else level for level in
                 (float(dataset["clip_level_low"]), float(dataset["clip_level_high"])))
    return ImpactResult(events, ringing, statistics, excluded, clip,
                        comparison=str(dataset.attrs["comparison"]),
                        messages=lines(dataset.attrs["messages"]))
