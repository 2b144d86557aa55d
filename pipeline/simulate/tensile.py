"""The virtual tensile bench: logs of a cyclic tensile test with known truth.

A segment of chain of gauge length ``L`` is held at the preload ``F_p``, then
loaded ``n_cycles`` times to the upper force ``F_u`` and unloaded back to the
preload at a constant loading rate (Paper 001, section 3: segments of about
0.9 m, two dial gauges read to 0.01 mm, three cycles up to about 1/3 of the
breaking force). :func:`simulate_tensile` returns the log in the canonical SI
layout of :mod:`pipeline.ingest.table` (``time``, ``force``, ``gauge_1``,
``gauge_2``).

The truth
---------
With ``u = (F - F_p) / (F_u - F_p)`` the load fraction of the programmed
(noise-free) force, ``Delta = (F_u - F_p) L / E0`` and ``x_k`` the mean
elongation at the start of cycle ``k`` (``x_1 = 0``: the gauges are zeroed at
the preload), the mean elongation of cycle ``k`` is

loading
    ``x = x_k + Delta u + T_k(u)``, with the toe
    ``T_k(u) = S_k (1 - (1 - u / f_k)^3)`` for ``u < f_k`` and ``S_k`` above:
    slack ``S_1 = slack`` over ``f_1 = toe_fraction`` in cycle 1, re-seating
    ``S_k = reseat_slack`` over ``f_k = reseat_fraction`` in later cycles.
peak
    ``x = x_k + Delta + S_k`` (constant during the optional dwell).
unloading
    ``x = x_k + s_k + (Delta + S_k - s_k) u + 4 H u (1 - u)``: the hysteresis
    bulge ``H`` at mid-range, ending at the permanent set ``s_k``:
    ``s_1 = slack + set_first``, ``s_k = set_first * set_decay^(k-1)``;
    ``x_{k+1} = x_k + s_k``.

So above its toe every loading branch is exactly linear with slope ``E0`` in
force over mean strain ``x / L``: that slope is the truth the stiffness fit must
recover. By default (``reseat_slack = 0``) only cycle 1 has a toe, and the
loading branches of cycles ``>= 2`` are straight from the preload to the upper
force; a re-seating toe makes them straight above ``reseat_fraction``.

The permanent set of cycle ``k`` is ``s_k``, and the area of its loop, closed
at the preload (:meth:`TensileTruth.hysteresis_energy`), is
``(F_u - F_p) (s_k / 2 - S_k / 2 + S_k f_k / 4 + 2 H / 3)``.

What is measured
----------------
``force = F + N(0, force_noise)``; two gauges read ``x (1 + bending)`` and
``x (1 - bending)`` (bending of the segment: one reads more, one less; their
mean cancels it), each plus white noise ``N(0, gauge_noise)`` and a random
zero offset within one division, then quantised to ``gauge_resolution``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from pipeline.catalog import chain
from pipeline.theory.link_stiffness import table_1
from pipeline.units import to_si


def check_fields(
    settings: object, names: Iterable[str], valid: Callable[[float], bool], rule: str
) -> None:
    """Raise ValueError for the first field of `names` of `settings` that is not `valid`.

    Parameters
    ----------
    settings : object
        A dataclass instance.
    names : iterable of str
        Its fields to check.
    valid : callable
        True for a valid value.
    rule : str
        The rule, as the message says it (``"> 0"``).
    """
    for name in names:
        value = getattr(settings, name)
        if not valid(value):
            raise ValueError(f"{name} must be {rule}, got {value!r}")


@dataclass(frozen=True)
class TensileTruth:
    """Settings and true properties of one virtual tensile run (SI units).

    Parameters
    ----------
    E0 : float
        True loading stiffness [N]: force over relative elongation (mean strain)
        on the loading branches above the toe.
    preload : float
        Preload [N], the lower force of every cycle.
    upper_force : float
        Upper force of every cycle [N].
    gauge_length : float
        Length of the measured segment [m] (Paper 001: about 0.9 m).
    n_cycles : int
        Number of load/unload cycles (Paper 001: 3).
    sample_rate : float
        Logging rate [Hz].
    loading_rate : float
        Rate of force change on loading and unloading [N/s].
    dwell : float
        Hold at the upper force in every cycle [s].
    hold : float
        Hold at the preload before the first and after the last cycle [s].
    slack : float
        Slack taken up in the toe of cycle 1 [m] (kept as permanent set).
    toe_fraction : float
        Load fraction over which the slack is taken up in cycle 1 [1].
    reseat_slack : float
        Re-seating slack of the toe of cycles >= 2 [m] (recovered on unloading).
    reseat_fraction : float
        Load fraction of the toe of cycles >= 2 [1].
    hysteresis : float
        Extra elongation of the unloading branch at mid-range, ``H`` [m].
    set_first : float
        Permanent set of cycle 1 on top of the slack [m].
    set_decay : float
        Ratio of the permanent set of cycle ``k + 1`` to that of cycle ``k`` [1].
    bending : float
        Relative bending error of the gauges [1]: gauge 1 reads ``1 + bending``,
        gauge 2 ``1 - bending`` times the mean elongation.
    gauge_resolution : float
        Gauge division [m] (Paper 001: 0.01 mm); 0 disables quantisation.
    gauge_noise : float
        Standard deviation of the gauge noise before quantisation [m].
    force_noise : float
        Standard deviation of the force noise [N].
    """

    E0: float
    preload: float
    upper_force: float
    gauge_length: float = 0.9
    n_cycles: int = 3
    sample_rate: float = 10.0
    loading_rate: float = 1000.0
    dwell: float = 0.0
    hold: float = 5.0
    slack: float = 0.3e-3
    toe_fraction: float = 0.3
    reseat_slack: float = 0.0
    reseat_fraction: float = 0.1
    hysteresis: float = 0.05e-3
    set_first: float = 0.1e-3
    set_decay: float = 0.3
    bending: float = 0.05
    gauge_resolution: float = 1e-5
    gauge_noise: float = 2e-6
    force_noise: float = 50.0

    def __post_init__(self) -> None:
        check_fields(self, ("E0", "gauge_length", "sample_rate", "loading_rate"),
                     lambda value: value > 0, "> 0")
        if not 0 <= self.preload < self.upper_force:
            raise ValueError(
                f"need 0 <= preload < upper_force, got {self.preload!r} and {self.upper_force!r}"
            )
        if self.n_cycles < 1:
            raise ValueError(f"n_cycles must be >= 1, got {self.n_cycles!r}")
        check_fields(self, ("toe_fraction", "reseat_fraction"),
                     lambda value: 0 < value <= 1, "in (0, 1]")
        non_negative = (
            "dwell",
            "hold",
            "slack",
            "reseat_slack",
            "hysteresis",
            "set_first",
            "set_decay",
            "gauge_resolution",
            "gauge_noise",
            "force_noise",
        )
        check_fields(self, non_negative, lambda value: value >= 0, ">= 0")
        if not 0 <= self.bending < 1:
            raise ValueError(f"bending must be in [0, 1), got {self.bending!r}")
        if self.hysteresis * 4 >= self.stroke:
            raise ValueError("hysteresis too large: the unloading branch would not be monotonic")

    @classmethod
    def for_chain(cls, name: str, E0: float | None = None, **settings) -> TensileTruth:
        """A run of catalogue chain `name` with Paper 001's preload and upper load.

        Parameters
        ----------
        name : str
            Catalogue round-link chain, e.g. ``"18x64"``.
        E0 : float, optional
            True stiffness [N]; default the experimental value of Paper 001,
            Table 1 (for the four chains the paper tested).
        **settings
            Any other field of :class:`TensileTruth`.
        """
        spec = chain(name)
        if E0 is None:
            published = table_1().get(name)
            if published is None:
                raise ValueError(f"no default E0 for chain {name!r} (not in Table 1): give E0")
            E0 = to_si(published.E0_exp_kgf, "kgf")
        settings.setdefault("preload", spec["preload"])
        settings.setdefault("upper_force", spec["upper_load"])
        return cls(E0=E0, **settings)

    def with_(self, **changes) -> TensileTruth:
        """A copy with some fields changed."""
        return replace(self, **changes)

    @property
    def stroke(self) -> float:
        """Elastic elongation ``Delta`` between preload and upper force [m]."""
        return (self.upper_force - self.preload) * self.gauge_length / self.E0

    def toe(self, cycle: int) -> tuple[float, float]:
        """Slack [m] and load fraction [1] of the toe of `cycle` (1-based)."""
        if cycle == 1:
            return self.slack, self.toe_fraction
        return self.reseat_slack, self.reseat_fraction

    def permanent_set(self, cycle: int) -> float:
        """Permanent set of `cycle` [m]: mean elongation gained from its start to its end."""
        if cycle == 1:
            return self.slack + self.set_first
        return self.set_first * self.set_decay ** (cycle - 1)

    def start_elongation(self, cycle: int) -> float:
        """Mean elongation at the start of `cycle` [m] (0 at the start of cycle 1)."""
        return sum(self.permanent_set(k) for k in range(1, cycle))

    def hysteresis_energy(self, cycle: int) -> float:
        """Area of the force-elongation loop of `cycle` [J], closed at the preload."""
        slack, fraction = self.toe(cycle)
        area = (
            self.permanent_set(cycle) / 2
            - slack / 2
            + slack * fraction / 4
            + 2 * self.hysteresis / 3
        )
        return (self.upper_force - self.preload) * area

    def knots(self) -> tuple[np.ndarray, np.ndarray]:
        """Times [s] and forces [N] of the corners of the force programme."""
        ramp = (self.upper_force - self.preload) / self.loading_rate
        times, forces = [0.0, self.hold], [self.preload, self.preload]
        for _ in range(self.n_cycles):
            for step, force in (
                (ramp, self.upper_force),
                (self.dwell, self.upper_force),
                (ramp, self.preload),
            ):
                times.append(times[-1] + step)
                forces.append(force)
        times.append(times[-1] + self.hold)
        forces.append(self.preload)
        return np.array(times), np.array(forces)


def toe_slack(u: np.ndarray, slack: float, fraction: float) -> np.ndarray:
    """Slack taken up at load fraction `u` [m]: ``S (1 - (1 - u/f)^3)``, S above f."""
    rest = np.clip(1.0 - u / fraction, 0.0, 1.0)
    return slack * (1.0 - rest**3)


def mean_elongation(truth: TensileTruth, time: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Programmed force [N] and true mean elongation [m] at `time` [s].

    Parameters
    ----------
    truth : TensileTruth
        The run.
    time : numpy.ndarray
        Sample times [s] from 0.

    Returns
    -------
    force, elongation : numpy.ndarray
        Noise-free force [N] and mean elongation [m] (see the module docstring).
    """
    knot_time, knot_force = truth.knots()
    force = np.interp(time, knot_time, knot_force)
    u = (force - truth.preload) / (truth.upper_force - truth.preload)
    # Knot intervals: 0 hold, then (up, dwell, down) per cycle, then the final hold.
    interval = np.clip(np.searchsorted(knot_time, time, side="right") - 1, 0, len(knot_time) - 2)
    elongation = np.full(time.shape, truth.start_elongation(truth.n_cycles + 1))
    elongation[interval == 0] = 0.0
    for cycle in range(1, truth.n_cycles + 1):
        start = truth.start_elongation(cycle)
        slack, fraction = truth.toe(cycle)
        permanent = truth.permanent_set(cycle)
        first = 1 + 3 * (cycle - 1)
        up, dwell, down = (interval == first), (interval == first + 1), (interval == first + 2)
        elongation[up] = start + truth.stroke * u[up] + toe_slack(u[up], slack, fraction)
        elongation[dwell] = start + truth.stroke + slack
        chord = truth.stroke + slack - permanent
        elongation[down] = (
            start + permanent + chord * u[down] + 4 * truth.hysteresis * u[down] * (1 - u[down])
        )
    return force, elongation


