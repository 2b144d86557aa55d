"""The virtual engagement bench: branch-tension logs of a chain wheel with known truth.

A round-link chain runs on a pocket wheel of ``z`` teeth at angular velocity
``omega``. Every seating period ``P = 2 pi / (z omega)`` a horizontal link seats
and strikes the wheel twice (Paper 000): the idle flank of one tooth (impact 1,
amplitude ``N_u1``) and, ``tau = pi / (z omega) = P / 2`` later, the working
flank of the next tooth (impact 2, ``N_u2``), with ``N_u1, N_u2`` from eq. (16)
with (1)-(2) (:func:`pipeline.theory.wheel_impact.impact_tensions`). Each strike
rings the active branch as a damped oscillation and the responses superpose.

The signal
----------
With ``T1_m = t_0 + m P + j_m`` the seating times (``j_m`` the seating jitter,
normal with standard deviation ``jitter``) and ``T2_m = T1_m + tau``::

    force(t) = pretension + polygon_amplitude cos(2 pi (t - t_0) / P)
               + sum_m sum_i A_im h(t - Ti_m) + noise
    h(s) = exp(-zeta omega_n s) sin(omega_d s) for s >= 0, 0 before,
    omega_d = omega_n sqrt(1 - zeta^2)

``A_im = N_ui (1 + amplitude_scatter e_im)``, ``e_im`` standard normal. The
noise is white and normal with standard deviation ``N_u1 / snr``. Strikes start
long before the log does (the branch is already ringing in steady state at
``t = 0``). The sum is evaluated exactly (no truncation of the responses) as a
first-order complex recursion driven by the strikes at their fractional sample
times, in O(n) (:func:`scipy.signal.lfilter`): 10^7 samples take about a second.

Optional channels: ``angle`` [rad], the wheel angle wrapped to [0, 2 pi), equal
to ``impact_angle + m 2 pi / z`` at the nominal (jitter-free) impact-1 times;
clipping: the force channel saturates at ``clip_level``.

Writers: :func:`write_engagement_csv` (plain CSV, units in brackets, the layout
:mod:`pipeline.ingest` reads) and :func:`write_engagement_tdms` (NI TDMS, time
from the waveform properties ``wf_start_offset`` / ``wf_increment``).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.theory.wheel_impact import (
    RYABOV_MASS_SHARE,
    impact_tensions,
    impact_velocities,
    seating_period,
    time_between_impacts,
)

#: Number of decay times ``1 / (zeta omega_n)`` of strikes simulated before the
#: log starts, so that the first samples ring in steady state (e^-20 ~ 2e-9).
_SETTLING_DECAY_TIMES = 20.0


@dataclass(frozen=True)
class EngagementSettings:
    """Operating point, branch and measurement of one virtual engagement run (SI units).

    Defaults are Paper 000's example: chain 18x64 (6.6 kg/m), E0 = 2.26e7 N,
    branch 2 m, k = 2 (Ryabov), z = 8, psi = 40 deg, omega = 20 1/s.

    Parameters
    ----------
    z : int
        Number of teeth (pockets) of the wheel [-].
    psi : float
        Tooth apex angle [rad].
    omega : float
        Angular velocity of the wheel [1/s].
    t, d : float
        Chain pitch and bar diameter [m].
    mass_per_length : float
        Chain mass per metre q/g [kg/m].
    E0 : float
        Chain stiffness [N].
    branch_length : float
        Length L of the active branch [m].
    k : float
        Share of link masses in the impact [-] (Ryabov: 2; any value > 0).
    pretension : float
        Mean branch tension [N].
    polygon_amplitude : float
        Amplitude of the polygon effect [N]: a sinusoid at the seating frequency
        ``z omega / (2 pi)``.
    damping_ratio : float
        Damping ratio zeta of the branch [-], in (0, 1).
    natural_frequency : float, optional
        Undamped natural angular frequency omega_n of the branch [rad/s];
        default ``sqrt(E0 / (L m_branch))`` with ``m_branch = mass_per_length L``
        (about 2 pi 147 Hz for the defaults).
    sample_rate : float
        Logging rate [Hz].
    duration : float
        Length of the log [s].
    snr : float
        Amplitude of the weaker strike N_u1 over the standard deviation of the
        white noise [-] (an amplitude ratio, not dB); ``math.inf`` for no noise.
    jitter : float
        Standard deviation of the seating times about the nominal grid [s]
        (both strikes of a seating move together).
    amplitude_scatter : float
        Relative standard deviation of each strike's amplitude about N_u [-].
    with_angle : bool
        Whether the log has a wheel-angle channel ``angle`` [rad].
    clip_level : float, optional
        Saturation level of the force channel [N]; None for no clipping.
    """

    z: int = 8
    psi: float = math.radians(40.0)
    omega: float = 20.0
    t: float = 0.064
    d: float = 0.018
    mass_per_length: float = 6.6
    E0: float = 2.26e7
    branch_length: float = 2.0
    k: float = RYABOV_MASS_SHARE
    pretension: float = 20e3
    polygon_amplitude: float = 500.0
    damping_ratio: float = 0.03
    natural_frequency: float | None = None
    sample_rate: float = 20e3
    duration: float = 2.0
    snr: float = 20.0
    jitter: float = 1e-4
    amplitude_scatter: float = 0.0
    with_angle: bool = True
    clip_level: float | None = None

    def __post_init__(self) -> None:
        positive = ("psi", "omega", "t", "d", "mass_per_length", "E0", "branch_length", "k",
                    "sample_rate", "duration", "snr")
        for name in positive:
            value = getattr(self, name)
            if not (isinstance(value, int | float) and value > 0):
                raise ValueError(f"{name} must be a number > 0, got {value!r}")
        for name in ("pretension", "polygon_amplitude", "jitter", "amplitude_scatter"):
            value = getattr(self, name)
            if not (isinstance(value, int | float) and math.isfinite(value) and value >= 0):
                raise ValueError(f"{name} must be a finite number >= 0, got {value!r}")
        if not 0 < self.damping_ratio < 1:
            raise ValueError(f"damping_ratio must be in (0, 1), got {self.damping_ratio!r}")
        if self.natural_frequency is not None and not self.natural_frequency > 0:
            raise ValueError(f"natural_frequency must be > 0, got {self.natural_frequency!r}")
        if self.omega_n >= np.pi * self.sample_rate:
            raise ValueError(
                f"sample_rate {self.sample_rate!r} Hz is below twice the branch's natural "
                f"frequency {self.omega_n / (2 * np.pi):.4g} Hz"
            )
        # Validates z, psi, t, d the way the theory does (ValueError naming the parameter).
        impact_velocities(self.t, self.d, self.z, self.psi, self.omega)

    def with_(self, **changes) -> EngagementSettings:
        """A copy with some fields changed."""
        return replace(self, **changes)

    @property
    def omega_n(self) -> float:
        """Undamped natural angular frequency of the branch [rad/s]."""
        if self.natural_frequency is not None:
            return float(self.natural_frequency)
        branch_mass = self.mass_per_length * self.branch_length
        return math.sqrt(self.E0 / (self.branch_length * branch_mass))

    @property
    def seating_period(self) -> float:
        """Seating period 2 pi / (z omega) [s] (Paper 000, eq. (9))."""
        return float(seating_period(self.z, self.omega))

    @property
    def tau(self) -> float:
        """Time between impact 1 and impact 2, pi / (z omega) [s] (Paper 000)."""
        return float(time_between_impacts(self.z, self.omega))

    def impact_tensions(self) -> tuple[float, float]:
        """N_u1, N_u2 [N] of Paper 000, eq. (16) with (1)-(2), for these settings."""
        n_u1, n_u2 = impact_tensions(self.t, self.d, self.z, self.psi, self.omega,
                                     self.mass_per_length, self.E0, self.branch_length, self.k)
        return float(n_u1), float(n_u2)


def strike_response(amplitudes, onsets, time: np.ndarray, omega_n: float, zeta: float):
    """Superposed responses ``sum_i A_i h(time - onset_i)`` of strikes on a uniform grid.

    Parameters
    ----------
    amplitudes : array_like
        Strike amplitudes A_i [N].
    onsets : array_like
        Strike times [s], any order, may lie before the grid.
    time : numpy.ndarray
        Uniform sample times [s], increasing.
    omega_n : float
        Undamped natural angular frequency [rad/s].
    zeta : float
        Damping ratio [-], in (0, 1).

    Returns
    -------
    numpy.ndarray
        The response [N] at `time`, with ``h(s) = exp(-zeta omega_n s) sin(omega_d s)``
        for ``s >= 0`` (0 before), ``omega_d = omega_n sqrt(1 - zeta^2)``.

    Notes
    -----
    With ``lambda = -zeta omega_n + i omega_d`` the response is the imaginary part of
    ``s(t) = sum_{T_i <= t} A_i exp(lambda (t - T_i))``, which obeys
    ``s_j = exp(lambda dt) s_{j-1} + u_j`` with ``u_j`` the strikes falling in
    ``(t_{j-1}, t_j]`` propagated to ``t_j``: exact, O(n).
    """
    from scipy.signal import lfilter  # here: scipy.signal takes ~1 s to import

    amplitudes = np.asarray(amplitudes, dtype=float)
    onsets = np.asarray(onsets, dtype=float)
    dt = (time[-1] - time[0]) / (time.size - 1) if time.size > 1 else 1.0
    lam = complex(-zeta * omega_n, omega_n * math.sqrt(1.0 - zeta**2))
    index = np.ceil((onsets - time[0]) / dt).astype(np.int64)
    before = index <= 0
    drive = np.zeros(time.size, dtype=complex)
    # Strikes before the first sample: their state at time[0].
    drive[0] = np.sum(amplitudes[before] * np.exp(lam * (time[0] - onsets[before])))
    inside = ~before & (index < time.size)
    sample = index[inside]
    np.add.at(drive, sample,
              amplitudes[inside] * np.exp(lam * (time[0] + sample * dt - onsets[inside])))
    state = lfilter([1.0], [1.0, -np.exp(lam * dt)], drive)
    return state.imag


def simulate_engagement(
    settings: EngagementSettings, seed: int | None = None
) -> tuple[pd.DataFrame, dict]:
    """Log of one virtual engagement run in the canonical SI layout, and its truth.

    Parameters
    ----------
    settings : EngagementSettings
        Operating point, branch and measurement.
    seed : int, optional
        Seed of the random phase, jitter, amplitude scatter and noise.

    Returns
    -------
    table : pandas.DataFrame
        Columns ``time`` [s], ``force`` [N] (the branch tension) and, when
        ``settings.with_angle``, ``angle`` [rad]; float64, one row per sample.
    truth : dict
        ``N_u1``, ``N_u2`` [N] (model amplitudes, eq. (16)), ``v_u1``, ``v_u2``
        [m/s], ``tau``, ``seating_period`` [s], ``omega_n`` [rad/s], ``zeta``,
        ``noise_std`` [N], ``impact_angle`` [rad], ``settings`` (a dict), and per
        seating whose impact 1 lies in the log: ``event_time`` (impact 1) and
        ``impact2_time`` [s], ``N_u1_event``, ``N_u2_event`` and ``baseline_event``
        (pretension + polygon effect at impact 1) [N], ``clipped_event`` (bool:
        the force reached ``clip_level`` within one period after impact 1).

    Examples
    --------
    >>> table, truth = simulate_engagement(EngagementSettings(duration=0.5), seed=1)
    >>> list(table.columns), round(truth["N_u2"])
    (['time', 'force', 'angle'], 3423)
    """
    s = settings
    rng = np.random.default_rng(seed)
    n_u1, n_u2 = s.impact_tensions()
    v_u1, v_u2 = impact_velocities(s.t, s.d, s.z, s.psi, s.omega)
    period, tau, omega_n, zeta = s.seating_period, s.tau, s.omega_n, s.damping_ratio
    n_samples = int(math.floor(s.duration * s.sample_rate)) + 1
    time = np.arange(n_samples) / s.sample_rate

    t0 = rng.uniform(0.0, period)  # first nominal impact 1 at or after t = 0
    first = -math.ceil(_SETTLING_DECAY_TIMES / (zeta * omega_n) / period)
    last = math.ceil((time[-1] - t0) / period)
    cycle = np.arange(first, last + 1)
    nominal = t0 + cycle * period
    onset1 = nominal + rng.normal(0.0, s.jitter, cycle.size) if s.jitter > 0 else nominal
    onset2 = onset1 + tau
    scatter = (rng.standard_normal((2, cycle.size)) * s.amplitude_scatter
               if s.amplitude_scatter > 0 else np.zeros((2, cycle.size)))
    amp1, amp2 = n_u1 * (1.0 + scatter[0]), n_u2 * (1.0 + scatter[1])

    ringing = strike_response(np.concatenate([amp1, amp2]), np.concatenate([onset1, onset2]),
                              time, omega_n, zeta)
    phase = 2.0 * np.pi * (time - t0) / period
    force = s.pretension + s.polygon_amplitude * np.cos(phase) + ringing
    noise_std = n_u1 / s.snr if math.isfinite(s.snr) else 0.0
    if noise_std > 0:
        force += rng.normal(0.0, noise_std, n_samples)
    clipped = np.zeros(cycle.size, dtype=bool)
    if s.clip_level is not None:
        hit = np.flatnonzero(force >= s.clip_level)
        start_index = np.ceil(onset1 * s.sample_rate).astype(np.int64)
        clipped = (np.searchsorted(hit, start_index + int(period * s.sample_rate))
                   > np.searchsorted(hit, start_index))
        np.minimum(force, s.clip_level, out=force)

    columns = {"time": time, "force": force}
    impact_angle = rng.uniform(0.0, 2.0 * np.pi / s.z)
    if s.with_angle:
        columns["angle"] = np.mod(impact_angle + s.omega * (time - t0), 2.0 * np.pi)

    in_log = (onset1 >= 0.0) & (onset1 <= time[-1])
    baseline = s.pretension + s.polygon_amplitude * np.cos(2.0 * np.pi * (onset1 - t0) / period)
    truth = {
        "N_u1": n_u1, "N_u2": n_u2, "v_u1": float(v_u1), "v_u2": float(v_u2),
        "tau": tau, "seating_period": period, "omega_n": omega_n, "zeta": zeta,
        "noise_std": noise_std, "impact_angle": impact_angle, "seating_origin": t0,
        "settings": asdict(s),
        "event_time": onset1[in_log], "impact2_time": onset2[in_log],
        "N_u1_event": amp1[in_log], "N_u2_event": amp2[in_log],
        "baseline_event": baseline[in_log], "clipped_event": clipped[in_log],
    }
    return pd.DataFrame(columns), truth


def write_engagement_csv(table: pd.DataFrame, path: str | Path) -> Path:
    """Write an engagement log as plain CSV with units in brackets.

    :func:`pipeline.simulate.export.write_table` writes tensile logs (force and
    gauges); this writes the engagement layout, fast enough for 10^7 rows
    (pyarrow).

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table (``time`` [s], ``force`` [N], optional ``angle`` [rad]).
    path : str or Path
        File to write.

    Returns
    -------
    Path
        `path`: header ``time [s],force [N],angle [rad]``, then one row per
        sample, numbers in their shortest round-trip form.
    """
    import pyarrow as pa
    import pyarrow.csv as pa_csv

    path = Path(path)
    units = {"time": "s", "force": "N", "angle": "rad"}
    roles = [role for role in units if role in table]
    body = pa.table({role: table[role].to_numpy(dtype=float) for role in roles})
    with path.open("wb") as stream:
        stream.write((",".join(f"{role} [{units[role]}]" for role in roles) + "\n").encode())
        pa_csv.write_csv(body, stream, pa_csv.WriteOptions(include_header=False))
    return path


#: TDMS group and channel names written by :func:`write_engagement_tdms`.
TDMS_GROUP = "Engagement"
TDMS_CHANNELS = {"force": "Branch tension", "angle": "Wheel angle"}


def write_engagement_tdms(table: pd.DataFrame, path: str | Path) -> Path:
    """Write an engagement log as NI TDMS, time carried by the waveform properties.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table with a uniform ``time`` [s] column, ``force`` [N] and
        optional ``angle`` [rad].
    path : str or Path
        File to write.

    Returns
    -------
    Path
        `path`: group :data:`TDMS_GROUP`, channels ``"Branch tension"`` (unit
        ``N``) and ``"Wheel angle"`` (``rad``), each with ``wf_start_offset`` [s],
        ``wf_increment`` [s], ``wf_samples`` and ``unit_string``; no time channel.
    """
    from nptdms import ChannelObject, GroupObject, RootObject, TdmsWriter

    path = Path(path)
    time = table["time"].to_numpy()
    increment = (time[-1] - time[0]) / (time.size - 1) if time.size > 1 else 1.0
    units = {"force": "N", "angle": "rad"}
    channels = [
        ChannelObject(TDMS_GROUP, TDMS_CHANNELS[role], table[role].to_numpy(), properties={
            "wf_start_offset": float(time[0]), "wf_increment": float(increment),
            "wf_samples": int(time.size), "unit_string": units[role],
        })
        for role in ("force", "angle") if role in table
    ]
    with TdmsWriter(path) as writer:
        writer.write_segment([RootObject({"title": "chainbench virtual engagement bench"}),
                              GroupObject(TDMS_GROUP), *channels])
    return path
