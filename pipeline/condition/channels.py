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
side of a chain differ by its bending; the mean cancels it). Otherwise one
channel is used: of the kind first in :data:`PREFERENCE`, the stiffer one when
in doubt (a channel that includes more of the machine reads more elongation),
and every channel left out is named in a warning with its stiffness relative
to the one used. Never a silent average of different kinds.
"""

from __future__ import annotations

from dataclasses import dataclass, field

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


def _agree(slopes: list[float]) -> bool:
    return min(slopes) >= (1.0 - SAME_SLOPE_TOLERANCE) * max(slopes)


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
    if average is None and len(group) > 1 and _agree([slopes[name] for name in group]):
        used = group
    else:
        used = [max(group, key=lambda name: slopes[name])]
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
            f"({why}): its stiffness is {slopes[name] / reference:.3g} x that of the channel "
            "used")
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
