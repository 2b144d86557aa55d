"""The result of one wear run, and its dataset: the run file ``<run id>.nc``.

Layout (``docs/outputs.md``). A wear log runs over the running time [s] or the
cycles [1] (the ``abscissa`` attribute); every value counted in it (``tau``,
lives, the run-in time constant) is in that unit, and rates are per second or
per cycle. Per reading (dimension ``reading``): ``tau``, the elongation per
pitch ``elongation`` [m] (Paper 004's delta_t, counted from the
``reference``), ``relative_elongation`` [1], the fitted ``elongation_fit`` and
the ``residual`` [m], and the logged ``load`` [N] and ``speed`` [m s-1] where
the log has them. The fitted curve with its pointwise band, from the start to
beyond the last life (dimension ``curve_point``). The fit's parameters with
their standard errors as scalars. Per pitch-growth limit (dimension
``limit``: ``eq3``, Paper 004's eq. (3) for the sprocket; ``lab``, the lab's
own): the limit, the life to it with its interval, the pitch growth by wear
there and the pin wear it implies (eq. (2)). The pin criterion, eqs. (1)-(5),
as scalars ``pin_*``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.fit.wear import PinWear, WearFit, WearLife
from pipeline.results.notes import joined, lines
from pipeline.results.tensile import variable_attrs
from pipeline.theory.pin_criterion import PinCheck, pin_wear_allowance

#: Units of a value counted over the running coordinate, by the log's abscissa:
#: ``tau`` (a time or a count) and ``rate`` (a length per tau).
RUNNING_UNITS = {"time": {"tau": "s", "rate": "m s-1"}, "cycles": {"tau": "1", "rate": "m"}}

#: Per-reading variables: units (or a key of :data:`RUNNING_UNITS`) and long names.
READING_VARIABLES = {
    "tau": ("tau", "running time (or cycles) of the reading"),
    "elongation": ("m", "elongation per pitch delta_t, counted from the reference"),
    "relative_elongation": ("1", "elongation per pitch over the pitch, delta_t / t"),
    "elongation_fit": ("m", "fitted elongation per pitch"),
    "residual": ("m", "measured minus fitted elongation per pitch"),
    "load": ("N", "load logged"),
    "speed": ("m s-1", "chain speed logged"),
}

#: Variables of the fitted curve on ``curve_point``.
CURVE_VARIABLES = {
    "curve_tau": ("tau", "running time (or cycles) of the fitted curve"),
    "curve_elongation": ("m", "fitted elongation per pitch"),
    "curve_ci_low": ("m", "lower edge of the {level} pointwise band of the fitted curve"),
    "curve_ci_high": ("m", "upper edge of the {level} pointwise band of the fitted curve"),
}

#: Scalars of the fit (:class:`~pipeline.fit.wear.WearFit`); NaN where the model lacks one.
FIT_VARIABLES = {
    "wear_rate": ("rate", "steady wear rate w: elongation per pitch per unit of tau"),
    "wear_rate_stderr": ("rate", "standard error of the wear rate"),
    "wear_rate_ci_low": ("rate", "lower limit of the {level} interval of the wear rate"),
    "wear_rate_ci_high": ("rate", "upper limit of the {level} interval of the wear rate"),
    "offset": ("m", "fitted elongation per pitch at tau = 0, delta_t0"),
    "offset_stderr": ("m", "standard error of delta_t0"),
    "run_in": ("m", "run-in elongation per pitch A (run-in model)"),
    "run_in_stderr": ("m", "standard error of A"),
    "run_in_time": ("tau", "run-in time constant tau0 (run-in model)"),
    "run_in_time_stderr": ("tau", "standard error of tau0"),
    "dof": ("1", "residual degrees of freedom of the fit"),
    "bic_run_in": ("1", "Bayesian information criterion of the run-in model (NaN: not fitted)"),
    "bic_linear": ("1", "Bayesian information criterion of the linear model"),
    "tau_end": ("tau", "running time (or cycles) of the last reading"),
    "growth_measured": ("m", "pitch growth by wear over the log: fitted delta_t at the last "
                             "reading less delta_t0"),
}

#: Per-limit variables on dimension ``limit`` (the texts ``limit_source`` and
#: ``life_note`` beside them).
LIMIT_VARIABLES = {
    "limit_elongation": ("m", "limit of delta_t, counted as the log counts delta_t"),
    "limit_relative": ("1", "limit of delta_t over the pitch"),
    "life": ("tau", "running time (or cycles) at which the fitted curve reaches the limit"),
    "life_ci_low": ("tau", "lower limit of the {level} interval of the life"),
    "life_ci_high": ("tau", "upper limit of the {level} interval of the life"),
    "limit_growth": ("m", "pitch growth by wear at the limit (limit less delta_t0)"),
    "limit_pin_wear": ("m", "pin wear the growth at the limit implies, Paper 004 eq. (2)"),
    "limit_pin_within": ("1", "1: the pin wear at the limit is within the allowed pin wear "
                              "delta_d; 0: beyond it; -1: not evaluated"),
}

#: Scalars of Paper 004's pin criterion (NaN, and -1 for the verdict, when not evaluated).
PIN_VARIABLES = {
    "pin_allowed_growth": ("m", "allowed pitch growth delta_t1, Paper 004 eq. (3)"),
    "pin_allowed_wear": ("m", "allowed pin wear delta_d = (delta_t1 / 2) K_e, eq. (2)"),
    "pin_critical_diameter": ("m", "critical pin diameter d_k, eq. (5)"),
    "pin_required_diameter": ("m", "required pin diameter d_k + delta_d, eq. (1)"),
    "pin_diameter": ("m", "nominal pin diameter d of the chain"),
    "pin_passes": ("1", "1: d >= d_k + delta_d (eq. (1)); 0: not; -1: not evaluated"),
    "pin_wear_coefficient": ("1", "pin wear coefficient K_e"),
    "pin_force": ("N", "largest force on a chain link F_max"),
    "pin_allowable_stress": ("Pa", "allowable bending stress of the pin [sigma_T]"),
    "pin_support_factor": ("1", "support factor K of the pin, eq. (4)"),
    "pin_wear_measured": ("m", "pin wear the pitch growth over the log implies, eq. (2)"),
    "pin_wear_share": ("1", "pin wear over the log over the allowed pin wear delta_d"),
}

#: The limits a wear run is set against: Paper 004's eq. (3) for its sprocket, the lab's.
LIMITS = ("eq3", "lab")

#: Global attributes written from the result's fields (the others are its :attr:`attrs`).
DERIVED_ATTRS = ("ingest_warnings", "warnings")

#: Points of the stored fitted curve.
CURVE_POINTS = 241


def _units(key: str, abscissa: str) -> str:
    """A variable's units: `key` itself, or the running unit it names."""
    return RUNNING_UNITS[abscissa].get(key, key)


