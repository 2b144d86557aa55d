"""Roller-chain engagement runs: the impact-velocity coefficient xi fitted to strike amplitudes.

A roller chain runs on a sprocket of ``z`` teeth at angular velocity ``omega``;
every tooth pitch ``2 pi / (z omega)`` a roller strikes the sprocket at the
normal velocity of Paper 002, eqs. (2), (5)::

    V_y = omega t xi,    xi = sin(Theta)    (Theta of eq. (3) on an involute tooth)

The strike amplitude law (the project's model, not Paper 002's)
-----------------------------------------------------------------
Paper 002 stops at the impact energy of one link (eq. (6)); it says nothing of
the tension the strike rings into the branch. Paper 000 does, for round-link
chains: the energy balance of the striking link mass and the elastic branch,
eq. (16), gives the amplitude::

    N = V_y sqrt(k q t E0 / L)

(:func:`pipeline.theory.wheel_impact.impact_tension`: q the mass per metre, t
the pitch, E0 the chain stiffness, L the branch length, k the share of link
masses in the impact). chainbench bridges the two papers by giving that law
Paper 002's roller impact velocity, :func:`strike_amplitude`::

    N = omega t xi sqrt(k q t E0 / L)

This is chainbench's model of a roller-chain engagement run, an assumption
that the runs themselves test (the amplitude must be proportional to omega:
see the linearity reported beside the fit); neither paper states it. With
everything but xi known, the measured amplitudes at several speeds give xi.

The fit
-------
:func:`fit_roller_engagement` fits xi, one parameter, by weighted least
squares (lmfit), every point weighted by the standard error of its run median,
with the uncertainty policy of :mod:`pipeline.fit.impact_model`: the standard
error is scaled by the Birge ratio ``sqrt(chi2_red)`` when the points scatter
more than their errors say, and the interval then uses Student's t with the
residual degrees of freedom (the normal quantile otherwise). Beside it: xi of
the sprocket's involute (Paper 002, eqs. (3)-(5)), its bounds ``[sin(pi/z),
cos(pi/z)]``, the straight line of the amplitudes in omega, and per point the
impact energy (eq. (6)) and specific energy (eq. (7)) with the fitted xi and
the speed against n_max of eq. (8).

From an engagement log to a point
---------------------------------
The engagement pipeline (:mod:`pipeline.engagement_log`) looks for two strikes
per seating, half a seating period apart, and needs both to be positive. A
roller log has one strike per tooth pitch: read with
``z = engagement_teeth(teeth)`` (half the teeth), two successive strikes make one
seating, both slots (``N_u1``, ``N_u2``) measure the same roller strike, and
:func:`strike_statistics` pools them into the run's point.

References
----------
Paper 002, eqs. (2)-(8); Paper 000, eq. (16).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import lmfit
import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pipeline.errors import FitError
from pipeline.fit.impact import ImpactResult
from pipeline.fit.impact_model import CONFIDENCE, LINE_SPEEDS
from pipeline.fit.intervals import scaled_error, straight_line
from pipeline.statistics import MedianStatistics
from pipeline.theory.roller_impact import (
    G_LIM,
    base_radius,
    impact_energy,
    impact_velocity,
    impact_velocity_coefficient,
    impact_velocity_coefficient_bounds,
    max_angular_velocity,
    specific_impact_energy,
)
from pipeline.theory.wheel_impact import impact_tension
from pipeline.units import from_si

#: Fewest distinct speeds a fit of xi needs.
MIN_SPEEDS = 2


@dataclass(frozen=True)
class RollerBranch:
    """The roller chain of the active branch, and the branch (SI units).

    Parameters
    ----------
    pitch : float
        Chain pitch t [m].
    mass_per_length : float
        Chain mass per metre q [kg/m].
    E0 : float
        Chain stiffness (force over relative elongation) [N].
    branch_length : float
        Length L of the active branch [m].
    k : float
        Share of link masses in the impact [-] (Paper 000's Ryabov value is 2).
    roller_diameter : float
        Roller diameter D [m] (Paper 002, eq. (7)).
    roller_length : float
        Roller length [m]; Paper 002's eq. (8) uses the inner width B.
    """

    pitch: float
    mass_per_length: float
    E0: float
    branch_length: float
    k: float
    roller_diameter: float
    roller_length: float

    def __post_init__(self) -> None:
        for name, value in vars(self).items():
            if not (isinstance(value, int | float) and math.isfinite(value) and value > 0):
                raise ValueError(f"{name} must be a finite number > 0, got {value!r}")


@dataclass(frozen=True)
class Sprocket:
    """A sprocket: its teeth and, for an involute tooth, the tool that cut it.

    Parameters
    ----------
    teeth : int
        Number of teeth z [-], at least 4.
    module : float, optional
        Module m of the cutting tool [m] (with `profile_angle`).
    profile_angle : float, optional
        Profile angle alpha of the cutting tool [rad] (with `module`).
    base_radius : float, optional
        Base-circle radius r_b of the involute [m], instead of `module` and
        `profile_angle`. Without either, the profile is not an involute the
        model knows (e.g. GOST 591 / 592) and xi is only measured.
    """

    teeth: int
    module: float | None = None
    profile_angle: float | None = None
    base_radius: float | None = None

    def __post_init__(self) -> None:
        if (self.module is None) != (self.profile_angle is None):
            raise ValueError("give module and profile_angle together")
        if self.module is not None and self.base_radius is not None:
            raise ValueError("give module and profile_angle, or base_radius, not both")
        impact_velocity_coefficient_bounds(self.teeth)  # a whole number >= 4

    def involute_xi(self, pitch: float) -> tuple[float, str]:
        """xi of the involute tooth for chain pitch `pitch` [m], or NaN and why not.

        Parameters
        ----------
        pitch : float
            Current chain pitch t_K [m].

        Returns
        -------
        xi : float
            sin(Theta) of Paper 002, eqs. (3)-(5) [-], r_b from eq. (4) when the
            module is given; NaN when the geometry does not determine it.
        reason : str
            Empty, or why xi is NaN.
        """
        r_b = (base_radius(self.module, self.teeth, self.profile_angle)
               if self.module is not None else self.base_radius)
        if r_b is None:
            return math.nan, ("no involute geometry given (module and profile angle, or base "
                              "radius): Paper 002 gives no xi for other profiles")
        try:
            return impact_velocity_coefficient(self.teeth, r_b, pitch), ""
        except ValueError as error:
            return math.nan, f"the involute does not engage this chain: {error}"


def strike_amplitude(omega: ArrayLike, xi: ArrayLike, branch: RollerBranch
                     ) -> float | np.ndarray:
    """Branch-tension amplitude of a roller strike (chainbench's model, see the module notes).

    Parameters
    ----------
    omega : float or array_like
        Sprocket angular velocity [rad/s].
    xi : float or array_like
        Impact-velocity coefficient [-].
    branch : RollerBranch
        Chain and branch (pitch, q, E0, L, k).

    Returns
    -------
    float or numpy.ndarray
        N = V_y sqrt(k q t E0 / L) [N] with V_y = omega t xi.

    References
    ----------
    Paper 002, eqs. (2), (5) (V_y); Paper 000, eq. (16) (N for an impact at V_y).

    Examples
    --------
    >>> branch = RollerBranch(0.0254, 2.7, 1e7, 1.0, 2.0, 0.01588, 0.01702)
    >>> round(strike_amplitude(10.0, 0.5, branch), 1)
    148.7
    """
    velocity = impact_velocity(omega, branch.pitch, xi)
    return impact_tension(velocity, branch.mass_per_length, branch.pitch, branch.E0,
                          branch.branch_length, branch.k)


def engagement_teeth(teeth: int) -> int:
    """Teeth to give :mod:`pipeline.engagement_log` for a log of a sprocket of `teeth` teeth.

    The engagement pipeline expects two positive strikes per seating, half a
    seating apart; a roller strikes once per tooth. Read as a wheel of half the
    teeth at the same speed, two successive roller strikes are one seating,
    and the wheel angle still gives the seatings.

    Parameters
    ----------
    teeth : int
        Number of sprocket teeth z [-].

    Returns
    -------
    int
        z / 2 [-].

    Raises
    ------
    FitError
        When `teeth` is odd or below 6 (the pipeline's wheel needs 3 teeth).

    Examples
    --------
    >>> engagement_teeth(18)
    9
    """
    if teeth % 2 or teeth < 6:
        raise FitError(f"a sprocket of {teeth} teeth cannot be read by the engagement pipeline",
                       hint="the pipeline pairs two successive roller strikes into one seating: "
                            "it needs an even number of teeth, at least 6")
    return teeth // 2


def strike_statistics(impacts: ImpactResult) -> MedianStatistics:
    """The run's roller-strike amplitude: both strikes of every valid seating pooled.

    Parameters
    ----------
    impacts : ImpactResult
        The extraction of a roller log read with :func:`engagement_teeth`: its
        ``N_u1`` and ``N_u2`` are the amplitudes of two successive strikes [N].

    Returns
    -------
    MedianStatistics
        Median, spread and standard error [N] of the pooled amplitudes; the
        part of the error due to the run's ringing fit is the mean of the two
        slots' (they share the ringing).
    """
    valid = impacts.events[impacts.events["status"] == "ok"]
    pooled = np.concatenate([valid["N_u1"].to_numpy(), valid["N_u2"].to_numpy()])
    ringing = 0.5 * (impacts.N_u1.stderr_ringing + impacts.N_u2.stderr_ringing)
    return MedianStatistics.of(pooled, ringing)


@dataclass(frozen=True)
class RollerEngagementFit:
    """xi fitted to the strike amplitudes of one sprocket's runs, with Paper 002's checks.

    Attributes
    ----------
    xi, stderr : float
        Fitted impact-velocity coefficient and its standard error [-].
    ci_low, ci_high : float
        Confidence interval of xi at `confidence` [-].
    confidence : float
        Level of the interval [-].
    chi2_reduced : float
        Weighted chi-square per degree of freedom [-].
    dof : int
        Residual degrees of freedom (points minus 1).
    scaled : bool
        Whether the error was scaled by the Birge ratio (``chi2_reduced > 1``).
    xi_model : float
        xi of the sprocket's involute, Paper 002 eqs. (3)-(5) [-]; NaN when the
        geometry does not determine it.
    xi_model_reason : str
        Why `xi_model` is NaN (empty otherwise).
    xi_bounds : tuple of float
        ``(sin(pi/z), cos(pi/z))`` [-] (Paper 002, eq. (3)).
    within_bounds, interval_within_bounds : bool
        Whether xi, and its whole interval, lie within `xi_bounds`.
    slope, intercept : float
        Straight line of the measured amplitudes in omega: [N s], [N].
    r2 : float
        Its R^2 [-]; NaN below :data:`~pipeline.fit.impact_model.LINE_SPEEDS` speeds.
    model_slope : float
        The model's amplitude over omega with the fitted xi [N s]: a
        proportional law has ``slope == model_slope`` and ``intercept == 0``.
    g_lim : float
        Limit of the specific impact energy [J/m^2].
    n_max_rpm : float
        Speed limit of Paper 002, eq. (8), with the fitted xi [rpm].
    points : pandas.DataFrame
        Per point: ``omega`` [rad/s], ``n_rpm``, ``amplitude``, ``stderr``,
        ``model``, ``residual`` [N], ``normalized`` (residual in standard errors),
        ``impact_velocity`` [m/s] (eqs. (2), (5)), ``energy`` [J] (eq. (6)),
        ``specific_energy`` [J/m^2] (eq. (7)), ``above_n_max`` (n > n_max, eq. (8)),
        all with the fitted xi.
    result : lmfit.minimizer.MinimizerResult
        The lmfit result.
    """

    xi: float
    stderr: float
    ci_low: float
    ci_high: float
    confidence: float
    chi2_reduced: float
    dof: int
    scaled: bool
    xi_model: float
    xi_model_reason: str
    xi_bounds: tuple[float, float]
    within_bounds: bool
    interval_within_bounds: bool
    slope: float
    intercept: float
    r2: float
    model_slope: float
    g_lim: float
    n_max_rpm: float
    points: pd.DataFrame
    result: lmfit.minimizer.MinimizerResult = field(repr=False, compare=False)

    def covers(self, truth: float) -> bool:
        """Whether the confidence interval holds `truth` [-]."""
        return self.ci_low <= truth <= self.ci_high


def _measurements(omega: ArrayLike, amplitude: ArrayLike, stderr: ArrayLike
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The points as float arrays [rad/s, N, N], refused with a hint when unfit to fit."""
    arrays = [np.atleast_1d(np.asarray(values, dtype=float))
              for values in (omega, amplitude, stderr)]
    if len({values.shape for values in arrays}) != 1 or arrays[0].ndim != 1:
        raise FitError("omega, amplitude and stderr must be 1-D and of one length",
                       hint="give one speed, median amplitude and standard error per point")
    for name, values in zip(("omega", "amplitude", "stderr"), arrays, strict=True):
        if not np.all(np.isfinite(values) & (values > 0)):
            raise FitError(f"every {name} must be a finite number > 0", column=name,
                           hint="drop the runs without a measured amplitude; speeds in rad/s, "
                                "amplitudes and their standard errors in N")
    if np.unique(arrays[0]).size < MIN_SPEEDS:
        raise FitError(f"xi needs runs at {MIN_SPEEDS} speeds or more, got "
                       f"{np.unique(arrays[0]).size}", column="omega",
                       hint="run the sprocket at two or more speeds (three check the linearity)")
    return arrays[0], arrays[1], arrays[2]


def _points(omega: np.ndarray, amplitude: np.ndarray, stderr: np.ndarray, xi: float,
            branch: RollerBranch, n_max_rpm: float) -> pd.DataFrame:
    """The per-point table of :class:`RollerEngagementFit` for the fitted `xi` [-]."""
    model = strike_amplitude(omega, xi, branch)
    energy = impact_energy(branch.mass_per_length, omega, branch.pitch, xi)
    n_rpm = from_si(omega, "rpm")
    return pd.DataFrame({
        "omega": omega, "n_rpm": n_rpm, "amplitude": amplitude, "stderr": stderr,
        "model": model, "residual": amplitude - model, "normalized": (amplitude - model) / stderr,
        "impact_velocity": impact_velocity(omega, branch.pitch, xi), "energy": energy,
        "specific_energy": specific_impact_energy(energy, branch.roller_diameter,
                                                  branch.roller_length),
        "above_n_max": n_rpm > n_max_rpm,
    })


def fit_roller_engagement(
    omega: ArrayLike,
    amplitude: ArrayLike,
    stderr: ArrayLike,
    *,
    sprocket: Sprocket,
    branch: RollerBranch,
    g_lim: float = G_LIM[0],
    confidence: float = CONFIDENCE,
) -> RollerEngagementFit:
    """Fit xi to the measured strike amplitudes of one sprocket at several speeds.

    Parameters
    ----------
    omega : array_like
        Sprocket angular velocity of every point [rad/s], two distinct or more.
    amplitude : array_like
        Measured strike amplitude (run median, e.g. :func:`strike_statistics`) [N].
    stderr : array_like
        Standard error of every amplitude [N].
    sprocket : Sprocket
        Teeth and, for an involute, its geometry.
    branch : RollerBranch
        Chain and branch.
    g_lim : float, optional
        Limit of the specific impact energy [J/m^2] (default 3e-4 J/mm^2, the
        lower end of Paper 002's :data:`~pipeline.theory.roller_impact.G_LIM`).
    confidence : float, optional
        Level of the confidence interval [-] (default 0.95).

    Returns
    -------
    RollerEngagementFit

    Raises
    ------
    FitError
        With a hint: points of unequal lengths, fewer than two speeds, a speed,
        amplitude or standard error not finite and > 0, a failed fit, or a
        fitted xi outside (0, 1] (sin Theta: check q, t, E0, L, k and the
        amplitudes' unit).

    References
    ----------
    Paper 002, eqs. (2)-(8); Paper 000, eq. (16) (the amplitude law, see the module notes).
    """
    omega, amplitude, stderr = _measurements(omega, amplitude, stderr)
    per_xi = strike_amplitude(omega, 1.0, branch)
    params = lmfit.Parameters()
    params.add("xi", value=0.5)
    result = lmfit.minimize(lambda p: (amplitude - p["xi"].value * per_xi) / stderr, params,
                            method="leastsq", scale_covar=False)
    if not result.success or result.params["xi"].stderr is None:
        raise FitError(f"xi could not be fitted: {result.message}",
                       hint="check the amplitudes and their standard errors")
    xi = float(result.params["xi"].value)
    if not 0 < xi <= 1:
        raise FitError(f"the fitted xi = {xi:.4g} lies outside (0, 1] (xi = sin Theta)",
                       hint="check the branch's mass per metre, pitch, E0, length and k, and "
                            "that the amplitudes are in N")
    dof = omega.size - 1
    scaled = scaled_error(float(result.params["xi"].stderr), float(result.chisqr), dof,
                          confidence)
    low, high = impact_velocity_coefficient_bounds(sprocket.teeth)
    xi_model, reason = sprocket.involute_xi(branch.pitch)
    slope, intercept, r2 = straight_line(omega, amplitude)
    if np.unique(omega).size < LINE_SPEEDS:
        r2 = math.nan
    n_max_rpm = from_si(max_angular_velocity(branch.mass_per_length, branch.pitch, xi,
                                             branch.roller_diameter, branch.roller_length,
                                             g_lim), "rpm")
    ci_low, ci_high = xi - scaled.quantile * scaled.stderr, xi + scaled.quantile * scaled.stderr
    return RollerEngagementFit(
        xi=xi, stderr=scaled.stderr, ci_low=ci_low, ci_high=ci_high, confidence=confidence,
        chi2_reduced=scaled.chi2_reduced, dof=dof, scaled=scaled.scaled, xi_model=xi_model,
        xi_model_reason=reason, xi_bounds=(low, high), within_bounds=low <= xi <= high,
        interval_within_bounds=low <= ci_low and ci_high <= high, slope=slope,
        intercept=intercept, r2=r2, model_slope=strike_amplitude(1.0, xi, branch), g_lim=g_lim,
        n_max_rpm=n_max_rpm, points=_points(omega, amplitude, stderr, xi, branch, n_max_rpm),
        result=result)
