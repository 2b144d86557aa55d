"""Impact tensions N_u1, N_u2 per engagement event, from a branch-tension log (fit stage).

Each seating of a link strikes the wheel twice, ``tau = P / 2`` apart (Paper
000); each strike rings the branch as ``A exp(-zeta omega_n s) sin(omega_d s)``,
``omega_d = omega_n sqrt(1 - zeta^2)``, on top of the slowly varying tension,
and the ringing of earlier strikes goes on underneath. The amplitude ``A`` of a
strike's response is the measured counterpart of the model's N_u (Paper 000,
eq. (16)): this module extracts ``A`` for both strikes of every event the
detection found (:mod:`pipeline.condition.scan`). It lives in ``fit/`` because
it is a model fit (the stage that also fits the campaign's impact model,
:mod:`pipeline.fit.impact_model`).

Its steps, in map-reduce shape like the detection's (composed, for a table or
a file read chunk by chunk, by :mod:`pipeline.engagement_log`):
:func:`plan_extraction` (the events' windows and statuses, once per run) ->
:func:`fit_ringing` (on the windows of up to :data:`RINGING_EVENTS` events) ->
:func:`fit_chunk` (per chunk: the events whose impact 1 lies in it) ->
:func:`impact_result` (merge, failed-fit and overlap rules, statistics).

The model of one event
----------------------
In the window from ``0.4 tau`` before impact 1 to ``0.15 tau`` before the next
seating, with ``r`` the time from the first sample at or after impact 1::

    y(r) = b0 + b1 r / W + b2 cos(2 pi r / P) + b3 sin(2 pi r / P)    slow tension
         + Im[(c0) exp(lambda r)]                                     earlier strikes
         + A1 h(r - r1) + A2 h(r - r2)                                this event's strikes

``lambda = -zeta omega_n + i omega_d``. The superposed free ringing of all
earlier strikes, however many, is one damped sinusoid of unknown phase (two
linear coefficients), so the model is *linear* once omega_n, zeta and the onsets
are known, and it is fitted to all events at once by linear least squares:

1. Per run, omega_n and zeta are fitted with lmfit (Levenberg-Marquardt) on up to
   :data:`RINGING_EVENTS` events, the linear coefficients projected out (variable
   projection), after a grid search over omega_n around the detector's estimate;
   events the first fit does not describe (glitches) are dropped before the second.
2. Each strike is first fitted as a damped sinusoid of free phase starting at its
   detected onset: the phase of the fitted complex amplitude gives the onset to a
   fraction of a sample (``h`` starts at phase 0). The events whose masks then
   move are refitted until every mask starts at the first sample after its onset.
3. The final fit has the strikes' phases fixed by their onsets, so ``A1`` and
   ``A2`` keep their sign, with standard errors from the residual. All windows
   share a basis (the event-specific part is a mask start and a complex scale), so
   the normal equations of every event come from one matrix product over the
   windows, suffix sums of the basis and a few samples around the masks: no loop
   over events, and the refits of step 2 touch no window again.

Per run, the medians of ``A1`` and ``A2`` over the valid events, their
interquartile range, median absolute deviation, standard error of the median and
count are reported. The standard error adds in quadrature the scatter of the
events (``sqrt(pi/2) 1.4826 MAD / sqrt(n)``) and the uncertainty of the fitted
omega_n and zeta, which every event of the run shares (propagated by central
differences over the ringing-fit events). Events whose window leaves the log
(``truncated``), holds missing samples (``gap``), touches a clipping level
(``clipped``, given or detected from flat tops), holds a neighbour's strike
(``overlap``, irregular spacing) or whose fit fails (``fit_failed``: non-finite
or non-positive amplitude, an onset moved by more than :data:`MAX_ONSET_SHIFT`
ringing periods, or a residual above :data:`RESIDUAL_OUTLIER` times the run's
median and above 0.1 % of the typical strike) are counted by reason and never
enter the medians.

The comparison with theory uses the amplitude ``A``. The first-peak height of a
strike's own response (ringing of the other strikes removed),
``A sqrt(1 - zeta^2) exp(-zeta acos(zeta) / sqrt(1 - zeta^2))`` (0.954 A at
zeta = 0.03), is reported beside it as ``peak1`` / ``peak2``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from pathlib import Path

import lmfit
import numpy as np
import pandas as pd

from pipeline.condition.engagement import ASSUMED_DAMPING, EngagementEvents
from pipeline.condition.samples import LogSamples
from pipeline.errors import FitError
from pipeline.fit.windows import (
    MAX_ONSET_SHIFT,
    WINDOW_GUARD,
    WINDOW_PRE,
    FreePhaseResiduals,
    Ringing,
    WindowGeometry,
    fit_amplitudes,
    settle_onsets,
)
from pipeline.statistics import MedianStatistics

#: Events used to fit omega_n and zeta per run.
RINGING_EVENTS = 64
#: Residual RMS above this multiple of the run's median marks a failed fit...
RESIDUAL_OUTLIER = 4.0
#: ...when it is also above this fraction of the run's typical strike amplitude.
RESIDUAL_FLOOR = 1e-3
#: Reasons an event is excluded from a run's statistics, in order of precedence.
EXCLUSIONS = ("truncated", "gap", "clipped", "overlap", "fit_failed")
@dataclass(frozen=True)
class ImpactResult:
    """Impact extraction of one engagement run.

    Attributes
    ----------
    events : pandas.DataFrame
        One row per detected seating: ``event_time`` and ``impact2_time``
        (onsets of impact 1 and 2) [s], ``tau`` [s], ``baseline`` (slow branch
        tension at impact 1, ringing excluded) [N], ``N_u1``, ``N_u2`` (strike
        amplitudes A) and their ``_stderr`` [N], ``peak1``, ``peak2`` (first-peak
        heights of the strikes' own responses) [N], ``residual_rms`` [N] and
        ``status`` (``"ok"`` or one of :data:`EXCLUSIONS`).
    ringing : Ringing
        Natural frequency and damping used.
    statistics : dict of str to MedianStatistics
        Per quantity (``N_u1``, ``N_u2``, ``peak1``, ``peak2``, ``baseline``,
        ``tau``) over the ``"ok"`` events.
    excluded : dict of str to int
        Events excluded per reason of :data:`EXCLUSIONS`.
    clip_levels : tuple of (float or None)
        Lower and upper clipping level used [N].
    comparison : str
        The quantity compared with the model's N_u: ``"amplitude"`` (A).
    messages : tuple of str
        Warnings given on the way (the detection's, e.g. a speed mismatch).
    """

    events: pd.DataFrame
    ringing: Ringing
    statistics: dict[str, MedianStatistics]
    excluded: dict[str, int]
    clip_levels: tuple[float | None, float | None] = (None, None)
    comparison: str = "amplitude"
    messages: tuple[str, ...] = field(default_factory=tuple)

    @property
    def N_u1(self) -> MedianStatistics:
        """Statistics of the impact-1 amplitudes [N]."""
        return self.statistics["N_u1"]

    @property
    def N_u2(self) -> MedianStatistics:
        """Statistics of the impact-2 amplitudes [N]."""
        return self.statistics["N_u2"]

    def summary(self) -> dict[str, float | int | str]:
        """Flat run-level summary: ``<quantity>_<statistic>``, exclusions, ringing."""
        flat: dict[str, float | int | str] = {}
        for name, stats in self.statistics.items():
            for key in ("median", "iqr", "mad", "stderr", "count", "stderr_events",
                        "stderr_ringing"):
                flat[f"{name}_{key}"] = getattr(stats, key)
        flat.update({f"excluded_{reason}": count for reason, count in self.excluded.items()})
        flat.update(omega_n=self.ringing.omega_n, zeta=self.ringing.zeta,
                    omega_n_stderr=self.ringing.omega_n_stderr,
                    zeta_stderr=self.ringing.zeta_stderr, comparison=self.comparison,
                    events_total=int(len(self.events)))
        return flat


def _require_ringing_events(onset1: np.ndarray) -> None:
    if onset1.size < 2:
        raise FitError("too few events to fit the branch's ringing",
                       hint="check the speed and teeth in the run sheet and the force "
                            "channel, or record a longer log")


def _fit_ringing(y: np.ndarray, onset1: np.ndarray, onset2: np.ndarray, geo: WindowGeometry,
                omega_n: float, margin: float, span: int
                ) -> tuple[Ringing, np.ndarray, np.ndarray]:
    """Fit omega_n and zeta of the branch on a few events.

    `y` holds the events' reaches of `span` samples end to end. A grid search
    over omega_n (0.88-1.14 times `omega_n`, zeta = 0.03), then twice: onsets
    refined with the current values, lmfit (Levenberg-Marquardt) of omega_n and
    zeta on the free-phase model, the linear coefficients projected out. After
    each refinement, events whose onsets moved too far (out of the accepted
    shift, or their window out of their reach, where it would take samples of
    the next event's) are dropped; before the second fit, so are events whose
    residual exceeds :data:`RESIDUAL_OUTLIER` times the median (a glitch, a
    missed seating). Returns the fit and the refined onsets [s] of the events
    kept.
    """
    _require_ringing_events(onset1)
    reach = np.arange(onset1.size)  # each event's reach: samples reach * span on
    grid = omega_n * np.exp(np.linspace(math.log(0.88), math.log(1.14), 9))
    residuals = FreePhaseResiduals(y, onset1, onset2, geo)
    best = float(min(grid, key=lambda w: float(np.sum(residuals(Ringing(w, ASSUMED_DAMPING))
                                                       ** 2))))
    ringing = Ringing(best, ASSUMED_DAMPING)
    params = lmfit.Parameters()
    params.add("omega_n", value=best, min=0.8 * best, max=1.25 * best)
    params.add("zeta", value=ASSUMED_DAMPING, min=1e-4, max=0.5)
    for second in (False, True):
        fits = settle_onsets(y, onset1, onset2, margin, geo, ringing)
        start = geo.first_sample(fits.onset1) - geo.pre
        kept = ~fits.moved & (start >= reach * span) & (start + geo.width <= (reach + 1) * span)
        onset1, onset2, reach, margin = fits.onset1[kept], fits.onset2[kept], reach[kept], 0.0
        _require_ringing_events(onset1)
        if second:
            residual = FreePhaseResiduals(y, onset1, onset2, geo)(ringing)
            rms = np.sqrt(np.mean(residual.reshape(onset1.size, -1) ** 2, axis=1))
            kept = rms <= RESIDUAL_OUTLIER * np.median(rms)
            onset1, onset2, reach = onset1[kept], onset2[kept], reach[kept]
        _require_ringing_events(onset1)
        residuals = FreePhaseResiduals(y, onset1, onset2, geo)
        try:
            result = lmfit.minimize(_trial_residuals, params, args=(residuals,),
                                    method="leastsq")
        except ValueError as error:  # lmfit refuses NaN residuals (a singular window)
            raise FitError(f"the fit of the branch's ringing failed: {error}",
                           hint="check that the force channel is the branch tension") from None
        if not result.success:
            raise FitError(f"the fit of the branch's ringing failed: {result.message}",
                           hint="check that the force channel is the branch tension")
        params = result.params
        omega_fit, zeta_fit = params["omega_n"], params["zeta"]
        correlation = (omega_fit.correl or {}).get("zeta", 0.0)
        ringing = Ringing(omega_fit.value, zeta_fit.value, omega_fit.stderr or math.nan,
                          zeta_fit.stderr or math.nan, correlation, int(onset1.size))
    return ringing, onset1, onset2


def _trial_residuals(params: lmfit.Parameters, residuals: FreePhaseResiduals) -> np.ndarray:
    """The free-phase residuals [N] for the trial ringing of `params` (lmfit's objective)."""
    return residuals(Ringing(params["omega_n"].value, params["zeta"].value))


def _ringing_errors(y: np.ndarray, onset1: np.ndarray, onset2: np.ndarray, geo: WindowGeometry,
                    ringing: Ringing) -> dict[str, float]:
    """Relative standard errors of the median N_u1, N_u2, peak1, peak2 due to omega_n, zeta.

    Central differences of the medians over the events given (the same data, so
    the noise cancels) by one standard error of each parameter, combined with
    their correlation: ``sqrt(J C J^T)`` relative to the medians (NaN for a median of 0,
    relative to which nothing is defined).
    """
    if not ringing.fitted:
        return dict.fromkeys(("N_u1", "N_u2", "peak1", "peak2"), 0.0)
    if (ringing.omega_n_stderr >= ringing.omega_n or ringing.zeta_stderr >= ringing.zeta
            or ringing.zeta + ringing.zeta_stderr >= 1):
        raise FitError(
            f"the log does not determine the branch's ringing (omega_n = {ringing.omega_n:.4g} "
            f"+- {ringing.omega_n_stderr:.2g} rad/s, zeta = {ringing.zeta:.3g} "
            f"+- {ringing.zeta_stderr:.2g})",
            hint="check that the force channel is the branch tension and that the log holds "
                 "the strikes of the seating links")

    def medians(trial: Ringing) -> np.ndarray:
        fits = settle_onsets(y, onset1, onset2, 0.0, geo, trial, passes=2)
        coef = fit_amplitudes(fits, trial, geo.width)[0]
        amplitude = np.median(coef[:, 6:8], axis=0)
        return np.concatenate([amplitude, amplitude * trial.peak_factor])

    base = medians(ringing)
    steps = {"omega_n": ringing.omega_n_stderr, "zeta": ringing.zeta_stderr}
    slopes = []
    for name, step in steps.items():
        up = medians(replace(ringing, **{name: getattr(ringing, name) + step}))
        down = medians(replace(ringing, **{name: getattr(ringing, name) - step}))
        with np.errstate(divide="ignore", invalid="ignore"):  # a median of 0: undefined
            slopes.append((up - down) / 2 / base)  # relative change per standard error
    omega_part, zeta_part = slopes
    with np.errstate(invalid="ignore"):
        variance = (omega_part**2 + zeta_part**2
                    + 2 * ringing.correlation * omega_part * zeta_part)
    relative = np.sqrt(np.maximum(variance, 0.0))
    return dict(zip(("N_u1", "N_u2", "peak1", "peak2"), relative.tolist(), strict=True))


def _relative(force: np.ndarray, offset: float) -> np.ndarray:
    """``force - offset`` [N], 0 at the missing samples (windows holding them are excluded)."""
    missing = ~np.isfinite(force)
    return np.where(missing, 0.0, force - offset) if missing.any() else force - offset


def _slack(events: EngagementEvents, geo: WindowGeometry, file: str | Path | None) -> int:
    """Samples the windows may move by in the fits, on each side.

    Room for the onsets to move (the largest accepted shift, :data:`MAX_ONSET_SHIFT`,
    with the natural frequency possibly 30 % below its first estimate) plus the
    mask margin; a :class:`FitError` when the strikes come too fast for that.
    """
    reach = MAX_ONSET_SHIFT * 2 * np.pi / (0.7 * events.natural_frequency)
    if WINDOW_PRE * events.tau < reach + 2 / geo.rate:
        stated = events.stated_period / 2
        measured = ("" if math.isclose(events.tau, stated, rel_tol=0.02) else
                    f" (half the seating period measured in the log; the run sheet's speed "
                    f"and teeth give {stated:.3g} s: the log's strikes do not come at the "
                    "stated speed, or what was taken for them is no strike)")
        raise FitError(
            f"the strikes come too fast for their ringing to be told apart: tau = "
            f"{events.tau:.3g} s{measured} against a ringing period of "
            f"{2 * np.pi / events.natural_frequency:.3g} s", file=file,
            hint="the extraction needs tau = pi / (z omega) above about one ringing period of "
                 "the branch; check the speed and teeth in the run sheet, and that the force "
                 "column is the branch tension of a chain running over the wheel")
    return int(math.ceil((reach + events.onset_resolution) * geo.rate)) + 1


def _window_status(start: np.ndarray, span: int, size: int, gap: np.ndarray,
                   clipped: np.ndarray | None) -> np.ndarray:
    """Status of each event before its fit: ``ok``, ``truncated``, ``gap`` or ``clipped``.

    `start` is the first sample of each event's reach (window plus slack) of
    `span` samples in a log of `size`; `gap` and `clipped` say whether the reach
    holds a missing or a clipped sample (None: no clipping level).
    """
    status = np.full(start.size, "ok", dtype=object)
    status[(start < 0) | (start + span > size)] = "truncated"
    status[(status == "ok") & gap] = "gap"
    if clipped is not None:
        status[(status == "ok") & clipped] = "clipped"
    return status


def _usable(status: np.ndarray, file: str | Path | None) -> np.ndarray:
    """Indices of the events still ``ok``; a :class:`FitError` when there are none."""
    usable = np.flatnonzero(status == "ok")
    if usable.size == 0:
        counts = {reason: int(np.sum(status == reason)) for reason in EXCLUSIONS}
        raise FitError(f"no engagement event can be fitted ({counts})", file=file,
                       hint="record a longer log or lower the gain so the force does not clip")
    return usable


def _ringing_pick(usable: np.ndarray) -> np.ndarray:
    """Up to :data:`RINGING_EVENTS` of the `usable` events, evenly spread over the log."""
    return usable[np.unique(np.linspace(0, usable.size - 1, min(RINGING_EVENTS, usable.size))
                            .round().astype(int))]


@dataclass(frozen=True)
class ExtractionPlan:
    """The run-level set-up of the extraction (:func:`plan_extraction`).

    Attributes
    ----------
    events : EngagementEvents
        The seatings of the whole log.
    geometry : WindowGeometry
        Sampling and window of the events.
    reach_start : numpy.ndarray
        First sample of each event's reach (window plus slack).
    span : int
        Samples of the reach.
    status : numpy.ndarray
        Status of each event before the fits (``ok``, ``truncated``, ``gap``, ``clipped``).
    usable : numpy.ndarray
        Indices of the events fitted (those ``ok``).
    clip_levels : tuple of (float or None)
        Lower and upper clipping levels used [N].
    offset : float
        Subtracted from the force before the fits [N] (conditions them only).
    file : str or None
        The log's file, named in errors.
    """

    events: EngagementEvents
    geometry: WindowGeometry
    reach_start: np.ndarray
    span: int
    status: np.ndarray
    usable: np.ndarray
    clip_levels: tuple[float | None, float | None]
    offset: float
    file: str | None = None

    @property
    def margin(self) -> float:
        """Mask margin of the first pass [s]: the masks start after the detected onsets."""
        return 0.5 * self.events.onset_resolution

    @property
    def ringing_events(self) -> np.ndarray:
        """The events the ringing is fitted on (up to :data:`RINGING_EVENTS`, spread out)."""
        return _ringing_pick(self.usable)

    def events_of(self, start: int, stop: int) -> np.ndarray:
        """The usable events whose impact 1 lies in samples ``[start, stop)``."""
        first = self.geometry.first_sample(self.events.impact1_time[self.usable])
        return self.usable[(first >= start) & (first < stop)]


def plan_extraction(events: EngagementEvents, samples: LogSamples,
                    file: str | Path | None = None) -> ExtractionPlan:
    """Where each event's window lies, which events can be fitted, the clipping levels.

    Parameters
    ----------
    events : EngagementEvents
        The seatings of the log.
    samples : LogSamples
        The summary of the log's samples (:mod:`pipeline.condition.samples`):
        gaps, clipping, offset.
    file : str or Path, optional
        The log's file, named in errors.

    Returns
    -------
    ExtractionPlan

    Raises
    ------
    FitError
        When the strikes come too fast to be told apart, or no event's window
        lies whole, gap-free and unclipped in the log.
    """
    geo = WindowGeometry.of(events)
    slack = _slack(events, geo, file)
    reach_start = geo.first_sample(events.impact1_time) - geo.pre - slack
    span = geo.width + 2 * slack
    status = _window_status(reach_start, span, events.n_samples, samples.missing(reach_start, span),
                            samples.clipped(reach_start, span))
    return ExtractionPlan(events, geo, reach_start, span, status, _usable(status, file),
                          samples.clip_levels, samples.offset,
                          None if file is None else str(file))


def fit_ringing(windows: list[np.ndarray], plan: ExtractionPlan, ringing: Ringing | None = None
                ) -> tuple[Ringing, dict[str, float]]:
    """The run's ringing, fitted on the windows of :attr:`ExtractionPlan.ringing_events`.

    Parameters
    ----------
    windows : list of numpy.ndarray
        The force [N] over the reach of each of those events (samples
        ``plan.reach_start[e]`` to ``+ plan.span``).
    plan : ExtractionPlan
        The run's plan.
    ringing : Ringing, optional
        The ringing when known (then only its relative errors are computed).

    Returns
    -------
    ringing : Ringing
    relative_errors : dict of str to float
        Relative standard errors of the medians of ``N_u1``, ``N_u2``, ``peak1``,
        ``peak2`` due to the ringing's uncertainty.

    Notes
    -----
    The windows are laid end to end and each event's onsets shifted by as much,
    so the fit sees the same samples around each event as on the whole log.
    """
    pick, events, geo = plan.ringing_events, plan.events, plan.geometry
    shift = (plan.reach_start[pick] - plan.span * np.arange(pick.size)) / geo.rate
    y = _relative(np.concatenate(windows), plan.offset)
    prior1, prior2 = events.impact1_time[pick] - shift, events.impact2_time[pick] - shift
    if ringing is None:
        ringing, prior1, prior2 = _fit_ringing(y, prior1, prior2, geo, events.natural_frequency,
                                               plan.margin, plan.span)
    return ringing, _ringing_errors(y, prior1, prior2, geo, ringing)


@dataclass(frozen=True)
class EventFits:
    """Final fits of a set of events (see :func:`_fit_events`), one row per event.

    Attributes
    ----------
    onset1, onset2 : numpy.ndarray
        Refined onsets of impact 1 and 2 [s].
    moved : numpy.ndarray
        Whether an onset left its reach (then kept at its prior).
    coef : numpy.ndarray
        (n, 8) coefficients: slow tension 0-3 [N], earlier strikes 4-5 [N],
        ``A1`` 6 and ``A2`` 7 [N].
    variance : numpy.ndarray
        (n, 2) variances of ``A1``, ``A2`` [N^2].
    rms : numpy.ndarray
        Residual RMS [N].
    baseline : numpy.ndarray
        Slow tension at impact 1 [N].
    """

    onset1: np.ndarray
    onset2: np.ndarray
    moved: np.ndarray
    coef: np.ndarray
    variance: np.ndarray
    rms: np.ndarray
    baseline: np.ndarray

    @classmethod
    def none(cls) -> EventFits:
        """Fits of no event."""
        empty = np.zeros(0)
        return cls(empty, empty, np.zeros(0, dtype=bool), np.zeros((0, 8)), np.zeros((0, 2)),
                   empty, empty)

    @classmethod
    def concatenate(cls, parts: list[EventFits]) -> EventFits:
        """The fits of `parts`, one after the other."""
        return cls(*(np.concatenate([getattr(part, name) for part in parts])
                     for name in cls.__dataclass_fields__))


def _fit_events(y: np.ndarray, prior1: np.ndarray, prior2: np.ndarray, margin: float,
                geo: WindowGeometry, ringing: Ringing, offset: float) -> EventFits:
    """Onsets, amplitudes and baselines of events (priors [s]) in `y` (force - `offset` [N])."""
    fits = settle_onsets(y, prior1, prior2, margin, geo, ringing)
    coef, variance, rss = fit_amplitudes(fits, ringing, geo.width)
    r1 = fits.onset1 - fits.ref
    phase = 2 * np.pi * r1 / geo.period
    baseline = (offset + coef[:, 0] + coef[:, 1] * r1 * geo.rate / geo.width
                + coef[:, 2] * np.cos(phase) + coef[:, 3] * np.sin(phase))
    return EventFits(fits.onset1, fits.onset2, fits.moved, coef, variance,
                     np.sqrt(rss / geo.width), baseline)


def _event_table(prior1: np.ndarray, prior2: np.ndarray, status: np.ndarray,
                 usable: np.ndarray, fits: EventFits, geo: WindowGeometry,
                 ringing: Ringing) -> pd.DataFrame:
    """The events' rows of :attr:`ImpactResult.events`, their fits judged against the run's.

    `status` (before the fits) is updated with ``fit_failed`` and ``overlap``;
    `fits` are those of the events `usable`.
    """
    coef, variance, rms = fits.coef, fits.variance, fits.rms
    # a negative variance (round-off in a degenerate fit) is no error estimate either
    variance = np.where(variance >= 0, variance, np.nan)
    finite = np.all(np.isfinite(coef), axis=1) & np.all(np.isfinite(variance), axis=1)
    failed = fits.moved | ~finite | ~(coef[:, 6] > 0) | ~(coef[:, 7] > 0)
    if np.any(~failed):
        # (a residual below RESIDUAL_FLOOR of the typical strike is a good fit whatever
        # its ratio)
        typical = np.median(rms[~failed]), np.median(coef[~failed, 7])
        failed |= rms > max(RESIDUAL_OUTLIER * typical[0], RESIDUAL_FLOOR * typical[1])

    time1, time2 = prior1.copy(), prior2.copy()
    time1[usable], time2[usable] = fits.onset1, fits.onset2
    # Neighbours' strikes inside a window: irregular spacing or a missed seating.
    window_start = geo.time_of(geo.first_sample(time1) - geo.pre)
    window_end = window_start + geo.width / geo.rate
    overlap = np.zeros(prior1.size, dtype=bool)
    overlap[1:] |= time2[:-1] > window_start[1:]
    overlap[:-1] |= time1[1:] < window_end[:-1]
    status[usable[failed]] = "fit_failed"
    status[(status == "ok") & overlap] = "overlap"

    def column(values: np.ndarray) -> np.ndarray:
        full = np.full(prior1.size, np.nan)
        full[usable] = values
        return full

    return pd.DataFrame({
        "event_time": time1, "impact2_time": time2, "tau": time2 - time1,
        "baseline": column(fits.baseline), "N_u1": column(coef[:, 6]),
        "N_u2": column(coef[:, 7]),
        "N_u1_stderr": column(np.sqrt(variance[:, 0])),
        "N_u2_stderr": column(np.sqrt(variance[:, 1])),
        "peak1": column(coef[:, 6] * ringing.peak_factor),
        "peak2": column(coef[:, 7] * ringing.peak_factor),
        "residual_rms": column(rms), "status": status.astype(str),
    })


def _run_statistics(frame: pd.DataFrame, relative_errors: dict[str, float],
                    file: str | Path | None) -> tuple[dict[str, MedianStatistics], dict[str, int]]:
    """Statistics of the ``ok`` events of `frame` and the exclusion counts.

    `relative_errors` are the relative standard errors of the medians due to the
    ringing (:func:`_ringing_errors`); a :class:`FitError` when no event is ``ok``.
    """
    ok = frame["status"] == "ok"
    if not ok.any():
        raise FitError("every engagement event failed its fit", file=file,
                       hint="check the speed and teeth in the run sheet and the force channel")
    statistics = {}
    for name in ("N_u1", "N_u2", "peak1", "peak2", "baseline", "tau"):
        values = frame.loc[ok, name].to_numpy()
        systematic = relative_errors.get(name, 0.0) * abs(float(np.median(values)))
        statistics[name] = MedianStatistics.of(values, systematic)
    status = frame["status"].to_numpy()
    excluded = {reason: int(np.sum(status == reason)) for reason in EXCLUSIONS}
    return statistics, excluded


def fit_chunk(force: np.ndarray, data_start: int, start: int, stop: int, plan: ExtractionPlan,
              ringing: Ringing) -> EventFits:
    """Final fits of the events whose impact 1 lies in samples ``[start, stop)`` (a pure function).

    Parameters
    ----------
    force : numpy.ndarray
        Samples ``data_start`` on of the log's force [N], holding the reach of
        every such event (a chunk plus its overlap).
    data_start : int
        The log's index of ``force[0]``.
    start, stop : int
        The chunk's own span [samples of the log].
    plan : ExtractionPlan
        The run's plan.
    ringing : Ringing
        The run's ringing (:func:`fit_ringing`).

    Returns
    -------
    EventFits
        Onsets, amplitudes, variances, residuals and baselines of those events,
        in the order of the log (none when no event is the chunk's).
    """
    mine = plan.events_of(start, stop)
    if mine.size == 0:
        return EventFits.none()
    geo = replace(plan.geometry, origin=data_start)
    return _fit_events(_relative(force, plan.offset), plan.events.impact1_time[mine],
                       plan.events.impact2_time[mine], plan.margin, geo, ringing, plan.offset)


def impact_result(plan: ExtractionPlan, fits: list[EventFits], ringing: Ringing,
                  relative_errors: dict[str, float]) -> ImpactResult:
    """The run's :class:`ImpactResult` from the fits of all its chunks, in order.

    The failed-fit and overlap rules compare an event with the run and its
    neighbours, so they are applied here, on the merged fits.

    Parameters
    ----------
    plan : ExtractionPlan
        The run's plan.
    fits : list of EventFits
        :func:`fit_chunk` of every chunk, in order (together: every usable event once).
    ringing : Ringing
        The run's ringing.
    relative_errors : dict of str to float
        From :func:`fit_ringing`.

    Raises
    ------
    FitError
        When every event failed its fit.
    """
    events = plan.events
    frame = _event_table(events.impact1_time, events.impact2_time, plan.status.copy(),
                         plan.usable, EventFits.concatenate(fits), plan.geometry, ringing)
    statistics, excluded = _run_statistics(frame, relative_errors, plan.file)
    return ImpactResult(frame, ringing, statistics, excluded, plan.clip_levels,
                        messages=events.messages)


def extraction_settings() -> dict[str, float]:
    """The settings this extraction applies, to be recorded as attributes of its outputs.

    Returns
    -------
    dict
        ``event_window_pre`` and ``event_window_guard`` [1, fractions of tau]:
        an event's window runs from ``event_window_pre`` tau before impact 1 to
        ``event_window_guard`` tau before the next seating; ``max_onset_shift``
        [ringing periods], ``residual_outlier`` [1, times the run's median
        residual] and ``residual_floor`` [1, fraction of the typical strike]:
        beyond them an event's fit has failed; ``ringing_events_max`` [1]:
        events the natural frequency and damping are fitted on.
    """
    return {"event_window_pre": WINDOW_PRE, "event_window_guard": WINDOW_GUARD,
            "max_onset_shift": MAX_ONSET_SHIFT, "residual_outlier": RESIDUAL_OUTLIER,
            "residual_floor": RESIDUAL_FLOOR, "ringing_events_max": RINGING_EVENTS}
