"""Paper 003's contact geometry fitted to measured tooth-segment load ratios.

The measured ratios of a segment-load run (per seating or per operating point,
:mod:`pipeline.condition.segment_load`) are compared with eqs. (1)-(4)::

    k = r - (d/2) [1 - cos(pi/2 - beta + eps_n)],   psi = 2 acos(s / (2 k)),
    F_K / F = 1 / (2 sin(psi / 2)),                 F_P / F = 1 / (2 tan(psi / 2))

(computed by :mod:`pipeline.theory.tooth_segments`). One parameter is fitted
with lmfit, weighting every measured ratio by its standard error:

``vary="s"``
    the distance s between the contact points, r, d, beta and eps_n known,
    within c <= s < 2 k;
``vary="beta"``
    the flank inclination beta, s known, within 0 < beta <= pi/2 + eps_n
    (the branch on which k grows with beta, eq. (1)) and s < 2 k.

A measured ratio outside what the parameter's range gives (an F_K / F below
that of edge contact s = c, or below 0.5, which no opening angle gives) is
refused with a :class:`~pipeline.errors.FitError`: no number is made up.

Uncertainty
-----------
As :mod:`pipeline.fit.impact_model`, the standard error of the weighted
least squares, ``1 / sqrt(sum J^2)`` with J the derivative of the normalized
residuals at the solution, scaled by the Birge ratio ``sqrt(chi2_red)`` when
the ratios scatter more than their standard errors say (never shrunk). J is a
difference quotient into the parameter's range, not lmfit's covariance: lmfit
maps a bounded parameter through a sine, whose zero slope at a bound would
make the error vanish at edge contact s = c. The interval is
``value +- q stderr``, clipped to the parameter's range, with ``q`` Student's
t with the residual degrees of freedom whether or not the error was scaled,
since the standard errors are themselves estimates (of a run's median from a
few dozen seatings); the normal quantile only without residual degrees of
freedom (one measured ratio, its error taken as stated). F_K / F and F_P / F
of one seating share the noise of F; they are weighted as independent.

Beside the fit: the model's ratios and friction increase ``2 F_K / F - 1`` at
the fitted geometry and at the run sheet's, the measured ones (weighted
means), and the measured friction increase against Paper 003's claim of over
50 % (:data:`pipeline.theory.tooth_segments.CLAIMS`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import lmfit
import numpy as np
import pandas as pd
from scipy import stats
from scipy.optimize import brentq

from pipeline.errors import FitError
from pipeline.fit.intervals import birge_ratio
from pipeline.theory.tooth_segments import (
    CLAIMS,
    contact_force_ratio,
    contact_radius,
    friction_increase,
    opening_angle,
    side_force_ratio,
)
from pipeline.units import from_si

#: Level of the interval of the fitted parameter.
CONFIDENCE = 0.95
#: The measured ratios fitted, as columns (each with ``<ratio>_stderr``) [-].
RATIOS = ("F_K/F", "F_P/F")
#: The parameters that can be fitted.
VARY = ("s", "beta")
#: Paper 003's claimed friction increase 2 F_K / F - 1 (Fig. 9) [-].
FRICTION_CLAIM = CLAIMS["friction_increase"]
#: Relative margin kept from an open end of a parameter's range (s = 2 k) [-].
_OPEN_END = 1e-9
#: Step of the difference quotient of the residuals, as a share of the range [-].
_STEP = 1e-7


@dataclass(frozen=True)
class ContactRatios:
    """Paper 003's contact geometry and load ratios at one geometry.

    Attributes
    ----------
    s : float
        Distance between the contact points [m].
    beta : float
        Flank inclination [rad].
    k : float
        Contact radius [m] (eq. (1)).
    psi : float
        Segment opening angle [rad] (eq. (2)).
    contact_force : float
        F_K / F [-] (eq. (3)).
    side_force : float
        F_P / F [-] (eq. (4)).
    friction_increase : float
        2 F_K / F - 1 [-].
    """

    s: float
    beta: float
    k: float
    psi: float
    contact_force: float
    side_force: float
    friction_increase: float

    def ratio(self, name: str) -> float:
        """The ratio named as in :data:`RATIOS` [-]."""
        return self.contact_force if name == "F_K/F" else self.side_force


def contact_ratios(chain: Mapping[str, float], *, beta: float, s: float,
                   eps_n: float = 0.0) -> ContactRatios:
    """Contact radius, opening angle and load ratios of one geometry.

    Parameters
    ----------
    chain : mapping
        The chain's outer torus radius ``r_outer``, link thickness ``d`` and
        the drum's ``groove_width`` c [m].
    beta : float
        Flank inclination at the contact [rad].
    s : float
        Distance between the contact points [m].
    eps_n : float, optional
        Inclination of the link to the pocket floor [rad].

    Returns
    -------
    ContactRatios

    Raises
    ------
    FitError
        When s is below the groove width or not below 2 k: eq. (2) does not hold.

    References
    ----------
    Paper 003, eqs. (1)-(4).

    Examples
    --------
    Chain 34x126 at s = 45 mm, beta = 80 deg (Paper 003, Figs. 6-7, publishes
    psi = 128.7 deg and F_K / F = 0.555):

    >>> chain = {"r_outer": 52e-3, "d": 34e-3, "groove_width": 45e-3}
    >>> ratios = contact_ratios(chain, beta=math.radians(80), s=45e-3)
    >>> round(math.degrees(ratios.psi), 2), round(ratios.contact_force, 3)
    (128.45, 0.555)
    """
    k = float(contact_radius(chain["r_outer"], chain["d"], beta, eps_n))
    groove = chain["groove_width"]
    if not groove <= s < 2 * k:
        raise FitError(
            f"s = {from_si(s, 'mm'):.4g} mm lies outside c <= s < 2 k = "
            f"[{from_si(groove, 'mm'):.4g}, {from_si(2 * k, 'mm'):.4g}) mm at beta = "
            f"{math.degrees(beta):.4g} deg, eps_n = {math.degrees(eps_n):.4g} deg: the link "
            "cannot touch both segments (Paper 003, eq. (2))", column="s",
            hint="check s, beta, eps_n and the chain's r_outer, d and groove_width in the run "
                 "sheet")
    psi = float(opening_angle(s, k, groove))
    return ContactRatios(s=s, beta=beta, k=k, psi=psi,
                         contact_force=float(contact_force_ratio(psi)),
                         side_force=float(side_force_ratio(psi)),
                         friction_increase=float(friction_increase(psi)))


@dataclass(frozen=True)
class SegmentLoadFit:
    """Paper 003's contact geometry fitted to the measured load ratios of a run or campaign.

    Attributes
    ----------
    parameter : str
        ``"s"`` (contact distance) or ``"beta"`` (flank inclination).
    value, stderr : float
        Fitted value and its standard error [m for s, rad for beta].
    ci_low, ci_high : float
        Confidence interval at `confidence`, within `bounds` [as `value`].
    confidence : float
        Level of the interval (0.95).
    bounds : tuple of float
        Range the parameter was fitted in [as `value`].
    chi2_reduced : float
        Weighted chi-square per degree of freedom (NaN without one).
    dof : int
        Residual degrees of freedom (measured ratios minus 1).
    scaled : bool
        Whether the error was scaled by the Birge ratio (``chi2_reduced > 1``).
    fitted : ContactRatios
        The model at the fitted geometry.
    declared : ContactRatios
        The model at the run sheet's geometry.
    measured : dict of str to float
        Per ratio of :data:`RATIOS` measured, its weighted mean and
        ``<ratio>_stderr`` (Birge-scaled), and ``friction_increase``,
        ``friction_increase_stderr`` (2 F_K / F - 1) [-].
    points : pandas.DataFrame
        The measured rows with per ratio ``_model``, ``_residual``
        (measured - model) and ``_normalized`` (in standard errors) [-].
    result : lmfit.minimizer.MinimizerResult
        The lmfit result.
    """

    parameter: str
    value: float
    stderr: float
    ci_low: float
    ci_high: float
    confidence: float
    bounds: tuple[float, float]
    chi2_reduced: float
    dof: int
    scaled: bool
    fitted: ContactRatios
    declared: ContactRatios
    measured: dict[str, float]
    points: pd.DataFrame
    result: lmfit.minimizer.MinimizerResult = field(repr=False, compare=False)

    def covers(self, truth: float) -> bool:
        """Whether the confidence interval holds `truth` [as `value`]."""
        return self.ci_low <= truth <= self.ci_high

    def claim_note(self) -> str:
        """The measured friction increase against Paper 003's claim, in one sentence."""
        measured = self.measured["friction_increase"]
        error = self.measured["friction_increase_stderr"]
        verdict = ("above it" if measured - 2 * error > FRICTION_CLAIM else
                   "below it" if measured + 2 * error < FRICTION_CLAIM else
                   "not told apart from it")
        return (f"Friction increase 2 F_K/F - 1: measured {100 * measured:.1f} % "
                f"± {100 * error:.2g} %, the model {100 * self.fitted.friction_increase:.1f} % "
                f"at the fitted {self.parameter} and {100 * self.declared.friction_increase:.1f} "
                f"% at the run sheet's; Paper 003 claims over {100 * FRICTION_CLAIM:g} % (at "
                f"s = {from_si(CLAIMS['s'], 'mm'):g} mm, β = {math.degrees(CLAIMS['beta']):g}°):"
                f" the measured increase is {verdict} (two standard errors).")


