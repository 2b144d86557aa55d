"""Which displacement channels give the specimen's strain, and when they may be averaged.

A file may carry several displacement channels, of different kinds (the
reader names the kind from the column name, see
:func:`pipeline.ingest.names.gauge_kind`):

``extensometer``
    on the specimen: an extensometer, a dial gauge, or a strain column;
``gauge``
    the name does not say (``Extension``, ``Weg 1``, ``Wydłużenie``);
``crosshead``
    the machine's crosshead or actuator travel: it includes the compliance of
    the machine, so its stiffness is too low.

Channels are averaged only when they measure the same thing: the run sheet
says so (``average_gauges = true``), or they are of one kind and their
stiffnesses agree within :data:`SAME_SLOPE_TOLERANCE` (two gauges on either
side of a chain differ by its bending; the mean cancels it): of the channels
of the kind first in :data:`PREFERENCE`, the most that agree so are averaged
(three transducers around a specimen, one of them off: the other two), the
stiffer ones on a tie. Where none agree, one channel is used: the stiffest
(a channel that includes more of the machine reads more elongation). Every
channel left out is named in a warning with its stiffness relative to the
ones used. Never a silent average of different kinds.

A strain column may be no measurement of its own but a length channel of the
file divided by a length (Bluehill's ``Tensile strain``, a NanoSuite's
``Engineering Strain``: the crosshead's extension over the gauge length), or
the logarithm of one plus that (a ``True Strain``). Its name then says nothing
of what it measures; :func:`find_copies` finds it by its readings, which
follow the length channel's to the last digit. A length
column may likewise repeat another's readings (MTS TestSuite's ``Extension``
beside ``Crosshead`` when no extensometer is fitted): :func:`find_duplicates`
finds it, and it counts as the kind of the two that claims least.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

#: Kinds of displacement channel, the preferred first.
PREFERENCE = ("extensometer", "gauge", "crosshead")

#: Channels of one kind agree when the lower stiffness is at least ``1 - tolerance`` of
#: the higher (0.2: gauges bending up to +-11 % about their mean agree; a crosshead
#: whose machine takes 30 % of the travel does not).
SAME_SLOPE_TOLERANCE = 0.2

#: Force range of the first loading on which channels are compared, as fractions of its
#: force range (from its lowest force: of its maximum for a loading from zero).
COMPARISON_RANGE = (0.1, 0.4)

#: Fewest samples a channel needs in the comparison range.
MIN_COMPARED = 5

#: A strain column is a copy of a length channel when no sample departs from the straight
#: line through both by more than this many times what rounding both to their printed
#: digits can explain (a copy departs by up to 0.67 of it; two sensors on a real
#: specimen, 4 times or more).
COPY_MARGIN = 1.5
#: Departure always allowed, as a fraction of the strain's range (values printed with
#: varying significant digits have no decimal grid to take their rounding from).
COPY_FLOOR = 1e-6
#: Fewest samples two channels need in common to be found one the other's copy.
MIN_COPY_SAMPLES = 20
#: Two length channels on one straight line (to within their rounding) repeat one
#: another when its slope is 1 (or -1) to within this: the same readings to another zero.
DUPLICATE_SCALE_TOLERANCE = 1e-3


class Copy(NamedTuple):
    """How a strain column was worked out from a length channel of the file."""

    source: str  #: the length channel
    length: float  #: the length the software divided it by [m]
    #: True for a true (logarithmic) strain ln(1 + source / length), False for source / length
    logarithmic: bool = False

    def formula(self, source: str) -> str:
        """The working in words, the length channel called `source`."""
        ratio = f"{source} over {self.length * 1e3:.4g} mm"
        return f"ln(1 + {ratio})" if self.logarithmic else ratio


@dataclass(frozen=True)
class Choice:
    """The channels used for the specimen's strain, and why."""

    used: list[str]  #: canonical names of the channels averaged (one when not averaged)
    slopes: dict[str, float]  #: stiffness of each channel on the comparison range [N]
    warnings: list[str] = field(default_factory=list)


