"""Wear of a roller chain from its wear log, its life to a pitch-growth limit, and its pins.

Two models of the elongation per pitch ``delta_t`` [m] over the running time
``tau`` [s] (or the cycles [-]; rates are then per cycle) are fitted with lmfit
to a :class:`~pipeline.condition.wear.WearLog`:

``"run-in"``
    ``delta_t = delta_t0 + A (1 - exp(-tau / tau0)) + w tau``: a run-in
    elongation ``A`` [m] (``A >= 0``) settling with the time constant
    ``tau0`` [s], then steady wear at the rate ``w`` [m/s];
``"linear"``
    ``delta_t = delta_t0 + w tau``.

``delta_t0`` [m] is the elongation at ``tau = 0``: the new chain's pitch error
on a log against the nominal pitch, about 0 on one relative to its first
reading.

Model choice
------------
``model="auto"`` chooses the run-in model when the data support it, that is
when all of these hold, and the linear model otherwise:

1. the log has more readings than the run-in model has parameters (five or more);
2. the run-in fit converged with a covariance (no parameter stuck at a bound);
3. its Bayesian information criterion is lower than the linear model's (the
   two extra parameters pay for themselves: ``n ln(chi2 / n) + p ln n``);
4. the interval of ``A`` at the fit's confidence lies above 0;
5. ``tau0`` is shorter than the log (its last ``tau``): a run-in slower than
   the log cannot be told from the wear rate.

``model="run-in"`` or ``"linear"`` forces one. :attr:`WearFit.choice` says
which rule decided.

Uncertainty
-----------
The readings are fitted unweighted; their scatter about the curve is their
error: the covariance is scaled by ``chi2 / dof`` (lmfit's ``scale_covar``,
the Birge ratio of unit weights), and intervals use Student's t with the
residual degrees of freedom ``dof = n - p``.

Life
----
The life to a limit ``delta_t_lim`` [m] is the ``tau`` at which the fitted
curve reaches it (:func:`predict_life`). The limit is compared with
``delta_t`` as the log counts it: Paper 004's jump-off growth of eq. (3) for
the sprocket's teeth z, or a lab's limit as a percentage of the pitch
(:func:`pitch_growth_limit`). Its interval inverts the pointwise confidence
band of the fitted curve (delta method on the scaled covariance, the same t
quantile): from the earliest ``tau`` at which the band's upper edge reaches the
limit to the latest at which its lower edge is still below it. For the linear
model this is Fieller's interval of ``(delta_t_lim - delta_t0) / w``, exact for
normal errors. No life is given (:class:`~pipeline.errors.FitError`) when the
wear rate's interval does not lie above 0: the life is then undefined (infinite
at no wear), not a number.

On the virtual bench (:class:`pipeline.simulate.wear.WearTruth` defaults: run-in
then 0.75 um/h per pitch, 10 um noise on a 10-pitch section read every 5 h for
300 h; 400 seeds) the run-in model is chosen in every seed, the wear rate errs
by at most 0.7 %, and the 95 % interval of the life covers the true life in
96.8 % of seeds for a 3 % limit (700 h) and 96.5 % for eq. (3) with z = 40
(1200 h); without run-in the linear model is chosen in every seed (200 seeds).

Pins
----
:func:`compare_pin_wear` turns the pitch growth by wear up to the limit into
the pin wear it implies by Paper 004, eq. (2), and sets it beside the pin wear
allowed until jump-off, ``delta_d = (delta_t1 / 2) K_e`` with ``delta_t1`` of
eq. (3).

References
----------
Paper 004, eqs. (2)-(3) (:mod:`pipeline.theory.pin_criterion`,
``docs/models/paper-004-pin-criterion.md``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import lmfit
import numpy as np
from scipy import optimize, stats

from pipeline.condition.wear import WearLog
from pipeline.errors import FitError
from pipeline.theory.pin_criterion import allowed_pitch_growth, pin_wear_allowance

#: Level of every interval of this module.
CONFIDENCE = 0.95

#: Models of :func:`fit_wear`, each with the parameters it fits.
PARAMETERS = {
    "run-in": ("offset", "run_in", "run_in_time", "wear_rate"),
    "linear": ("offset", "wear_rate"),
}

#: Values of ``model`` :func:`fit_wear` accepts.
MODEL_CHOICES = ("auto", *PARAMETERS)

#: Trial run-in time constants of the starting values, as fractions of the log's span.
_TRIAL_RUN_IN_TIMES = np.geomspace(1e-3, 1.0, 61)

#: Points of the grid on which a crossing of the limit is bracketed (:func:`_crossing`).
_CROSSING_GRID = 2049


def wear_curve(
    tau: np.ndarray, offset: float, wear_rate: float, run_in: float = 0.0,
    run_in_time: float = 1.0,
) -> np.ndarray:
    """Elongation per pitch of the wear models [m].

    Parameters
    ----------
    tau : numpy.ndarray
        Running time [s] (or cycles [-]).
    offset : float
        Elongation at ``tau = 0``, delta_t0 [m].
    wear_rate : float
        Steady wear rate w [m/s] (or [m] per cycle).
    run_in : float, optional
        Run-in elongation A [m]; 0 (the default) for the linear model.
    run_in_time : float, optional
        Run-in time constant tau0 [s] (or cycles [-]).

    Returns
    -------
    numpy.ndarray
        ``delta_t0 + A (1 - exp(-tau / tau0)) + w tau`` [m].

    Examples
    --------
    >>> wear_curve(np.array([0.0, 10.0]), 1e-5, 2e-6, run_in=3e-5, run_in_time=1e-9).tolist()
    [1e-05, 6e-05]
    """
    return offset + run_in * -np.expm1(-tau / run_in_time) + wear_rate * tau


def _quantile(confidence: float, dof: int) -> float:
    """Two-sided Student-t quantile at `confidence` with `dof` degrees of freedom [-]."""
    return float(stats.t.ppf((1 + confidence) / 2, dof))


def _curve_gradient(tau: np.ndarray, values: dict[str, float]) -> np.ndarray:
    """d delta_t / d parameter at each `tau`, one column per parameter of `values` (SI)."""
    decay = np.exp(-tau / values.get("run_in_time", 1.0))
    columns = {
        "offset": np.ones_like(tau),
        "wear_rate": tau,
        "run_in": 1.0 - decay,
        "run_in_time": -values.get("run_in", 0.0) * tau * decay
        / values.get("run_in_time", 1.0) ** 2,
    }
    return np.column_stack([columns[name] for name in values])


@dataclass(frozen=True)
class WearFit:
    """A wear model fitted to a wear log (SI units; per cycle on a log over cycles).

    Attributes
    ----------
    model : str
        The model used: ``"run-in"`` or ``"linear"``.
    choice : str
        Why that model: forced, or the rule of the module docstring that decided.
    wear_rate, wear_rate_stderr : float
        Steady wear rate w and its standard error [m/s].
    wear_rate_ci_low, wear_rate_ci_high : float
        Interval of w at `confidence` [m/s].
    confidence : float
        Level of the intervals (0.95).
    dof : int
        Residual degrees of freedom, readings minus parameters.
    params, stderrs : dict of str to float
        Fitted value and standard error of each parameter of the model:
        ``offset`` delta_t0 [m], ``wear_rate`` w [m/s] and, for the run-in
        model, ``run_in`` A [m] and ``run_in_time`` tau0 [s].
    covariance : numpy.ndarray
        Scaled covariance of the parameters, in the order of `params` (SI).
    bic : dict of str to float
        Bayesian information criterion of every model fitted [-].
    residuals : numpy.ndarray
        Measured minus fitted delta_t at each reading [m].
    log : WearLog
        The log fitted.
    result : lmfit.model.ModelResult
        lmfit's result (in the internal scaled units).
    """

    model: str
    choice: str
    wear_rate: float
    wear_rate_stderr: float
    wear_rate_ci_low: float
    wear_rate_ci_high: float
    confidence: float
    dof: int
    params: dict[str, float]
    stderrs: dict[str, float]
    covariance: np.ndarray = field(repr=False)
    bic: dict[str, float]
    residuals: np.ndarray = field(repr=False)
    log: WearLog = field(repr=False, compare=False)
    result: lmfit.model.ModelResult = field(repr=False, compare=False)

    @property
    def quantile(self) -> float:
        """Student-t quantile of the intervals at `confidence` with `dof` [-]."""
        return _quantile(self.confidence, self.dof)

    def curve(self, tau: np.ndarray) -> np.ndarray:
        """Fitted delta_t [m] at `tau` [s]."""
        return wear_curve(np.asarray(tau, dtype=float), **self.params)

    def curve_stderr(self, tau: np.ndarray) -> np.ndarray:
        """Standard error of the fitted delta_t [m] at `tau` [s] (delta method)."""
        gradient = _curve_gradient(np.atleast_1d(np.asarray(tau, dtype=float)), self.params)
        variance = np.einsum("ij,jk,ik->i", gradient, self.covariance, gradient)
        return np.sqrt(np.maximum(variance, 0.0)).reshape(np.shape(tau))

    def covers(self, wear_rate: float) -> bool:
        """Whether the interval of w holds `wear_rate` [m/s]."""
        return self.wear_rate_ci_low <= wear_rate <= self.wear_rate_ci_high


def fit_wear(log: WearLog, *, model: str = "auto", confidence: float = CONFIDENCE) -> WearFit:
    """Fit the run-in or the linear wear model to a wear log.

    Parameters
    ----------
    log : WearLog
        The conditioned log (:mod:`pipeline.condition.wear`).
    model : {"auto", "run-in", "linear"}, optional
        ``"auto"`` chooses by the rule of the module docstring; the others force.
    confidence : float, optional
        Level of the intervals [-] (default :data:`CONFIDENCE`).

    Returns
    -------
    WearFit

    Raises
    ------
    FitError
        When the forced run-in model has too few readings or cannot be fitted
        with a covariance, or the linear model has too few readings.
    ValueError
        On an unknown `model`.

    References
    ----------
    Paper 004, eq. (3): delta_t is the pitch growth it limits.
    """
    if model not in MODEL_CHOICES:
        raise ValueError(f"model must be one of {', '.join(MODEL_CHOICES)}, got {model!r}")
    results = {name: _fit(log, name) for name in PARAMETERS
               if model in ("auto", name) and _enough_readings(log, name, forced=model == name)}
    if model != "auto":
        if results[model].covar is None:  # only the run-in model can lose a parameter
            raise FitError("the run-in model has no covariance: a parameter is not determined",
                           hint="the log shows no run-in the readings can resolve: fit the "
                                "linear model (model='linear')")
        return _summary(log, results, model, "forced", confidence)
    chosen, choice = _choose(results, confidence)
    return _summary(log, results, chosen, choice, confidence)


def _enough_readings(log: WearLog, model: str, *, forced: bool) -> bool:
    """Whether the log has more readings than `model` has parameters; raises if `forced`."""
    needed = len(PARAMETERS[model]) + 1
    if len(log.table) >= needed:
        return True
    if forced:
        raise FitError(f"the {model} model needs at least {needed} readings, the log has "
                       f"{len(log.table)}",
                       hint="log more readings, or fit the linear model (model='linear')")
    return False


def _scales(log: WearLog) -> dict[str, float]:
    """SI value of one internal unit of each parameter: lengths in pitches, tau in log spans."""
    span = float(log.tau[-1])
    return {"offset": log.pitch, "run_in": log.pitch, "run_in_time": span,
            "wear_rate": log.pitch / span}


def _fit(log: WearLog, model: str) -> lmfit.model.ModelResult:
    """lmfit's fit of `model` in internal units (lengths in pitches, tau in the log's span)."""
    scales = _scales(log)
    x = log.tau / scales["run_in_time"]
    y = log.elongation / log.pitch
    params = _starting_values(x, y, model)
    return lmfit.Model(wear_curve).fit(y, params, tau=x)


def _starting_values(x: np.ndarray, y: np.ndarray, model: str) -> lmfit.Parameters:
    """Parameters of `model` with starting values from linear least squares (internal units).

    For the run-in model the best of :data:`_TRIAL_RUN_IN_TIMES` is kept; at
    a fixed tau0 the model is linear in delta_t0, A and w.
    """
    params = lmfit.Parameters()
    if model == "linear":
        slope, intercept = np.polyfit(x, y, 1)
        params.add_many(("offset", intercept), ("wear_rate", slope),
                        ("run_in", 0.0, False), ("run_in_time", 1.0, False))
        return params
    trials = []
    for trial in _TRIAL_RUN_IN_TIMES:
        basis = np.column_stack([np.ones_like(x), -np.expm1(-x / trial), x])
        coefficients = np.linalg.lstsq(basis, y, rcond=None)[0]
        trials.append((float(np.sum((basis @ coefficients - y) ** 2)), trial, coefficients))
    _, trial, (offset, run_in, slope) = min(trials, key=lambda item: item[0])
    params.add_many(("offset", offset), ("wear_rate", slope),
                    ("run_in", max(run_in, 1e-3 * np.ptp(y)), True, 0.0),
                    ("run_in_time", trial, True, 0.0))
    return params


def _choose(results: dict[str, lmfit.model.ModelResult], confidence: float) -> tuple[str, str]:
    """The model the data support, and the rule that decided (module docstring)."""
    if "run-in" not in results:
        return "linear", "too few readings for the run-in model"
    run_in, linear = results["run-in"], results["linear"]
    if run_in.covar is None:
        return "linear", "the run-in fit has no covariance (a parameter is not determined)"
    if run_in.bic >= linear.bic:
        return "linear", f"BIC of the run-in model {run_in.bic - linear.bic:+.3g} above linear"
    amplitude = run_in.params["run_in"]
    if amplitude.value - _quantile(confidence, run_in.nfree) * amplitude.stderr <= 0:
        return "linear", f"the {confidence:.0%} interval of the run-in elongation A reaches 0"
    if run_in.params["run_in_time"].value >= 1.0:
        return "linear", "the run-in time constant tau0 is longer than the log"
    return "run-in", (f"BIC {run_in.bic - linear.bic:+.3g} against linear, the "
                      f"{confidence:.0%} interval of A above 0, tau0 within the log")


def _summary(log: WearLog, results: dict[str, lmfit.model.ModelResult], model: str,
             choice: str, confidence: float) -> WearFit:
    """The :class:`WearFit` of `model` in SI units."""
    result = results[model]
    names = PARAMETERS[model]
    scales = np.array([_scales(log)[name] for name in names])
    order = [result.var_names.index(name) for name in names]
    covariance = result.covar[np.ix_(order, order)] * np.outer(scales, scales)
    values = {name: float(result.params[name].value * scale)
              for name, scale in zip(names, scales, strict=True)}
    stderrs = dict(zip(names, np.sqrt(np.diag(covariance)).tolist(), strict=True))
    dof = int(result.nfree)
    half = _quantile(confidence, dof) * stderrs["wear_rate"]
    return WearFit(
        model=model, choice=choice, wear_rate=values["wear_rate"],
        wear_rate_stderr=stderrs["wear_rate"], wear_rate_ci_low=values["wear_rate"] - half,
        wear_rate_ci_high=values["wear_rate"] + half, confidence=confidence, dof=dof,
        params=values, stderrs=stderrs, covariance=covariance,
        bic={name: float(fitted.bic) for name, fitted in results.items()},
        residuals=log.elongation - wear_curve(log.tau, **values), log=log, result=result)


def pitch_growth_limit(
    pitch: float, reference: str, *, teeth: int | None = None,
    limit_percent: float | None = None,
) -> tuple[float, str]:
    """The limit of delta_t [m], counted as the log counts it, and where it comes from.

    Parameters
    ----------
    pitch : float
        Nominal pitch t [m].
    reference : {"nominal", "first"}
        What the log's delta_t is counted from (:class:`~pipeline.condition.wear.WearLog`).
    teeth : int, optional
        Teeth z of the driven sprocket [-]: the limit is Paper 004's jump-off.
        Eq. (3) allows the growth ``delta_t1 = 2.5 psi t / z - delta_t_n``
        beyond a new chain's pitch error ``delta_t_n = 0.004 t``: the limit of
        a log relative to its (new chain's) first reading. Against the nominal
        pitch the chain's own error counts, and the limit is the jump-off pitch
        error itself, ``2.5 psi t / z`` (eq. (3) with ``delta_t_n = 0``).
    limit_percent : float, optional
        A lab's own limit, as a percentage of the pitch [%] (e.g. 1.5 or 3).

    Returns
    -------
    limit : float
        The limit of delta_t [m].
    source : str
        Where it comes from, in words.

    Raises
    ------
    ValueError
        Unless exactly one of `teeth` and `limit_percent` is given, or on an
        unknown `reference` or a `limit_percent` not above 0.

    References
    ----------
    Paper 004, eq. (3) (:func:`pipeline.theory.pin_criterion.allowed_pitch_growth`).

    Examples
    --------
    >>> limit, source = pitch_growth_limit(0.01905, "first", teeth=20)
    >>> round(limit * 1e3, 5), source
    (1.8288, 'Paper 004, eq. (3), z = 20: delta_t1 = 2.5 psi t / z - delta_t_n')
    """
    if (teeth is None) == (limit_percent is None):
        raise ValueError("give exactly one of teeth (Paper 004, eq. (3)) and limit_percent")
    if reference not in ("nominal", "first"):
        raise ValueError(f"reference must be 'nominal' or 'first', got {reference!r}")
    if limit_percent is not None:
        if not (math.isfinite(limit_percent) and limit_percent > 0):
            raise ValueError(f"limit_percent must be a finite number > 0, got {limit_percent!r}")
        return limit_percent / 100.0 * pitch, f"{limit_percent:g} % of the pitch"
    if reference == "nominal":
        return (float(allowed_pitch_growth(pitch, teeth, pitch_error_fraction=0.0)),
                f"Paper 004, eq. (3), z = {teeth}: jump-off pitch error 2.5 psi t / z")
    return (float(allowed_pitch_growth(pitch, teeth)),
            f"Paper 004, eq. (3), z = {teeth}: delta_t1 = 2.5 psi t / z - delta_t_n")


@dataclass(frozen=True)
class WearLife:
    """Running time until delta_t reaches a limit (SI; cycles on a log over cycles).

    Attributes
    ----------
    life : float
        Running time at which the fitted curve reaches `limit` [s].
    ci_low, ci_high : float
        Its interval at `confidence` [s] (module docstring); `ci_low` is the
        first reading's time when the curve's band reaches the limit there.
    confidence : float
        Level of the interval.
    limit : float
        The limit of delta_t [m], counted as the log counts delta_t.
    limit_source : str
        Where the limit comes from (:func:`pitch_growth_limit`).
    growth : float
        Pitch growth by wear at the limit, ``limit - delta_t0`` [m] (the fitted
        elongation at ``tau = 0`` taken off).
    pitch : float
        Nominal pitch t [m].
    model : str
        The wear model of the fit.
    """

    life: float
    ci_low: float
    ci_high: float
    confidence: float
    limit: float
    limit_source: str
    growth: float
    pitch: float
    model: str

    def covers(self, life: float) -> bool:
        """Whether the interval holds `life` [s]."""
        return self.ci_low <= life <= self.ci_high


def predict_life(
    fit: WearFit, *, teeth: int | None = None, limit_percent: float | None = None
) -> WearLife:
    """Running time until the fitted delta_t reaches a pitch-growth limit, with its interval.

    Parameters
    ----------
    fit : WearFit
        The fitted wear model (:func:`fit_wear`).
    teeth : int, optional
        Teeth z of the driven sprocket [-]: the limit of Paper 004, eq. (3)
        (:func:`pitch_growth_limit`).
    limit_percent : float, optional
        A lab's own limit as a percentage of the pitch [%].

    Returns
    -------
    WearLife

    Raises
    ------
    FitError
        When the wear rate's interval does not lie above 0 (no significant
        wear: the life is undefined), or the fitted delta_t is at the limit
        already at the first reading.
    ValueError
        Unless exactly one of `teeth` and `limit_percent` is given.

    References
    ----------
    Paper 004, eq. (3).
    """
    log = fit.log
    limit, source = pitch_growth_limit(log.pitch, log.reference, teeth=teeth,
                                       limit_percent=limit_percent)
    _check_wears(fit)
    start = float(log.tau[0])
    if fit.curve(start) >= limit:
        raise FitError(
            f"the chain is at its limit ({source}, {limit:.4g} m per pitch) already at the "
            f"first reading: fitted delta_t {float(fit.curve(start)):.4g} m",
            column="elongation",
            hint="no life is left to predict; check the limit, and that the log's reference "
                 "(nominal pitch or first reading) is the one the limit is meant for")
    q, end = fit.quantile, float(log.tau[-1])
    return WearLife(
        life=_crossing(lambda tau: fit.curve(tau) - limit, start, end, last=False),
        ci_low=_crossing(lambda tau: fit.curve(tau) + q * fit.curve_stderr(tau) - limit,
                         start, end, last=False),
        ci_high=_crossing(lambda tau: fit.curve(tau) - q * fit.curve_stderr(tau) - limit,
                          start, end, last=True),
        confidence=fit.confidence, limit=limit, limit_source=source,
        growth=limit - fit.params["offset"], pitch=log.pitch, model=fit.model)


def _check_wears(fit: WearFit) -> None:
    """Raise a :class:`FitError` unless the wear rate's interval lies above 0."""
    if fit.wear_rate_ci_low > 0:
        return
    unit = "m/s" if fit.log.abscissa == "time" else "m per cycle"
    raise FitError(
        f"no significant wear: the wear rate is {fit.wear_rate:.4g} +- "
        f"{fit.wear_rate_stderr:.2g} {unit} ({fit.confidence:.0%} interval from "
        f"{fit.wear_rate_ci_low:.4g}), so the life to a "
        "limit is undefined (infinite without wear)",
        column="elongation",
        hint="run the test longer, or read the section more precisely, until the elongation "
             "grows beyond the scatter of the readings")


