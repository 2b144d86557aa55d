"""Conditioning of a tensile run: gauges to strain, cycles, loops and set.

:func:`condition_tensile` takes the canonical table of :mod:`pipeline.ingest.table`
(``time``, ``force``, ``gauge_1``...) and returns a :class:`TensileRun`:

- checks the record (NaN stretches, saturated gauges) and raises a
  :class:`~pipeline.errors.SignalError` with a hint when it is unfit; time is
  not needed (the readers warn of repeated or reset time stamps); sets aside,
  with a warning, the samples that are a recorder's over-range codes, not
  readings (:data:`SPIKE_FACTOR`);
- finds a fracture and leaves everything after it out
  (:mod:`pipeline.condition.breaks`), and cuts each channel where it stopped
  following the specimen (an extensometer taken off);
- turns each channel into strain (a length over the gauge length, a strain as
  read), and chooses the channels that give the specimen's strain: averaged
  only when they measure the same thing (:mod:`pipeline.condition.channels`),
  the spread of the averaged ones kept as a quality figure; a strain column
  worked out from a length channel counts as that channel, whatever its name;
- segments the force into cycles and branches
  (:func:`pipeline.condition.segmentation.segment_cycles`);
- computes per cycle the hysteresis energy (loop area) [J] and the permanent
  set [m].
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from pipeline.condition.breaks import (
    FRACTURE_DROP,
    Removal,
    find_fracture,
    find_removal,
)
from pipeline.condition.channels import (
    Copy,
    choose_channels,
    compared_slopes,
    find_derived,
    find_switch,
)
from pipeline.condition.segmentation import BRANCHES, Segmentation, load_sign, segment_cycles
from pipeline.condition.tares import join_tares
from pipeline.errors import SignalError

#: Longest run of missing samples that is dropped rather than reported [samples].
MAX_NAN_RUN = 3

#: Largest relative difference between the length a file's strain column divides a length
#: channel by and the run sheet's gauge length that goes without a warning.
GAUGE_LENGTH_TOLERANCE = 0.01

#: Shortest length a file's strain column may divide a length channel by [m]: no gauge is
#: shorter, and a strain whose numbers are off by a power of ten (a ratio read as %, a
#: lost decimal mark) divides by such a length.
MIN_GAUGE_LENGTH = 1e-3

#: A sample this many times larger than the channel's other samples (all but
#: :data:`SPIKE_SHARE` of them), in magnitude, is no reading but a code a recorder writes
#: when a sensor is over its range or drops out (Bluehill's 21474.8, 2^31 / 10^5; an
#: infinity): a specimen never moves so far in one sample. A reading between zero and the
#: others (the one sample before a hold) is never one.
SPIKE_FACTOR = 100

#: Largest share of a channel's samples that may be such codes: the rest set the scale.
SPIKE_SHARE = 1e-3

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
        [s] (if present, not necessarily increasing), ``force`` [N], the
        channels as read (``gauge_1``... [m], ``strain_1``... [1]), ``strain``
        [1] (mean strain of the channels used, NaN where one of them is not
        usable), ``elongation`` [m] (strain times the gauge length, NaN without
        one), ``gauge_spread`` [m] (largest minus smallest channel used),
        ``cycle`` (int, 0 before the first loading) and ``branch`` (categorical,
        one of :data:`~pipeline.condition.segmentation.BRANCHES`).
    cycles : pandas.DataFrame
        One row per cycle (index ``cycle``, 1-based): ``peak_force`` and
        ``valley_force`` [N] (medians at the peak and at the lower force before
        the cycle, magnitudes in the direction of the load), ``hysteresis_energy``
        [J], ``permanent_strain`` [1] and ``permanent_set`` [m] (in the
        direction of the load) and ``complete`` (bool: the unloading returned to
        the lower force; else the permanent set is NaN).
    gauge_length : float
        Gauge length [m]; NaN when the run sheet gives none (strain channels only).
    gauge_disagreement : float
        Spread of the channels averaged per unit mean strain [1] (slope of the
        spread over the mean on the loading branches): 0.1 means they differ by
        10 % of the mean (bending); NaN with a single channel.
    segmentation : Segmentation
        The cycle and branch segmentation of the samples up to the fracture
        (indices refer to ``samples`` rows by position).
    channels : pandas.DataFrame
        One row per displacement channel (index: canonical name): ``column``
        (the file's name), ``kind`` (extensometer, gauge, crosshead), ``slope``
        [N] (its stiffness on the first loading, see
        :mod:`pipeline.condition.channels`), ``used`` (bool), ``removed_at``
        (position of the first unusable sample, -1 when usable throughout),
        ``removal`` (why: ``"runs backwards"``, ``"jumps"``, ``"freezes"`` or "") and
        ``zeroed`` (bool: the lab zeroed it during the record, so its readings count from
        that zero, :func:`~pipeline.condition.tares.join_tares`).
    channel_strains : pandas.DataFrame
        Strain [1] of each channel that can give one (index as ``samples``): a
        strain as read, an elongation over the gauge length; NaN from where the
        channel stopped following the specimen, and after a fracture.
    fracture : int or None
        Position of the last sample before fracture; None when it did not break.
    single_pull : bool
        One loading (asked with ``cycles = 1``, or found): E0 comes from it.
    warnings : list of str
        What was repaired or decided on the way (dropped samples, channels left
        out or cut, fracture).
    """

    samples: pd.DataFrame
    cycles: pd.DataFrame
    gauge_length: float
    gauge_disagreement: float
    segmentation: Segmentation
    channels: pd.DataFrame
    channel_strains: pd.DataFrame
    fracture: int | None = None
    single_pull: bool = False
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