def compared_slopes(force: np.ndarray, strains: dict[str, np.ndarray],
                    loading: np.ndarray) -> dict[str, float]:
    """Stiffness [N] of each channel: least-squares slope of force over its strain.

    Parameters
    ----------
    force : numpy.ndarray
        Force in the direction of the load [N].
    strains : dict of numpy.ndarray
        Channel -> strain in the direction of the load [1] (NaN where unusable).
    loading : numpy.ndarray
        Boolean mask of the first loading's samples.

    Returns
    -------
    dict
        Channel -> slope on the samples of the first loading whose force lies in
        :data:`COMPARISON_RANGE` of its range (NaN when a channel has fewer than
        :data:`MIN_COMPARED` usable samples there).
    """
    low, top = (force[loading].min(), force[loading].max()) if loading.any() else (0, np.nan)
    limits = [low + fraction * (top - low) for fraction in COMPARISON_RANGE]
    inside = loading & (force >= limits[0]) & (force <= limits[1])
    slopes = {}
    for name, strain in strains.items():
        usable = inside & np.isfinite(strain)
        if usable.sum() < MIN_COMPARED or not np.ptp(strain[usable]) > 0:
            slopes[name] = np.nan
            continue
        slopes[name] = float(np.polyfit(strain[usable], force[usable], 1)[0])
    return slopes


def find_copies(readings: dict[str, np.ndarray]) -> dict[str, Copy]:
    """The strain channels that are a length channel divided by a length, or the logarithm
    of one plus that.

    Parameters
    ----------
    readings : dict of numpy.ndarray
        Channel -> readings in SI (``strain_1``... [1], ``gauge_1``... [m]; NaN where
        missing).

    Returns
    -------
    dict
        Strain channel -> how it was worked out (:class:`Copy`), for each strain whose
        readings (or their exponential less one, for a true strain) lie on a straight line
        through a length channel's to within their rounding (:data:`COPY_MARGIN`). A
        copy's offset (another zero) and sign do not matter.

    Examples
    --------
    >>> extension = np.round(np.linspace(0.0, 2e-3, 50) + 1e-5 * np.sin(np.arange(50)), 7)
    >>> strain = np.round(extension / 0.05, 5)  # printed to 5 decimals, as Bluehill does
    >>> extensometer = np.round(0.8 * extension / 0.05 + 2e-5 * np.cos(np.arange(50)), 5)
    >>> true_strain = np.round(np.log1p(extension / 0.05), 6)
    >>> copies = find_copies({"gauge_1": extension, "strain_1": strain,
    ...                       "strain_2": extensometer, "strain_3": true_strain})
    >>> {name: copy.formula(copy.source) for name, copy in copies.items()}
    {'strain_1': 'gauge_1 over 50 mm', 'strain_3': 'ln(1 + gauge_1 over 50 mm)'}
    """
    lengths = [name for name in readings if name.startswith("gauge_")]
    copies = {}
    for name, strain in readings.items():
        if not name.startswith("strain_"):
            continue
        copy = next((Copy(source, 1.0 / abs(scale), logarithmic)
                     for logarithmic in (False, True) for source in lengths
                     if (scale := _copy_scale(strain, readings[source], logarithmic))
                     is not None), None)
        if copy is not None:
            copies[name] = copy
    return copies


def find_switch(strain: np.ndarray, lengths: dict[str, np.ndarray]) -> tuple[int, Copy] | None:
    """Where a strain channel, its own before, turns into a length channel divided by a
    length to its end (Bluehill goes on with the crosshead's travel once the extensometer
    is taken off, in the extensometer's column), and how; None if it never does.

    Parameters
    ----------
    strain : numpy.ndarray
        The strain channel's readings [1], NaN where missing.
    lengths : dict of numpy.ndarray
        The length channels' readings [m], same samples.

    Returns
    -------
    tuple of (int, Copy) or None
        The first sample of the copy (:data:`MIN_COPY_SAMPLES` at least to the end, to
        within their rounding, :func:`find_copies`) and what it copies.

    Examples
    --------
    >>> extension = np.round(np.linspace(0.0, 2e-3, 80) + 1e-5 * np.sin(np.arange(80)), 7)
    >>> strain = np.round(0.8 * extension / 0.05 + 2e-5 * np.cos(np.arange(80)), 5)
    >>> strain[50:] = np.round((extension[50:] - 4e-5) / 0.05, 5)
    >>> position, copy = find_switch(strain, {"gauge_1": extension})
    >>> position, copy.formula(copy.source)
    (50, 'gauge_1 over 50 mm')
    """
    for source, length in lengths.items():
        tail = slice(strain.size - MIN_COPY_SAMPLES, None)
        if (_copy_scale(strain[tail], length[tail]) is None
                or _copy_scale(strain, length) is not None):  # a whole copy: find_copies'
            continue
        low, high = 0, tail.start  # the tail from `high` is a copy, from `low` not
        while high - low > 1:
            middle = (low + high) // 2
            if _copy_scale(strain[middle:], length[middle:]) is None:
                low = middle
            else:
                high = middle
        scale = _copy_scale(strain[high:], length[high:])
        return high, Copy(source, 1.0 / abs(scale))
    return None


