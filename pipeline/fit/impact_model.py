"""Paper 000's impact model fitted to the measured impact tensions of a campaign.

Across the operating points of a campaign (wheels, speeds, chains, branches),
the measured strike amplitudes ``N_u1``, ``N_u2`` (:mod:`pipeline.fit.impact`)
are compared with eq. (16) with (1)-(2)::

    N_ui = v_ui sqrt(k m t (s E0) / L),
    v_u1 = omega (t - d) sin(psi / 2),  v_u2 = omega (t + d) sin(pi / z + psi / 2)

(computed by :func:`pipeline.theory.wheel_impact.impact_velocities` and
:func:`~pipeline.theory.wheel_impact.impact_tension`). One parameter is fitted
with lmfit, weighting every point by the standard error of its median:

``vary="k"``
    the mass share k (Ryabov: 2), the stiffness scale ``s`` fixed at 1;
``vary="stiffness"``
    an effective stiffness per branch length ``s E0 / L`` through the scale
    ``s``, k fixed (default 2).

k and s enter only as the product ``k s``: they cannot be fitted together.

Uncertainty
-----------
The standard error comes from the weighted least-squares covariance, scaled by
the Birge ratio ``sqrt(chi2_red)`` when the points scatter more than their
standard errors say (``chi2_red > 1``; never shrunk below the stated errors).
The confidence interval is ``value +- q stderr`` with ``q`` the normal quantile,
or Student's t with the residual degrees of freedom when the errors were scaled
(:mod:`pipeline.fit.intervals`, shared with the other weighted fits).

Checks reported beside the fit: the residual of every point (absolute,
relative, and in standard errors), and per wheel and impact the linearity of
N_u in omega (eq. (16) is proportional to omega): slope, intercept and R^2 of
a straight-line fit, next to the model's slope.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import lmfit
import numpy as np
import pandas as pd

from pipeline.errors import FitError
from pipeline.fit.intervals import scaled_error, straight_line
from pipeline.statistics import median_stderr
from pipeline.theory.wheel_impact import RYABOV_MASS_SHARE, impact_tension, impact_velocities

#: Columns of an operating point [SI units]: teeth z [-], apex angle psi [rad],
#: omega [1/s], pitch t and bar diameter d [m], mass per length [kg/m], E0 [N],
#: branch length L [m].
POINT_COLUMNS = ("teeth", "apex_angle", "omega", "t", "d", "mass_per_length", "E0",
                 "branch_length")
#: Columns identifying a wheel for the linearity check.
_WHEEL_COLUMNS = ("teeth", "apex_angle", "t", "d", "mass_per_length", "E0", "branch_length")
#: Level of the interval of the fitted parameter.
CONFIDENCE = 0.95
#: Speeds a wheel needs for its line of N_u in omega to be checked (R^2 needs three).
LINE_SPEEDS = 3
#: How :func:`fit_impact_model` fits, in words (for the outputs' provenance).
FIT_METHOD = ("k of Paper 000 eq. (16) by weighted least squares (lmfit) over every operating "
              "point, each weighted by the standard error of its run median; the error scaled "
              "by the Birge ratio when the points scatter more than their errors")


@dataclass(frozen=True)
class ImpactModelFit:
    """The impact model fitted to a campaign's operating points.

    Attributes
    ----------
    parameter : str
        ``"k"`` (mass share) or ``"stiffness_scale"`` (s in ``s E0 / L``).
    value, stderr : float
        Fitted value and its standard error [-].
    ci_low, ci_high : float
        Confidence interval at `confidence` [-].
    confidence : float
        Level of the interval (0.95).
    k : float
        The mass share used: fitted, or fixed when the stiffness is fitted [-].
    stiffness_scale : float
        The stiffness scale used: fitted, or 1 [-].
    chi2_reduced : float
        Weighted chi-square per degree of freedom.
    dof : int
        Residual degrees of freedom (measured values minus 1).
    scaled : bool
        Whether the error was scaled by the Birge ratio (``chi2_reduced > 1``).
    points : pandas.DataFrame
        The input points with ``N_u1_model``, ``N_u2_model`` [N] and per impact
        ``_residual`` (measured - model) [N], ``_relative`` [-] and
        ``_normalized`` (in standard errors) [-].
    linearity : pandas.DataFrame
        Per wheel and impact (see :func:`linearity`).
    result : lmfit.minimizer.MinimizerResult
        The lmfit result.
    """

    parameter: str
    value: float
    stderr: float
    ci_low: float
    ci_high: float
    confidence: float
    k: float
    stiffness_scale: float
    chi2_reduced: float
    dof: int
    scaled: bool
    points: pd.DataFrame
    linearity: pd.DataFrame
    result: lmfit.minimizer.MinimizerResult = field(repr=False, compare=False)

    def covers(self, truth: float) -> bool:
        """Whether the confidence interval holds `truth`."""
        return self.ci_low <= truth <= self.ci_high


def _column(points: pd.DataFrame, name: str) -> np.ndarray:
    if name not in points:
        raise FitError(f"the operating points have no column {name!r}", column=name,
                       hint=f"give {', '.join(POINT_COLUMNS)}, N_u1_meas, N_u2_meas and their "
                            "standard errors (N_u1_stderr, or N_u1_mad and N_u1_count)")
    return points[name].to_numpy(dtype=float)


def _standard_errors(points: pd.DataFrame, impact: str) -> np.ndarray:
    """Standard error of the median of `impact` per point [N]: given, or from MAD and count."""
    if f"{impact}_stderr" in points:
        return _column(points, f"{impact}_stderr")
    mad, count = _column(points, f"{impact}_mad"), _column(points, f"{impact}_count")
    with np.errstate(divide="ignore", invalid="ignore"):
        return median_stderr(mad, count)


def model_tensions(points: pd.DataFrame, k: float = RYABOV_MASS_SHARE,
                   stiffness_scale: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """N_u1, N_u2 [N] of Paper 000, eq. (16) with (1)-(2), at every operating point.

    Parameters
    ----------
    points : pandas.DataFrame
        Operating points with the columns of :data:`POINT_COLUMNS`.
    k : float, optional
        Share of link masses in the impact [-] (default 2, Ryabov).
    stiffness_scale : float, optional
        Factor s on E0 / L [-] (default 1).

    References
    ----------
    Paper 000, eqs. (1)-(2), (16).

    Examples
    --------
    Paper 000's example (z = 8, psi = 40 deg, omega = 20 1/s, k = 2):

    >>> point = pd.DataFrame({"teeth": [8], "apex_angle": [np.radians(40)], "omega": [20.0],
    ...                       "t": [0.064], "d": [0.018], "mass_per_length": [6.6],
    ...                       "E0": [2.26e7], "branch_length": [2.0]})
    >>> [round(float(n[0])) for n in model_tensions(point)]
    [972, 3423]
    """
    z, psi, omega, t, d, mass, e0, length = (_column(points, name) for name in POINT_COLUMNS)
    v_u1, v_u2 = impact_velocities(t, d, z, psi, omega)
    return tuple(np.atleast_1d(impact_tension(v, mass, t, stiffness_scale * e0, length, k))
                 for v in (v_u1, v_u2))


def linearity(points: pd.DataFrame, model: tuple[np.ndarray, np.ndarray] | None = None
              ) -> pd.DataFrame:
    """Straight-line fit of the measured N_u against omega, per wheel and impact.

    Parameters
    ----------
    points : pandas.DataFrame
        Operating points (:data:`POINT_COLUMNS`, ``N_u1_meas``, ``N_u2_meas``).
    model : tuple of numpy.ndarray, optional
        Model N_u1, N_u2 per point [N], for the model's slope N_u / omega.

    Returns
    -------
    pandas.DataFrame
        One row per wheel (the :data:`POINT_COLUMNS` but omega) and impact:
        ``impact`` (1 or 2), ``n_speeds``, ``slope`` [N s], ``intercept`` [N],
        ``r2`` [-] (NaN below 3 speeds), ``model_slope`` [N s] and ``largest``
        [N] (the largest measured N_u of the line). Eq. (16) is proportional to
        omega: R^2 near 1 and an intercept near 0 support it.
    """
    rows = []
    frame = points.reset_index(drop=True)
    for key, group in frame.groupby(list(_WHEEL_COLUMNS), sort=True):
        omega = group["omega"].to_numpy(dtype=float)
        for impact in (1, 2):
            measured = group[f"N_u{impact}_meas"].to_numpy(dtype=float)
            keep = np.isfinite(measured)
            x, y = omega[keep], measured[keep]
            slope = intercept = r2 = math.nan
            if np.unique(x).size >= 2:
                slope, intercept, line_r2 = straight_line(x, y)
                r2 = line_r2 if x.size >= 3 else math.nan
            model_slope = (float(np.mean(model[impact - 1][group.index] / omega))
                           if model is not None else math.nan)
            rows.append(dict(zip(_WHEEL_COLUMNS, key, strict=True), impact=impact,
                             n_speeds=int(np.unique(x).size), slope=float(slope),
                             intercept=float(intercept), r2=float(r2), model_slope=model_slope,
                             largest=float(np.max(np.abs(y))) if y.size else math.nan))
    return pd.DataFrame(rows)


def linearity_note(lines: pd.DataFrame) -> str:
    """How straight the measured N_u are in omega, in one sentence (eq. (16): N_u ∝ omega).

    Parameters
    ----------
    lines : pandas.DataFrame
        The lines of :func:`linearity`: ``n_speeds``, ``r2`` [1], ``intercept``
        and ``largest`` [N]; lines of fewer than :data:`LINE_SPEEDS` speeds are
        not judged.

    Returns
    -------
    str
        The smallest R^2 and the largest intercept, as a share of the largest
        N_u of its line, over the lines judged; or that none could be.

    Examples
    --------
    >>> lines = pd.DataFrame({"n_speeds": [3, 3, 2], "r2": [0.99991, 0.9995, 0.5],
    ...                       "intercept": [2.0, -30.0, 500.0],
    ...                       "largest": [1000.0, 3000.0, 900.0]})
    >>> print(linearity_note(lines))  # doctest: +NORMALIZE_WHITESPACE
    Eq. (16) makes N_u proportional to ω. Straight lines through each wheel's measured medians
    (2 lines: wheels × impacts) give R² ≥ 0.9995, and their intercepts are at most 1.0 % of
    N_u at the highest speed (proportional: R² = 1, intercept 0).
    """
    judged = lines[lines["n_speeds"] >= LINE_SPEEDS] if len(lines) else lines
    if judged.empty:
        return ("Linearity in ω not checked: no wheel was run at three or more speeds "
                "(eq. (16) makes N_u proportional to ω).")
    share = np.nanmax(np.abs(judged["intercept"] / judged["largest"]))
    return (f"Eq. (16) makes N_u proportional to ω. Straight lines through each wheel's measured "
            f"medians ({len(judged)} lines: wheels × impacts) give R² ≥ "
            f"{np.nanmin(judged['r2']):.4f}, and their intercepts are at most "
            f"{100 * share:.1f} % of N_u at the highest speed (proportional: R² = 1, "
            "intercept 0).")


def fit_impact_model(points: pd.DataFrame, *, vary: str = "k", k: float = RYABOV_MASS_SHARE,
                     confidence: float = CONFIDENCE) -> ImpactModelFit:
    """Fit the mass share k (or an effective E0 / L) of Paper 000's model to measured N_u.

    Parameters
    ----------
    points : pandas.DataFrame
        One row per operating point: :data:`POINT_COLUMNS` (SI units),
        ``N_u1_meas``, ``N_u2_meas`` [N] (run medians; NaN where not measured)
        and their standard errors ``N_u1_stderr``, ``N_u2_stderr`` [N], or
        ``N_u1_mad``, ``N_u1_count``, ``N_u2_mad``, ``N_u2_count``.
    vary : {"k", "stiffness"}, optional
        The fitted parameter: the mass share k, or the scale s of E0 / L.
    k : float, optional
        The mass share when ``vary="stiffness"`` (default 2, Ryabov).
    confidence : float, optional
        Level of the confidence interval [1] (default :data:`CONFIDENCE`).

    Returns
    -------
    ImpactModelFit

    Raises
    ------
    FitError
        On a missing column, a measured value without a positive standard
        error, no measured value, or a failed fit.

    References
    ----------
    Paper 000, eq. (16) with eqs. (1)-(2); k = 2 after Ryabov (its ref. [1]).
    """
    if vary not in ("k", "stiffness"):
        raise ValueError(f"vary must be 'k' or 'stiffness', got {vary!r}")
    measured = np.concatenate([_column(points, "N_u1_meas"), _column(points, "N_u2_meas")])
    errors = np.concatenate([_standard_errors(points, "N_u1"), _standard_errors(points, "N_u2")])
    keep = np.isfinite(measured)
    if not keep.any():
        raise FitError("no measured impact tension to fit", column="N_u1_meas",
                       hint="give N_u1_meas or N_u2_meas for at least one operating point")
    if not np.all(np.isfinite(errors[keep]) & (errors[keep] > 0)):
        raise FitError("a measured impact tension has no positive standard error",
                       column="N_u1_stderr",
                       hint="give each measured N_u its standard error (or MAD and count)")
    name = "k" if vary == "k" else "stiffness_scale"
    params = lmfit.Parameters()
    params.add(name, value=RYABOV_MASS_SHARE if vary == "k" else 1.0, min=1e-9)

    def residual(p: lmfit.Parameters) -> np.ndarray:
        trial = (p[name].value, 1.0) if vary == "k" else (k, p[name].value)
        return ((measured - np.concatenate(model_tensions(points, *trial))) / errors)[keep]

    result = lmfit.minimize(residual, params, method="leastsq", scale_covar=False)
    if not result.success or result.params[name].stderr is None:
        raise FitError(f"the impact model could not be fitted: {result.message}",
                       hint="check the operating points and their standard errors")
    value = float(result.params[name].value)
    dof = int(keep.sum()) - 1
    error = scaled_error(float(result.params[name].stderr), result.chisqr, dof, confidence)
    fitted_k, scale = (value, 1.0) if vary == "k" else (k, value)

    model1, model2 = model_tensions(points, fitted_k, scale)
    frame = points.copy()
    frame["N_u1_model"], frame["N_u2_model"] = model1, model2
    for impact, model in ((1, model1), (2, model2)):
        meas = frame[f"N_u{impact}_meas"].to_numpy(dtype=float)
        frame[f"N_u{impact}_residual"] = meas - model
        frame[f"N_u{impact}_relative"] = meas / model - 1
        frame[f"N_u{impact}_normalized"] = (meas - model) / _standard_errors(points,
                                                                              f"N_u{impact}")
    return ImpactModelFit(
        parameter=name, value=value, stderr=error.stderr,
        ci_low=value - error.quantile * error.stderr,
        ci_high=value + error.quantile * error.stderr, confidence=confidence, k=fitted_k,
        stiffness_scale=scale, chi2_reduced=error.chi2_reduced, dof=dof, scaled=error.scaled,
        points=frame, linearity=linearity(frame, (model1, model2)), result=result)
