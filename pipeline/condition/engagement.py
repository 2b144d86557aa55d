"""Engagement-event detection in a branch-tension log (condition stage).

An engagement log (``docs/file-formats.md``, "What the logs contain") holds the
tension of the active chain branch, and optionally the wheel angle, at a fixed
operating point. Every seating period ``P = 2 pi / (z omega)`` a horizontal link
seats and strikes the wheel twice, ``tau = pi / (z omega) = P / 2`` apart
(Paper 000): the idle flank (impact 1), then the working flank of the next
tooth (impact 2). This module holds the signal steps that locate both strikes
of every seating, to about a millisecond, and the :class:`EngagementEvents`
they give; :mod:`pipeline.condition.scan` composes them chunk by chunk (set-up,
scan, merge) and :mod:`pipeline.fit.impact` refines the times to a fraction of
a sample and extracts the impact tensions.

How
---
1. The branch's natural frequency is estimated from the spectrum of the head of
   the log (of its first difference, so the slow tension does not leak over it),
   or searched near a given one.
2. Onset strength: the log is block-averaged to about 10 samples per ringing
   period, its slow part (pretension, polygon effect) removed, and an inverse
   filter of the branch's ringing mode applied (the second-order prediction
   error ``e_j = x_j - 2 r cos(omega_d dt) x_{j-1} + r^2 x_{j-2}``,
   ``r = exp(-zeta omega_n dt)``). Free ringing, however many strikes are
   superposed in it, predicts itself and vanishes; the start of a new strike does
   not, so ``e^2`` peaks at every strike onset.
3. Seatings: from the **angle channel** when there is one (the measured speed,
   every tooth passage interpolated from the unwrapped angle, the angular phase
   of the strikes found by folding the onset strength over the tooth pitch
   angle ``2 pi / z``, or given as `impact_angle`; each seating then placed at
   the strongest onset within an eighth of a period of where the angle puts it,
   which follows the seating jitter); otherwise from the **force** itself (the
   period from the autocorrelation of the onset strength, then the strongest
   onset of every period). Folds and autocorrelations use the onset strengths
   capped at their 99th percentile, so a glitch cannot outweigh the strikes.
4. Impact 2 is the stronger strike of a seating: ``v_u2 > v_u1`` for every
   wheel (Paper 000, eqs. (1)-(2): ``(t + d) sin(pi/z + psi/2) > (t - d)
   sin(psi/2)``); impact 1 lies ``P / 2`` before it.
5. The measured period is checked against the run sheet's ``2 pi / (z omega)``:
   a disagreement beyond `period_tolerance` gives a :class:`SpeedMismatchWarning`
   (also kept in :attr:`EngagementEvents.messages`) and detection goes on with the
   measured period.

Logs shorter than :data:`MIN_PERIODS` seating periods, with gaps in time or
without data raise :class:`~pipeline.errors.SignalError` with a hint.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.signal import find_peaks, welch

from pipeline.errors import SignalError
from pipeline.theory.wheel_impact import seating_period

#: Fewest seating periods a log must hold for events to be detected and checked.
MIN_PERIODS = 5

#: Relative difference between measured and stated seating period above which a
#: :class:`SpeedMismatchWarning` is given (2 %: a lab's speed is set to about 1 %).
PERIOD_TOLERANCE = 0.02

#: Damping ratio assumed by the onset filter [-]: chain branches ring with a few
#: per cent (``docs/file-formats.md``); the filter is insensitive to it.
ASSUMED_DAMPING = 0.03

#: Sampling rate an engagement log is advised to have, at the least [Hz]: a chain branch
#: rings at some hundred hertz, and its ringing needs ten samples a period.
ADVISED_SAMPLE_RATE = 5e3

#: Samples per ringing period of the block-averaged signal used for the onsets.
SAMPLES_PER_RINGING = 10

#: Seating periods at the head of a log that the period (autocorrelation of the
#: onsets) and the strikes' angular phase (fold over the tooth pitch) are found from.
HEAD_PERIODS = 200

#: Welch segments at the head of a log that the natural frequency is estimated from.
SPECTRUM_SEGMENTS = 64


class SpeedMismatchWarning(UserWarning):
    """The seating period of a log disagrees with the speed stated in the run sheet."""


@dataclass(frozen=True)
class EngagementEvents:
    """Seatings detected in one engagement log.

    Attributes
    ----------
    impact1_time, impact2_time : numpy.ndarray
        Onset of impact 1 (idle flank) and impact 2 (working flank) of every
        seating found [s], to about :attr:`onset_resolution`.
    seating_period : float
        Mean seating period measured in the log [s].
    stated_period : float
        ``2 pi / (z omega)`` from the run sheet's teeth and speed [s].
    omega : float
        Wheel speed measured in the log, ``2 pi / (z P)`` [1/s].
    stated_omega : float
        Wheel speed stated in the run sheet [1/s].
    z : int
        Number of teeth [-].
    sample_rate : float
        Sampling rate of the log [Hz].
    start_time : float
        Time of the first sample [s].
    n_samples : int
        Samples in the log.
    natural_frequency : float
        First estimate of the branch's natural angular frequency [rad/s].
    source : str
        ``"angle"`` (seatings from the angle channel) or ``"force"``.
    onset_resolution : float
        Resolution of the onset times [s] (one averaged block).
    messages : tuple of str
        Warnings given during detection (e.g. the speed mismatch).
    """

    impact1_time: np.ndarray
    impact2_time: np.ndarray
    seating_period: float
    stated_period: float
    omega: float
    stated_omega: float
    z: int
    sample_rate: float
    start_time: float
    n_samples: int
    natural_frequency: float
    source: str
    onset_resolution: float
    messages: tuple[str, ...] = ()

    @property
    def tau(self) -> float:
        """Nominal time between impact 1 and impact 2, half the measured period [s]."""
        return self.seating_period / 2

    @property
    def count(self) -> int:
        """Number of seatings found."""
        return int(self.impact1_time.size)


def sampling(table: pd.DataFrame, file: str | Path | None = None) -> tuple[float, float]:
    """Start time [s] and sampling rate [Hz] of a uniformly sampled log.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table with a ``time`` column [s].
    file : str or Path, optional
        The log's file, for error messages.

    Returns
    -------
    start_time, sample_rate : float

    Raises
    ------
    SignalError
        No ``time`` column, fewer than 3 samples, a non-finite or non-increasing
        time, or a gap (a step off the mean step by more than half a step).
    """
    if "time" not in table:
        raise SignalError("the engagement log has no time channel", file=file, column="time",
                          hint="map the time column in the run sheet (columns = {time = ...})")
    time = table["time"].to_numpy(dtype=float)
    if time.size < 3:
        raise SignalError(f"the engagement log holds {time.size} samples", file=file,
                          hint="check that the file is complete")
    step = (time[-1] - time[0]) / (time.size - 1)
    if not (np.isfinite(step) and step > 0):
        raise SignalError("the time channel does not increase", file=file, column="time",
                          hint="check the time column and its unit")
    check_uniform(time, step, file)
    return float(time[0]), float(1.0 / step)


def check_uniform(time: np.ndarray, step: float, file: str | Path | None = None,
                  first: int = 0) -> None:
    """Check that every step of `time` lies within half a step of `step`.

    Parameters
    ----------
    time : numpy.ndarray
        Sample times [s], at least 2.
    step : float
        Mean time step of the whole log [s].
    file : str or Path, optional
        The log's file, for error messages.
    first : int, optional
        Index of ``time[0]`` in the whole log (errors name samples of the log).

    Raises
    ------
    SignalError
        At the worst step, when one is off (or not finite).
    """
    steps = np.diff(time)
    if not (steps.min() >= 0.5 * step and steps.max() <= 1.5 * step):  # also catches NaN
        deviation = np.abs(steps - step)
        worst = int(np.argmax(np.where(np.isfinite(deviation), deviation, np.inf)))
        missed = steps[worst] / step - 1
        lost = (f"{round(missed)} sample(s) missing there (the logger dropped them); "
                if missed > 0.5 and abs(missed - round(missed)) < 0.1 else "")
        raise SignalError(
            f"the log is not uniformly sampled: time goes from {time[worst]:.9g} to "
            f"{time[worst + 1]:.9g} s (samples {first + worst + 1} to {first + worst + 2}) "
            f"where the mean step is {step:.6g} s", file=file, column="time",
            hint=f"{lost}a gap or a repeated block in the recording: an engagement log must be "
                 "sampled at one rate throughout (a data acquisition card's own clock); export "
                 "the log again or cut it into uniformly sampled pieces")


def spectrum_segment(sample_rate: float, period: float) -> int:
    """Samples per Welch segment of :func:`natural_frequency_estimate`: about one period.

    A power of 2 of at least 64 samples, `period` [s] at `sample_rate` [Hz].
    """
    return int(2 ** math.ceil(math.log2(max(64.0, sample_rate * period))))


def natural_frequency_estimate(force: np.ndarray, sample_rate: float, period: float,
                               near: float | None = None,
                               file: str | Path | None = None) -> float:
    """First estimate of the branch's natural angular frequency from the log's spectrum.

    Parameters
    ----------
    force : numpy.ndarray
        Branch tension [N] (NaN-free).
    sample_rate : float
        Sampling rate [Hz].
    period : float
        Seating period [s]: the spectrum is searched above 1.5 seating frequencies.
    near : float, optional
        Expected natural angular frequency [rad/s] (e.g. ``sqrt(E0 / (L m_branch))``):
        the search is narrowed to 0.6-1.6 times it.
    file : str or Path, optional
        The log's file, for error messages.

    Returns
    -------
    float
        The peak of the Welch power spectrum of the first difference of the
        force (segments about one seating period long, so that the lines of the
        seating harmonics merge into the branch's resonance), parabolically
        interpolated [rad/s]; good to about 10 %.
    """
    segment = spectrum_segment(sample_rate, period)
    # The first difference weights the spectrum by frequency^2: the slow tension
    # (polygon effect, load changes) no longer leaks over the branch's resonance.
    head = np.diff(force[: min(force.size, SPECTRUM_SEGMENTS * segment + 1)])
    frequency, power = welch(head, fs=sample_rate, nperseg=min(segment, head.size))
    low, high = 1.5 / period, 0.4 * sample_rate
    if near is not None:
        low, high = 0.6 * near / (2 * np.pi), min(high, 1.6 * near / (2 * np.pi))
    band = np.flatnonzero((frequency >= low) & (frequency <= high))
    if band.size == 0:
        where = (f"no spectrum between {low:.4g} and {high:.4g} Hz to find the branch's "
                 "ringing in" if low < high else
                 f"the branch's ringing, expected above {low:.4g} Hz, lies beyond what "
                 f"{sample_rate:.4g} samples a second can show (up to {high:.4g} Hz)")
        raise SignalError(
            where, file=file, hint="the sampling rate is too low for this branch and speed; log at "
                            f"{ADVISED_SAMPLE_RATE / 1e3:g} kHz or more")
    peak = band[np.argmax(power[band])]
    f_peak = frequency[peak]
    if 0 < peak < frequency.size - 1:
        left, centre, right = np.log(power[peak - 1: peak + 2] + 1e-300)
        curvature = left - 2 * centre + right
        if curvature < 0:
            f_peak += 0.5 * (left - right) / curvature * (frequency[1] - frequency[0])
    return float(2 * np.pi * f_peak)


def onset_strength(force: np.ndarray, block: int, sample_rate: float, omega_n: float,
                   zeta: float = ASSUMED_DAMPING) -> np.ndarray:
    """Strike-onset strength per block of `block` samples (see the module notes, step 2).

    Parameters
    ----------
    force : numpy.ndarray
        Branch tension [N] (NaN-free).
    block : int
        Samples averaged per block.
    sample_rate : float
        Sampling rate [Hz].
    omega_n : float
        Natural angular frequency of the branch [rad/s].
    zeta : float, optional
        Damping ratio [-].

    Returns
    -------
    numpy.ndarray
        ``e_j^2 + e_{j+1}^2`` [N^2] per block ``j``: large at the block where a
        strike starts and the next one, small in free ringing.
    """
    blocks = force.size // block
    x = force[: blocks * block].reshape(blocks, block).mean(axis=1)
    dt = block / sample_rate
    ringing_blocks = max(3, int(round(2 * np.pi / omega_n / dt)))
    kernel = np.ones(ringing_blocks) / ringing_blocks
    x = x - np.convolve(np.pad(x, ringing_blocks // 2, mode="edge"), kernel, mode="valid")[:blocks]
    r = math.exp(-zeta * omega_n * dt)
    a1 = 2 * r * math.cos(omega_n * math.sqrt(1 - zeta**2) * dt)
    error = np.zeros(blocks)
    error[2:] = x[2:] - a1 * x[1:-1] + r * r * x[:-2]
    strength = error**2
    strength[:-1] += strength[1:]
    strength[:3] = 0.0
    return strength


def _winsorized(strength: np.ndarray) -> np.ndarray:
    """Onset strengths capped at their 99th percentile, so a glitch weighs like one strike.

    A seating's two onsets fill some 3 % of the blocks (tau / block ~ 30): the cap
    lies among the strikes, and a single step or spike of any size cannot
    outweigh them in a fold or an autocorrelation.
    """
    return np.minimum(strength, np.percentile(strength, 99))


def period_from_autocorrelation(strength: np.ndarray, dt: float, stated: float) -> float:
    """Seating period [s] from the autocorrelation of the onsets at 0.25-4 stated periods.

    The onsets are smoothed over 5 blocks first (so that a peak does not hinge on
    where the period falls between two lags); the period is the shortest lag whose
    correlation reaches 70 % of the highest (multiples of the period correlate as
    well as the period; half the period, impact 1 against impact 2, reaches at most
    2 r / (1 + r^2) < 25 % of it, r > 10 the ratio of their onset strengths).
    """
    head = _winsorized(strength[: min(strength.size, int(HEAD_PERIODS * stated / dt))])
    x = np.convolve(head, np.ones(5) / 5, mode="same")
    x -= x.mean()
    size = 2 ** math.ceil(math.log2(2 * x.size))
    spectrum = np.fft.rfft(x, size)
    correlation = np.fft.irfft(spectrum * np.conj(spectrum), size)[: x.size]
    low = max(2, int(0.25 * stated / dt))
    high = min(int(4 * stated / dt), int(0.6 * x.size))
    if high <= low + 2:
        return stated
    window = correlation[low:high]
    peaks, _ = find_peaks(window, height=0.7 * window.max())
    lag = low + int(peaks[0] if peaks.size else np.argmax(window))
    left, centre, right = correlation[lag - 1: lag + 2]
    curvature = left - 2 * centre + right
    shift = 0.5 * (left - right) / curvature if curvature < 0 else 0.0
    return float((lag + shift) * dt)


def block_size(rate: float, omega_n: float) -> int:
    """Samples averaged per block of the onset strength: about a tenth of a ringing period.

    Parameters
    ----------
    rate : float
        Sampling rate [Hz].
    omega_n : float
        Natural angular frequency of the branch [rad/s].

    Returns
    -------
    int
        At least 1.
    """
    return max(1, int(rate * 2 * np.pi / omega_n / SAMPLES_PER_RINGING))


def onset_peaks(strength: np.ndarray, dt: float, guess: float) -> tuple[np.ndarray, np.ndarray]:
    """Blocks of the strongest onset of every period, and their strengths.

    Peaks of `strength` at least ``0.7 guess`` apart (`guess` the seating period
    [s], `dt` the block duration [s]); :func:`strong_peaks` then drops the weak ones.
    """
    peaks, props = find_peaks(strength, distance=max(1, int(0.7 * guess / dt)), height=0.0)
    return peaks, props["peak_heights"]


def strong_peaks(heights: np.ndarray) -> np.ndarray:
    """Mask of the peaks of at least a fifth of the median strength (the seatings)."""
    return heights >= 0.2 * np.median(heights) if heights.size else np.ones(0, dtype=bool)


def period_from_onsets(onsets: np.ndarray, guess: float) -> float:
    """Mean seating period [s]: least-squares slope of the onsets [s] over their cycles.

    Cycle numbers count the periods of `guess` [s] between onsets, so missed
    seatings are skipped; `guess` itself with fewer than 2 onsets.
    """
    if onsets.size < 2:
        return guess
    cycle = np.concatenate([[0.0], np.cumsum(np.maximum(1, np.round(np.diff(onsets) / guess)))])
    centred = cycle - cycle.mean()
    return float(np.dot(centred, onsets - onsets.mean()) / np.dot(centred, centred))


def _strongest_near(strength: np.ndarray, block_time: np.ndarray, expected: np.ndarray,
                    half_width: float) -> np.ndarray:
    """Time [s] of the block with the strongest onset within `half_width` [s] of each expected."""
    dt = block_time[1] - block_time[0]
    half = max(1, int(half_width / dt))
    centre = np.clip(np.round((expected - block_time[0]) / dt).astype(np.int64), half,
                     strength.size - half - 1)
    windows = np.lib.stride_tricks.sliding_window_view(strength, 2 * half + 1)
    return block_time[centre - half + np.argmax(windows[centre - half], axis=1)]


def unwrapped_angle(angle: np.ndarray, angle_time: np.ndarray,
                    file: str | Path | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and unwrapped angle [rad] of the finite samples of an angle channel.

    Raises
    ------
    SignalError
        When fewer than 3 samples are finite.
    """
    finite = np.isfinite(angle)
    if finite.sum() < 3:
        raise SignalError("the angle channel holds no data", file=file, column="angle",
                          hint="remove the angle mapping from the run sheet to detect the "
                               "seatings from the force alone")
    return angle_time[finite], np.unwrap(angle[finite])


def angle_slope(t: np.ndarray, theta: np.ndarray) -> float:
    """Least-squares slope of the unwrapped angle `theta` [rad] over `t` [s]: the speed [1/s]."""
    centred = t - t.mean()
    return float(np.dot(centred, theta - theta.mean()) / np.dot(centred, centred))


def angle_track(t: np.ndarray, theta: np.ndarray, slope: float, z: int,
                file: str | Path | None = None) -> np.ndarray:
    """The unwrapped angle turned forward (sign of `slope`) and made non-decreasing [rad].

    Raises
    ------
    SignalError
        When the angle advances by less than one tooth pitch ``2 pi / z`` over `t`.
    """
    if not abs(slope) * (t[-1] - t[0]) > 2 * np.pi / z:
        raise SignalError("the angle channel advances by less than one tooth pitch",
                          file=file, column="angle",
                          hint="check the angle channel's unit (rad expected) and mapping")
    return np.maximum.accumulate(np.sign(slope) * theta)


def impact_phase(strength: np.ndarray, t: np.ndarray, track: np.ndarray,
                 block_time: np.ndarray, period: float, z: int) -> float:
    """Angle of impact 1 modulo the tooth pitch [rad], on the forward track.

    The onset strengths of the first :data:`HEAD_PERIODS` periods (`period` [s]) folded over the
    tooth pitch angle ``2 pi / z``; `track` is :func:`angle_track` at `t`.
    """
    pitch = 2 * np.pi / z
    dt = block_time[1] - block_time[0]
    head = block_time[: int(HEAD_PERIODS * period / dt)]
    bins = max(8, int(round(period / dt)))
    phase = np.mod(np.interp(head, t, track), pitch)
    index = np.minimum((phase / pitch * bins).astype(np.int64), bins - 1)
    weights = _winsorized(strength[: head.size])
    profile = (np.bincount(index, weights=weights, minlength=bins)
               / np.maximum(1, np.bincount(index, minlength=bins)))
    return float((np.argmax(profile) + 0.5) * pitch / bins - pitch / 2)


def seatings_on_track(strength: np.ndarray, t: np.ndarray, track: np.ndarray,
                      block_time: np.ndarray, z: int, phase1: float, period: float
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Impact-1 and impact-2 onsets [s] of every seating the angle track covers.

    Seatings lie at ``phase1 + m 2 pi / z`` on `track` (:func:`angle_track` at
    `t`); each impact 2 is the strongest onset within ``period / 8`` of where the
    angle puts it (the angle gives the speed, the onsets the seating's jitter),
    impact 1 lies where the angle puts it relative to impact 2.
    """
    pitch = 2 * np.pi / z
    first = math.ceil((track[0] - phase1) / pitch)
    seat = phase1 + pitch * np.arange(first, math.floor((track[-1] - phase1) / pitch) + 1)
    seat = seat[seat + pitch / 2 <= track[-1]]
    expected1 = np.interp(seat, track, t)
    expected2 = np.interp(seat + pitch / 2, track, t)
    impact2 = _strongest_near(strength, block_time, expected2, period / 8)
    return impact2 - (expected2 - expected1), impact2


def force_channel(table: pd.DataFrame, file: str | Path | None = None) -> np.ndarray:
    """The branch tension of a canonical table [N], as float64.

    Raises
    ------
    SignalError
        When the table has no ``force`` column.
    """
    if "force" not in table:
        raise SignalError("the engagement log has no force channel", file=file, column="force",
                          hint="map the branch-tension column in the run sheet "
                               "(columns = {force = ...})")
    return table["force"].to_numpy(dtype=float)


def _short_hint(stated: float, z: int, omega: float) -> str:
    return (f"record at least {MIN_PERIODS} seating periods ({MIN_PERIODS * stated:.3g} s "
            f"at omega = {omega:.4g} 1/s, z = {z}), better a hundred; or check the speed "
            "and the teeth in the run sheet")


def check_duration(duration: float, stated: float, z: int, omega: float,
                   file: str | Path | None = None) -> None:
    """Raise a :class:`SignalError` when a log of `duration` [s] holds too few periods.

    Parameters
    ----------
    duration : float
        Samples over the sampling rate [s].
    stated : float
        Seating period ``2 pi / (z omega)`` [s].
    z : int
        Number of teeth [-].
    omega : float
        Stated wheel speed [1/s].
    file : str or Path, optional
        The log's file, for error messages.
    """
    if duration < MIN_PERIODS * stated:
        raise SignalError(
            f"the log lasts {duration:.4g} s, fewer than {MIN_PERIODS} seating periods of "
            f"{stated:.4g} s", file=file, hint=_short_hint(stated, z, omega))


def fill_missing(force: np.ndarray, value: float | None = None,
                 file: str | Path | None = None) -> np.ndarray:
    """`force` [N] with its missing samples replaced by `value` (default: the others' median).

    Raises
    ------
    SignalError
        When every sample is missing and no `value` is given.
    """
    missing = ~np.isfinite(force)
    if not missing.any():
        return force
    if value is None:
        if missing.all():
            raise SignalError("the force channel holds no numbers", file=file, column="force",
                              hint="check the column mapping and the file")
        value = np.median(force[~missing])
    return np.where(missing, value, force)


def collect_events(impact1: np.ndarray, impact2: np.ndarray, period: float,
                   measured_omega: float, *, z: int, omega: float, n_samples: int,
                   sample_rate: float, start_time: float, natural_frequency: float, source: str,
                   onset_resolution: float, period_tolerance: float = PERIOD_TOLERANCE,
                   file: str | Path | None = None) -> EngagementEvents:
    """The :class:`EngagementEvents` of a log, its measured period checked against the stated.

    Parameters
    ----------
    impact1, impact2 : numpy.ndarray
        Onsets of impact 1 and 2 of every seating [s].
    period : float
        Measured seating period [s].
    measured_omega : float
        Measured wheel speed ``2 pi / (z period)`` [1/s].
    z, omega, n_samples, sample_rate, start_time, natural_frequency, source, onset_resolution
        As in :class:`EngagementEvents` (`omega` the stated speed [1/s]).
    period_tolerance : float, optional
        Relative disagreement between measured and stated seating period that
        gives a :class:`SpeedMismatchWarning` (default :data:`PERIOD_TOLERANCE`).
    file : str or Path, optional
        The log's file, named in errors and warnings.

    Raises
    ------
    SignalError
        When the log holds fewer than :data:`MIN_PERIODS` measured periods or no seating.

    Warns
    -----
    SpeedMismatchWarning
        When the measured seating period differs from ``2 pi / (z omega)`` by
        more than `period_tolerance` (also kept in :attr:`EngagementEvents.messages`).
    """
    stated = float(seating_period(z, omega))
    duration = n_samples / sample_rate
    messages = []
    mismatch = period / stated - 1
    if abs(mismatch) > period_tolerance:
        where = f"{file}: " if file is not None else ""
        message = (
            f"{where}the seating period measured from the {source} "
            f"channel, {period:.5g} s (omega = {measured_omega:.4g} 1/s), differs from the run "
            f"sheet's 2 pi / (z omega) = {stated:.5g} s (z = {z}, omega = {omega:.4g} 1/s) by "
            f"{mismatch:+.1%}; the measured period is used (hint: check omega_per_s / rpm and "
            "the wheel's teeth in campaign.toml)")
        messages.append(message)
        warnings.warn(message, SpeedMismatchWarning, stacklevel=3)
    if duration < MIN_PERIODS * period:
        raise SignalError(
            f"the log lasts {duration:.4g} s, fewer than {MIN_PERIODS} measured seating periods "
            f"of {period:.4g} s", file=file, hint=_short_hint(stated, z, omega))
    if impact1.size == 0:
        raise SignalError("no engagement event found in the log", file=file, column="force",
                          hint="check that the wheel turned and the force channel is the "
                               "branch tension")
    return EngagementEvents(
        impact1_time=impact1, impact2_time=impact2, seating_period=float(period),
        stated_period=stated, omega=float(measured_omega), stated_omega=float(omega), z=int(z),
        sample_rate=sample_rate, start_time=start_time, n_samples=int(n_samples),
        natural_frequency=natural_frequency,
        source=source, onset_resolution=onset_resolution, messages=tuple(messages))
