"""Where a displacement channel was zeroed during the test, and the channel joined again.

Labs zero (tare) an extensometer once the preload is on; some controllers
write that into the exported log, as MTS TestSuite does: the reading steps to
zero in one sample while the specimen has not moved. Left as it is, the step
looks like a gauge running backwards or jumping, and the record is cut there.

A zeroing is a step that

* lands at zero: the reading after it is within :data:`ZERO_LANDING` of the
  step from zero (the specimen may have moved a little more by the next
  sample, the loading having begun);
* stands out of the steps before it (at least :data:`MIN_BEFORE` of them):
  :data:`STANDS_OUT` times their median, and more than the channel's noise;
* comes before the force's maximum, as a lab zeroes its gauges before the
  test (a reading that happens to land near zero as it jumps in the fall
  after the maximum is none);
* comes while the force holds: up to the sample before the step, over
  :data:`HOLD_SPAN` of the record, the force moves by no more than
  :data:`HOLD` of its range or :data:`HOLD_NOISE` times its noise (a gauge
  unplugged in the middle of a loading may drop to zero too: that is a
  removal, :func:`~pipeline.condition.breaks.find_removal`).

The readings before a zeroing are moved by its step, so that the channel
reads from the new zero throughout, as the lab meant. Lengths and strains
change only by that constant: the stiffness, read from the slope, does not.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from pipeline.condition.breaks import JUMP_NEIGHBOURHOOD, channel_tolerance
from pipeline.condition.segmentation import noise_level

#: The reading after a zeroing is within this fraction of the step from zero.
ZERO_LANDING = 0.1

#: A zeroing is this many times the median of the steps before it. Less than a jump
#: (:data:`~pipeline.condition.breaks.JUMP_FACTOR`): landing at zero while the force
#: holds says the rest. A machine's own displacement channel wanders by a twentieth of
#: the step during the hold before a zeroing (a real MTS TestSuite export).
STANDS_OUT = 10.0

#: Steps a zeroing is compared with, at least: those before it, up to half of
#: :data:`~pipeline.condition.breaks.JUMP_NEIGHBOURHOOD`.
MIN_BEFORE = 3

#: The force holds when it moves by no more than this fraction of its range over the
#: :data:`HOLD_SPAN` of the record up to the sample before the step (or from its start).
HOLD = 0.01

#: ... or by no more than this many times its noise, if more.
HOLD_NOISE = 10.0

#: See :data:`HOLD`: a fiftieth of the record, at least half of
#: :data:`~pipeline.condition.breaks.JUMP_NEIGHBOURHOOD` samples. A loading rises by
#: more than :data:`HOLD` of the force's range over it, even a single pull's.
HOLD_SPAN = 0.02


class Tare(NamedTuple):
    """A zeroing of a channel."""

    position: int  #: first sample read from the new zero (position in the record)
    step: float  #: the reading taken away [channel's unit]: before minus after


def find_tares(channel: np.ndarray, force: np.ndarray) -> list[Tare]:
    """The zeroings of `channel` (see the module docstring), in time order.

    Parameters
    ----------
    channel : numpy.ndarray
        A displacement or strain channel, finite, in time order [any unit].
    force : numpy.ndarray
        The force, same samples [N].

    Examples
    --------
    An extensometer zeroed at sample 50, at a preload of 5 kN, then loaded:

    >>> force = np.concatenate([np.full(50, 5e3), np.linspace(5e3, 30e3, 50)])
    >>> reading = np.concatenate([np.full(50, 0.75), 0.002 * np.arange(50)])
    >>> find_tares(reading, force)
    [Tare(position=50, step=0.75)]
    """
    channel = np.asarray(channel, dtype=float)
    steps = np.diff(channel)
    size = np.abs(steps)
    tolerance = channel_tolerance(channel)
    hold = max(HOLD * np.ptp(force), HOLD_NOISE * noise_level(force))
    landings = np.flatnonzero((size > tolerance)
                              & (np.abs(channel[1:]) <= ZERO_LANDING * size))
    before = JUMP_NEIGHBOURHOOD // 2
    held = max(before, int(HOLD_SPAN * channel.size))
    peak = int(np.argmax(np.abs(force)))
    return [Tare(int(step) + 1, float(-steps[step])) for step in landings
            if MIN_BEFORE <= step < peak
            and size[step] > STANDS_OUT * np.median(size[max(step - before, 0) : step])
            and np.ptp(force[max(step - held, 0) : step + 1]) <= hold]


def join_tares(channel: np.ndarray, force: np.ndarray) -> tuple[np.ndarray, list[Tare]]:
    """`channel` read from its last zero throughout, and its zeroings (:func:`find_tares`).

    >>> force = np.array([1e3] * 12 + [2e3, 3e3])
    >>> joined, tares = join_tares(np.array([5.0] * 11 + [0.0, 0.25, 0.5]), force)
    >>> joined[9:].tolist(), tares
    ([0.0, 0.0, 0.0, 0.25, 0.5], [Tare(position=11, step=5.0)])
    """
    joined = np.array(channel, dtype=float)
    tares = find_tares(joined, force)
    for tare in tares:
        joined[: tare.position] -= tare.step
    return joined, tares