def _spikes(values: np.ndarray) -> np.ndarray:
    """Mask of the samples of `values` that are codes, not readings (:data:`SPIKE_FACTOR`),
    in runs of at most :data:`MAX_NAN_RUN`: a longer run is a sensor at the end of its
    range, which the channel cuts see (:func:`~pipeline.condition.breaks.find_removal`)."""
    magnitude = np.abs(values)
    allowed = max(1, int(values.size * SPIKE_SHARE))
    ranked = np.sort(magnitude[~np.isnan(magnitude)])
    if ranked.size <= allowed or ranked[-allowed - 1] == 0:
        return np.zeros(values.size, dtype=bool)
    spikes = magnitude > SPIKE_FACTOR * ranked[-allowed - 1]
    for start, stop in _runs(spikes):
        if stop - start > MAX_NAN_RUN:
            spikes[start:stop] = False
    return spikes


def _blank_spikes(table: pd.DataFrame, columns: Mapping[str, str], warnings: list[str]
                  ) -> pd.DataFrame:
    """`table` with the samples of :func:`_spikes` in each of `columns` (canonical name ->
    the file's) set to NaN, each told in `warnings`."""
    for name, column in columns.items():
        spikes = _spikes(table[name].to_numpy())
        if spikes.any():
            rows = ", ".join(str(row) for row in table.index[spikes][:5])
            warnings.append(f"{column!r}: {int(spikes.sum())} sample(s) over {SPIKE_FACTOR} "
                            "times larger than the channel's other readings "
                            f"(sample {rows}): a code of a sensor over its range or dropping "
                            "out, no reading: left out")
            table.loc[spikes, name] = np.nan
    return table


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
    if gauge.size < 2:
        return
    force_span = np.ptp(force)
    for extreme in (gauge.max(), gauge.min()):
        for start, stop in _runs(gauge == extreme):
            if np.ptp(force[start:stop]) > CLIPPING_FORCE_FRACTION * force_span:
                raise SignalError(
                    f"the gauge stays at {extreme:.6g} from sample {rows[start]} to "
                    f"{rows[stop - 1]} while the force keeps changing: it is stuck or saturated "
                    "(out of range)",
                    column=name,
                    hint="reset the gauge within its range, or leave this gauge out",
                )