def find_duplicates(readings: dict[str, np.ndarray], kinds: dict[str, str]) -> dict[str, str]:
    """The length channels that repeat another's readings: one transducer written twice.

    Parameters
    ----------
    readings : dict of numpy.ndarray
        Channel -> readings in SI (``gauge_1``... [m]; NaN where missing); strain
        channels are passed over.
    kinds : dict
        Channel -> its kind as the name says (``"extensometer"``, ``"gauge"``,
        ``"crosshead"``; ``"gauge"`` when missing).

    Returns
    -------
    dict
        Repeating channel -> the channel it repeats, for each length channel whose
        readings are another's to within their rounding (:data:`COPY_MARGIN`), another
        zero and sign allowed. Of two such channels the one of the kind last in
        :data:`PREFERENCE` is the source: an ``Extension`` that repeats the
        ``Crosshead`` to the last digit is the crosshead's travel, whatever its name.

    Examples
    --------
    >>> crosshead = np.round(np.linspace(0.0, 2e-3, 50) + 1e-5 * np.sin(np.arange(50)), 7)
    >>> find_duplicates({"gauge_1": crosshead, "gauge_2": crosshead + 1e-4},
    ...                 {"gauge_1": "crosshead", "gauge_2": "gauge"})
    {'gauge_2': 'gauge_1'}
    """
    def claims(name: str) -> int:
        return -PREFERENCE.index(kinds.get(name) or "gauge")

    lengths = sorted((name for name in readings if name.startswith("gauge_")), key=claims)
    duplicates: dict[str, str] = {}
    for index, source in enumerate(lengths):
        if source in duplicates:
            continue
        for name in lengths[index + 1:]:
            scale = (None if name in duplicates
                     else _copy_scale(readings[name], readings[source]))
            if scale is not None and abs(abs(scale) - 1) <= DUPLICATE_SCALE_TOLERANCE:
                duplicates[name] = source
    return duplicates


def find_derived(readings: dict[str, np.ndarray], kinds: dict[str, str]
                 ) -> tuple[dict[str, str], dict[str, Copy]]:
    """The channels that measure nothing of their own: the length channels that repeat
    another (:func:`find_duplicates`) and the strain channels worked out from a length
    channel (:func:`find_copies`), a copy's source being the channel its source repeats,
    if it does (parameters as there)."""
    duplicates = find_duplicates(readings, kinds)
    copies = {name: copy._replace(source=duplicates.get(copy.source, copy.source))
              for name, copy in find_copies(readings).items()}
    return duplicates, copies


def _copy_scale(copy: np.ndarray, source: np.ndarray, logarithmic: bool = False
                ) -> float | None:
    """The slope of `copy` (of its exponential less one, if `logarithmic`) over `source` if
    that is `source` rescaled (to within their rounding, :data:`COPY_MARGIN`), else None."""
    both = np.isfinite(copy) & np.isfinite(source)
    if both.sum() < MIN_COPY_SAMPLES or not (np.ptp(copy[both]) > 0):
        return None
    copy, source = copy[both], source[both]
    copy_rounding = _rounding(copy)
    if logarithmic:  # the rounding of ln(1 + e) grows by 1 + e in e
        copy_rounding *= np.exp(copy.max())
        copy = np.expm1(copy)
    y, x = copy - copy.mean(), source - source.mean()
    if not (np.ptp(x) > 0 and np.ptp(y) > 0):
        return None
    scale = float(x @ y / (x @ x))
    allowed = (COPY_MARGIN * (copy_rounding + abs(scale) * _rounding(source)) / 2
               + COPY_FLOOR * np.ptp(y))
    return scale if np.abs(y - scale * x).max() <= allowed else None


def _rounding(values: np.ndarray) -> float:
    """The decimal step every value of `values` is a multiple of (the last digit printed,
    in the unit the values are in now), or 0 if none is found: the coarsest of 10^-d
    (at least 20 steps to the range) within a thousandth of which every value lies."""
    first = int(np.ceil(-np.log10(np.ptp(values) / 20)))
    for digits in range(first, first + 13):
        scaled = values * 10.0**digits
        if np.all(np.abs(scaled - np.round(scaled)) < 1e-3):
            return 10.0**-digits
    return 0.0


