"""The virtual segment-load bench: tooth-segment force logs of a chain drum with known truth.

A horizontal link seats on a tooth of a chain drum whose two segments carry
strain gauges (Paper 003). While the link sits, the flank force ``F`` (here
the chain force, held at its level) is shared by the two segments: each
carries ``F_K = (F_K / F) F`` and its side component is ``F_P = (F_P / F) F``,
with the ratios of eqs. (1)-(4) for the true geometry
(:mod:`pipeline.theory.tooth_segments`).

The signal
----------
Seatings follow each other every ``P = 1 / seating_rate``; seating ``m``
occupies ``[t_m, t_m + 2 transition + plateau)`` with
``t_m = m P + (P - 2 transition - plateau) / 2``, so that every seating lies
whole inside the log of ``seatings`` periods. Its load shape ``h`` rises from
0 to 1 as a raised cosine over ``transition``, holds 1 for ``plateau`` and
falls back as a raised cosine::

    F(t)    = F_m + n_F
    F_K1(t) = (1 + imbalance / 2) (F_K / F) F_m h(t) + zero(t) + n_K1
    F_K2(t) = (1 - imbalance / 2) (F_K / F) F_m h(t) + zero(t) + n_K2
    F_P(t)  = (F_P / F) F_m h(t) + zero(t) + n_P
    zero(t) = zero_offset + zero_drift t

``F_m`` is the chain-force level of seating ``m`` (the levels given, in equal
consecutive blocks of seatings), and the noises ``n`` are white and normal with
the standard deviations given per channel. The gains ``1 +- imbalance / 2``
average to 1, so the mean of the two segments keeps the true ``F_K / F`` and
their relative difference ``(F_K1 - F_K2) / F_K`` is ``gain_imbalance``.

Defaults: chain 34x126 (r = 52 mm, d = 34 mm, c = 45 mm, Paper 003 section 3)
at beta = 50 deg, eps_n = 0, s = 60 mm and 100 kN; the noise (0.5 kN on every
channel, 0.5 % of the chain force) is that of strain-gauge bridges and a load
cell of some 500 kN range logged at 1 kHz.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from pipeline.theory.tooth_segments import (
    contact_force_ratio,
    contact_radius,
    friction_increase,
    opening_angle,
    side_force_ratio,
)


@dataclass(frozen=True)
class SegmentLoadTruth:
    """Geometry, load and measurement of one virtual segment-load run (SI units).

    Parameters
    ----------
    r_outer : float
        Outer torus radius r of the horizontal link [m].
    d : float
        Link bar thickness [m].
    groove_width : float
        Width c of the groove between the segments [m].
    beta : float
        Flank inclination at the contact [rad].
    eps_n : float
        Inclination of the link to the pocket floor [rad].
    s : float
        Distance between the contact points on the two segments [m]; c <= s < 2 k.
    chain_force : tuple of float
        Chain-force levels [N], each held over an equal block of consecutive
        seatings (one level: one operating point).
    seatings : int
        Seatings in the log [-].
    seating_rate : float
        Seatings per second [Hz].
    plateau : float
        Time the link sits with the full load [s].
    transition : float
        Time the segment forces take to rise, and to fall [s].
    sample_rate : float
        Logging rate [Hz].
    noise_chain, noise_segment, noise_side : float
        Standard deviation of the white noise on F, on each of F_K1 and F_K2,
        and on F_P [N].
    gain_imbalance : float
        Relative difference of the two segments' gains [-], in (-2, 2).
    zero_offset : float
        Zero of the segment and side-force channels at t = 0 [N].
    zero_drift : float
        Drift of that zero [N/s].
    with_side_force : bool
        Whether the log has the side-force channel F_P.
    """

    r_outer: float = 52e-3
    d: float = 34e-3
    groove_width: float = 45e-3
    beta: float = math.radians(50.0)
    eps_n: float = 0.0
    s: float = 60e-3
    chain_force: tuple[float, ...] = (100e3,)
    seatings: int = 30
    seating_rate: float = 0.5
    plateau: float = 0.8
    transition: float = 0.2
    sample_rate: float = 1e3
    noise_chain: float = 500.0
    noise_segment: float = 500.0
    noise_side: float = 500.0
    gain_imbalance: float = 0.0
    zero_offset: float = 0.0
    zero_drift: float = 0.0
    with_side_force: bool = True

    def __post_init__(self) -> None:
        for name in ("seating_rate", "plateau", "transition", "sample_rate"):
            _check(name, getattr(self, name), lambda value: value > 0, "> 0")
        for name in ("noise_chain", "noise_segment", "noise_side"):
            _check(name, getattr(self, name), lambda value: value >= 0, ">= 0")
        for name in ("zero_offset", "zero_drift"):
            _check(name, getattr(self, name), lambda value: True, "finite")
        _check("gain_imbalance", self.gain_imbalance, lambda value: abs(value) < 2, "in (-2, 2)")
        if not (isinstance(self.seatings, int) and self.seatings >= 1):
            raise ValueError(f"seatings must be a whole number >= 1, got {self.seatings!r}")
        if not (self.chain_force and all(_finite(f) and f > 0 for f in self.chain_force)):
            raise ValueError(f"chain_force must be levels > 0 [N], got {self.chain_force!r}")
        if self.busy >= self.seating_period:
            raise ValueError(
                f"a seating (2 transition + plateau = {self.busy:g} s) must be shorter than the "
                f"seating period 1 / seating_rate = {self.seating_period:g} s")
        # Validates the geometry the way the theory does (ValueError naming the parameter).
        opening_angle(self.s, self.k, self.groove_width)

    def with_(self, **changes) -> SegmentLoadTruth:
        """A copy with some fields changed."""
        return replace(self, **changes)

    @property
    def seating_period(self) -> float:
        """Time from one seating to the next, 1 / seating_rate [s]."""
        return 1.0 / self.seating_rate

    @property
    def busy(self) -> float:
        """Time a seating loads the segments, 2 transition + plateau [s]."""
        return 2.0 * self.transition + self.plateau

    @property
    def k(self) -> float:
        """Contact radius [m] (Paper 003, eq. (1))."""
        return float(contact_radius(self.r_outer, self.d, self.beta, self.eps_n))

    @property
    def psi(self) -> float:
        """Segment opening angle [rad] (Paper 003, eq. (2))."""
        return float(opening_angle(self.s, self.k, self.groove_width))

    @property
    def contact_force_ratio(self) -> float:
        """F_K / F [-] (Paper 003, eq. (3))."""
        return float(contact_force_ratio(self.psi))

    @property
    def side_force_ratio(self) -> float:
        """F_P / F [-] (Paper 003, eq. (4))."""
        return float(side_force_ratio(self.psi))

    @property
    def friction_increase(self) -> float:
        """2 F_K / F - 1 [-] (Paper 003, section 4)."""
        return float(friction_increase(self.psi))

    def levels(self) -> np.ndarray:
        """Chain-force level of every seating [N]: the levels in equal consecutive blocks."""
        block = np.arange(self.seatings) * len(self.chain_force) // self.seatings
        return np.asarray(self.chain_force, dtype=float)[block]


def _finite(value) -> bool:
    return isinstance(value, int | float) and math.isfinite(value)


def _check(name: str, value, condition, wanted: str) -> None:
    """Raise a ValueError naming `name` unless `value` is a finite number meeting `condition`."""
    if not (_finite(value) and condition(value)):
        raise ValueError(f"{name} must be a finite number {wanted}, got {value!r}")


def load_shape(truth: SegmentLoadTruth, time: np.ndarray) -> np.ndarray:
    """Load shape h of the seatings at `time`: 0 idle, 1 while the link sits [-].

    Parameters
    ----------
    truth : SegmentLoadTruth
        Seating rate, plateau and transition times.
    time : numpy.ndarray
        Sample times from the start of the log [s].

    Returns
    -------
    numpy.ndarray
        Raised-cosine rise over ``transition``, 1 over ``plateau``, raised-cosine
        fall; 0 between seatings.
    """
    lead = (truth.seating_period - truth.busy) / 2.0
    knots = np.cumsum([0.0, lead, truth.transition, truth.plateau, truth.transition])
    ramp = np.interp(np.mod(time, truth.seating_period), knots, [0.0, 0.0, 1.0, 1.0, 0.0])
    return (1.0 - np.cos(np.pi * ramp)) / 2.0


def simulate_segment_load(truth: SegmentLoadTruth, seed: int | None = None) -> pd.DataFrame:
    """Log of one virtual segment-load run in SI units.

    Parameters
    ----------
    truth : SegmentLoadTruth
        Geometry, load and measurement.
    seed : int, optional
        Seed of the noise.

    Returns
    -------
    pandas.DataFrame
        Columns ``time`` [s], ``F`` (chain force), ``F_K1``, ``F_K2`` (segment
        forces) and, when ``truth.with_side_force``, ``F_P`` (side force) [N];
        float64, ``seatings / seating_rate * sample_rate`` rows.

    References
    ----------
    Paper 003, eqs. (1)-(4), through :class:`SegmentLoadTruth`.
    """
    rng = np.random.default_rng(seed)
    n = int(round(truth.seatings * truth.seating_period * truth.sample_rate))
    time = np.arange(n) / truth.sample_rate
    seating = np.minimum((time // truth.seating_period).astype(np.int64), truth.seatings - 1)
    chain = truth.levels()[seating]
    flank = chain * load_shape(truth, time)
    zero = truth.zero_offset + truth.zero_drift * time
    segment = truth.contact_force_ratio * flank
    columns = {
        "time": time,
        "F": chain + truth.noise_chain * rng.standard_normal(n),
        "F_K1": (1 + truth.gain_imbalance / 2) * segment + zero
        + truth.noise_segment * rng.standard_normal(n),
        "F_K2": (1 - truth.gain_imbalance / 2) * segment + zero
        + truth.noise_segment * rng.standard_normal(n),
    }
    if truth.with_side_force:
        columns["F_P"] = (truth.side_force_ratio * flank + zero
                          + truth.noise_side * rng.standard_normal(n))
    return pd.DataFrame(columns)