def _joined(channel: pd.Series, force: np.ndarray, column: str, warnings: list[str]
            ) -> pd.Series:
    """`channel` read from its last zero throughout (:func:`join_tares`), each zeroing
    told in `warnings`; the same Series when the record holds none."""
    joined, tares = join_tares(channel.to_numpy(), force)
    for tare in tares:
        step = (f"{-tare.step * 1e3:.4g} mm" if str(channel.name).startswith("gauge_")
                else f"{-tare.step:.4g}")
        warnings.append(f"{column!r} is zeroed at sample {channel.index[tare.position]} "
                        f"({abs(force[tare.position]) / 1e3:.4g} kN, the force holding): it "
                        f"stepped by {step} to zero; its readings before are moved by as "
                        "much, to join those after")
    return pd.Series(joined, index=channel.index, name=channel.name) if tares else channel


def _no_fracture_note(oriented_force: np.ndarray, gave_way: bool) -> list[str]:
    """The note of a single pull whose record ends with the force fallen from its maximum
    but still carried, with no fracture found (:func:`~pipeline.condition.breaks.find_fracture`):
    a record cut before the break, or a test stopped while the force fell; the figures at
    fracture are not given. Empty when it ends within
    :data:`~pipeline.condition.breaks.FRACTURE_DROP` of the maximum, or below
    :data:`UNLOADED` of it unless the specimen `gave_way` (:func:`_lengthens_as_it_falls`): a
    pull brought back there was unloaded (a proof-load test)."""
    maximum, last = float(np.max(oriented_force)), float(oriented_force[-1])
    low = 0.0 if gave_way else UNLOADED * maximum
    if not maximum > 0 or not low < last < (1.0 - FRACTURE_DROP) * maximum:
        return []
    return [f"no fracture found: the force ends at {last / 1e3:.4g} kN, {last / maximum:.0%} "
            f"of its maximum ({maximum / 1e3:.4g} kN), after falling with no sudden drop (a "
            "record cut before the break, or a test stopped while the force fell): nothing "
            "is given at fracture"]


#: A first loading of fewer samples cannot show which channel grows with the force (the
#: channels are compared on at least 5 samples within a third of its range).
SHORT_LOADING = 15

#: A single pull whose force ends below this fraction of its maximum was unloaded.
UNLOADED = 0.1

#: A single pull's last fall of the force that lengthens the specimen by more than this
#: fraction of what its loading did is no unloading (:func:`_lengthens_as_it_falls`).
FAILING_LENGTHENING = 0.01


def _permanent_strains(strain: np.ndarray, segmentation: Segmentation) -> np.ndarray:
    """Median strain at the valley after each cycle minus the one before it [1].

    In the direction of the load: positive when the specimen keeps part of its
    deformation, for tension- and compression-positive records alike.
    """
    rest = [np.nan] * len(segmentation.valleys)
    for number, valley in enumerate(segmentation.valleys):
        at_rest = strain[valley[0] : valley[1] + 1] if valley is not None else strain[:0]
        if np.isfinite(at_rest).any():
            rest[number] = float(np.nanmedian(at_rest))
    return segmentation.sign * np.diff(np.array(rest))


def _channel_strains(
    samples: pd.DataFrame, channels: list[str], gauge_length: float | None,
    columns: Mapping[str, str], warnings: list[str],
) -> dict[str, np.ndarray]:
    """Strain [1] of each channel: a strain as read, an elongation over the gauge length."""
    strains = {}
    for name in channels:
        values = samples[name].to_numpy()
        if name.startswith("strain_"):
            strains[name] = values.copy()
        elif gauge_length is not None:
            strains[name] = values / gauge_length
        elif len(channels) > 1:
            warnings.append(f"channel {columns[name]!r} not used: it reads a length and the run "
                            "sheet gives no gauge_length_mm")
    if not strains:
        raise SignalError(
            "the gauge channels read lengths, and the run sheet gives no gauge length",
            hint="set gauge_length_mm for the run (the length the gauges measure over)",
        )
    return strains


