"""The virtual wear bench: wear logs of a roller chain with known truth.

A roller chain runs on a wear rig; at regular intervals the lab measures a
section of ``N`` pitches. The true elongation per pitch follows the run-in
model of :mod:`pipeline.fit.wear`::

    delta_t(tau) = delta_t0 + A (1 - exp(-tau / tau0)) + w tau

with ``delta_t0`` the new chain's pitch error against the nominal pitch. The
log holds the section's length ``L = N (t + delta_t) + e`` or its elongation
against the nominal length ``N delta_t + e``, with ``e`` white normal noise of
standard deviation ``noise`` (one reading of the section).

The defaults: a 19.05 mm roller chain (a common pitch of open drives of farm
machines, Paper 004's subject), a 10-pitch section read every 5 h for 300 h;
new-chain error 0.1 % of t (within the +0.15 % length tolerance of new roller
chains), run-in 0.03 mm per pitch settling with tau0 = 10 h, then 0.75 um per
hour per pitch (1.2 % of the pitch in 300 h, 3 % in about 700 h). The noise,
10 um on the section's length, is a dial gauge of 0.01 mm graduation with a few
kelvin of temperature change between readings (steel: 11.5 um/(m K), 2.2 um/K
on 190.5 mm): 1 um on delta_t.

:func:`simulate_wear` returns the log in SI units (``time`` [s], ``cycles``
[-], ``length`` or ``elongation`` [m], optionally ``load`` [N] and ``speed``
[m/s]).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd
from scipy import optimize

#: Seconds per hour.
HOUR = 3600.0

#: Channels a wear log can hold: the section's length, or its elongation.
CHANNELS = ("length", "elongation")


@dataclass(frozen=True)
class WearTruth:
    """A virtual wear test (SI units).

    Parameters
    ----------
    pitch : float
        Nominal pitch t [m].
    pitches : int
        Pitches N of the measured section [-].
    initial_error : float
        Elongation per pitch of the new chain against the nominal pitch,
        delta_t0 [m].
    run_in : float
        Run-in elongation per pitch A [m]; 0 for no run-in.
    run_in_time : float
        Run-in time constant tau0 [s].
    wear_rate : float
        Steady wear rate per pitch w [m/s].
    noise : float
        Standard deviation of one reading of the section [m] (length or elongation).
    duration : float
        Running time of the test [s]; the last reading is at or before it.
    interval : float
        Running time between readings [s]; the first reading is at 0.
    cycle_rate : float
        Cycles counted per second [1/s] (e.g. circulations of the chain
        loop: chain speed over loop length).
    channel : {"length", "elongation"}
        What the log holds: the section's length L [m], or its elongation
        against the nominal length ``L - N t`` [m].
    load : float, optional
        Chain tension of the rig [N], logged as a constant ``load`` column.
    speed : float, optional
        Chain speed of the rig [m/s], logged as a constant ``speed`` column.
    """

    pitch: float = 0.01905
    pitches: int = 10
    initial_error: float = 0.001 * 0.01905
    run_in: float = 0.03e-3
    run_in_time: float = 10 * HOUR
    wear_rate: float = 0.75e-6 / HOUR
    noise: float = 10e-6
    duration: float = 300 * HOUR
    interval: float = 5 * HOUR
    cycle_rate: float = 0.5
    channel: str = "length"
    load: float | None = None
    speed: float | None = None

    def __post_init__(self) -> None:
        for name in ("pitch", "run_in_time", "duration", "interval", "cycle_rate"):
            _check(name, getattr(self, name), lambda value: value > 0, "> 0")
        for name in ("run_in", "wear_rate", "noise"):
            _check(name, getattr(self, name), lambda value: value >= 0, ">= 0")
        _check("initial_error", self.initial_error, math.isfinite, "finite")
        for name in ("load", "speed"):
            if getattr(self, name) is not None:
                _check(name, getattr(self, name), lambda value: value > 0, "> 0 or None")
        if not (isinstance(self.pitches, int) and self.pitches >= 1):
            raise ValueError(f"pitches must be a whole number >= 1, got {self.pitches!r}")
        if self.channel not in CHANNELS:
            raise ValueError(f"channel must be one of {', '.join(CHANNELS)}, got {self.channel!r}")
        if self.interval > self.duration:
            raise ValueError(f"interval {self.interval!r} s is longer than the test "
                             f"({self.duration!r} s)")

    def with_(self, **changes) -> WearTruth:
        """A copy with some fields changed."""
        return replace(self, **changes)

    def reading_times(self) -> np.ndarray:
        """Running time of each reading [s]: 0, interval, ... up to `duration`."""
        count = math.floor(self.duration / self.interval * (1 + 1e-12)) + 1
        return np.arange(count) * self.interval

    def elongation(self, tau: np.ndarray) -> np.ndarray:
        """True elongation per pitch delta_t [m] against the nominal pitch at `tau` [s]."""
        tau = np.asarray(tau, dtype=float)
        return (self.initial_error + self.run_in * -np.expm1(-tau / self.run_in_time)
                + self.wear_rate * tau)

    def time_to(self, limit: float) -> float:
        """Running time [s] at which the true delta_t reaches `limit` [m].

        Raises
        ------
        ValueError
            When the chain does not wear (``wear_rate`` 0) or is at the limit
            already at the start.
        """
        if not self.wear_rate > 0 or self.elongation(0.0) >= limit:
            raise ValueError(f"delta_t never reaches {limit!r} m from below")
        end = (limit - self.initial_error) / self.wear_rate  # delta_t(end) >= limit
        return float(optimize.brentq(lambda tau: self.elongation(tau) - limit, 0.0, end,
                                     xtol=1e-12 * end, rtol=1e-15))


def _check(name: str, value, condition, requirement: str) -> None:
    if not (isinstance(value, int | float) and math.isfinite(value) and condition(value)):
        raise ValueError(f"{name} must be a finite number {requirement}, got {value!r}")


def simulate_wear(truth: WearTruth, seed: int | None = None) -> pd.DataFrame:
    """Wear log of one virtual wear test, in SI units.

    Parameters
    ----------
    truth : WearTruth
        The chain, its wear and the measurement.
    seed : int, optional
        Seed of the noise.

    Returns
    -------
    pandas.DataFrame
        One row per reading: ``time`` [s], ``cycles`` [-] (``cycle_rate``
        times ``time``), ``length`` L [m] or ``elongation`` L - N t [m] (as
        ``truth.channel`` says) and, when given, ``load`` [N] and ``speed``
        [m/s]; float64.
    """
    time = truth.reading_times()
    noise = np.random.default_rng(seed).normal(0.0, truth.noise, time.size)
    elongation = truth.pitches * truth.elongation(time) + noise
    nominal = truth.pitches * truth.pitch
    columns = {"time": time, "cycles": truth.cycle_rate * time,
               truth.channel: elongation + (nominal if truth.channel == "length" else 0.0)}
    for name in ("load", "speed"):
        if getattr(truth, name) is not None:
            columns[name] = np.full(time.size, float(getattr(truth, name)))
    return pd.DataFrame(columns)
