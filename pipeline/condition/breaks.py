"""Where a tensile record stops being usable: fracture, and an extensometer taken off.

Both are found from the signals alone, in the direction of the load (``sign *
force`` rises on loading, see :func:`~pipeline.condition.segmentation.load_sign`).

Fracture (:func:`find_fracture`)
    A sudden drop of the force from near its maximum: after the maximum, the
    force falls by at least :data:`FRACTURE_DROP` of the maximum within
    :data:`FRACTURE_SAMPLES` samples, far faster than it ever rose (at least
    :data:`SUDDEN` times the median step of the record, and well above its
    noise), from at least :data:`NEAR_MAXIMUM` of the maximum. A controlled
    unloading (a proof-load test, the end of a cycle) is no faster than a few
    loading steps and is not a fracture. Nothing after the fracture is
    analysed.

Channel removal (:func:`find_removal`)
    A clip-on extensometer is often taken off before fracture. From then on
    its signal runs backwards while the force keeps rising (it falls off),
    jumps (a single step far larger than its neighbours), or freezes (it stays
    within its noise while the force rises by :data:`FREEZE_RISE` of the
    maximum). The first sample where one of these happens ends the channel's
    usable data.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.ndimage import median_filter

from pipeline.condition.segmentation import noise_level

#: Smallest sudden force drop that counts as fracture, as a fraction of the maximum force.
FRACTURE_DROP = 0.03

#: Samples over which a fracture drop must happen.
FRACTURE_SAMPLES = 5

#: A fracture drop is at least this many times the median force step of the record.
SUDDEN = 50.0

#: A fracture starts at or above this fraction of the maximum force.
NEAR_MAXIMUM = 0.5

#: A channel that stays within its noise while the force rises by this fraction of
#: the maximum force has frozen (it no longer follows the specimen).
FREEZE_RISE = 0.05

#: A channel step this many times the median of its neighbouring steps is a jump.
JUMP_FACTOR = 30.0

#: Neighbourhood of the jump test [samples].
JUMP_NEIGHBOURHOOD = 21


@dataclass(frozen=True)
class Removal:
    """Where a displacement channel stopped following the specimen."""

    position: int  #: first unusable sample (position in the record)
    reason: str  #: ``"runs backwards"``, ``"jumps"`` or ``"freezes"``


def find_fracture(oriented_force: np.ndarray) -> int | None:
    """Position of the last sample before fracture, or None when the specimen did not break.

    Parameters
    ----------
    oriented_force : numpy.ndarray
        Force in the direction of the load [N], finite, in time order.

    Returns
    -------
    int or None
        The sample from which the force drops suddenly (see the module docstring).

    Examples
    --------
    A ramp to 100 N that breaks to 2 N:

    >>> force = np.concatenate([np.linspace(0, 100, 200), [2.0, 1.0, 1.5]])
    >>> find_fracture(force)
    199
    """
    force = np.asarray(oriented_force, dtype=float)
    if force.size < 3:
        return None
    peak = int(np.argmax(force))
    maximum = force[peak]
    if not maximum > 0:
        return None
    steps = np.abs(np.diff(force))
    threshold = max(FRACTURE_DROP * maximum, SUDDEN * float(np.median(steps)),
                    10.0 * noise_level(force))
    after = force[peak:]
    size = after.size
    lowest_ahead = np.full(size, np.inf)
    for lag in range(1, min(FRACTURE_SAMPLES, size - 1) + 1):
        lowest_ahead[: size - lag] = np.minimum(lowest_ahead[: size - lag], after[lag:])
    drops = np.flatnonzero((after - lowest_ahead >= threshold)
                           & (after >= NEAR_MAXIMUM * maximum))
    if not drops.size:
        return None
    start = int(drops[0])
    bottom = start + int(np.argmin(after[start : start + FRACTURE_SAMPLES + 1]))
    last = bottom - 1  # the last sample before the sudden fall to the bottom
    while last > start and after[last] - after[bottom] < threshold:
        last -= 1
    return peak + last


def _envelope(force: np.ndarray) -> np.ndarray:
    """Positions where the force reaches a new maximum (the rising envelope)."""
    running = np.maximum.accumulate(force)
    new = np.concatenate([[True], force[1:] > running[:-1]])
    return np.flatnonzero(new)


def _backwards(force: np.ndarray, channel: np.ndarray, tolerance: float) -> int | None:
    """First sample where the channel fell back from its running maximum by more than
    `tolerance` while the force is at least as high as when that maximum was reached."""
    running = np.maximum.accumulate(channel)
    at = np.maximum.accumulate(np.where(channel >= running, np.arange(channel.size), 0))
    hits = np.flatnonzero((channel < running - tolerance) & (force >= force[at]))
    return int(hits[0]) if hits.size else None


def _jump(channel: np.ndarray, tolerance: float) -> int | None:
    """First sample reached by a step far larger than the neighbouring steps."""
    steps = np.abs(np.diff(channel))
    if steps.size < JUMP_NEIGHBOURHOOD:
        return None
    typical = median_filter(steps, JUMP_NEIGHBOURHOOD, mode="nearest")
    span = np.ptp(channel)
    hits = np.flatnonzero((steps > JUMP_FACTOR * typical) & (steps > tolerance)
                          & (steps > 0.02 * span))
    return int(hits[0]) + 1 if hits.size else None


def _freeze(force: np.ndarray, channel: np.ndarray, tolerance: float) -> int | None:
    """First sample of a stretch of the rising envelope over which the force rises by
    :data:`FREEZE_RISE` of its maximum while the channel stays within `tolerance`."""
    rising = _envelope(force)
    if rising.size < 3:
        return None
    rise = FREEZE_RISE * force.max()
    on_force, on_channel = force[rising], channel[rising]
    ends = np.searchsorted(on_force, on_force + rise, side="left")
    starts = np.flatnonzero(ends < rising.size)
    # a frozen stretch ends where it began: only those starts need the full test; and
    # only where the channel had been moving clearly with the force before
    level = np.abs(on_channel[ends[starts]] - on_channel[starts]) <= tolerance
    with np.errstate(divide="ignore", invalid="ignore"):
        moving = (rise * (on_channel[starts] - on_channel[0]) / (on_force[starts] - on_force[0])
                  > 4.0 * tolerance)
    for start in starts[level & moving & (on_force[starts] > 0.1 * force.max())]:
        if np.ptp(on_channel[start : ends[start] + 1]) <= tolerance:
            return int(rising[start])
    return None


def find_removal(oriented_force: np.ndarray, oriented_channel: np.ndarray) -> Removal | None:
    """Where a displacement channel stops following the specimen, or None.

    Parameters
    ----------
    oriented_force : numpy.ndarray
        Force in the direction of the load [N]; only the samples up to its
        maximum are examined (while the force keeps rising).
    oriented_channel : numpy.ndarray
        The channel's reading in the direction of the load [any unit], same samples.

    Returns
    -------
    Removal or None
        The first sample of the first misbehaviour (module docstring).

    Examples
    --------
    An extensometer that falls off (reads backwards) while the force keeps rising:

    >>> force = np.linspace(0, 100, 100)
    >>> channel = np.where(np.arange(100) < 60, force / 1e3, -0.05)
    >>> find_removal(force, channel)
    Removal(position=60, reason='runs backwards')
    """
    rising = int(np.argmax(oriented_force)) + 1  # the force keeps rising up to its maximum
    force = np.asarray(oriented_force[:rising], dtype=float)
    channel = np.asarray(oriented_channel[:rising], dtype=float)
    if force.size < 3:
        return None
    tolerance = max(5.0 * noise_level(channel), 0.005 * np.ptp(channel))
    found = [
        (position, reason)
        for position, reason in (
            (_backwards(force, channel, tolerance), "runs backwards"),
            (_jump(channel, tolerance), "jumps"),
            (_freeze(force, channel, tolerance), "freezes"),
        )
        if position is not None
    ]
    if not found:
        return None
    position, reason = min(found, key=lambda item: item[0])
    return Removal(position=int(position), reason=reason)