def _settle_duplicates(duplicates: Mapping[str, str], strains: dict[str, np.ndarray],
                       kinds: dict[str, str], columns: Mapping[str, str],
                       warnings: list[str]) -> None:
    """Give each length channel that repeats another (:func:`~pipeline.condition.channels.
    find_duplicates`) that one's kind, and leave it out: it measures nothing more."""
    for name, source in duplicates.items():
        kinds[name] = kinds[source]
        if strains.pop(name, None) is not None:
            warnings.append(f"channel {columns[name]!r} moves with {columns[source]!r} "
                            f"({kinds[source]}) to the last digit, its zero and sign aside: "
                            "one transducer written twice; not used")


def _settle_copies(copies: Mapping[str, Copy], strains: dict[str, np.ndarray],
                   kinds: dict[str, str], gauge_length: float | None,
                   columns: Mapping[str, str], warnings: list[str]) -> None:
    """Give each strain column worked out from a length channel (:func:`~pipeline.condition.
    channels.find_copies`) that channel's kind, whatever its name says; leave it out where
    that channel gives a strain of its own (the run sheet sets the gauge length), warning
    when the two lengths differ; a true strain kept is turned back into the engineering
    strain it was worked out from."""
    for name, copy in copies.items():
        source, length = copy.source, copy.length
        kinds[name] = kinds[source]
        said = (f"channel {columns[name]!r} is "
                f"{copy.formula(f'{columns[source]!r} ({kinds[source]})')} to the last "
                "digit: a strain worked out from it, not measured by itself")
        if length < MIN_GAUGE_LENGTH:
            warnings.append(f"no gauge is {length * 1e3:.4g} mm long: the numbers of "
                            f"{columns[name]!r} are likely off by a power of ten (a ratio "
                            "written as %, a lost decimal mark); check its unit in the export")
        if source not in strains:
            if copy.logarithmic:
                strains[name] = np.expm1(strains[name])
                said += "; used as exp() - 1 of it, the engineering strain"
            warnings.append(f"{said}; E0 from it is the {kinds[source]}'s")
            continue
        del strains[name]
        warnings.append(f"{said}; not used")
        if abs(length / gauge_length - 1) > GAUGE_LENGTH_TOLERANCE:
            warnings.append(
                f"the file divides {columns[source]!r} by {length * 1e3:.4g} mm for its strain "
                f"{columns[name]!r}, the run sheet's gauge_length_mm is "
                f"{gauge_length * 1e3:.4g}: E0 scales with the gauge length, check which is "
                "right")


def _cut_removed(force: np.ndarray, strains: dict[str, np.ndarray],
                 readings: dict[str, np.ndarray], loading: slice, sign: int,
                 columns: Mapping[str, str], warnings: list[str],
                 gauge_length: float | None) -> dict:
    """Cut each channel where it stopped following the specimen within `loading` (the first
    loading of a cyclic test, a single pull up to its fracture), judged on its own and
    against the other channels' `readings`; a strain channel also where it turns into a
    length channel over the `gauge_length` [m] (:func:`_switched`)."""
    removals = {}
    lengths = {key: value[loading] for key, value in readings.items() if key.startswith("gauge_")}
    for name, strain in strains.items():
        others = [sign * other[loading] for key, other in readings.items() if key != name]
        removal = find_removal(sign * force[loading], sign * strain[loading], others)
        switch = _switched(strain[loading], lengths, gauge_length, name)
        if switch is not None and (removal is None or switch[0] <= removal.position):
            removal = Removal(switch[0], f"turns into {columns[switch[1].source]!r} over "
                              f"{switch[1].length * 1e3:.4g} mm",
                              cause="the extensometer taken off, the software going on with "
                                    "another channel in its column")
        if removal is None:
            continue
        removals[name] = removal
        position = loading.start + removal.position
        strain[position:] = np.nan
        warnings.append(
            f"channel {columns[name]!r} {removal.reason} at {abs(force[position]) / 1e3:.4g} kN "
            f"while the specimen lengthens ({removal.cause}): its data from there on "
            "are not used")
    return removals


