"""The result of one segment-load run, and its dataset: the run file ``<run id>.nc``.

A segment-load run is one operating point of a segmented chain-drum tooth
(Paper 003). Layout (``docs/outputs.md``): per seating (dimension ``seating``)
its times [s], the plateau medians of the chain force ``F``, the segment forces
``F_K1``, ``F_K2`` and the side force ``F_P`` [N] with the zeros they were read
from, the ratios ``contact_force_ratio`` (F_K / F, eq. (3)),
``contact_force_ratio_1``, ``contact_force_ratio_2`` (each segment's) and
``side_force_ratio`` (F_P / F, eq. (4)) [1] with standard errors, the
segments' ``imbalance`` [1], ``imbalanced`` (1 yes, 0 no) and ``status``
(``ok`` or the reason it is excluded). As scalars: per quantity over the valid
seatings its ``_median``, ``_iqr``, ``_stderr`` and ``_count``; the seatings
excluded per reason; the detection's levels; and the model of eqs. (1)-(4) at
the run sheet's geometry (``model_*``), with that geometry. On dimension
``sample``, the log around its first :data:`TRACE_SEATINGS` seatings as read
(``trace_time`` [s], ``trace_F``, ``trace_F_K1``, ``trace_F_K2`` and
``trace_F_P`` [N], the segment forces with their zeros), for the run's page.

netCDF names carry no ``/``: the ratios are named as in :data:`NAMES`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.condition.segment_load import EXCLUSIONS, SegmentLoadEvents
from pipeline.fit.segment_load import ContactRatios
from pipeline.results.notes import joined, lines

#: The conditioning's names (:mod:`pipeline.condition.segment_load`) -> the run file's.
NAMES = {"F_K/F": "contact_force_ratio", "F_K1/F": "contact_force_ratio_1",
         "F_K2/F": "contact_force_ratio_2", "F_P/F": "side_force_ratio",
         "F_K/F_stderr": "contact_force_ratio_stderr",
         "F_P/F_stderr": "side_force_ratio_stderr"}

#: Per-seating numbers: units and long names (run-file names).
SEATING_VARIABLES = {
    "start": ("s", "first sample of the seating at or above the lower trigger"),
    "stop": ("s", "last sample of the seating at or above the lower trigger"),
    "plateau_start": ("s", "first sample of the plateau"),
    "plateau_stop": ("s", "last sample of the plateau"),
    "samples": ("1", "samples of the plateau"),
    "F": ("N", "chain force F, plateau median"),
    "F_K1": ("N", "force on segment 1 from its zero, plateau median"),
    "F_K2": ("N", "force on segment 2 from its zero, plateau median"),
    "F_P": ("N", "side force F_P from its zero, plateau median"),
    "zero_K1": ("N", "zero of segment 1 at the plateau"),
    "zero_K2": ("N", "zero of segment 2 at the plateau"),
    "zero_P": ("N", "zero of the side force at the plateau"),
    "contact_force_ratio": ("1", "F_K / F, the mean of the two segments (Paper 003, eq. (3))"),
    "contact_force_ratio_1": ("1", "F_K1 / F of segment 1"),
    "contact_force_ratio_2": ("1", "F_K2 / F of segment 2"),
    "contact_force_ratio_stderr": ("1", "standard error of F_K / F"),
    "side_force_ratio": ("1", "F_P / F (Paper 003, eq. (4))"),
    "side_force_ratio_stderr": ("1", "standard error of F_P / F"),
    "imbalance": ("1", "(F_K1 - F_K2) / F_K of the seating"),
    "imbalanced": ("1", "1: the segments disagree beyond the tolerance; 0: not"),
}

#: Statistics over the valid seatings stored per quantity: suffix, long name.
STATISTICS = {"median": "median", "iqr": "interquartile range", "stderr":
              "standard error of the median", "count": "valid seatings"}

#: The model of eqs. (1)-(4) at the run sheet's geometry, and that geometry.
MODEL_VARIABLES = {
    "torus_radius": ("m", "outer torus radius r of the horizontal link"),
    "bar_diameter": ("m", "link bar thickness d"),
    "groove_width": ("m", "groove width c between the segments"),
    "contact_distance": ("m", "distance s between the contact points (run sheet)"),
    "flank_inclination": ("rad", "flank inclination beta (run sheet)"),
    "link_inclination": ("rad", "inclination eps_n of the link to the pocket floor"),
    "model_contact_radius": ("m", "contact radius k, Paper 003 eq. (1)"),
    "model_opening_angle": ("rad", "segment opening angle psi, eq. (2)"),
    "model_contact_force_ratio": ("1", "F_K / F of the model, eq. (3)"),
    "model_side_force_ratio": ("1", "F_P / F of the model, eq. (4)"),
    "model_friction_increase": ("1", "friction increase 2 F_K / F - 1 of the model"),
}

#: Seatings of the log kept in the run file for its page (:func:`log_excerpt`).
TRACE_SEATINGS = 4

#: The reader's roles -> the channels of the conditioning and of the excerpt.
TRACE_ROLES = {"time": "time", "force": "F", "segment_force_1": "F_K1",
               "segment_force_2": "F_K2", "side_force": "F_P"}

#: The log excerpt on dimension ``sample``: units and long names (run-file names).
TRACE_VARIABLES = {
    "trace_time": ("s", "time of the logged sample"),
    "trace_F": ("N", "chain force F as logged"),
    "trace_F_K1": ("N", "force on segment 1 as logged (with its zero)"),
    "trace_F_K2": ("N", "force on segment 2 as logged (with its zero)"),
    "trace_F_P": ("N", "side force F_P as logged (with its zero)"),
}


def log_excerpt(table: pd.DataFrame, seatings: pd.DataFrame,
                count: int = TRACE_SEATINGS) -> pd.DataFrame:
    """The stretch of a segment-load log around its first `count` seatings.

    Parameters
    ----------
    table : pandas.DataFrame
        The canonical table (:func:`pipeline.ingest.read_table`): ``time`` [s],
        ``force``, ``segment_force_1``, ``segment_force_2`` and optionally
        ``side_force`` [N].
    seatings : pandas.DataFrame
        The seatings found in it, with ``start`` and ``stop`` [s], in time order.
    count : int
        Seatings to keep [-].

    Returns
    -------
    pandas.DataFrame
        ``time``, ``F``, ``F_K1``, ``F_K2`` (and ``F_P``) from half a seating
        period before the first seating to half a period after the
        `count`-th; the whole log when it has one seating (its idle time
        around it as margin).
    """
    starts, stops = seatings["start"].to_numpy(), seatings["stop"].to_numpy()
    shown = min(count, len(starts))
    margin = (float(np.median(np.diff(starts))) / 2 if len(starts) > 1
              else float(table["time"].iloc[-1] - table["time"].iloc[0]))
    time = table["time"].to_numpy()
    inside = (time >= starts[0] - margin) & (time <= stops[shown - 1] + margin)
    columns = {role: name for role, name in TRACE_ROLES.items() if role in table}
    return table.loc[inside, list(columns)].rename(columns=columns).reset_index(drop=True)


#: Global attributes written from the result's fields (the others are its :attr:`attrs`).
DERIVED_ATTRS = ("ingest_warnings", "warnings")


def _unit(quantity: str) -> str:
    """Units of a quantity's statistics: N for a force, 1 for a ratio."""
    return "N" if quantity in ("F", "F_K1", "F_K2", "F_P") else "1"


