"""The virtual roller-chain engagement bench: branch-tension logs of a sprocket with known xi.

A roller chain runs on a sprocket of ``z`` teeth at angular velocity ``omega``.
Every tooth pitch ``P = 2 pi / (z omega)`` a roller strikes the sprocket at
V_y = omega t xi (Paper 002, eqs. (2), (5)), with the amplitude of chainbench's
strike law :func:`pipeline.fit.roller_engagement.strike_amplitude` (Paper 000's
eq. (16) at V_y: the project's model, not Paper 002's). Each strike rings the
branch as the round-link bench's strikes do
(:func:`~pipeline.simulate.engagement.strike_response`)::

    force(t) = pretension + polygon_amplitude cos(2 pi (t - t_0) / P)
               + sum_m A_m h(t - T_m) + noise,    T_m = t_0 + m P + j_m

``A_m = N (1 + amplitude_scatter e_m)``, ``e_m`` and the jitter ``j_m / jitter``
standard normal; the noise is white and normal with standard deviation
``noise_std`` [N], the same at every speed (a load cell's noise does not depend
on the speed). The polygon effect of a roller chain has the tooth period.
Strikes start long before the log does (steady ringing at ``t = 0``), and the
optional ``angle`` channel is the sprocket angle wrapped to [0, 2 pi).

The logs are in the canonical layout the engagement pipeline reads
(:mod:`pipeline.engagement_log`), with half the teeth
(:func:`pipeline.fit.roller_engagement.engagement_teeth`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from pipeline.fit.roller_engagement import RollerBranch, strike_amplitude
from pipeline.simulate.engagement import strike_response
from pipeline.theory.roller_impact import impact_velocity
from pipeline.theory.wheel_impact import seating_period

#: Decay times ``1 / (zeta omega_n)`` of strikes simulated before the log starts.
SETTLING_DECAY_TIMES = 20.0

#: The chain of the bench's default branch: ISO 606 16B simplex (pitch, mass per metre,
#: roller diameter and inner width of ``pipeline/data/chains.csv``) with E0 = 1e7 N
#: (about 0.2 % elastic elongation at a third of the breaking force; assumed), a 1 m
#: branch and Paper 000's k = 2.
CHAIN_16B = RollerBranch(pitch=0.0254, mass_per_length=2.70, E0=1.0e7, branch_length=1.0, k=2.0,
                         roller_diameter=0.01588, roller_length=0.01702)


@dataclass(frozen=True)
class RollerEngagementTruth:
    """Sprocket, branch, speeds and measurement of a virtual roller-chain campaign (SI units).

    Parameters
    ----------
    teeth : int
        Number of sprocket teeth z [-].
    xi : float
        True impact-velocity coefficient [-], in (0, 1] (e.g.
        :meth:`pipeline.fit.roller_engagement.Sprocket.involute_xi`).
    branch : RollerBranch
        Chain and branch (pitch, q, E0, L, k).
    speeds : tuple of float
        Sprocket angular velocities of the runs [rad/s].
    noise_std : float
        Standard deviation of the white noise of the force channel [N].
    amplitude_scatter : float
        Relative standard deviation of each strike's amplitude about N [-].
    jitter : float
        Standard deviation of the strike times about the tooth grid [s].
    pretension : float
        Mean branch tension [N].
    polygon_amplitude : float
        Amplitude of the polygon effect, a sinusoid of the tooth period [N].
    damping_ratio : float
        Damping ratio zeta of the branch [-], in (0, 1).
    natural_frequency : float, optional
        Undamped natural angular frequency of the branch [rad/s]; default
        ``sqrt(E0 / (L m_branch))``, ``m_branch = q L``.
    sample_rate : float
        Logging rate [Hz].
    strikes : int
        Strikes (tooth pitches) per log [-].
    with_angle : bool
        Whether the logs have a sprocket-angle channel ``angle`` [rad].
    """

    teeth: int
    xi: float
    branch: RollerBranch = CHAIN_16B
    speeds: tuple[float, ...] = tuple(2 * math.pi * n / 60 for n in (100.0, 200.0, 300.0))
    noise_std: float = 5.0
    amplitude_scatter: float = 0.05
    jitter: float = 1e-4
    pretension: float = 2e3
    polygon_amplitude: float = 0.0
    damping_ratio: float = 0.03
    natural_frequency: float | None = None
    sample_rate: float = 10e3
    strikes: int = 80
    with_angle: bool = True

    def __post_init__(self) -> None:
        seating_period(self.teeth, 1.0)  # a whole number of teeth >= 3
        if not 0 < self.xi <= 1:
            raise ValueError(f"xi must be in (0, 1], got {self.xi!r}")
        if not (self.speeds and all(math.isfinite(w) and w > 0 for w in self.speeds)):
            raise ValueError(f"speeds must be finite numbers > 0, got {self.speeds!r}")
        for name in ("noise_std", "amplitude_scatter", "jitter", "pretension",
                     "polygon_amplitude"):
            if not (math.isfinite(getattr(self, name)) and getattr(self, name) >= 0):
                raise ValueError(f"{name} must be a finite number >= 0, got "
                                 f"{getattr(self, name)!r}")
        if not 0 < self.damping_ratio < 1:
            raise ValueError(f"damping_ratio must be in (0, 1), got {self.damping_ratio!r}")
        if not self.strikes >= 1:
            raise ValueError(f"strikes must be >= 1, got {self.strikes!r}")
        if self.omega_n >= np.pi * self.sample_rate:
            raise ValueError(f"sample_rate {self.sample_rate!r} Hz is below twice the branch's "
                             f"natural frequency {self.omega_n / (2 * np.pi):.4g} Hz")

    @property
    def omega_n(self) -> float:
        """Undamped natural angular frequency of the branch [rad/s]."""
        if self.natural_frequency is not None:
            return float(self.natural_frequency)
        b = self.branch
        return math.sqrt(b.E0 / (b.branch_length * b.mass_per_length * b.branch_length))

    def amplitude(self, omega: float) -> float:
        """True strike amplitude N at `omega` [rad/s] [N] (chainbench's strike law)."""
        return strike_amplitude(omega, self.xi, self.branch)


def _strikes(truth: RollerEngagementTruth, omega: float, end: float,
             rng: np.random.Generator) -> tuple[float, np.ndarray, np.ndarray]:
    """First nominal strike time t_0 [s], the strike times [s] and amplitudes [N] up to `end`."""
    period = float(seating_period(truth.teeth, omega))
    t0 = rng.uniform(0.0, period)
    first = -math.ceil(SETTLING_DECAY_TIMES / (truth.damping_ratio * truth.omega_n) / period)
    cycle = np.arange(first, math.ceil((end - t0) / period) + 1)
    onsets = t0 + cycle * period + rng.normal(0.0, truth.jitter, cycle.size)
    scatter = 1.0 + truth.amplitude_scatter * rng.standard_normal(cycle.size)
    return t0, onsets, truth.amplitude(omega) * scatter


def simulate_roller_engagement(truth: RollerEngagementTruth, omega: float,
                               seed: int | None = None) -> tuple[pd.DataFrame, dict]:
    """Log of one virtual roller-chain run at `omega`, in the canonical SI layout, and its truth.

    Parameters
    ----------
    truth : RollerEngagementTruth
        Sprocket, branch and measurement.
    omega : float
        Sprocket angular velocity of the run [rad/s] (one of ``truth.speeds``, or any > 0).
    seed : int, optional
        Seed of the phase, jitter, amplitude scatter, noise and angle offset.

    Returns
    -------
    table : pandas.DataFrame
        ``time`` [s], ``force`` [N] and, with ``truth.with_angle``, ``angle``
        [rad]; ``truth.strikes`` tooth pitches long.
    run : dict
        ``amplitude`` N [N], ``impact_velocity`` V_y [m/s], ``strike_period`` P
        [s], ``omega_n`` [rad/s], ``zeta`` [-], ``noise_std`` [N], and per strike
        in the log ``strike_time`` [s] and ``strike_amplitude`` [N].

    Examples
    --------
    >>> truth = RollerEngagementTruth(teeth=18, xi=0.5)
    >>> table, run = simulate_roller_engagement(truth, 10.0, seed=1)
    >>> list(table.columns), round(run["amplitude"], 1)
    (['time', 'force', 'angle'], 148.7)
    """
    rng = np.random.default_rng(seed)
    period = float(seating_period(truth.teeth, omega))
    time = np.arange(int(truth.strikes * period * truth.sample_rate) + 1) / truth.sample_rate
    t0, onsets, amplitudes = _strikes(truth, omega, time[-1], rng)
    force = (truth.pretension
             + truth.polygon_amplitude * np.cos(2.0 * np.pi * (time - t0) / period)
             + strike_response(amplitudes, onsets, time, truth.omega_n, truth.damping_ratio)
             + rng.normal(0.0, truth.noise_std, time.size))
    columns = {"time": time, "force": force}
    if truth.with_angle:
        offset = rng.uniform(0.0, 2.0 * np.pi / truth.teeth)
        columns["angle"] = np.mod(offset + omega * (time - t0), 2.0 * np.pi)
    in_log = (onsets >= 0.0) & (onsets <= time[-1])
    run = {"amplitude": truth.amplitude(omega),
           "impact_velocity": impact_velocity(omega, truth.branch.pitch, truth.xi),
           "strike_period": period, "omega_n": truth.omega_n, "zeta": truth.damping_ratio,
           "noise_std": truth.noise_std, "strike_time": onsets[in_log],
           "strike_amplitude": amplitudes[in_log]}
    return pd.DataFrame(columns), run