def _switched(strain: np.ndarray, lengths: dict[str, np.ndarray], gauge_length: float | None,
              name: str) -> tuple[int, Copy] | None:
    """Where strain channel `name` turns into a length channel over the `gauge_length` [m]
    (:func:`~pipeline.condition.channels.find_switch`), to within
    :data:`GAUGE_LENGTH_TOLERANCE`: a software's strain source once the extensometer is
    taken off. Any other length is none: two channels that move in proportion, as a
    necking specimen's extensometer and crosshead do, agree over some samples by chance."""
    if not name.startswith("strain_") or gauge_length is None:
        return None
    switch = find_switch(strain, lengths)
    if switch is None or abs(switch[1].length / gauge_length - 1) > GAUGE_LENGTH_TOLERANCE:
        return None
    return switch


def _lengthens_as_it_falls(segmentation: Segmentation, oriented_strain: np.ndarray) -> bool:
    """Whether the fall of the force back to its lower level that ends the record's last
    cycle lengthens the specimen (`oriented_strain`, in the direction of the load) by over
    :data:`FAILING_LENGTHENING` of what its loading did: the specimen giving way while the
    machine pulls on (a real rope's crimp slipping from 222 N to 22 N as the crosshead ran
    on by 4 mm), no unloading, whose stiffness, loop and set would be meaningless."""
    if not segmentation.n_cycles or not segmentation.complete[-1]:
        return False
    load_start, _, unload_start, unload_end = segmentation.turns[-1]
    ends = [oriented_strain[index] for index in (load_start, unload_start, unload_end)]
    if not np.all(np.isfinite(ends)):
        return False
    return ends[2] - ends[1] > FAILING_LENGTHENING * (ends[1] - ends[0]) > 0


def _label_after(segmentation: Segmentation, size: int, single_pull: bool,
                 fracture: int | None) -> tuple[np.ndarray, np.ndarray]:
    """Cycle and branch of every sample: the segmentation's, then ``after_fracture``;
    in a single pull the fall from the peak that is no unloading is ``beyond_peak``."""
    end = segmentation.cycle.size
    cycle = np.concatenate([segmentation.cycle, np.full(size - end, segmentation.n_cycles)])
    branch = np.concatenate([segmentation.branch.astype(object),
                             np.full(size - end, "after_fracture", dtype=object)])
    if single_pull and not segmentation.complete[-1]:
        last = segmentation.turns[-1]
        branch[last[2] : end][branch[last[2] : end] == "unloading"] = "beyond_peak"
    return cycle, branch


def cuts_of_channels_used(run: TensileRun) -> str:
    """Where the channels `run` takes its strain from were cut (the conditioning found them
    taken off, slipping or stuck), as ``"; 'Ext' runs backwards from 1.2 kN on"`` for
    each; empty when none was. For a fit that finds too few samples: they say why."""
    cut = run.channels[run.channels["used"] & (run.channels["removed_at"] >= 0)]
    force = run.samples["force"].to_numpy()
    return "".join(_cut_said(row.column, row.removal, force[row.removed_at])
                   for row in cut.itertuples())


def _cut_said(column: str, reason: str, force: float) -> str:
    """``"; 'Ext' runs backwards from 1.2 kN on"``: a channel cut at `force` [N]."""
    return f"; {column!r} {reason} from {abs(force) / 1e3:.4g} kN on"