def _verdict(value: bool | None) -> int:
    """1 (true), 0 (false) or -1 (not evaluated)."""
    return -1 if value is None else int(bool(value))


@dataclass(frozen=True)
class LimitOutcome:
    """One pitch-growth limit of a wear run and what the fit says of it.

    Attributes
    ----------
    limit : float
        The limit of delta_t [m], counted as the log counts it.
    source : str
        Where it comes from (:func:`pipeline.fit.wear.pitch_growth_limit`).
    life : WearLife or None
        The life to it; None when none can be given (`note` says why).
    pin : PinWear or None
        The pin wear at the limit (None without a life or a pin criterion).
    note : str
        Why there is no life ("" when there is).
    """

    limit: float
    source: str
    life: WearLife | None = None
    pin: PinWear | None = None
    note: str = ""


@dataclass(frozen=True, eq=False)
class WearResult:
    """What one wear run gave, as its run file holds it (SI; tau in the log's abscissa).

    Attributes
    ----------
    attrs : dict
        Global attributes: provenance, the run's identity (``campaign``,
        ``run_id``, ``kind``, ``chain``, ``layout``) and its settings
        (``abscissa``, ``channel``, ``reference``, ``section_pitches``,
        ``pitch``, ``sprocket_teeth``, ``model``, ``model_choice``,
        ``confidence_level``, ``pin_criterion``).
    readings : pandas.DataFrame
        Per reading: the columns of :data:`READING_VARIABLES` it has.
    curve : pandas.DataFrame
        The fitted curve: the columns of :data:`CURVE_VARIABLES`.
    fit : dict of str to float
        The scalars of :data:`FIT_VARIABLES`.
    limits : pandas.DataFrame
        Per limit (index: names of :data:`LIMITS`): the columns of
        :data:`LIMIT_VARIABLES`, ``limit_source`` and ``life_note``.
    pin : dict of str to float
        The scalars of :data:`PIN_VARIABLES`.
    ingest_warnings, warnings : tuple of str
        What the reader, and the stages, decided or found.
    """

    attrs: dict[str, Any]
    readings: pd.DataFrame
    curve: pd.DataFrame
    fit: dict[str, float]
    limits: pd.DataFrame
    pin: dict[str, float]
    ingest_warnings: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @property
    def abscissa(self) -> str:
        """The running coordinate: ``"time"`` [s] or ``"cycles"`` [1]."""
        return str(self.attrs["abscissa"])

    @classmethod
    def of(cls, fit: WearFit, limits: dict[str, LimitOutcome],
           pin: tuple[PinCheck, dict[str, float]] | None, logged: pd.DataFrame,
           attrs: dict[str, Any], ingest_warnings: list[str], warnings: list[str]
           ) -> WearResult:
        """The result of the stages' outputs.

        Parameters
        ----------
        fit : WearFit
            The fitted wear model (its log is the conditioned log).
        limits : dict of str to LimitOutcome
            Per name of :data:`LIMITS` the run has.
        pin : (PinCheck, dict) or None
            Paper 004's pin criterion for the run's chain, sprocket and loads
            (:func:`pipeline.theory.pin_criterion.check_pin`) and its inputs
            ``pin_wear_coefficient``, ``pin_force`` [N], ``pin_allowable_stress``
            [Pa] and ``pin_support_factor``; None when the run sheet does not
            ask for it.
        logged : pandas.DataFrame
            The ``load`` [N] and ``speed`` [m/s] the log has, one row per reading.
        attrs : dict
            Provenance, identity and settings (see :attr:`attrs`).
        ingest_warnings, warnings : list of str
            The reader's, and the stages', warnings.
        """
        log = fit.log
        readings = pd.DataFrame({"tau": log.tau, "elongation": log.elongation,
                                 "relative_elongation": log.table["relative_elongation"]
                                 .to_numpy(dtype=float),
                                 "elongation_fit": log.elongation - fit.residuals,
                                 "residual": fit.residuals})
        for name in ("load", "speed"):
            if name in logged:
                readings[name] = logged[name].to_numpy(dtype=float)
        attrs = {**attrs, "model": fit.model, "model_choice": fit.choice,
                 "confidence_level": fit.confidence}
        return cls(attrs=attrs, readings=readings, curve=_curve(fit, limits),
                   fit=_fit_values(fit), limits=_limit_rows(fit, limits),
                   pin=_pin_values(fit, pin), ingest_warnings=tuple(ingest_warnings),
                   warnings=tuple(warnings))

    def global_attrs(self) -> dict[str, Any]:
        """The run file's global attributes: :attr:`attrs` and those of the fields."""
        return {**self.attrs, "ingest_warnings": joined(self.ingest_warnings),
                "warnings": joined(self.warnings)}

    def to_dataset(self) -> xr.Dataset:
        """The run file (layout in the module docstring and ``docs/outputs.md``)."""
        level = float(self.attrs["confidence_level"])
        data = {}
        for dim, frame, variables in (("reading", self.readings, READING_VARIABLES),
                                      ("curve_point", self.curve, CURVE_VARIABLES),
                                      ("limit", self.limits, LIMIT_VARIABLES)):
            for name in frame.columns:
                if name in variables:
                    units, long_name = variables[name]
                    data[name] = (dim, frame[name].to_numpy(dtype=float), variable_attrs(
                        _units(units, self.abscissa), long_name, name, level))
        for name in ("limit_source", "life_note"):
            data[name] = ("limit", self.limits[name].astype(str).to_numpy(),
                          {"long_name": "where the limit comes from" if name == "limit_source"
                           else "why no life is given (empty: a life is given)"})
        for values, variables in ((self.fit, FIT_VARIABLES), (self.pin, PIN_VARIABLES)):
            for name, value in values.items():
                units, long_name = variables[name]
                data[name] = ((), float(value), variable_attrs(
                    _units(units, self.abscissa), long_name, name, level))
        dataset = xr.Dataset(data, coords={"limit": list(self.limits.index)})
        dataset.attrs.update(self.global_attrs())
        return dataset

    @classmethod
    def from_dataset(cls, dataset: xr.Dataset) -> WearResult:
        """The result a run file holds (the inverse of :meth:`to_dataset`).

        Parameters
        ----------
        dataset : xarray.Dataset
            A wear run file, loaded (:func:`pipeline.store.netcdf.read_dataset`).
        """
        def frame(variables, index=None) -> pd.DataFrame:
            return pd.DataFrame({name: dataset[name].values for name in variables
                                 if name in dataset}, index=index)

        limits = frame([*LIMIT_VARIABLES, "limit_source", "life_note"],
                       pd.Index(dataset["limit"].values.astype(str), name="limit"))
        for name in ("limit_source", "life_note"):
            limits[name] = limits[name].astype(str)
        attrs = {key: value for key, value in dataset.attrs.items() if key not in DERIVED_ATTRS}
        return cls(attrs=attrs, readings=frame(READING_VARIABLES), curve=frame(CURVE_VARIABLES),
                   fit={name: float(dataset[name]) for name in FIT_VARIABLES},
                   limits=limits, pin={name: float(dataset[name]) for name in PIN_VARIABLES},
                   ingest_warnings=lines(dataset.attrs["ingest_warnings"]),
                   warnings=lines(dataset.attrs["warnings"]))