@dataclass(frozen=True, eq=False)
class SegmentLoadResult:
    """What one segment-load run gave, as its run file holds it (SI units).

    Attributes
    ----------
    attrs : dict
        Global attributes: provenance, the run's identity (``campaign``,
        ``run_id``, ``kind``, ``chain``, ``drum``, ``layout``), ``fitted`` (the
        drum's fitted parameter), ``imbalance_tolerance`` [1] and the detection's
        ``noise``, ``idle``, ``height`` [N].
    seatings : pandas.DataFrame
        Per seating: the columns of :data:`SEATING_VARIABLES` and ``status``.
    statistics : dict of str to float
        ``<quantity>_<statistic>`` over the valid seatings (:data:`STATISTICS`;
        quantities with run-file names), and ``excluded_<reason>``.
    model : dict of str to float
        The scalars of :data:`MODEL_VARIABLES`.
    trace : pandas.DataFrame
        The log around the first seatings (:func:`log_excerpt`).
    ingest_warnings, warnings : tuple of str
        What the reader, and the conditioning, decided or found.
    """

    attrs: dict[str, Any]
    seatings: pd.DataFrame
    statistics: dict[str, float]
    model: dict[str, float]
    trace: pd.DataFrame
    ingest_warnings: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @classmethod
    def of(cls, events: SegmentLoadEvents, declared: ContactRatios,
           geometry: dict[str, float], attrs: dict[str, Any],
           ingest_warnings: list[str], trace: pd.DataFrame) -> SegmentLoadResult:
        """The result of the stages' outputs.

        Parameters
        ----------
        events : SegmentLoadEvents
            The seatings and their statistics.
        declared : ContactRatios
            Eqs. (1)-(4) at the run sheet's geometry.
        geometry : dict of str to float
            ``r_outer``, ``d``, ``groove_width`` [m] of the chain and drum.
        attrs : dict
            Provenance, identity and settings (see :attr:`attrs`).
        ingest_warnings : list of str
            The reader's warnings.
        trace : pandas.DataFrame
            The log around the first seatings (:func:`log_excerpt`).
        """
        seatings = events.events.rename(columns=NAMES)
        seatings["imbalanced"] = seatings["imbalanced"].astype(int)
        statistics = {f"{NAMES.get(name, name)}_{key}": float(getattr(stats, key))
                      for name, stats in events.statistics.items() for key in STATISTICS}
        statistics.update({f"excluded_{reason}": float(count)
                           for reason, count in events.excluded.items()})
        model = {"torus_radius": geometry["r_outer"], "bar_diameter": geometry["d"],
                 "groove_width": geometry["groove_width"], "contact_distance": declared.s,
                 "flank_inclination": declared.beta, "link_inclination": geometry["eps_n"],
                 "model_contact_radius": declared.k, "model_opening_angle": declared.psi,
                 "model_contact_force_ratio": declared.contact_force,
                 "model_side_force_ratio": declared.side_force,
                 "model_friction_increase": declared.friction_increase}
        detection = events.detection
        attrs = {**attrs, "imbalance_tolerance": events.imbalance_tolerance,
                 "noise": detection.noise, "idle": detection.idle, "height": detection.height}
        return cls(attrs=attrs, seatings=seatings, statistics=statistics, model=model,
                   trace=trace, ingest_warnings=tuple(ingest_warnings),
                   warnings=events.messages)

    @property
    def has_side_force(self) -> bool:
        """Whether the log had the side force F_P."""
        return "side_force_ratio" in self.seatings

    def point(self) -> dict[str, float]:
        """The run as one operating point, in the names of :mod:`pipeline.fit.segment_load`.

        Returns
        -------
        dict
            ``F_K/F``, ``F_K/F_stderr`` and (with a side force) ``F_P/F``,
            ``F_P/F_stderr`` [1]: the medians over the valid seatings and their
            standard errors; ``F`` [N], the median chain force.
        """
        point = {"F": self.statistics["F_median"]}
        for name in ("F_K/F", "F_P/F"):
            stem = NAMES[name]
            if f"{stem}_median" in self.statistics:
                point[name] = self.statistics[f"{stem}_median"]
                point[f"{name}_stderr"] = self.statistics[f"{stem}_stderr"]
        return point

    def global_attrs(self) -> dict[str, Any]:
        """The run file's global attributes: :attr:`attrs` and those of the fields."""
        return {**self.attrs, "ingest_warnings": joined(self.ingest_warnings),
                "warnings": joined(self.warnings)}

    def to_dataset(self) -> xr.Dataset:
        """The run file (layout in the module docstring and ``docs/outputs.md``)."""
        data = {}
        for name in self.seatings.columns:
            if name in SEATING_VARIABLES:
                units, long_name = SEATING_VARIABLES[name]
                data[name] = ("seating", self.seatings[name].to_numpy(dtype=float),
                              {"units": units, "long_name": long_name})
        data["status"] = ("seating", self.seatings["status"].astype(str).to_numpy(),
                          {"long_name": "ok, or why the seating is excluded: "
                                        + ", ".join(EXCLUSIONS)})
        for name, value in self.statistics.items():
            data[name] = ((), value, _statistic_attrs(name))
        for name, value in self.model.items():
            units, long_name = MODEL_VARIABLES[name]
            data[name] = ((), float(value), {"units": units, "long_name": long_name})
        for name in self.trace.columns:
            units, long_name = TRACE_VARIABLES[f"trace_{name}"]
            data[f"trace_{name}"] = ("sample", self.trace[name].to_numpy(dtype=float),
                                     {"units": units, "long_name": long_name})
        dataset = xr.Dataset(data, coords={"seating": np.arange(len(self.seatings))})
        dataset.attrs.update(self.global_attrs())
        return dataset

    @classmethod
    def from_dataset(cls, dataset: xr.Dataset) -> SegmentLoadResult:
        """The result a run file holds (the inverse of :meth:`to_dataset`).

        Parameters
        ----------
        dataset : xarray.Dataset
            A segment-load run file, loaded (:func:`pipeline.store.netcdf.read_dataset`).
        """
        seatings = pd.DataFrame({name: dataset[name].values for name in SEATING_VARIABLES
                                 if name in dataset})
        seatings["status"] = dataset["status"].values.astype(str)
        statistics = {name: float(dataset[name]) for name in dataset.data_vars
                      if dataset[name].ndim == 0 and name not in MODEL_VARIABLES}
        trace = pd.DataFrame({name[len("trace_"):]: dataset[name].values
                              for name in TRACE_VARIABLES if name in dataset})
        attrs = {key: value for key, value in dataset.attrs.items() if key not in DERIVED_ATTRS}
        return cls(attrs=attrs, seatings=seatings, statistics=statistics,
                   model={name: float(dataset[name]) for name in MODEL_VARIABLES}, trace=trace,
                   ingest_warnings=lines(dataset.attrs["ingest_warnings"]),
                   warnings=lines(dataset.attrs["warnings"]))


def _statistic_attrs(name: str) -> dict[str, str]:
    """Units and long name of a scalar ``<quantity>_<statistic>`` or ``excluded_<reason>``."""
    if name.startswith("excluded_"):
        return {"units": "1", "long_name": f"seatings excluded: {name[len('excluded_'):]}"}
    stem, _, key = name.rpartition("_")
    quantity = {value: key for key, value in NAMES.items()}.get(stem, stem)
    units = "1" if key == "count" else _unit(quantity)
    return {"units": units, "long_name": f"{STATISTICS[key]} of {quantity} over the valid "
                                         "seatings"}
