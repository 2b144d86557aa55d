"""The virtual tensile bench, single pulls: one loading to fracture, or a proof-load test.

A chain specimen is held in the grips of a tensile machine over its free length
``L_f``; a clip-on extensometer measures the elongation of a gauge length
``L_g`` on it. The crosshead moves at a constant speed ``v``: from the preload
``F_0`` the force rises to the maximum force, falls while the specimen necks,
and drops to a small residue within a few samples at fracture. A proof-load
test loads to the proof force ``P``, holds it, unloads to the preload and then,
if it goes on to fracture, pulls to fracture. :func:`simulate_pull` returns the
log (``time``, ``force``, ``extensometer`` or ``extensometer_strain``,
``crosshead``).

The truth
---------
The force over the strain ``e`` of the specimen's material (from zero force,
slack excluded; ``e_y = F_y / E0``) is, on first loading,

linear
    ``F = E0 e`` up to the proportional limit ``F_y`` (:attr:`PullTruth.yield_force`);
hardening
    ``F = F_m - (F_m - F_y) (a (1 - s)^k_1 + (1 - a) (1 - s)^2)`` with
    ``s = (e - e_y) / (e_m - e_y)``, ``a`` the knee share and
    ``k_1 = (k - 2 (1 - a)) / a``, ``k = E0 (e_m - e_y) / (F_m - F_y)``: its
    slope starts at ``E0`` and falls continuously to zero at the maximum force
    ``F_m`` at ``e = e_m``, a sharp knee (share ``a`` of the rise) on a
    parabolic hardening (the rest);
necking
    ``F = F_m - (F_m - F_f) ((e - e_m) / (e_f - e_m))^2`` with
    ``F_f = F_m (1 - neck_drop)``: the force falls from the maximum to the
    fracture force ``F_f`` at the fracture strain ``e_f``.

Unloading and reloading (proof test) follow the elastic line of slope ``E0``.
The extensometer reads ``L_g (e - e_0) + T(F)``, with ``e_0 = F_0 / E0`` (it is
zeroed at the preload) and the toe ``T(F) = S (1 - (1 - u / f)^3)``, ``S`` above
``u = f``, where ``u = (F - F_0) / (F_m - F_0)`` (links seating: the slack
``S`` is taken up over the load fraction ``f`` and kept). So between the toe and
the proportional limit the force over the extensometer strain is exactly linear
with slope ``E0``. The crosshead reads ``L_f eps + T_g(F) + C_m (F - F_0)``:
the elongation of the free length at the same strain ``eps`` as the gauge
length, the grips' slack ``T_g`` (the same toe with ``S_g``) and the machine's
own compliance ``C_m``. After fracture the force drops linearly to
``fracture_residue F_m`` over ``fracture_samples`` sample intervals, the
extensometer springs back elastically and the crosshead goes on for
``after_fracture`` seconds.

What is measured
----------------
``force = F + N(0, force_noise)``; extensometer and crosshead read their true
values plus white noise, quantised to their resolution with a random zero
offset (:func:`pipeline.simulate.tensile.measured`). From the sample where the
extensometer is taken off (:attr:`PullTruth.removal_index`) its channel
misbehaves as :attr:`PullTruth.removal_mode` says.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from itertools import pairwise
from typing import NamedTuple

import numpy as np
import pandas as pd
from scipy.optimize import brentq

from pipeline.catalog import chain
from pipeline.simulate.tensile import check_fields, measured, toe_slack
from pipeline.theory.link_stiffness import table_1
from pipeline.units import to_si

#: How a removed extensometer misbehaves: it jumps by :data:`REMOVAL_JUMP` and reads
#: noise of :data:`REMOVAL_NOISE`; it freezes at its last reading; or it runs
#: backwards over :data:`REMOVAL_FALL` seconds to minus its last reading.
REMOVAL_MODES = ("jump", "freeze", "reverse")

#: Jump of a removed extensometer [m].
REMOVAL_JUMP = 20e-3

#: Standard deviation of the noise a jumped extensometer reads [m].
REMOVAL_NOISE = 50e-6

#: Time a reversing extensometer takes to run back to minus its last reading [s].
REMOVAL_FALL = 1.0

#: Minimum breaking force of round-link chains, DIN 22252 grade C as tabulated by
#: chain makers (approximate) [kN]; the default maximum force is 1.1 times it.
MIN_BREAKING_FORCE_KN = {"14x50": 250.0, "18x64": 410.0, "22x86": 610.0, "34x126": 1450.0}

#: Default true maximum force over the minimum breaking force [1].
MAX_FORCE_MARGIN = 1.1

#: Default proportional limit over the maximum force [1].
YIELD_RATIO = 0.65

#: Default share of the machine in the crosshead's compliance in the linear region [1].
MACHINE_SHARE = 0.3


@dataclass(frozen=True)
class PullTruth:
    """Settings and true properties of one virtual single pull (SI units).

    Parameters
    ----------
    E0 : float
        True specimen stiffness [N]: force per unit strain of the specimen over
        the gauge length, in the linear region.
    yield_force : float
        Proportional limit ``F_y`` [N]: the curve is linear up to it.
    max_force : float
        Maximum force ``F_m`` [N].
    max_force_strain : float
        Material strain ``e_m`` at the maximum force [1] (from zero force, slack
        excluded; see the module docstring).
    knee_share : float
        Share ``a`` of the rise from ``F_y`` to ``F_m`` taken in the knee above
        the proportional limit [1]; the rest rises parabolically up to ``e_m``.
    fracture_strain : float
        Material strain ``e_f`` at fracture [1].
    neck_drop : float
        Fall of the force from the maximum to fracture, relative to ``F_m`` [1].
    preload : float
        Force at the start of the test [N]; the channels are zeroed there, and a
        proof test unloads to it.
    gauge_length : float
        Gauge length of the extensometer [m].
    free_length : float
        Length of the specimen between the grips [m].
    machine_share : float
        Share of the machine (frame, grips, load cell) in the crosshead's
        compliance in the linear region [1]; it sets
        :attr:`machine_compliance`.
    crosshead_speed : float
        Speed of the crosshead [m/s] (default 50 mm/min).
    sample_rate : float
        Logging rate [Hz].
    slack : float
        Slack taken up in the toe over the gauge length [m] (links seating); the
        free length takes up ``slack L_f / L_g``.
    grip_slack : float
        Slack of the grips and shackles [m], seen by the crosshead only.
    toe_fraction : float
        Load fraction ``(F - F_0) / (F_m - F_0)`` over which the slack is taken up [1].
    fracture_samples : int
        Sample intervals over which the force drops at fracture.
    fracture_residue : float
        Force left after fracture, relative to ``F_m`` [1].
    after_fracture : float
        Logging after fracture [s].
    proof_force : float, optional
        Proof force [N]: load to it, hold, unload to the preload before the pull.
    proof_hold : float
        Hold at the proof force [s].
    to_fracture : bool
        Pull to fracture (after the proof load, if any); False ends a proof-load
        test after its unloading.
    extensometer_removed_at : float, optional
        Fraction of ``F_m`` on the rising branch at which the extensometer is
        taken off [1].
    removal_mode : str
        How the channel then misbehaves, one of :data:`REMOVAL_MODES`.
    strain_channel : bool
        Log the extensometer as a strain [1] (``extensometer_strain``) instead of
        an elongation [m] (``extensometer``).
    repeated_first_time : bool
        Log the first sample twice, both rows at time 0 (as Bluehill writes).
    force_noise : float
        Standard deviation of the force noise [N].
    extensometer_noise, crosshead_noise : float
        Standard deviation of the channel's noise [m].
    extensometer_resolution, crosshead_resolution : float
        Division of the channel [m]; 0 disables quantisation.
    """

    E0: float
    yield_force: float
    max_force: float
    max_force_strain: float = 0.10
    knee_share: float = 0.5
    fracture_strain: float = 0.14
    neck_drop: float = 0.03
    preload: float = 0.0
    gauge_length: float = 0.32
    free_length: float = 0.576
    machine_share: float = MACHINE_SHARE
    crosshead_speed: float = 50e-3 / 60
    sample_rate: float = 20.0
    slack: float = 0.2e-3
    grip_slack: float = 2e-3
    toe_fraction: float = 0.05
    fracture_samples: int = 2
    fracture_residue: float = 0.005
    after_fracture: float = 1.0
    proof_force: float | None = None
    proof_hold: float = 10.0
    to_fracture: bool = True
    extensometer_removed_at: float | None = None
    removal_mode: str = "jump"
    strain_channel: bool = False
    repeated_first_time: bool = False
    force_noise: float = 100.0
    extensometer_noise: float = 1e-6
    extensometer_resolution: float = 1e-6
    crosshead_noise: float = 2e-6
    crosshead_resolution: float = 1e-5

    def __post_init__(self) -> None:
        check_fields(self, ("E0", "gauge_length", "free_length", "crosshead_speed",
                            "sample_rate"), lambda value: value > 0, "> 0")
        check_fields(self, ("machine_share",), lambda value: 0 <= value < 1, "in [0, 1)")
        check_fields(self, ("slack", "grip_slack", "after_fracture", "proof_hold",
                            "force_noise", "extensometer_noise", "extensometer_resolution",
                            "crosshead_noise", "crosshead_resolution"),
                     lambda value: value >= 0, ">= 0")
        if not 0 <= self.preload < self.yield_force < self.max_force:
            raise ValueError("need 0 <= preload < yield_force < max_force, got "
                             f"{self.preload!r}, {self.yield_force!r}, {self.max_force!r}")
        check_fields(self, ("knee_share",), lambda value: 0 < value <= 1, "in (0, 1]")
        if not self.knee_exponent > 1:
            raise ValueError("max_force_strain too small for the knee: need "
                             "E0 (max_force_strain - yield_force / E0) > "
                             "(2 - knee_share) (max_force - yield_force)")
        if not self.fracture_strain > self.max_force_strain:
            raise ValueError("fracture_strain must be > max_force_strain")
        if not 0 <= self.neck_drop < 1 or not 0 <= self.fracture_residue < 1 - self.neck_drop:
            raise ValueError("need 0 <= neck_drop < 1 and 0 <= fracture_residue < 1 - neck_drop")
        if not self.free_length >= self.gauge_length:
            raise ValueError("free_length must be >= gauge_length")
        if not 0 < self.toe_fraction <= 1 or not self.toe_force < self.yield_force:
            raise ValueError("toe_fraction must be in (0, 1] and end below yield_force")
        if self.fracture_samples < 1:
            raise ValueError(f"fracture_samples must be >= 1, got {self.fracture_samples!r}")
        if self.free_length + self.machine_compliance * self._steepest_neck_slope <= 0:
            raise ValueError("the crosshead would run back while necking: "
                             "reduce machine_share or neck_drop")
        self._check_proof_and_removal()

    def _check_proof_and_removal(self) -> None:
        if self.proof_force is not None and not self.toe_force <= self.proof_force < self.max_force:
            raise ValueError("proof_force must be in [toe force, max_force), got "
                             f"{self.proof_force!r}")
        if not self.to_fracture and self.proof_force is None:
            raise ValueError("a test that does not go to fracture needs a proof_force")
        if self.removal_mode not in REMOVAL_MODES:
            raise ValueError(f"removal_mode must be one of {', '.join(REMOVAL_MODES)}, "
                             f"got {self.removal_mode!r}")
        removed = self.extensometer_removed_at
        if removed is None:
            return
        if not 0 < removed < 1 or not self.to_fracture:
            raise ValueError("extensometer_removed_at must be in (0, 1) and the test "
                             "must go to fracture")
        if removed * self.max_force <= max(self.preload, self.proof_force or 0.0):
            raise ValueError("extensometer_removed_at must lie above the preload and "
                             "the proof force")

    @classmethod
    def for_chain(cls, name: str, E0: float | None = None, **settings) -> PullTruth:
        """A single pull of catalogue chain `name` with documented defaults.

        Parameters
        ----------
        name : str
            Catalogue chain, e.g. ``"18x64"``.
        E0 : float, optional
            True stiffness [N]; default the experimental value of Paper 001,
            Table 1 (for the four chains the paper tested).
        **settings
            Any other field of :class:`PullTruth`. Defaults: ``max_force``
            :data:`MAX_FORCE_MARGIN` times the minimum breaking force (the
            catalogue's ``breaking_force``, else :data:`MIN_BREAKING_FORCE_KN`),
            ``yield_force`` :data:`YIELD_RATIO` times ``max_force``, ``preload``
            the catalogue's (Paper 001), else 2 % of ``max_force``, gauge length
            5 pitches and free length 9 pitches.

        Raises
        ------
        KeyError
            For a chain the catalogue does not have.
        ValueError
            Without E0 or a breaking force to default to, or for invalid settings.
        """
        spec = chain(name)
        if E0 is None:
            published = table_1().get(name)
            if published is None:
                raise ValueError(f"no default E0 for chain {name!r} (not in Table 1): give E0")
            E0 = to_si(published.E0_exp_kgf, "kgf")
        if "max_force" not in settings:
            breaking = spec.get("breaking_force")
            if breaking is None and name not in MIN_BREAKING_FORCE_KN:
                raise ValueError(f"no breaking force for chain {name!r}: give max_force")
            breaking = breaking or to_si(MIN_BREAKING_FORCE_KN[name], "kN")
            settings["max_force"] = MAX_FORCE_MARGIN * breaking
        settings.setdefault("yield_force", YIELD_RATIO * settings["max_force"])
        settings.setdefault("preload", spec.get("preload", 0.02 * settings["max_force"]))
        settings.setdefault("gauge_length", 5 * spec["t"])
        settings.setdefault("free_length", 9 * spec["t"])
        return cls(E0=E0, **settings)

    def with_(self, **changes) -> PullTruth:
        """A copy with some fields changed."""
        return replace(self, **changes)

    # -- the material curve -------------------------------------------------------

    @property
    def yield_strain(self) -> float:
        """Material strain ``e_y`` at the proportional limit [1]."""
        return self.yield_force / self.E0

    @property
    def knee_exponent(self) -> float:
        """Exponent ``k_1`` of the knee [1] (> 1: the slope falls from E0)."""
        k = self.E0 * (self.max_force_strain - self.yield_strain) / (
            self.max_force - self.yield_force)
        return (k - 2 * (1 - self.knee_share)) / self.knee_share

    def _hardening(self, s: np.ndarray | float) -> np.ndarray:
        """Force [N] at the hardening fraction `s` in [0, 1] of the strain from e_y to e_m."""
        a = self.knee_share
        rest = a * (1 - s) ** self.knee_exponent + (1 - a) * (1 - s) ** 2
        return self.max_force - (self.max_force - self.yield_force) * rest

    @property
    def fracture_force(self) -> float:
        """Force at fracture, just before the drop [N]."""
        return self.max_force * (1 - self.neck_drop)

    @property
    def _steepest_neck_slope(self) -> float:
        """Slope of force over material strain at fracture [N] (negative)."""
        return -2 * (self.max_force - self.fracture_force) / (
            self.fracture_strain - self.max_force_strain)

    def force_at(self, strain: np.ndarray | float) -> np.ndarray:
        """Force [N] on the first-loading curve at material strain `strain` [1].

        Parameters
        ----------
        strain : array_like
            Material strain ``e`` [1], from 0 to :attr:`fracture_strain`.
        """
        e = np.asarray(strain, dtype=float)
        e_y, e_m = self.yield_strain, self.max_force_strain
        hardening = self._hardening(np.clip((e - e_y) / (e_m - e_y), 0.0, 1.0))
        neck = self.max_force - (self.max_force - self.fracture_force) * (
            np.clip(e - e_m, 0.0, None) / (self.fracture_strain - e_m)) ** 2
        return np.where(e <= e_y, self.E0 * e, np.where(e <= e_m, hardening, neck))

    def strain_at(self, force: float) -> float:
        """Material strain [1] where the rising curve reaches `force` [N] (< max_force)."""
        if force <= self.yield_force:
            return force / self.E0
        s = brentq(lambda s: float(self._hardening(s)) - force, 0.0, 1.0, xtol=1e-15)
        return self.yield_strain + s * (self.max_force_strain - self.yield_strain)

    # -- what the channels read ---------------------------------------------------

    @property
    def toe_force(self) -> float:
        """Force where the toe ends and all slack is taken up [N]."""
        return self.preload + self.toe_fraction * (self.max_force - self.preload)

    def _toe(self, force: np.ndarray, slack: float) -> np.ndarray:
        u = (np.asarray(force, dtype=float) - self.preload) / (self.max_force - self.preload)
        return toe_slack(np.clip(u, 0.0, None), slack, self.toe_fraction)

    def extensometer_strain(self, strain: np.ndarray | float) -> np.ndarray:
        """Extensometer strain [1] on first loading at material strain `strain` [1]."""
        e = np.asarray(strain, dtype=float)
        toe = self._toe(self.force_at(e), self.slack)
        return e - self.preload / self.E0 + toe / self.gauge_length

    def _crosshead(self, strain: np.ndarray, force: np.ndarray) -> np.ndarray:
        """Crosshead travel [m] at extensometer strain `strain` and force `force` [N]."""
        return (self.free_length * strain + self._toe(force, self.grip_slack)
                + self.machine_compliance * (force - self.preload))

    @property
    def machine_compliance(self) -> float:
        """Compliance of the machine ``C_m`` [m/N], :attr:`machine_share` of the crosshead's."""
        return self.machine_share / (1 - self.machine_share) * self.free_length / self.E0

    @property
    def crosshead_compliance(self) -> float:
        """Crosshead travel per force in the linear region [m/N]: specimen and machine."""
        return self.free_length / self.E0 + self.machine_compliance

    # -- truth accessors ----------------------------------------------------------

    @property
    def strain_at_max_force(self) -> float:
        """Extensometer strain at the maximum force [1]."""
        return float(self.extensometer_strain(self.max_force_strain))

    @property
    def strain_at_fracture(self) -> float:
        """Extensometer strain at fracture, just before the drop [1]."""
        return float(self.extensometer_strain(self.fracture_strain))

    @property
    def elongation_at_fracture(self) -> float:
        """Elongation of the gauge length at fracture, just before the drop [m]."""
        return self.gauge_length * self.strain_at_fracture

    def offset_yield_force(self, offset: float = 0.002) -> float:
        """Yield-like force by the offset method [N] (``offset = 0.002``: like Rp0.2).

        The force where the noise-free curve meets the line parallel to its
        linear region, shifted by `offset` along the extensometer strain:
        ``F = E0 (eps - eps_lin - offset)``, ``eps_lin`` the strain intercept
        of the linear region (the slack).

        Parameters
        ----------
        offset : float
            Offset strain [1], > 0.

        Raises
        ------
        ValueError
            If the curve does not meet the line before fracture.
        """
        if not offset > 0:
            raise ValueError(f"offset must be > 0, got {offset!r}")

        def gap(e: float) -> float:
            return float(self.force_at(e)) - self.E0 * (e - offset)

        if gap(self.fracture_strain) > 0:
            raise ValueError(f"the curve does not reach the offset line of {offset!r} "
                             "before fracture")
        root = brentq(gap, self.yield_strain, self.fracture_strain, xtol=1e-15, rtol=1e-15)
        return float(self.force_at(root))

    @property
    def elongation_at_proof(self) -> float | None:
        """Extensometer elongation at the proof force on loading [m] (None: no proof)."""
        if self.proof_force is None:
            return None
        e_p = self.strain_at(self.proof_force)
        return self.gauge_length * float(self.extensometer_strain(e_p))

    @property
    def permanent_set(self) -> float | None:
        """Extensometer elongation after the proof unloading, at the preload [m] (None: no proof).

        The slack and the plastic strain ``e_P - P / E0`` over the gauge length.
        """
        if self.proof_force is None:
            return None
        plastic = self.strain_at(self.proof_force) - self.proof_force / self.E0
        return self.gauge_length * plastic + self.slack

    def sample_times(self) -> np.ndarray:
        """Time stamps of the samples [s] (the first twice if :attr:`repeated_first_time`)."""
        duration = sum(phase.duration for phase in _phases(self))
        time = np.arange(int(np.floor(duration * self.sample_rate)) + 1) / self.sample_rate
        return np.concatenate([[0.0], time]) if self.repeated_first_time else time

    def event_time(self, name: str) -> float:
        """Start [s] of phase `name`: ``"hold"``, ``"unload"``, ``"pull"`` or ``"break"``.

        Raises
        ------
        KeyError
            If the test has no such phase.
        """
        start = 0.0
        for phase in _phases(self):
            if phase.name == name:
                return start
            start += phase.duration
        raise KeyError(f"the test has no {name!r} phase")

    @property
    def fracture_index(self) -> int | None:
        """Row of the first sample after fracture (None: no fracture).

        The force drops from this row on and is down to the residue from row
        ``fracture_index + fracture_samples``. Rows count from 0 and include a
        repeated first row.
        """
        if not self.to_fracture:
            return None
        return int(np.searchsorted(self.sample_times(), self.event_time("break"), side="right"))

    @property
    def max_force_time(self) -> float | None:
        """Time of the maximum force [s] (None: the test does not go to fracture)."""
        if not self.to_fracture:
            return None
        e_start = self.preload / self.E0 if self.proof_force is None else self.strain_at(
            self.proof_force)
        travel = np.diff(self._virgin_crosshead(np.array([e_start, self.max_force_strain])))
        return self.event_time("pull") + float(travel[0]) / self.crosshead_speed

    @property
    def removal_index(self) -> int | None:
        """Row of the first sample without the extensometer (None: never removed).

        The first sample before the maximum force whose noise-free force reaches
        ``extensometer_removed_at * max_force``; rows as in :attr:`fracture_index`.
        """
        if self.extensometer_removed_at is None:
            return None
        time = self.sample_times()
        force, _, _ = pull_curve(self, time)
        reached = (force >= self.extensometer_removed_at * self.max_force) & (
            time <= self.max_force_time)
        return int(np.argmax(reached))

    @property
    def removal_force(self) -> float | None:
        """Noise-free force at :attr:`removal_index` [N] (None: never removed)."""
        index = self.removal_index
        if index is None:
            return None
        return float(pull_curve(self, self.sample_times()[index : index + 1])[0][0])

    def _virgin_crosshead(self, strain: np.ndarray) -> np.ndarray:
        """Crosshead travel [m] on first loading at material strain `strain`."""
        return self._crosshead(self.extensometer_strain(strain), self.force_at(strain))

    def summary(self, offset: float = 0.002) -> dict[str, float | int | None]:
        """The true values a fit should recover, SI, JSON-ready (keys carry units).

        Parameters
        ----------
        offset : float
            Offset strain of ``offset_yield_force_N`` [1].
        """
        return {
            "E0_N": self.E0,
            "max_force_N": self.max_force,
            "strain_at_max_force": self.strain_at_max_force,
            "fracture_force_N": self.fracture_force if self.to_fracture else None,
            "strain_at_fracture": self.strain_at_fracture if self.to_fracture else None,
            "elongation_at_fracture_m": self.elongation_at_fracture if self.to_fracture else None,
            "proportional_limit_N": self.yield_force,
            "offset_yield_offset": offset,
            "offset_yield_force_N": self.offset_yield_force(offset),
            "proof_force_N": self.proof_force,
            "elongation_at_proof_m": self.elongation_at_proof,
            "permanent_set_m": self.permanent_set,
            "machine_compliance_m_per_N": self.machine_compliance,
            "machine_share": self.machine_share,
            "removal_index": self.removal_index,
            "removal_force_N": self.removal_force,
            "fracture_index": self.fracture_index,
            "n_samples": int(self.sample_times().size),
        }


class _Phase(NamedTuple):
    """One part of the test: its name, duration [s] and the noise-free channels in it."""

    name: str
    duration: float
    #: local times [s] -> force [N], extensometer elongation [m], crosshead [m]
    channels: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


#: Points of the grid on which the crosshead travel of first loading is inverted.
_GRID = 20001


def _virgin(truth: PullTruth, name: str, e_start: float, e_stop: float) -> _Phase:
    """First loading from material strain `e_start` to `e_stop` at constant crosshead speed."""
    knots = sorted({e_start, e_stop, *(e for e in (truth.yield_strain, truth.max_force_strain)
                                       if e_start < e < e_stop)})
    strain = np.unique(np.concatenate(
        [np.linspace(a, b, _GRID) for a, b in pairwise(knots)]))
    travel = truth._virgin_crosshead(strain)
    start = travel[0]

    def channels(tau: np.ndarray):
        e = np.interp(start + truth.crosshead_speed * tau, travel, strain)
        force = truth.force_at(e)
        eps = truth.extensometer_strain(e)
        return force, truth.gauge_length * eps, truth._crosshead(eps, force)

    return _Phase(name, (travel[-1] - start) / truth.crosshead_speed, channels)


def _elastic(truth: PullTruth, name: str, e_proof: float, downward: bool) -> _Phase:
    """Unloading (or reloading) on the elastic line between the preload and the proof force."""
    proof = truth.proof_force
    top = float(truth.extensometer_strain(e_proof))
    rate = truth.crosshead_speed / truth.crosshead_compliance  # force per time [N/s]

    def channels(tau: np.ndarray):
        fall = rate * tau if downward else (proof - truth.preload) - rate * tau
        force = proof - fall
        eps = top - fall / truth.E0
        return force, truth.gauge_length * eps, truth._crosshead(eps, force)

    return _Phase(name, (proof - truth.preload) / rate, channels)


def _hold(truth: PullTruth, e_proof: float) -> _Phase:
    force = truth.proof_force
    eps = float(truth.extensometer_strain(e_proof))
    travel = float(truth._crosshead(np.array(eps), np.array(force)))

    def channels(tau: np.ndarray):
        ones = np.ones(tau.shape)
        return force * ones, truth.gauge_length * eps * ones, travel * ones

    return _Phase("hold", truth.proof_hold, channels)


def _break(truth: PullTruth) -> _Phase:
    """Fracture: the force drops to the residue, the extensometer springs back."""
    before = truth.fracture_force
    eps = truth.strain_at_fracture
    travel = float(truth._virgin_crosshead(np.array(truth.fracture_strain)))
    residue = truth.fracture_residue * truth.max_force
    drop_time = truth.fracture_samples / truth.sample_rate

    def channels(tau: np.ndarray):
        force = before + (residue - before) * np.clip(tau / drop_time, 0.0, 1.0)
        extensometer = truth.gauge_length * (eps - (before - force) / truth.E0)
        return force, extensometer, travel + truth.crosshead_speed * tau

    return _Phase("break", truth.after_fracture, channels)


def _phases(truth: PullTruth) -> list[_Phase]:
    """The test, phase by phase."""
    e0 = truth.preload / truth.E0
    if truth.proof_force is None:
        return [_virgin(truth, "pull", e0, truth.fracture_strain), _break(truth)]
    e_proof = truth.strain_at(truth.proof_force)
    phases = [_virgin(truth, "load", e0, e_proof), _hold(truth, e_proof),
              _elastic(truth, "unload", e_proof, downward=True)]
    if truth.to_fracture:
        phases += [_elastic(truth, "reload", e_proof, downward=False),
                   _virgin(truth, "pull", e_proof, truth.fracture_strain), _break(truth)]
    return phases


def pull_curve(
    truth: PullTruth, time: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Noise-free force [N], extensometer elongation [m] and crosshead travel [m] at `time`.

    Parameters
    ----------
    truth : PullTruth
        The test.
    time : numpy.ndarray
        Times [s] from 0; beyond the end the last state is kept.

    Returns
    -------
    force, extensometer, crosshead : numpy.ndarray
        The true channels (the extensometer as if it stayed on).
    """
    time = np.asarray(time, dtype=float)
    force, extensometer, crosshead = (np.zeros(time.shape) for _ in range(3))
    start = 0.0
    phases = _phases(truth)
    for number, phase in enumerate(phases):
        last = number == len(phases) - 1
        inside = (time >= start) & ((time < start + phase.duration) | last)
        local = np.minimum(time[inside] - start, phase.duration)
        force[inside], extensometer[inside], crosshead[inside] = phase.channels(local)
        start += phase.duration
    return force, extensometer, crosshead


def _removed(truth: PullTruth, reading: np.ndarray, time: np.ndarray,
             rng: np.random.Generator) -> np.ndarray:
    """The extensometer channel after its removal at :attr:`PullTruth.removal_index`."""
    index = truth.removal_index
    if index is None:
        return reading
    reading = reading.copy()
    last = reading[index - 1]
    after = time[index:] - time[index - 1]
    if truth.removal_mode == "jump":
        reading[index:] = last + REMOVAL_JUMP + rng.normal(0.0, REMOVAL_NOISE, after.size)
    elif truth.removal_mode == "freeze":
        reading[index:] = last + rng.normal(0.0, truth.extensometer_noise, after.size)
    else:
        reading[index:] = last * (1 - 2 * np.clip(after / REMOVAL_FALL, 0.0, 1.0))
    return reading


def simulate_pull(truth: PullTruth, seed: int | None = None) -> pd.DataFrame:
    """Log of one virtual single pull (or proof-load test) in SI units.

    Parameters
    ----------
    truth : PullTruth
        Settings and true properties of the test.
    seed : int, optional
        Seed of the noise and the channels' zero offsets.

    Returns
    -------
    pandas.DataFrame
        Columns ``time`` [s], ``force`` [N], ``extensometer`` [m] (or
        ``extensometer_strain`` [1] with :attr:`PullTruth.strain_channel`) and
        ``crosshead`` [m], float64, one row per sample.

    Examples
    --------
    >>> truth = PullTruth.for_chain("18x64", sample_rate=2.0)
    >>> list(simulate_pull(truth, seed=1).columns)
    ['time', 'force', 'extensometer', 'crosshead']
    """
    rng = np.random.default_rng(seed)
    time = truth.sample_times()
    force, extensometer, crosshead = pull_curve(truth, time)
    force = force + rng.normal(0.0, truth.force_noise, time.size)
    extensometer = measured(extensometer, truth.extensometer_noise,
                            truth.extensometer_resolution, rng)
    extensometer = _removed(truth, extensometer, time, rng)
    crosshead = measured(crosshead, truth.crosshead_noise, truth.crosshead_resolution, rng)
    if truth.strain_channel:
        columns = {"extensometer_strain": extensometer / truth.gauge_length}
    else:
        columns = {"extensometer": extensometer}
    return pd.DataFrame({"time": time, "force": force, **columns, "crosshead": crosshead})