def simulate_tensile(truth: TensileTruth, seed: int | None = None) -> pd.DataFrame:
    """Log of one virtual tensile run in the canonical SI layout.

    Parameters
    ----------
    truth : TensileTruth
        Settings and true properties of the run.
    seed : int, optional
        Seed of the noise, the gauges' zero offsets (quantisation phases).

    Returns
    -------
    pandas.DataFrame
        Columns ``time`` [s], ``force`` [N], ``gauge_1`` and ``gauge_2`` [m]
        (float64), one row per sample.

    Examples
    --------
    >>> truth = TensileTruth.for_chain("18x64", sample_rate=2.0)
    >>> log = simulate_tensile(truth, seed=1)
    >>> list(log.columns)
    ['time', 'force', 'gauge_1', 'gauge_2']
    """
    rng = np.random.default_rng(seed)
    duration = truth.knots()[0][-1]
    time = np.arange(int(np.floor(duration * truth.sample_rate)) + 1) / truth.sample_rate
    force, elongation = mean_elongation(truth, time)
    columns = {"time": time, "force": force + rng.normal(0.0, truth.force_noise, time.size)}
    for number, factor in ((1, 1.0 + truth.bending), (2, 1.0 - truth.bending)):
        columns[f"gauge_{number}"] = measured(
            elongation * factor, truth.gauge_noise, truth.gauge_resolution, rng)
    return pd.DataFrame(columns)


def measured(
    values: np.ndarray, noise: float, resolution: float, rng: np.random.Generator
) -> np.ndarray:
    """`values` as a channel reads them: plus white noise, quantised with a random zero offset.

    Parameters
    ----------
    values : numpy.ndarray
        True values [any unit].
    noise : float
        Standard deviation of the white noise [same unit].
    resolution : float
        Division of the reading [same unit]; 0 disables quantisation.
    rng : numpy.random.Generator
        Source of the noise and of the zero offset (within half a division).

    Returns
    -------
    numpy.ndarray
        The readings.
    """
    reading = values + rng.normal(0.0, noise, values.size)
    if resolution > 0:
        offset = rng.uniform(-resolution / 2, resolution / 2)
        reading = resolution * np.round((reading + offset) / resolution)
    return reading
