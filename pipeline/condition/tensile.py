"""Conditioning of a tensile run: gauges to strain, cycles, loops and set.

:func:`condition_tensile` takes the canonical table of :mod:`pipeline.ingest.table`
(``time``, ``force``, ``gauge_1``...) and returns a :class:`TensileRun`:

- checks the record (monotonic time, NaN stretches, saturated gauges) and
  raises a :class:`~pipeline.errors.SignalError` with a hint when it is unfit;
- averages the gauges (the mean cancels the bending of the segment) and keeps
  their spread as a quality figure;
- divides the mean elongation by the gauge length (relative elongation);
- segments the force into cycles and branches
  (:func:`pipeline.condition.segmentation.segment_cycles`);
- computes per cycle the hysteresis energy (loop area) [J] and the permanent
  set [m].
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from pipeline.condition.segmentation import BRANCHES, Segmentation, segment_cycles
from pipeline.errors import SignalError

#: Longest run of missing samples that is dropped rather than reported [samples].
MAX_NAN_RUN = 3

#: A gauge resting at its extreme while the force changes by more than this
#: fraction of its range is saturated (clipped).
CLIPPING_FORCE_FRACTION = 0.1


@dataclass(frozen=True)
class TensileRun:
    """A conditioned tensile run.

    Attributes
    ----------
    samples : pandas.DataFrame
        One row per kept sample (index: row of the canonical table): ``time``
        [s] (if present), ``force`` [N], ``gauge_1``... [m], ``elongation`` [m]
        (mean of the gauges), ``gauge_spread`` [m] (largest minus smallest
        gauge), ``strain`` [1] (elongation over gauge length), ``cycle`` (int,
        0 before the first loading) and ``branch`` (categorical, one of
        :data:`~pipeline.condition.segmentation.BRANCHES`).
    cycles : pandas.DataFrame
        One row per cycle (index ``cycle``, 1-based): ``peak_force`` and
        ``valley_force`` [N] (medians at the peak and at the lower force before
        the cycle, magnitudes in the direction of the load), ``hysteresis_energy``
        [J], ``permanent_set`` [m] (in the direction of the load) and
        ``complete`` (bool: the unloading returned to the lower force; else the
        permanent set is NaN).
    gauge_length : float
        Gauge length [m].
    gauge_disagreement : float
        Gauge spread per unit mean elongation [1] (slope of ``gauge_spread``
        over ``elongation`` on the loading branches): 0.1 means the gauges differ
        by 10 % of the mean elongation (bending); NaN with a single gauge.
    segmentation : Segmentation
        The cycle and branch segmentation (indices refer to ``samples`` rows
        by position).
    warnings : list of str
        What was repaired on the way (dropped samples, unused gauges).
    """

    samples: pd.DataFrame
    cycles: pd.DataFrame
    gauge_length: float
    gauge_disagreement: float
    segmentation: Segmentation
    warnings: list[str] = field(default_factory=list)

    @property
    def sign(self) -> int:
        """+1 for tension-positive records, -1 for compression-negative ones."""
        return self.segmentation.sign


def loop_energy(force: np.ndarray, elongation: np.ndarray) -> float:
    """Area of a force-elongation loop [J], closed by a straight line from end to start.

    Parameters
    ----------
    force : numpy.ndarray
        Force along the path [N].
    elongation : numpy.ndarray
        Elongation along the path [m].

    Returns
    -------
    float
        ``closed integral of F dx`` (trapezoidal): positive for a loop whose
        loading branch lies above its unloading branch (energy dissipated), the
        same for compression-negative records.

    Examples
    --------
    A parallelogram with sides 2 mm and 1 kN, sheared by 1 mm:

    >>> loop_energy(np.array([0, 1e3, 1e3, 0]), np.array([0, 1e-3, 3e-3, 2e-3]))
    2.0
    """
    closed_force = np.append(force, force[0])
    closed_elongation = np.append(elongation, elongation[0])
    area = 0.5 * (closed_force[1:] + closed_force[:-1]) * np.diff(closed_elongation)
    return float(np.sum(area))


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """Start and stop (exclusive) of each run of True in `mask`."""
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return list(zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1), strict=True))


def _check_time(time: np.ndarray) -> None:
    steps = np.diff(time)
    bad = np.flatnonzero(~(steps > 0) & np.isfinite(steps))
    if bad.size:
        sample = int(bad[0]) + 1
        raise SignalError(
            f"time is not strictly increasing at sample {sample} "
            f"({time[sample - 1]:.6g} s then {time[sample]:.6g} s)",
            column="time",
            hint="the log may hold several tests or a restarted acquisition: split it",
        )


def _drop_missing(table: pd.DataFrame, columns: list[str], warnings: list[str]) -> pd.DataFrame:
    """Drop isolated missing samples; raise on a stretch longer than MAX_NAN_RUN."""
    for column in columns:
        for start, stop in _runs(table[column].isna().to_numpy()):
            if stop - start > MAX_NAN_RUN:
                raise SignalError(
                    f"{stop - start} missing values in a row (samples {start} to {stop - 1})",
                    column=column,
                    hint="the channel dropped out: repeat the test or cut the log before the gap",
                )
    missing = table[columns].isna().any(axis=1)
    if missing.any():
        warnings.append(f"dropped {int(missing.sum())} sample(s) with a missing value")
    return table.loc[~missing]


def _check_clipping(force: np.ndarray, gauge: np.ndarray, name: str, rows: pd.Index) -> None:
    """Raise when `gauge` rests at its extreme while the force keeps changing."""
    force_span = np.ptp(force)
    for extreme in (gauge.max(), gauge.min()):
        for start, stop in _runs(gauge == extreme):
            if np.ptp(force[start:stop]) > CLIPPING_FORCE_FRACTION * force_span:
                raise SignalError(
                    f"the gauge stays at {extreme:.6g} m from sample {rows[start]} to "
                    f"{rows[stop - 1]} while the force keeps changing: it is stuck or saturated "
                    "(out of range)",
                    column=name,
                    hint="reset the gauge within its range, or leave this gauge out",
                )


def _permanent_sets(elongation: np.ndarray, segmentation: Segmentation) -> np.ndarray:
    """Median elongation at the valley after each cycle minus the one before it [m].

    In the direction of the load: positive when the specimen keeps part of its
    deformation, for tension- and compression-positive records alike.
    """
    rest = [
        np.nan if valley is None else float(np.median(elongation[valley[0] : valley[1] + 1]))
        for valley in segmentation.valleys
    ]
    return segmentation.sign * np.diff(np.array(rest))


def condition_tensile(
    table: pd.DataFrame,
    gauge_length: float,
    *,
    preload: float | None = None,
    n_cycles: int | None = None,
) -> TensileRun:
    """Condition the canonical table of a tensile run.

    Error messages number the samples from 0 in table order.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table (SI): ``force`` [N], ``gauge_1``... [m], optionally
        ``time`` [s]; other columns are ignored.
    gauge_length : float
        Length of the measured segment [m].
    preload : float, optional
        Magnitude of the preload [N]; the force must rise above it.
    n_cycles : int, optional
        Number of cycles the test should have; fewer is an error.

    Returns
    -------
    TensileRun
        Samples with elongation, strain, cycle and branch; per-cycle hysteresis
        energy and permanent set; the gauge disagreement; warnings.

    Raises
    ------
    SignalError
        Missing force or gauge column, non-monotonic time, a stretch of missing
        values, a saturated gauge, force never above the preload, fewer cycles
        than asked.
    ValueError
        When `gauge_length` is not a positive number.
    """
    if not gauge_length > 0:
        raise ValueError(f"gauge_length must be > 0 [m], got {gauge_length!r}")
    warnings: list[str] = []
    gauges = [name for name in table.columns if str(name).startswith("gauge_")]
    if "force" not in table.columns or not gauges:
        raise SignalError(
            "a tensile run needs a force column and at least one gauge column",
            hint="map the columns in the run sheet: columns = {force = ..., gauges = [...]}",
        )
    unused = [name for name in gauges if table[name].isna().all()]
    if unused:
        warnings.append(f"left out empty gauge column(s): {', '.join(unused)}")
        gauges = [name for name in gauges if name not in unused]
    if not gauges:
        raise SignalError("every gauge column is empty", hint="check the gauge column mapping")
    columns = (["time"] if "time" in table.columns else []) + ["force", *gauges]
    samples = table[columns].astype(float)
    if "time" in samples.columns:
        _check_time(samples["time"].to_numpy())
    samples = _drop_missing(samples, columns, warnings)
    force = samples["force"].to_numpy()
    readings = samples[gauges].to_numpy()
    for number, name in enumerate(gauges):
        _check_clipping(force, readings[:, number], name, samples.index)

    segmentation = segment_cycles(force, preload=preload, n_cycles=n_cycles)
    elongation = readings.mean(axis=1)
    samples = samples.assign(
        elongation=elongation,
        gauge_spread=readings.max(axis=1) - readings.min(axis=1),
        strain=elongation / gauge_length,
        cycle=segmentation.cycle,
        branch=pd.Categorical(segmentation.branch, categories=BRANCHES),
    )

    energies, peaks, valleys = [], [], []
    oriented = segmentation.sign * force
    for number, (load_start, load_end, unload_start, unload_end) in enumerate(segmentation.turns):
        path = slice(load_start, unload_end + 1)
        energies.append(loop_energy(force[path], elongation[path]))
        peaks.append(float(np.median(oriented[load_end : unload_start + 1])))
        rest = segmentation.valleys[number]
        valleys.append(
            float(np.median(oriented[rest[0] : rest[1] + 1] if rest else oriented[load_start]))
        )
    cycles = pd.DataFrame(
        {
            "peak_force": peaks,
            "valley_force": valleys,
            "hysteresis_energy": energies,
            "permanent_set": _permanent_sets(elongation, segmentation),
            "complete": segmentation.complete,
        },
        index=pd.Index(np.arange(1, segmentation.n_cycles + 1), name="cycle"),
    )
    loading = samples["branch"].to_numpy() == "loading"
    disagreement = np.nan
    if len(gauges) > 1 and loading.any() and np.ptp(elongation[loading]) > 0:
        spread = samples["gauge_spread"].to_numpy()
        disagreement = float(abs(np.polyfit(elongation[loading], spread[loading], 1)[0]))
    return TensileRun(
        samples=samples,
        cycles=cycles,
        gauge_length=float(gauge_length),
        gauge_disagreement=disagreement,
        segmentation=segmentation,
        warnings=warnings,
    )
