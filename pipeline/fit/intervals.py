"""Uncertainty rules the weighted fits share: the Birge ratio, scaled errors, a straight line.

A weighted least-squares fit states the errors of its points. When the points
scatter more about the model than those errors say (reduced chi-square above
1), the parameter's standard error is scaled by the Birge ratio
``sqrt(chi2 / dof)``; it is never shrunk below what the stated errors give.
The interval is ``value +- q stderr`` with ``q`` the normal quantile, or
Student's t with the residual degrees of freedom when the errors were scaled
(the scatter, not the stated errors, then sets the width).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import stats


def birge_ratio(chi2: float, dof: int) -> float:
    """``sqrt(chi2 / dof)`` when above 1, else 1 (also with no degree of freedom).

    Examples
    --------
    >>> birge_ratio(8.0, 2), birge_ratio(1.0, 2), birge_ratio(3.0, 0)
    (2.0, 1.0, 1.0)
    """
    return math.sqrt(chi2 / dof) if dof > 0 and chi2 > dof else 1.0


@dataclass(frozen=True)
class ScaledError:
    """A fitted parameter's standard error after the Birge rule, and its interval's quantile."""

    stderr: float  #: [unit of the parameter]
    quantile: float  #: q of ``value +- q stderr`` [-]
    chi2_reduced: float  #: chi2 / dof (NaN with no degree of freedom) [-]
    scaled: bool  #: whether the error was scaled by the Birge ratio


def scaled_error(stderr: float, chi2: float, dof: int, confidence: float) -> ScaledError:
    """The standard error of a weighted fit, scaled by the Birge ratio when ``chi2 > dof``.

    Parameters
    ----------
    stderr : float
        The standard error from the stated errors alone (unscaled covariance).
    chi2 : float
        Sum of the squared normalized residuals [-].
    dof : int
        Residual degrees of freedom.
    confidence : float
        Level of the interval [-], e.g. 0.95.

    Returns
    -------
    ScaledError
        With the normal quantile, or Student's t on `dof` when scaled.

    Examples
    --------
    >>> error = scaled_error(0.5, chi2=8.0, dof=2, confidence=0.95)
    >>> error.stderr, error.scaled, round(error.quantile, 3)
    (1.0, True, 4.303)
    """
    chi2_reduced = float(chi2 / dof) if dof > 0 else math.nan
    scaled = dof > 0 and chi2_reduced > 1
    level = (1 + confidence) / 2
    quantile = stats.t.ppf(level, dof) if scaled else stats.norm.ppf(level)
    return ScaledError(stderr * birge_ratio(chi2, dof), float(quantile), chi2_reduced, scaled)


def straight_line(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float]:
    """Least-squares slope, intercept and R^2 of `y` against `x` (two distinct x or more).

    R^2 is NaN when `y` does not vary.

    Examples
    --------
    >>> slope, intercept, r2 = straight_line(np.array([1.0, 2.0, 3.0]), np.array([3.0, 5.0, 7.0]))
    >>> round(slope, 12), round(intercept, 12), r2
    (2.0, 1.0, 1.0)
    """
    slope, intercept = np.polyfit(x, y, 1)
    total = np.sum((y - y.mean()) ** 2)
    fitted = slope * x + intercept
    r2 = 1 - np.sum((y - fitted) ** 2) / total if total > 0 else math.nan
    return float(slope), float(intercept), float(r2)