def _agreeing(group: list[str], slopes: dict[str, float]) -> list[str]:
    """The most channels of `group` whose stiffnesses agree within
    :data:`SAME_SLOPE_TOLERANCE`, the stiffer ones on a tie (one channel: the stiffest); in
    the group's order."""
    ordered = sorted(group, key=lambda name: slopes[name], reverse=True)
    best: list[str] = []
    for start, name in enumerate(ordered):
        agree = [other for other in ordered[start:]
                 if slopes[other] >= (1.0 - SAME_SLOPE_TOLERANCE) * slopes[name]]
        if len(agree) > len(best):
            best = agree
    return [name for name in group if name in best]


def choose_channels(
    slopes: dict[str, float],
    kinds: dict[str, str],
    columns: dict[str, str],
    average: bool | None = None,
) -> Choice:
    """Decide which channels give the strain (see the module docstring).

    Parameters
    ----------
    slopes : dict
        Channel -> stiffness on the comparison range [N] (:func:`compared_slopes`).
    kinds : dict
        Channel -> ``"extensometer"``, ``"gauge"`` or ``"crosshead"``.
    columns : dict
        Channel -> the file's column name, for the messages.
    average : bool, optional
        The run sheet's ``average_gauges``: True averages every usable channel,
        False never averages, None decides from kinds and slopes.

    Returns
    -------
    Choice
        ``used`` is empty when no channel has a positive stiffness.

    Examples
    --------
    An extensometer and a crosshead whose machine takes 30 % of the travel:

    >>> choice = choose_channels({"gauge_1": 7e6, "gauge_2": 1e7},
    ...                          {"gauge_1": "crosshead", "gauge_2": "extensometer"},
    ...                          {"gauge_1": "Traverse", "gauge_2": "Ext"})
    >>> choice.used, len(choice.warnings)
    (['gauge_2'], 1)
    """
    if len(slopes) == 1:  # nothing to choose from: the fit says whether it is usable
        return Choice(list(slopes), slopes, _crosshead_warnings(list(slopes), kinds, columns))
    usable = [name for name, slope in slopes.items() if np.isfinite(slope) and slope > 0]
    warnings = [
        f"channel {columns[name]!r} not used: it gives no positive stiffness on the first "
        "loading (not connected, removed early, or reading against the load)"
        for name in slopes if name not in usable
    ]
    if not usable:
        return Choice([], slopes, warnings)
    label = {name: f"{columns[name]!r} ({kinds[name]})" for name in slopes}
    if average:
        return Choice(usable, slopes, warnings + (
            [f"channels {', '.join(label[name] for name in usable)} averaged as the run sheet "
             "says (average_gauges = true)"] if len(usable) > 1 else []))
    kind = next(kind for kind in PREFERENCE if any(kinds[name] == kind for name in usable))
    group = [name for name in usable if kinds[name] == kind]
    used = _agreeing(group, slopes) if average is None else [
        max(group, key=lambda name: slopes[name])]
    reference = np.mean([slopes[name] for name in used])
    for name in usable:
        if name in used:
            continue
        why = ("the run sheet says not to average" if average is False and kinds[name] == kind
               else "another kind of channel" if kinds[name] != kind
               else f"the {kind} channels' stiffnesses disagree beyond "
               f"{100 * SAME_SLOPE_TOLERANCE:g} %")
        warnings.append(
            f"E0 from {' + '.join(label[n] for n in used)}, {label[name]} not used "
            f"({why}): its stiffness is {slopes[name] / reference:.3g} x "
            + ("that of the channel used" if len(used) == 1 else "the mean of those used"))
    return Choice(used, slopes, warnings + _crosshead_warnings(used, kinds, columns))


def _crosshead_warnings(used: list[str], kinds: dict[str, str], columns: dict[str, str]
                        ) -> list[str]:
    """The warning that E0 comes from the crosshead, when the channels `used` are its."""
    if kinds[used[0]] != "crosshead":
        return []
    names = " + ".join(repr(columns[name]) for name in used)
    return [f"E0 from the crosshead travel {names}: it includes the machine's own compliance, "
            "so E0 is too low; use an extensometer on the specimen, or name the file's "
            'extensometer or strain column in the run sheet (columns = {gauges = "..."})']