def _fit_values(fit: WearFit) -> dict[str, float]:
    """The scalars of :data:`FIT_VARIABLES` of `fit` (NaN where its model has none)."""
    end = float(fit.log.tau[-1])
    values = {"wear_rate_ci_low": fit.wear_rate_ci_low, "wear_rate_ci_high": fit.wear_rate_ci_high,
              "dof": fit.dof, "bic_run_in": fit.bic.get("run-in", math.nan),
              "bic_linear": fit.bic["linear"], "tau_end": end,
              "growth_measured": float(fit.curve(end)) - fit.params["offset"]}
    for name in ("wear_rate", "offset", "run_in", "run_in_time"):
        values[name] = fit.params.get(name, math.nan)
        values[f"{name}_stderr"] = fit.stderrs.get(name, math.nan)
    return {name: float(values[name]) for name in FIT_VARIABLES}


def _curve(fit: WearFit, limits: dict[str, LimitOutcome]) -> pd.DataFrame:
    """The fitted curve and its band from tau = 0 to beyond the log and every life."""
    ends = [float(fit.log.tau[-1])] + [outcome.life.ci_high for outcome in limits.values()
                                       if outcome.life is not None]
    tau = np.linspace(0.0, 1.05 * max(ends), CURVE_POINTS)
    value, half = fit.curve(tau), fit.quantile * fit.curve_stderr(tau)
    return pd.DataFrame({"curve_tau": tau, "curve_elongation": value,
                         "curve_ci_low": value - half, "curve_ci_high": value + half})


