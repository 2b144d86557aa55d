"""Seatings of a segment-load log: the plateaus of the tooth-segment forces (condition stage).

A rig with strain-gauged tooth segments on a chain drum logs, uniformly
sampled, the chain force ``F``, the forces ``F_K1``, ``F_K2`` on the two
segments of a tooth and optionally the side component ``F_P`` (Paper 003).
As a link seats the segment forces rise from about zero to a plateau, hold it
while the link sits, and fall back. Per seating the medians of every channel
over its plateau give ``F_K / F`` (eq. (3)) and ``F_P / F`` (eq. (4)); per run
(one operating point) their medians, IQR and standard errors.

Detection
---------
On the segment-force sum ``S = F_K1 + F_K2``:

1. **Noise floor** sigma of S from its first differences,
   ``1.4826 MAD(diff S) / sqrt(2)``: idle stretches and plateaus make most of
   the differences, the transitions few.
2. **Levels**: the idle level ``b`` is the median of S below the midpoint of
   its 1st and 99th percentiles, the load height ``H`` the 99th percentile
   less ``b``. The segments are zeroed: ``b`` farther from zero than
   ``max(`` :data:`IDLE_SHARE` ``H,`` :data:`ON_NOISE` ``sigma)`` is refused
   (inverted channels would swap plateaus and idle stretches).
3. **Hysteresis** (a Schmitt trigger): a seating is a run of samples at or
   above ``b + max(`` :data:`OFF_NOISE` ``sigma,`` :data:`OFF_SHARE` ``H)``
   that holds a sample at or above ``b + max(`` :data:`ON_NOISE` ``sigma,``
   :data:`ON_SHARE` ``H)``: noise can neither start a seating nor split one,
   and seatings down to a few percent of the highest are found (a load
   staircase); the shares only matter for a nearly noiseless log.
4. **Plateau**: its level ``L`` is the median of S over the seating's samples
   above halfway to its highest; the plateau runs from the first to the last
   sample within ``max(`` :data:`BAND_NOISE` ``sigma,`` :data:`BAND_SHARE`
   ``(L - b))`` of ``L``, less :data:`PLATEAU_TRIM` of its length at each end
   (where the transitions round into it).
5. **Zero**: each segment channel and F_P are read from their own zero at the
   plateau's middle, interpolated linearly between its medians over the idle
   half-stretches before and after the seating, so that a drifting bridge
   zero does not bias the ratios. An idle stretch runs from a seating's end
   plus its fall time to the next one's start less its rise time; its first
   half serves the seating before it, its second half the one after, so that
   no two seatings share a zero and their errors stay independent (as the
   run's standard error assumes). F is used as logged: the chain force need
   not return to zero between seatings.

A seating is excluded (``status``, in order of precedence, :data:`EXCLUSIONS`)
when it touches the start or end of the log (``truncated``), a missing sample
of any channel lies in it or next to it (``gap``), its plateau holds fewer
than :data:`MIN_PLATEAU_SAMPLES` samples (``short``: a spike), or an idle
half-stretch it reads its zero from fewer than :data:`MIN_IDLE_SAMPLES`
(``no_zero``).

Segments that disagree
----------------------
The two segments of a tooth carry equal forces by symmetry (eq. (3)). Per
seating the imbalance ``(F_K1 - F_K2) / F_K`` is recorded, with
``F_K = (F_K1 + F_K2) / 2``; beyond ``imbalance_tolerance`` (default
:data:`IMBALANCE_TOLERANCE`) the seating is flagged ``imbalanced``, the run
gives a :class:`SegmentImbalanceWarning`, and its message stays with the
result. ``F_K / F`` is still the mean of the two segments (a gain error of one
cancels in it, a real asymmetry of the seating does not), and both segments'
own ratios are kept beside it.

Standard errors
---------------
Per seating, the median of the sample-by-sample ratio's standard error over
the plateau, ``sqrt(pi/2) 1.4826 MAD / sqrt(n)`` (white noise; a chain-force
ripple common to F and the segments cancels in it), with that of the zeros
added in quadrature. Per run, the statistics of
:class:`pipeline.statistics.MedianStatistics` over the valid seatings.

Why not the engagement detection
--------------------------------
:mod:`pipeline.condition.engagement` and :mod:`pipeline.condition.scan` find
the onsets of ringing strikes from an onset strength at the branch's natural
frequency and a stated seating period; a plateau has neither, and its
clipping check (an extreme held for a few samples) would take every noiseless
plateau for a saturated amplifier. What fits is reused: the uniform-sampling
check (:func:`pipeline.condition.engagement.check_uniform`) and the runs of
flagged samples (:func:`pipeline.condition.samples.runs_of`,
:func:`~pipeline.condition.samples.run_hits`).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from pipeline.condition.engagement import check_uniform
from pipeline.condition.samples import run_hits, runs_of
from pipeline.errors import SignalError
from pipeline.statistics import MAD_TO_SIGMA, MedianStatistics

#: Seatings a run needs: fewer give no meaningful median absolute deviation.
MIN_EVENTS = 5
#: Relative disagreement of the two segments beyond which a seating is flagged [-]
#: (5 %: several times the calibration uncertainty of a strain-gauge bridge).
IMBALANCE_TOLERANCE = 0.05
#: Upper trigger above the idle level: multiple of the noise floor, share of the load height H.
ON_NOISE, ON_SHARE = 10.0, 0.05
#: Lower trigger above the idle level: multiple of the noise floor, share of H.
OFF_NOISE, OFF_SHARE = 5.0, 0.02
#: Largest distance of the idle level from zero, as a share of H.
IDLE_SHARE = 0.25
#: Plateau band about its level: multiple of the noise floor, share of the plateau height.
BAND_NOISE, BAND_SHARE = 4.0, 0.02
#: Share of the in-band span dropped at each end of a plateau [-].
PLATEAU_TRIM = 0.1
#: Fewest samples of a plateau, and of each idle half-stretch its zeros are read from.
MIN_PLATEAU_SAMPLES = 10
MIN_IDLE_SAMPLES = 10
#: Reasons a seating is excluded from the run's statistics, in order of precedence.
EXCLUSIONS = ("truncated", "gap", "short", "no_zero")
#: Channels of a segment-load log [N] (F_P optional).
CHANNELS = ("F", "F_K1", "F_K2", "F_P")
#: The ratios per seating [-].
RATIOS = ("F_K/F", "F_K1/F", "F_K2/F", "F_P/F")
#: Normal-noise MAD to sigma over the sqrt(2) of a difference of two samples.
_DIFF_MAD_TO_SIGMA = MAD_TO_SIGMA / math.sqrt(2.0)


class SegmentImbalanceWarning(UserWarning):
    """The two segments of a tooth disagree by more than the tolerance."""


@dataclass(frozen=True)
class Detection:
    """Levels of the segment-force sum S the seatings were found with (all [N]).

    Attributes
    ----------
    noise : float
        Noise floor sigma of S.
    idle : float
        Idle level b of S.
    height : float
        Load height H of S above b.
    on, off : float
        Upper and lower trigger levels of the hysteresis.
    """

    noise: float
    idle: float
    height: float
    on: float
    off: float


@dataclass(frozen=True)
class SegmentLoadEvents:
    """Seatings of one segment-load run and their statistics.

    Attributes
    ----------
    events : pandas.DataFrame
        One row per seating found: ``start``, ``stop`` (first and last sample at
        or above the lower trigger) [s], ``plateau_start``, ``plateau_stop``
        (first and last sample of the plateau) [s], ``samples`` (of the
        plateau), the plateau medians
        ``F``, ``F_K1``, ``F_K2`` (and ``F_P``) [N] (the segments from their
        zeros ``zero_K1``, ``zero_K2``, ``zero_P`` [N]), the ratios of
        :data:`RATIOS` [-] (``F_K/F`` the mean of the two segments) with
        ``F_K/F_stderr`` (and ``F_P/F_stderr``), ``imbalance`` [-],
        ``imbalanced`` (bool) and ``status`` (``"ok"`` or one of
        :data:`EXCLUSIONS`). Without F_P its columns are left out.
    statistics : dict of str to MedianStatistics
        Per channel and ratio (and ``imbalance``) over the ``"ok"`` seatings.
    excluded : dict of str to int
        Seatings excluded per reason of :data:`EXCLUSIONS`.
    detection : Detection
        Noise floor and trigger levels used.
    imbalance_tolerance : float
        Imbalance beyond which a seating is flagged [-].
    messages : tuple of str
        Warnings given (the segments' imbalance).
    """

    events: pd.DataFrame
    statistics: dict[str, MedianStatistics]
    excluded: dict[str, int]
    detection: Detection
    imbalance_tolerance: float
    messages: tuple[str, ...] = field(default_factory=tuple)

    @property
    def valid(self) -> pd.DataFrame:
        """The ``"ok"`` seatings (the rows a fit per seating takes)."""
        return self.events[self.events["status"] == "ok"]

    @property
    def imbalanced(self) -> bool:
        """Whether any valid seating's segments disagree beyond the tolerance."""
        return bool(self.valid["imbalanced"].any())

    def point(self) -> dict[str, float | int | bool]:
        """The run as one operating point: ``<quantity>`` (median), ``_iqr``, ``_stderr``.

        Returns
        -------
        dict
            Per quantity of :attr:`statistics` its median under its own name
            (``F_K/F``...) and ``<quantity>_iqr``, ``<quantity>_stderr``,
            ``<quantity>_count``; ``imbalanced`` and ``excluded_<reason>``.
        """
        flat: dict[str, float | int | bool] = {}
        for name, stats in self.statistics.items():
            flat.update({name: stats.median, f"{name}_iqr": stats.iqr,
                         f"{name}_stderr": stats.stderr, f"{name}_count": stats.count})
        flat.update({f"excluded_{reason}": count for reason, count in self.excluded.items()})
        flat["imbalanced"] = self.imbalanced
        return flat


def _channel(name: str, values, size: int | None) -> np.ndarray:
    """A channel as float64, refused when absent, all missing, or of another length."""
    if values is None:
        raise SignalError(f"the segment-load log has no {name} channel", column=name,
                          hint=f"map the {name} column of the log")
    array = np.asarray(values, dtype=float)
    if not np.isfinite(array).any():
        raise SignalError(f"the {name} channel holds no number", column=name,
                          hint=f"check that the {name} column is the right one and not empty")
    if size is not None and array.size != size:
        raise SignalError(f"the {name} channel has {array.size} samples, the time {size}",
                          column=name, hint="give every channel on the same time base")
    return array


def _check_time(time: np.ndarray) -> None:
    """Refuse a time channel that is too short, not increasing or not uniformly sampled."""
    if time.size < 3:
        raise SignalError(f"the segment-load log holds {time.size} samples", column="time",
                          hint="check that the file is complete")
    step = (time[-1] - time[0]) / (time.size - 1)
    if not (np.isfinite(step) and step > 0):
        raise SignalError("the time channel does not increase", column="time",
                          hint="check the time column and its unit")
    check_uniform(time, step)


def detection_levels(total: np.ndarray) -> Detection:
    """Noise floor, idle level, load height and trigger levels of the segment-force sum.

    Parameters
    ----------
    total : numpy.ndarray
        Segment-force sum S = F_K1 + F_K2 [N], NaN where missing.

    Returns
    -------
    Detection
        See the module's steps 1-3.
    """
    finite = total[np.isfinite(total)]
    steps = np.diff(total)
    steps = steps[np.isfinite(steps)]
    noise = _DIFF_MAD_TO_SIGMA * float(np.median(np.abs(steps - np.median(steps))))
    low, high = np.percentile(finite, [1, 99])
    idle = float(np.median(finite[finite < (low + high) / 2])) if high > low else float(low)
    height = float(high) - idle
    return Detection(noise=noise, idle=idle, height=height,
                     on=idle + max(ON_NOISE * noise, ON_SHARE * height),
                     off=idle + max(OFF_NOISE * noise, OFF_SHARE * height))


def seatings(total: np.ndarray, levels: Detection) -> tuple[np.ndarray, np.ndarray]:
    """First samples and ends (exclusive) of the seatings: the hysteresis of step 3.

    Parameters
    ----------
    total : numpy.ndarray
        Segment-force sum S [N] (a missing sample ends a seating).
    levels : Detection
        Trigger levels.

    Returns
    -------
    tuple of numpy.ndarray
        Runs of S at or above ``levels.off`` holding a sample at or above ``levels.on``.
    """
    with np.errstate(invalid="ignore"):
        starts, stops = runs_of(total >= levels.off)
        triggered = run_hits(runs_of(total >= levels.on), starts, stops - starts)
    return starts[triggered], stops[triggered]


def plateau(total: np.ndarray, start: int, stop: int, levels: Detection
            ) -> tuple[slice, int, int]:
    """Plateau of one seating (step 4), in samples of the log.

    Parameters
    ----------
    total : numpy.ndarray
        Segment-force sum S [N].
    start, stop : int
        The seating's first sample and end (exclusive).
    levels : Detection
        Noise floor and idle level.

    Returns
    -------
    span : slice
        The trimmed plateau (at least one sample).
    rise, fall : int
        Samples from `start` to the first sample in the band, and from the
        last one to `stop`.
    """
    seating = total[start:stop]  # all at or above the lower trigger: no missing sample
    level = np.median(seating[seating >= (levels.idle + seating.max()) / 2])
    distance = np.abs(seating - level)
    band = max(BAND_NOISE * levels.noise, BAND_SHARE * (level - levels.idle), distance.min())
    inside = np.flatnonzero(distance <= band)
    first, last = int(inside[0]), int(inside[-1]) + 1
    trim = int(PLATEAU_TRIM * (last - first))
    return slice(start + first + trim, start + last - trim), first, stop - start - last


def _median_stderr(values: np.ndarray) -> float:
    """Standard error of the median of `values` from their MAD (white noise)."""
    return MedianStatistics.of(values[np.isfinite(values)]).stderr_events


@dataclass(frozen=True)
class _Zero:
    """Zero of one channel at a plateau [N], and its standard error [N]."""

    value: float
    stderr: float


def _idle_median(values: np.ndarray, time: np.ndarray, stretch: slice
                 ) -> tuple[float, float, float]:
    """Middle time [s], median and its standard error [N] of `values` over an idle stretch."""
    finite = values[stretch][np.isfinite(values[stretch])]
    middle = (time[stretch.start] + time[stretch.stop - 1]) / 2
    return middle, float(np.median(finite)), _median_stderr(finite)


def _zero(values: np.ndarray, time: np.ndarray, before: slice, after: slice,
          at: float) -> _Zero:
    """Zero of a channel at time `at` [s]: linear between the idle stretches either side."""
    (t0, z0, e0), (t1, z1, e1) = (_idle_median(values, time, part) for part in (before, after))
    share = (at - t0) / (t1 - t0)
    return _Zero(z0 + share * (z1 - z0), math.hypot((1 - share) * e0, share * e1))


def _measure(time: np.ndarray, channels: dict[str, np.ndarray], span: slice,
             idle: tuple[slice, slice]) -> dict[str, float]:
    """Plateau medians, zeros, ratios and their standard errors of one seating.

    Parameters
    ----------
    time : numpy.ndarray
        Sample times [s].
    channels : dict of numpy.ndarray
        ``F``, ``F_K1``, ``F_K2`` and optionally ``F_P`` [N].
    span : slice
        The plateau's samples.
    idle : tuple of slice
        The idle half-stretches before and after the seating the zeros are read from.
    """
    middle = (time[span.start] + time[span.stop - 1]) / 2
    zeros = {name: _zero(channels[name], time, *idle, middle) for name in channels
             if name != "F"}
    load = {name: channels[name][span] - (zeros[name].value if name in zeros else 0.0)
            for name in channels}
    chain = float(np.median(load["F"]))
    row = {"F": chain, **{name: float(np.median(load[name])) for name in zeros}}
    row.update({f"zero_{name[2:]}": zero.value for name, zero in zeros.items()})
    row["F_K1/F"], row["F_K2/F"] = row["F_K1"] / chain, row["F_K2"] / chain
    row["F_K/F"] = (row["F_K1/F"] + row["F_K2/F"]) / 2
    zero_error = math.hypot(zeros["F_K1"].stderr, zeros["F_K2"].stderr) / 2
    row["F_K/F_stderr"] = math.hypot(
        _median_stderr((load["F_K1"] + load["F_K2"]) / 2 / load["F"]), zero_error / chain)
    if "F_P" in zeros:
        row["F_P/F"] = row["F_P"] / chain
        row["F_P/F_stderr"] = math.hypot(_median_stderr(load["F_P"] / load["F"]),
                                         zeros["F_P"].stderr / chain)
    row["imbalance"] = (row["F_K1/F"] - row["F_K2/F"]) / row["F_K/F"]
    return row


def _status(start: int, stop: int, span: slice, size: int,
            missing: tuple[np.ndarray, np.ndarray], finite_idle: list[int]) -> str:
    """``"ok"`` or the first reason of :data:`EXCLUSIONS` that holds for one seating."""
    first = max(start - 1, 0)
    if start == 0 or stop == size:
        return "truncated"
    if run_hits(missing, np.array([first]), stop + 1 - first)[0]:
        return "gap"
    if span.stop - span.start < MIN_PLATEAU_SAMPLES:
        return "short"
    if min(finite_idle) < MIN_IDLE_SAMPLES:
        return "no_zero"
    return "ok"


def _idle_stretches(starts: np.ndarray, stops: np.ndarray, rises: list[int], falls: list[int],
                    size: int) -> list[slice]:
    """The idle stretches before each seating and after the last (step 5), as slices."""
    begins = [0, *(stop + fall for stop, fall in zip(stops.tolist(), falls, strict=True))]
    ends = [*(start - rise for start, rise in zip(starts.tolist(), rises, strict=True)), size]
    return [slice(begin, max(end, begin)) for begin, end in zip(begins, ends, strict=True)]


def _halves(stretch: slice) -> tuple[slice, slice]:
    """The first and second half of an idle stretch."""
    middle = (stretch.start + stretch.stop) // 2
    return slice(stretch.start, middle), slice(middle, stretch.stop)


def _events(time: np.ndarray, channels: dict[str, np.ndarray], total: np.ndarray,
            levels: Detection, tolerance: float) -> pd.DataFrame:
    """One row per seating (see :attr:`SegmentLoadEvents.events`)."""
    starts, stops = seatings(total, levels)
    plateaus = [plateau(total, start, stop, levels)
                for start, stop in zip(starts.tolist(), stops.tolist(), strict=True)]
    idle = _idle_stretches(starts, stops, [p[1] for p in plateaus], [p[2] for p in plateaus],
                           total.size)
    missing = runs_of(~np.all([np.isfinite(c) for c in channels.values()], axis=0))
    rows = []
    for number, (start, stop, (span, _, _)) in enumerate(zip(starts.tolist(), stops.tolist(),
                                                             plateaus, strict=True)):
        around = (_halves(idle[number])[1], _halves(idle[number + 1])[0])
        finite_idle = [int(np.isfinite(total[part]).sum()) for part in around]
        status = _status(start, stop, span, total.size, missing, finite_idle)
        row = {"start": time[start], "stop": time[stop - 1],
               "plateau_start": time[span.start], "plateau_stop": time[span.stop - 1],
               "samples": span.stop - span.start, "status": status}
        if status == "ok":
            row.update(_measure(time, channels, span, around))
        rows.append(row)
    frame = pd.DataFrame(rows, columns=_columns("F_P" in channels))
    frame["imbalanced"] = frame["imbalance"].abs() > tolerance
    return frame


def _columns(side: bool) -> list[str]:
    """Columns of the seatings' table, with or without F_P."""
    names = ["start", "stop", "plateau_start", "plateau_stop", "samples", "F", "F_K1", "F_K2",
             "F_P", "zero_K1", "zero_K2", "zero_P", "F_K/F", "F_K1/F", "F_K2/F", "F_K/F_stderr",
             "F_P/F", "F_P/F_stderr", "imbalance", "status"]
    return names if side else [name for name in names if "F_P" not in name and name != "zero_P"]


def _check_zeroed(levels: Detection) -> None:
    """Refuse segment channels that idle far from zero (inverted, or not zeroed)."""
    if abs(levels.idle) > max(IDLE_SHARE * levels.height, ON_NOISE * levels.noise):
        raise SignalError(
            f"the segment forces idle at F_K1 + F_K2 = {levels.idle:.4g} N, not about zero, "
            f"for a load height of {levels.height:.4g} N", column="F_K1",
            hint="the segment forces must rise from about zero as the links seat: check the "
                 "sign of F_K1 and F_K2 (positive in compression of the segment) and that "
                 "their bridges were zeroed unloaded")


def _check_chain_force(valid: pd.DataFrame) -> None:
    """Refuse seatings whose chain force is not positive (F_K / F needs F > 0)."""
    bad = valid[~(valid["F"] > 0)]
    if len(bad):
        raise SignalError(
            f"the chain force is not positive at {len(bad)} of {len(valid)} seatings (first at "
            f"{bad['start'].iloc[0]:.6g} s: F = {bad['F'].iloc[0]:.4g} N)", column="F",
            hint="F_K / F needs the chain force F > 0 while the link sits: check the sign and "
                 "the mapping of the chain-force channel")


def _check_count(frame: pd.DataFrame, excluded: dict[str, int]) -> None:
    """Refuse a run with fewer than :data:`MIN_EVENTS` valid seatings."""
    valid = int((frame["status"] == "ok").sum())
    if valid < MIN_EVENTS:
        raise SignalError(
            f"{valid} valid seatings found ({len(frame)} in all, excluded: {excluded}); a run "
            f"needs at least {MIN_EVENTS}",
            hint="record more seatings, and check that the segment forces rise (positive) "
                 "from about zero as the links seat and that F_K1, F_K2 are mapped")


def _imbalance_messages(valid: pd.DataFrame, tolerance: float) -> tuple[str, ...]:
    """The warning when valid seatings' segments disagree beyond `tolerance` (also given)."""
    flagged = int(valid["imbalanced"].sum())
    if not flagged:
        return ()
    message = (f"the two segments disagree by more than {100 * tolerance:g} % at {flagged} of "
               f"{len(valid)} seatings (median imbalance (F_K1 - F_K2) / F_K = "
               f"{100 * valid['imbalance'].median():+.1f} %); F_K / F is their mean, and each "
               "segment's own ratio is kept: check the segments' calibration and the seating")
    warnings.warn(message, SegmentImbalanceWarning, stacklevel=3)
    return (message,)


def condition_segment_load(
    time,
    chain_force,
    segment_force_1,
    segment_force_2,
    side_force=None,
    *,
    imbalance_tolerance: float = IMBALANCE_TOLERANCE,
) -> SegmentLoadEvents:
    """Find the seatings of a segment-load log and the load ratios over their plateaus.

    Parameters
    ----------
    time : array_like
        Sample times [s], uniformly sampled.
    chain_force : array_like
        Chain force F [N], NaN where missing.
    segment_force_1, segment_force_2 : array_like
        Forces F_K1, F_K2 on the two segments of the tooth [N], NaN where missing.
    side_force : array_like, optional
        Side component F_P of the segment force [N]; None when not logged.
    imbalance_tolerance : float, optional
        Relative disagreement of the segments beyond which a seating is
        flagged [-] (default :data:`IMBALANCE_TOLERANCE`).

    Returns
    -------
    SegmentLoadEvents

    Raises
    ------
    SignalError
        A channel missing, all missing or of another length; a time channel
        not uniformly sampled; segment forces idling far from zero; fewer
        than :data:`MIN_EVENTS` valid seatings; a chain force not positive
        over a plateau.

    Warns
    -----
    SegmentImbalanceWarning
        When the segments of valid seatings disagree beyond the tolerance.

    References
    ----------
    Paper 003, eqs. (3)-(4): F_K / F and F_P / F.
    """
    time = _channel("time", time, None)
    _check_time(time)
    given = dict(zip(CHANNELS, (chain_force, segment_force_1, segment_force_2, side_force),
                     strict=True))
    channels = {name: _channel(name, values, time.size) for name, values in given.items()
                if name != "F_P" or values is not None}
    total = channels["F_K1"] + channels["F_K2"]
    levels = detection_levels(total)
    _check_zeroed(levels)
    frame = _events(time, channels, total, levels, imbalance_tolerance)
    excluded = {reason: int((frame["status"] == reason).sum()) for reason in EXCLUSIONS}
    _check_count(frame, excluded)
    valid = frame[frame["status"] == "ok"]
    _check_chain_force(valid)
    quantities = [name for name in (*channels, *RATIOS, "imbalance") if name in valid]
    statistics = {name: MedianStatistics.of(valid[name].to_numpy(dtype=float))
                  for name in quantities}
    return SegmentLoadEvents(events=frame, statistics=statistics, excluded=excluded,
                             detection=levels, imbalance_tolerance=imbalance_tolerance,
                             messages=_imbalance_messages(valid, imbalance_tolerance))