def _measured(rows: pd.DataFrame) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Per ratio of :data:`RATIOS` present: the finite measured values and their errors."""
    if "F_K/F" not in rows:
        raise FitError("the measured rows have no column 'F_K/F'", column="F_K/F",
                       hint="give F_K/F and F_K/F_stderr (and F_P/F, F_P/F_stderr) per seating "
                            "or operating point")
    found = {}
    for name in RATIOS:
        if name not in rows:
            continue
        values = rows[name].to_numpy(dtype=float)
        keep = np.isfinite(values)
        if not keep.any():
            continue
        if f"{name}_stderr" not in rows:
            raise FitError(f"the measured {name} have no standard errors",
                           column=f"{name}_stderr", hint=f"give {name}_stderr per row")
        errors = rows[f"{name}_stderr"].to_numpy(dtype=float)[keep]
        if not np.all(np.isfinite(errors) & (errors > 0)):
            raise FitError(f"a measured {name} has no positive standard error",
                           column=f"{name}_stderr",
                           hint="give each measured ratio its standard error (a noiseless log "
                                "has none: fit the model to measured data)")
        found[name] = (values[keep], errors)
    if "F_K/F" not in found:
        raise FitError("no measured F_K/F to fit", column="F_K/F",
                       hint="give F_K/F for at least one seating or operating point")
    _check_physical(found)
    return found


def _check_physical(found: dict[str, tuple[np.ndarray, np.ndarray]]) -> None:
    """Refuse ratios no opening angle 0 < psi < pi gives: F_K / F < 0.5, F_P / F < 0."""
    for name, least in (("F_K/F", 0.5), ("F_P/F", 0.0)):
        values = found.get(name, (np.zeros(0),))[0]
        if np.any(values < least):
            raise FitError(
                f"measured {name} = {values.min():.4g} is below {least:g}, which no opening angle "
                f"gives (Paper 003, eq. ({3 if name == 'F_K/F' else 4}))", column=name,
                hint="check the segment channels' calibration and sign, and that F is the "
                     "chain force at the tooth")


def _weighted_mean(values: np.ndarray, errors: np.ndarray) -> tuple[float, float]:
    """Inverse-variance weighted mean and its standard error, Birge-scaled when above 1."""
    weights = errors**-2.0
    mean = float(np.sum(weights * values) / np.sum(weights))
    chi2 = float(np.sum(weights * (values - mean) ** 2))
    return mean, math.sqrt(1.0 / np.sum(weights)) * birge_ratio(chi2, values.size - 1)


def _beta_bounds(chain: Mapping[str, float], s: float, eps_n: float) -> tuple[float, float]:
    """Range of beta [rad]: 0 < beta <= pi/2 + eps_n, and s < 2 k (eq. (1)).

    s < 2 r holds: the run sheet's geometry was checked (:func:`contact_ratios`).
    """
    top = math.pi / 2 + eps_n

    def gap(beta: float) -> float:
        return 2 * float(contact_radius(chain["r_outer"], chain["d"], beta, eps_n)) - s

    low = brentq(gap, 0.0, top) if gap(0.0) <= 0 else 0.0
    return low + _OPEN_END * top, top


def _bounds(vary: str, chain: Mapping[str, float], beta: float, s: float,
            eps_n: float) -> tuple[float, float]:
    """Range the parameter is fitted in [m or rad]."""
    if vary == "beta":
        return _beta_bounds(chain, s, eps_n)
    k = float(contact_radius(chain["r_outer"], chain["d"], beta, eps_n))
    return chain["groove_width"], 2 * k * (1 - _OPEN_END)


def _shown(vary: str, value: float) -> str:
    """A value of the fitted parameter for a message: s in mm, beta in deg."""
    return f"{from_si(value, 'mm'):.4g} mm" if vary == "s" else f"{math.degrees(value):.4g} deg"


def _solve(model: Callable[[float], ContactRatios], name: str, mean: tuple[float, float],
           bounds: tuple[float, float], vary: str) -> float:
    """The parameter at which the model's `name` ratio is the measured mean, within `bounds`.

    `mean` is the measured weighted mean and its standard error [-].
    """
    target, error = mean
    ends = [model(end).ratio(name) for end in bounds]
    if not min(ends) <= target <= max(ends):
        beyond = min(abs(target - end) for end in ends) / error
        raise FitError(
            f"the measured {name} = {target:.4g} ± {error:.2g} lies outside what eqs. (1)-(4) "
            f"give for {vary} from {_shown(vary, bounds[0])} to {_shown(vary, bounds[1])} "
            f"({min(ends):.4g} to {max(ends):.4g}), by {beyond:.3g} standard errors: no geometry "
            "of the run sheet's chain gives it", column=name,
            hint="check the segment and chain-force channels' calibration, the fixed geometry "
                 "(r_outer, d, groove_width, beta or s, eps_n) and which parameter is fitted")
    return float(brentq(lambda x: model(x).ratio(name) - target, *bounds))


def fit_segment_load(measured: pd.DataFrame, chain: Mapping[str, float], *, beta: float,
                     s: float, eps_n: float = 0.0, vary: str = "s",
                     confidence: float = CONFIDENCE) -> SegmentLoadFit:
    """Fit the contact distance s (or the flank inclination beta) to measured load ratios.

    Parameters
    ----------
    measured : pandas.DataFrame
        One row per seating or per operating point: ``F_K/F`` [-] with
        ``F_K/F_stderr`` and optionally ``F_P/F`` with ``F_P/F_stderr`` (NaN
        where not measured); :attr:`SegmentLoadEvents.valid` or rows of
        :meth:`SegmentLoadEvents.point`
        (:mod:`pipeline.condition.segment_load`).
    chain : mapping
        The chain's ``r_outer``, ``d`` and the drum's ``groove_width`` [m].
    beta : float
        Flank inclination from the run sheet [rad]: fixed, or the declared
        value when ``vary="beta"``.
    s : float
        Contact distance from the run sheet [m]: fixed, or the declared value
        when ``vary="s"``.
    eps_n : float, optional
        Inclination of the link to the pocket floor [rad].
    vary : {"s", "beta"}, optional
        The fitted parameter.
    confidence : float, optional
        Level of the confidence interval [-] (default :data:`CONFIDENCE`).

    Returns
    -------
    SegmentLoadFit

    Raises
    ------
    FitError
        On a missing column, a measured ratio without a positive standard
        error, a run-sheet geometry outside c <= s < 2 k, a measured ratio no
        geometry in the parameter's range gives (F_K / F below 0.5 among
        them), or a failed fit.

    References
    ----------
    Paper 003, eqs. (1)-(4).
    """
    if vary not in VARY:
        raise ValueError(f"vary must be 's' or 'beta', got {vary!r}")
    declared = contact_ratios(chain, beta=beta, s=s, eps_n=eps_n)
    found = _measured(measured)
    bounds = _bounds(vary, chain, beta, s, eps_n)

    def model(value: float) -> ContactRatios:
        geometry = {"beta": beta, "s": s, vary: value}
        return contact_ratios(chain, eps_n=eps_n, **geometry)

    means = {name: _weighted_mean(*pair) for name, pair in found.items()}
    # every ratio's mean must be reachable; the fit starts where F_K / F's is
    starts = {name: _solve(model, name, mean, bounds, vary) for name, mean in means.items()}

    def residual(value: float) -> np.ndarray:
        trial = model(value)
        return np.concatenate([(values - trial.ratio(name)) / errors
                               for name, (values, errors) in found.items()])

    params = lmfit.Parameters()
    params.add(vary, value=starts["F_K/F"], min=bounds[0], max=bounds[1])
    result = lmfit.minimize(lambda p: residual(p[vary].value), params, method="leastsq",
                            scale_covar=False)
    if not result.success:
        raise FitError(f"the contact geometry could not be fitted: {result.message}",
                       hint="check the measured ratios and their standard errors")
    value = float(result.params[vary].value)
    fitted = model(value)
    return SegmentLoadFit(
        parameter=vary, value=value, confidence=confidence, bounds=bounds, fitted=fitted,
        declared=declared, measured=_measured_summary(means),
        points=_points(measured, found, fitted), result=result,
        **_interval(residual, value, bounds, confidence))


def _interval(residual: Callable[[float], np.ndarray], value: float,
              bounds: tuple[float, float], confidence: float) -> dict[str, float | int | bool]:
    """Standard error, interval and goodness of fit of a one-parameter weighted fit.

    Parameters
    ----------
    residual : callable
        The normalized residuals (measured - model) / stderr at a parameter value.
    value : float
        The fitted value [m or rad].
    bounds : tuple of float
        The parameter's range [as `value`]: the difference quotient points into it.
    confidence : float
        Level of the interval [-].

    Returns
    -------
    dict
        ``stderr``, ``ci_low``, ``ci_high``, ``chi2_reduced``, ``dof``, ``scaled``
        (see :class:`SegmentLoadFit`).
    """
    step = _STEP * (bounds[1] - bounds[0])
    other = value + step if value + step <= bounds[1] else value - step
    at = residual(value)
    slope = (residual(other) - at) / (other - value)
    chi2, dof = float(np.sum(at**2)), at.size - 1
    stderr = birge_ratio(chi2, dof) / math.sqrt(float(np.sum(slope**2)))
    quantile = float(stats.t.ppf((1 + confidence) / 2, dof) if dof > 0
                     else stats.norm.ppf((1 + confidence) / 2))
    return {"stderr": stderr, "ci_low": max(value - quantile * stderr, bounds[0]),
            "ci_high": min(value + quantile * stderr, bounds[1]),
            "chi2_reduced": chi2 / dof if dof > 0 else math.nan, "dof": dof,
            "scaled": birge_ratio(chi2, dof) > 1}


def _measured_summary(means: dict[str, tuple[float, float]]) -> dict[str, float]:
    """The weighted means of the measured ratios, and the friction increase 2 F_K / F - 1."""
    summary = {}
    for name, (mean, error) in means.items():
        summary.update({name: mean, f"{name}_stderr": error})
    summary["friction_increase"] = 2 * summary["F_K/F"] - 1
    summary["friction_increase_stderr"] = 2 * summary["F_K/F_stderr"]
    return summary


def _points(measured: pd.DataFrame, found: dict, fitted: ContactRatios) -> pd.DataFrame:
    """The measured rows with the model, residual and normalized residual per ratio."""
    frame = measured.copy()
    for name in found:
        model = fitted.ratio(name)
        values = frame[name].to_numpy(dtype=float)
        frame[f"{name}_model"] = model
        frame[f"{name}_residual"] = values - model
        frame[f"{name}_normalized"] = (values - model) / frame[f"{name}_stderr"]
    return frame