def _crossing(excess: Callable[[np.ndarray], np.ndarray], start: float, end: float, *,
              last: bool) -> float:
    """First (or `last`) tau >= `start` at which `excess` rises through 0 [s].

    `end` is doubled (from `start`) until ``excess(end) >= 0``, which holds
    for large tau when the wear rate is significant; the crossing is then
    bracketed on a grid and found by Brent's method. `start` is returned when
    ``excess(start) >= 0`` (only the band's upper edge can be there).
    """
    while excess(np.array(end)) < 0:
        end = start + 2.0 * (end - start)
    grid = np.linspace(start, end, _CROSSING_GRID)
    values = excess(grid)
    if values[0] >= 0:
        return start
    index = np.flatnonzero(values < 0)[-1] if last else np.flatnonzero(values >= 0)[0] - 1
    return float(optimize.brentq(lambda tau: float(excess(np.array(tau))), grid[index],
                                 grid[index + 1], xtol=1e-12 * end, rtol=1e-12))


@dataclass(frozen=True)
class PinWear:
    """Pin wear implied at a limit beside the pin wear allowed until jump-off (m).

    Attributes
    ----------
    growth : float
        Pitch growth by wear at the limit [m] (:attr:`WearLife.growth`).
    pin_wear : float
        Pin wear it implies, ``(growth / 2) K_e`` [m] (Paper 004, eq. (2)).
    allowed_growth : float
        Allowed pitch growth delta_t1 [m] (Paper 004, eq. (3)).
    allowed_pin_wear : float
        Allowed pin wear delta_d = (delta_t1 / 2) K_e [m] (Paper 004, eq. (2)).
    wear_coefficient : float
        Pin wear coefficient K_e [-].
    within : bool
        Whether ``pin_wear <= allowed_pin_wear``: the limit keeps the pin
        within the wear allowance of the pin criterion, eq. (1).
    """

    growth: float
    pin_wear: float
    allowed_growth: float
    allowed_pin_wear: float
    wear_coefficient: float
    within: bool


def compare_pin_wear(life: WearLife, *, teeth: int, wear_coefficient: float) -> PinWear:
    """Pin wear implied when the chain reaches its limit, against Paper 004's allowance.

    Parameters
    ----------
    life : WearLife
        The life to a limit (:func:`predict_life`).
    teeth : int
        Teeth z of the driven sprocket [-] (Paper 004, eq. (3)).
    wear_coefficient : float
        Pin wear coefficient K_e [-] (Paper 004 gives no value).

    Returns
    -------
    PinWear

    References
    ----------
    Paper 004, eqs. (1)-(3) (:func:`pipeline.theory.pin_criterion.pin_wear_allowance`,
    :func:`~pipeline.theory.pin_criterion.allowed_pitch_growth`).
    """
    allowed_growth = float(allowed_pitch_growth(life.pitch, teeth))
    pin_wear = float(pin_wear_allowance(life.growth, wear_coefficient))
    allowed = float(pin_wear_allowance(allowed_growth, wear_coefficient))
    return PinWear(growth=life.growth, pin_wear=pin_wear, allowed_growth=allowed_growth,
                   allowed_pin_wear=allowed, wear_coefficient=float(wear_coefficient),
                   within=pin_wear <= allowed)