def condition_tensile(
    table: pd.DataFrame,
    gauge_length: float | None,
    *,
    preload: float | None = None,
    n_cycles: int | None = None,
    kinds: Mapping[str, str] | None = None,
    columns: Mapping[str, str] | None = None,
    average: bool | None = None,
) -> TensileRun:
    """Condition the canonical table of a tensile run.

    Error messages number the samples from 0 in table order.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table (SI): ``force`` [N], ``gauge_1``... [m] and/or
        ``strain_1``... [1], optionally ``time`` [s] (not needed: it may repeat,
        reset or be missing); other columns are ignored.
    gauge_length : float or None
        Length the gauges measure over [m]; None when every channel is a strain.
    preload : float, optional
        Magnitude of the preload [N]; the force must rise above it.
    n_cycles : int, optional
        Number of cycles the test should have; fewer is an error, 1 is a single
        pull.
    kinds : mapping, optional
        Channel -> kind (``"extensometer"``, ``"gauge"``, ``"crosshead"``), as
        the reader found it; default ``"gauge"``.
    columns : mapping, optional
        Channel -> the file's column name, for messages; default the channel.
    average : bool, optional
        The run sheet's ``average_gauges`` (see :mod:`pipeline.condition.channels`).

    Returns
    -------
    TensileRun
        Samples with strain, elongation, cycle and branch; per-cycle hysteresis
        energy and permanent set; the channels and which are used; the fracture;
        warnings.

    Raises
    ------
    SignalError
        Missing force or gauge column, a stretch of missing values, a saturated
        gauge, force never above the preload, fewer cycles than asked, lengths
        without a gauge length, no channel that grows with the force.
    ValueError
        When `gauge_length` is given and not a positive number.
    """
    if gauge_length is not None and not gauge_length > 0:
        raise ValueError(f"gauge_length must be > 0 [m], got {gauge_length!r}")
    warnings: list[str] = []
    channels = [name for name in table.columns if str(name).startswith(("gauge_", "strain_"))]
    if "force" not in table.columns or not channels:
        raise SignalError(
            "a tensile run needs a force column and at least one gauge column",
            hint="map the columns in the run sheet: columns = {force = ..., gauges = [...]}",
        )
    columns = {name: (columns or {}).get(name, name) for name in channels}
    kinds = {name: (kinds or {}).get(name) or "gauge" for name in channels}
    unused = [name for name in channels if table[name].isna().all()]
    if unused:
        warnings.append(f"left out empty gauge column(s): {', '.join(unused)}")
        channels = [name for name in channels if name not in unused]
    if not channels:
        raise SignalError("every gauge column is empty", hint="check the gauge column mapping")
    kept = (["time"] if "time" in table.columns else []) + ["force", *channels]
    samples = _blank_spikes(table[kept].astype(float),
                            {"force": "force"} | {name: columns[name] for name in channels},
                            warnings)
    samples = _drop_missing(samples, ["force", *channels], warnings)
    force = samples["force"].to_numpy()
    zeroed = set()
    for name in channels:
        channel = samples[name]
        joined = _joined(channel, force, columns[name], warnings)
        if joined is not channel:
            zeroed.add(name)
        samples[name] = joined
    sign = load_sign(force)
    if sign < 0:
        warnings.append("the force is negative as it loads (a compression test, or a "
                        "machine that logs tension negative): forces, elongations and E0 are "
                        "read in the direction of the load, as magnitudes")
    time = samples["time"].to_numpy() if "time" in samples.columns else None
    fracture = find_fracture(sign * force, time)
    end = force.size if fracture is None else fracture + 1
    if fracture is not None:
        warnings.append(f"fracture at {abs(force[fracture]) / 1e3:.4g} kN (sample "
                        f"{samples.index[fracture]}): the {force.size - end} samples after it "
                        "are not analysed")
    segmentation = segment_cycles(force[:end], preload=preload, n_cycles=n_cycles)
    single_pull = n_cycles == 1 or (n_cycles is None and segmentation.n_cycles == 1)
    if n_cycles == 1 and segmentation.n_cycles > 1:
        warnings.append(f"the run sheet says cycles = 1, the log has {segmentation.n_cycles} "
                        "loadings: E0 from the first loading only")

    for name in channels:
        _check_clipping(force[:end], samples[name].to_numpy()[:end], columns[name],
                        samples.index)
    strains = _channel_strains(samples, channels, gauge_length, columns, warnings)
    duplicates, copies = find_derived(
        {name: samples[name].to_numpy()[:end] for name in channels}, kinds)
    _settle_duplicates(duplicates, strains, kinds, columns, warnings)
    _settle_copies(copies, strains, kinds, gauge_length, columns, warnings)
    first = slice(0, int(segmentation.turns[0, 1]) + 1)  # up to the first peak
    readings = {name: samples[name].to_numpy() for name in channels}
    removals = _cut_removed(force, strains, readings, slice(0, end) if single_pull else first,
                            sign, columns, warnings, gauge_length)
    for strain in strains.values():
        strain[end:] = np.nan
    loading = np.zeros(force.size, dtype=bool)
    loading[first] = segmentation.branch[first] == "loading"
    oriented = {name: sign * strain for name, strain in strains.items()}
    choice = choose_channels(compared_slopes(sign * force, oriented, loading),
                             {name: kinds[name] for name in strains}, columns, average)
    warnings += choice.warnings
    if not choice.used:  # saying why, when the channels were cut where they misbehaved
        held = int(np.count_nonzero(loading))
        if held < SHORT_LOADING:
            raise SignalError(
                f"the first loading holds {held} samples: too few to tell which gauge channel "
                "grows with the force",
                hint="the record is too short: check that the file holds the whole test")
        raise SignalError(
            "no gauge channel grows with the force on the first loading" + "".join(
                _cut_said(columns[name], removal.reason, force[removal.position])
                for name, removal in removals.items()),
            hint="check the gauge columns, their sign and wiring, and the run sheet's columns",
        )

    used = np.column_stack([strains[name] for name in choice.used])
    strain = used.mean(axis=1)
    length = np.nan if gauge_length is None else float(gauge_length)
    failing = single_pull and _lengthens_as_it_falls(segmentation, sign * strain)
    if failing:  # no unloading: the last cycle is not complete
        segmentation = replace(segmentation, valleys=[*segmentation.valleys[:-1], None])
    if fracture is None and single_pull:
        warnings += _no_fracture_note(sign * force, failing)
    cycle, branch = _label_after(segmentation, force.size, single_pull, fracture)
    samples = samples.assign(
        strain=strain,
        elongation=strain * length,
        gauge_spread=(used.max(axis=1) - used.min(axis=1)) * length,
        cycle=cycle,
        branch=pd.Categorical(branch, categories=BRANCHES),
    )

    energies, peaks, valleys = [], [], []
    oriented_force = sign * force
    elongation = samples["elongation"].to_numpy()
    for number, (load_start, load_end, unload_start, unload_end) in enumerate(segmentation.turns):
        path = slice(load_start, unload_end + 1)
        energies.append(np.nan if failing else loop_energy(force[path], elongation[path]))
        peaks.append(float(np.median(oriented_force[load_end : unload_start + 1])))
        rest = segmentation.valleys[number]
        valleys.append(float(np.median(
            oriented_force[rest[0] : rest[1] + 1] if rest else oriented_force[load_start])))
    permanent = _permanent_strains(strain, segmentation)
    cycles = pd.DataFrame(
        {
            "peak_force": peaks,
            "valley_force": valleys,
            "hysteresis_energy": energies,
            "permanent_strain": permanent,
            "permanent_set": permanent * length,
            "complete": segmentation.complete,
        },
        index=pd.Index(np.arange(1, segmentation.n_cycles + 1), name="cycle"),
    )
    disagreement = np.nan
    on_loading = (samples["branch"].to_numpy() == "loading") & np.isfinite(strain)
    if len(choice.used) > 1 and on_loading.any() and np.ptp(strain[on_loading]) > 0:
        spread = used.max(axis=1) - used.min(axis=1)
        disagreement = float(abs(np.polyfit(strain[on_loading], spread[on_loading], 1)[0]))
    channel_table = pd.DataFrame(
        {
            "column": [columns[name] for name in channels],
            "kind": [kinds[name] for name in channels],
            "slope": [choice.slopes.get(name, np.nan) for name in channels],
            "used": [name in choice.used for name in channels],
            "removed_at": [removals[name].position if name in removals else -1
                           for name in channels],
            "removal": [removals[name].reason if name in removals else "" for name in channels],
            "zeroed": [name in zeroed for name in channels],
        },
        index=pd.Index(channels, name="channel"),
    )
    return TensileRun(
        samples=samples,
        cycles=cycles,
        gauge_length=length,
        gauge_disagreement=disagreement,
        segmentation=segmentation,
        channels=channel_table,
        channel_strains=pd.DataFrame(strains, index=samples.index),
        fracture=fracture,
        single_pull=single_pull,
        warnings=warnings,
    )