def _limit_rows(fit: WearFit, limits: dict[str, LimitOutcome]) -> pd.DataFrame:
    """One row per limit: :data:`LIMIT_VARIABLES`, ``limit_source`` and ``life_note``."""
    rows = {}
    for name, outcome in limits.items():
        life, pin = outcome.life, outcome.pin
        rows[name] = {
            "limit_elongation": outcome.limit, "limit_relative": outcome.limit / fit.log.pitch,
            "life": life.life if life else math.nan,
            "life_ci_low": life.ci_low if life else math.nan,
            "life_ci_high": life.ci_high if life else math.nan,
            "limit_growth": outcome.limit - fit.params["offset"],
            "limit_pin_wear": pin.pin_wear if pin else math.nan,
            "limit_pin_within": _verdict(pin.within if pin else None),
            "limit_source": outcome.source, "life_note": outcome.note}
    return pd.DataFrame.from_dict(rows, orient="index").rename_axis("limit")


def _pin_values(fit: WearFit, pin: tuple[PinCheck, dict[str, float]] | None
                ) -> dict[str, float]:
    """The scalars of :data:`PIN_VARIABLES` (NaN, and -1 for the verdict, without `pin`)."""
    values = dict.fromkeys(PIN_VARIABLES, math.nan)
    values["pin_passes"] = _verdict(None)
    if pin is None:
        return values
    check, inputs = pin
    growth = _fit_values(fit)["growth_measured"]
    measured = (pin_wear_allowance(growth, inputs["pin_wear_coefficient"]) if growth > 0
                else math.nan)
    values.update(inputs, pin_allowed_growth=check.pitch_growth,
                  pin_allowed_wear=check.wear_allowance,
                  pin_critical_diameter=check.critical_diameter,
                  pin_required_diameter=check.required_diameter,
                  pin_diameter=check.pin_diameter, pin_passes=_verdict(check.passes),
                  pin_wear_measured=measured,
                  pin_wear_share=measured / float(check.wear_allowance))
    return {name: float(value) for name, value in values.items()}
