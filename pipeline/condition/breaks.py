"""Where a tensile record stops being usable: fracture, and an extensometer taken off.

Both are found from the signals alone, in the direction of the load (``sign *
force`` rises on loading, see :func:`~pipeline.condition.segmentation.load_sign`).

Fracture (:func:`find_fracture`)
    A sudden drop of the force from near its maximum: after the maximum, from
    at least :data:`NEAR_MAXIMUM` of it, the force falls by at least
    :data:`FRACTURE_DROP` of the maximum (and well above its noise) within
    :data:`FRACTURE_SAMPLES` samples, and that fall is

    * at least :data:`SUDDEN` times any fall before it over as many samples
      (so a cyclic test's controlled unloadings, however fast, are not);
    * over within :data:`FRACTURE_SPAN` samples (an unloading, however fast
      at first, goes on falling for longer), counted at the rate the loading was
      logged at (a machine that logs faster once it detects the break, as
      Bluehill does at 2 ms after 0.1 s, writes a fall of 0.3 s in 25 samples);
    * never half recovered (the next cycle of a cyclic test rises again; after
      a fracture the force stays down, or rises a little where only part of
      the specimen broke);
    * down to :data:`FRACTURE_REMAINS` of the force it fell from by the time
      it stops, or else one step between two samples for half of it at least
      (a real Bluehill pull fell by 4.6 % in one sample, part of the specimen
      breaking, and loaded on): a test stopped near the maximum relaxes over
      many samples and holds the rest (a real hot pull at 370 °C shed 15 %
      over 15 samples, 0.3 s, then carried 85 % until the machine backed off).
      A record that ends while the force falls is a fracture whatever it holds
      at its end: the machine stopped recording at the break (real Bluehill
      pulls end 18 ms into the fall, at 55 % of the maximum).

    Nothing after the fracture is analysed.

Channel removal (:func:`find_removal`)
    A clip-on extensometer is often taken off before fracture. From then on
    its signal runs backwards while the force keeps rising, by
    :data:`BACKWARDS_RISE` of its maximum at least (it falls off),
    jumps (a single step far larger than its neighbours), or freezes (it stays
    within its noise while the force rises by :data:`FREEZE_RISE` of the
    maximum; or past the maximum, within its noise and resolution alone, while the
    force falls by as much and from there to the fracture, since a necking specimen
    can shed load faster than a channel that follows it moves by a share of its
    range; or while another displacement channel
    that follows the force keeps moving: the specimen lengthens all the while).
    The first sample where one of these happens ends the channel's usable
    data. A channel is judged from where the force rises through
    :data:`LOADED` of its maximum for the last time before reaching it: before
    that the specimen barely carries load, and the readings of the set-up (the
    crosshead's approach, an extensometer being clipped on, adjusted and zeroed
    at the preload, a seating knock) say nothing of whether the channel follows
    it. A channel is judged to within :data:`RESOLUTION_STEPS` steps of its
    resolution (:func:`reading_step`): a quantised reading flickers a step
    either way, and that is noise.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from scipy.ndimage import median_filter

from pipeline.condition.segmentation import noise_level

#: Smallest sudden force drop that counts as fracture, as a fraction of the maximum force.
FRACTURE_DROP = 0.03

#: Samples over which a fracture drop must happen.
FRACTURE_SAMPLES = 5

#: A fracture falls at least this many times more within :data:`FRACTURE_SAMPLES` than
#: the force ever fell before it (a cyclic test's controlled unloadings).
SUDDEN = 2.0

#: A fracture has stopped falling within this many samples.
FRACTURE_SPAN = 20

#: A fracture leaves at most this fraction of the force it fell from once the fall has
#: stopped, unless it fell in one step (a specimen that still carries more, shed over many
#: samples, was stopped, not broken).
FRACTURE_REMAINS = 0.5

#: A fracture starts at or above this fraction of the maximum force.
NEAR_MAXIMUM = 0.5

#: A channel is judged from where the force rises through this fraction of its maximum
#: for the last time before reaching it (a real concrete cylinder's set-up holds 1.5 %
#: after a seating knock of 9.6 %).
LOADED = 0.05

#: A channel that stays within its noise while the force rises by this fraction of
#: the maximum force has frozen (it no longer follows the specimen).
FREEZE_RISE = 0.05

#: A channel runs backwards when it reads less than at its running maximum while the force
#: stands at least this fraction of the maximum force above its level there.
BACKWARDS_RISE = 0.01

#: ... for this many samples in a row at least (or to the end of the record): a noisy
#: channel falls below its running maximum, itself a peak of the noise, by five times its
#: noise for a sample now and then (a machine's displacement read to 0.03 mm).
BACKWARDS_SAMPLES = 3

#: A channel that misbehaves before it has risen by this fraction of what it rises to the
#: force's maximum, and follows the force after, was seating (:func:`_seated`): knife edges
#: settle by a few µm, a sixth of a short extensometer's elastic travel; one that slips
#: later in the test has risen by more.
SEATING = 0.25

#: A channel that stands still for this fraction of the record while another channel
#: moves by :data:`OTHERS_MOVE` of its range has frozen.
STILL_WINDOW = 0.05

#: See :data:`STILL_WINDOW`.
OTHERS_MOVE = 0.02

#: Another channel witnesses the specimen lengthening only if it follows the force: the
#: rank correlation of the two up to the maximum is at least this (a crosshead rises with
#: the force, through yield too; an input left unconnected wanders with its noise).
WITNESS_CORRELATION = 0.8

#: A channel step this many times the median of its neighbouring steps is a jump.
JUMP_FACTOR = 30.0

#: Neighbourhood of the jump test [samples].
JUMP_NEIGHBOURHOOD = 21

#: A channel's reading is not judged finer than this many of its resolution steps: a
#: quantised reading flickers by a step either way about a steady value, so a fall of
#: two steps from a flicker up is noise, not a gauge running backwards.
RESOLUTION_STEPS = 3.0

#: Samples a channel must have followed the specimen, before it ran backwards or jumped,
#: for its freeze tolerance to be taken from those samples alone: the readings after
#: such an event (an extensometer taken off, hanging at -0.13) widen its range, and half a
#: per cent of that range can exceed what the extensometer moved over a twentieth of the
#: record while it was on.
MIN_FOLLOWED = 10


@dataclass(frozen=True)
class Removal:
    """Where a displacement channel stopped following the specimen."""

    position: int  #: first unusable sample (position in the record)
    reason: str  #: ``"runs backwards"``, ``"jumps"`` or ``"freezes"``
    cause: str = "taken off or slipped"  #: what it suggests, for the warning


#: The cause named for a jump by a power of ten: the channel's numbers, not the gauge.
DECADE_CAUSE = ("by a power of ten: its numbers may have lost their decimal mark, as a "
                "spreadsheet re-save does; check the export")


def _decade(channel: np.ndarray, position: int) -> bool:
    """Whether the step into sample `position` multiplies the reading by a power of ten
    (10, 100, ...; to 1 % of a decade)."""
    before, after = abs(channel[position - 1]), abs(channel[position])
    if not (before > 0 and after > 0):
        return False
    decades = abs(math.log10(after / before))
    return round(decades) >= 1 and abs(decades - round(decades)) < 0.01


def _falls(force: np.ndarray, window: int) -> np.ndarray:
    """Fall of the force from each sample to the lowest of the next `window` samples."""
    size = force.size
    lowest = np.full(size, np.inf)
    for lag in range(1, min(window, size - 1) + 1):
        lowest[: size - lag] = np.minimum(lowest[: size - lag], force[lag:])
    return np.where(np.isfinite(lowest), force - lowest, 0.0)


def _loading_intervals(time: np.ndarray | None, size: int, peak: int) -> np.ndarray:
    """Position of each sample counted in the sample intervals of the loading (up to the
    force's maximum at `peak`): a step under half the loading's median step counts as its
    share of it, any other as one sample. Without a time strictly rising after the maximum
    (none given, or stamps rounded so that rows repeat them) the samples are counted."""
    positions = np.arange(size, dtype=float)
    if time is None or size < 3 or peak < 2:
        return positions
    steps = np.diff(np.asarray(time, dtype=float))
    typical = np.median(steps[:peak])
    after = steps[peak:]
    if not (typical > 0 and np.all(np.isfinite(after)) and np.all(after > 0)):
        return positions
    counted = np.where(steps < typical / 2, steps / typical, 1.0)
    counted[:peak] = 1.0
    return np.concatenate([[0.0], np.cumsum(counted)])


def _within(positions: np.ndarray, start: int, intervals: float) -> int:
    """End (exclusive) of the samples within `intervals` loading intervals after `start`."""
    return int(np.searchsorted(positions, positions[start] + intervals, side="right"))


def _is_fracture(force: np.ndarray, start: int, falls: np.ndarray, settled: float,
                 positions: np.ndarray) -> bool:
    """The fall from `start` is a fracture (see the module docstring); `settled` [N] is the
    fall over :data:`FRACTURE_SAMPLES` below which the force has stopped falling, and
    `positions` count the samples in the loading's intervals (:func:`_loading_intervals`)."""
    span = _within(positions, start, FRACTURE_SPAN + 1)
    stopped = np.flatnonzero(falls[start + 1 : span] <= settled)
    if not stopped.size:
        return False
    stop = start + 2 + int(stopped[0]) + FRACTURE_SAMPLES
    fall = force[start:stop]
    low = fall.min()
    carries = (stop <= force.size  # a record that ends falling was stopped by the break
               and low > FRACTURE_REMAINS * force[start]
               and np.max(-np.diff(fall)) < (force[start] - low) / 2)
    rest = force[start + FRACTURE_SAMPLES + 1 :]
    recovers = rest.size > 0 and rest.max() >= force[start] - falls[start] / 2
    before = falls[: max(start - FRACTURE_SAMPLES, 0)]  # windows that end before the fall
    earlier = before.max() if before.size else 0.0
    return falls[start] >= SUDDEN * earlier and not recovers and not carries


def find_fracture(oriented_force: np.ndarray, time: np.ndarray | None = None) -> int | None:
    """Position of the last sample before fracture, or None when the specimen did not break.

    Parameters
    ----------
    oriented_force : numpy.ndarray
        Force in the direction of the load [N], finite, in time order.
    time : numpy.ndarray, optional
        Time of each sample [s]. A fall logged faster than the loading (a machine's break
        capture) is then judged in the loading's sample intervals; without it, in samples.

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
    threshold = max(FRACTURE_DROP * maximum, 10.0 * noise_level(force))
    falls = _falls(force, FRACTURE_SAMPLES)
    candidates = peak + np.flatnonzero((falls[peak:] >= threshold)
                                       & (force[peak:] >= NEAR_MAXIMUM * maximum))
    settled = max(3.0 * noise_level(force), 0.005 * maximum)
    positions = _loading_intervals(time, force.size, peak)
    start = next((int(i) for i in candidates
                  if _is_fracture(force, int(i), falls, settled, positions)), None)
    if start is None:
        return None
    reach = _within(positions, start, 1 + FRACTURE_SPAN + FRACTURE_SAMPLES)
    bottom = start + 1 + int(np.argmin(force[start + 1 : reach]))
    # the last sample before the fall: a fall over several samples (a slow log) begins
    # with the first step down of at least its share of a fracture's fall that is SUDDEN
    # times the step before it (a necking specimen sheds load faster and faster: a real
    # 1 Hz pull fell by 1 to 3 kN a sample, then broke by 108 kN)
    at = np.arange(start, bottom)
    drops = force[at] - force[at + 1]
    previous = np.where(at > 0, force[np.maximum(at - 1, 0)] - force[at], 0.0)
    large = drops > max(threshold / FRACTURE_SAMPLES, settled)
    sudden = np.flatnonzero(large & (drops > SUDDEN * np.maximum(previous, 0.0)))
    sudden = sudden if sudden.size else np.flatnonzero(large)
    return start + int(sudden[0]) if sudden.size else bottom - 1



def _envelope(force: np.ndarray) -> np.ndarray:
    """Positions where the force reaches a new maximum (the rising envelope)."""
    running = np.maximum.accumulate(force)
    new = np.concatenate([[True], force[1:] > running[:-1]])
    return np.flatnonzero(new)


def _backwards(force: np.ndarray, channel: np.ndarray, tolerance: float, rise: float
               ) -> int | None:
    """First sample of a fall of the channel from its running maximum by more than
    `tolerance` that lasts until the force has risen by `rise` above its level when that
    maximum was reached (a knife edge settling by a few steps while the force stands is
    no fall), and for :data:`BACKWARDS_SAMPLES` samples (one sample of noise is none)."""
    running = np.maximum.accumulate(channel)
    at = np.maximum.accumulate(np.where(channel >= running, np.arange(channel.size), 0))
    below = channel < running - tolerance
    lasting = below.copy()  # and the next BACKWARDS_SAMPLES - 1 the record holds
    for ahead in range(1, BACKWARDS_SAMPLES):
        lasting[:-ahead] &= below[ahead:]
    hits = np.flatnonzero(lasting & (force >= force[at] + rise))
    if not hits.size:
        return None
    hit = int(hits[0])
    above = np.flatnonzero(~below[: hit + 1])  # the fall began after the last sample above
    return int(above[-1]) + 1 if above.size else 0


def _jump(channel: np.ndarray, tolerance: float) -> int | None:
    """First sample reached by a step far larger than the neighbouring steps."""
    steps = np.abs(np.diff(channel))
    if steps.size < JUMP_NEIGHBOURHOOD:
        return None
    typical = median_filter(steps, JUMP_NEIGHBOURHOOD, mode="nearest")
    typical[-1] = np.median(steps[-JUMP_NEIGHBOURHOOD:-1])  # not among copies of itself
    span = np.ptp(channel)
    hits = np.flatnonzero((steps > JUMP_FACTOR * typical) & (steps > tolerance)
                          & (steps > 0.02 * span))
    return int(hits[0]) + 1 if hits.size else None


def _freeze(force: np.ndarray, channel: np.ndarray, tolerance: float, rise: float,
            low: float, to_end: bool = False) -> int | None:
    """First sample of a stretch of the rising envelope of `force` over which it rises by
    `rise` from above `low` while the channel stays within `tolerance` (with `to_end`:
    and stays so to the last sample)."""
    rising = _envelope(force)
    if rising.size < 3:
        return None
    on_force, on_channel = force[rising], channel[rising]
    ends = np.searchsorted(on_force, on_force + rise, side="left")
    starts = np.flatnonzero(ends < rising.size)
    # a frozen stretch ends where it began: only those starts need the full test; and
    # only where the channel had been moving clearly with the force before
    level = np.abs(on_channel[ends[starts]] - on_channel[starts]) <= tolerance
    with np.errstate(divide="ignore", invalid="ignore"):
        moving = (rise * np.abs(on_channel[starts] - on_channel[0])
                  / (on_force[starts] - on_force[0]) > 4.0 * tolerance)
    candidates = starts[level & moving & (on_force[starts] > low)]
    if to_end:  # the range of the channel from each sample to the last, in one pass
        ahead = channel[::-1]
        span = (np.maximum.accumulate(ahead) - np.minimum.accumulate(ahead))[::-1]
        still = candidates[span[rising[candidates]] <= tolerance]
        return int(rising[still[0]]) if still.size else None
    for start in candidates:
        if np.ptp(on_channel[start : ends[start] + 1]) <= tolerance:
            return int(rising[start])
    return None


def _misbehaviour(whole: np.ndarray, reading: np.ndarray, others: Sequence[np.ndarray],
                  loaded: int, peak: int) -> tuple[int, str, float] | None:
    """The first sample and kind of the channel `reading`'s first misbehaviour (module
    docstring), judged from sample `loaded` with the force `whole` rising to its maximum
    at `peak`, and the tolerance it was judged within; None if it has none."""
    force = whole[loaded : peak + 1]  # the force keeps rising up to its maximum
    channel = reading[loaded : peak + 1]
    if force.size < 3:
        return None
    tolerance = channel_tolerance(channel)
    backwards = _backwards(force, channel, tolerance, BACKWARDS_RISE * whole[peak])
    # a jump is one past the maximum too: a software that writes its strain back to zero
    # once it detects the break (testXpert) does so before the force has finished falling
    jump = _jump(reading[loaded:], tolerance)
    followed = min((position for position in (backwards, jump) if position is not None),
                   default=channel.size)
    if followed >= MIN_FOLLOWED:  # a reading off the specimen widens the range: not its own
        tolerance = min(tolerance, channel_tolerance(channel[:followed]))
    rise = FREEZE_RISE * whole[peak]
    # past the maximum the specimen still lengthens while the force falls (necking); so fast
    # can it fall before the fracture that a channel that follows moves less than a share
    # of its range meanwhile: one taken off stands within its noise, to the fracture
    falling = _freeze(whole[peak] - whole[peak:], reading[peak:],
                      channel_tolerance(channel, share_of_range=0.0), rise, -np.inf,
                      to_end=True)
    frozen = _freeze(force, channel, tolerance, rise, 0.1 * whole[peak])
    witnesses = [other for other in others if _follows(force, other[loaded : peak + 1])]
    # standing still is told within the noise: a share of the range may be the whole elastic
    # strain of an extensometer read to a plastic strain of 30 %, moving with the crosshead
    still = _still_while_others_move(reading[loaded:], [other[loaded:] for other in witnesses],
                                     channel_tolerance(channel, share_of_range=0.0))
    found = [
        (loaded + position, reason)
        for position, reason in ((backwards, "runs backwards"), (jump, "jumps"),
                                 (frozen, "freezes"), (still, "freezes"))
        if position is not None
    ] + ([] if falling is None else [(peak + falling, "freezes")])
    if not found:
        return None
    position, reason = min(found, key=lambda item: item[0])
    return position, reason, tolerance


def _seated(whole: np.ndarray, reading: np.ndarray, loaded: int, peak: int, position: int,
            reason: str, tolerance: float) -> int | None:
    """Where the channel `reading` is judged again when its misbehaviour at `position` (of
    `reason`, judged from `loaded` within `tolerance`) was its seating: before it, it had
    risen by under :data:`SEATING` of what it rises to the force's maximum at `peak`, and
    from where it rises past its reading before it, it follows the force's rising envelope
    up to the maximum (:func:`_follows`). Knife edges settle so while the first load comes
    on: a real modulus test's extensometer ran back by 6 µm at 25 % of the maximum, then
    read 430 kN/mm cycle after cycle. None when it was no seating: the misbehaviour
    stands."""
    if reason == "jumps" or position >= peak:
        return None
    start = reading[loaded]
    before = float(np.max(reading[loaded : position + 1])) - start
    if not before < SEATING * (reading[peak] - start):
        return None
    past = position + np.flatnonzero(reading[position:peak] > start + before + tolerance)
    if not past.size:
        return None
    rising = past[0] + _envelope(whole[past[0] : peak + 1])  # over load cycles too
    return int(past[0]) if _follows(whole[rising], reading[rising]) else None


def _still_while_others_move(channel: np.ndarray, others: Sequence[np.ndarray],
                             tolerance: float) -> int | None:
    """First window of :data:`STILL_WINDOW` of the record over which the channel stays
    within `tolerance` while another channel moves by :data:`OTHERS_MOVE` of its range."""
    width = max(10, int(STILL_WINDOW * channel.size))
    if channel.size < 2 * width:
        return None
    starts = np.arange(0, channel.size - width + 1, max(1, width // 4))
    still = np.array([np.ptp(channel[start : start + width]) <= tolerance for start in starts])
    for other in others:
        span = np.nanmax(other) - np.nanmin(other)
        moving = np.array([np.nanmax(other[start : start + width])
                           - np.nanmin(other[start : start + width]) >= OTHERS_MOVE * span
                           for start in starts])
        hits = np.flatnonzero(still & moving)
        if hits.size:
            return int(starts[hits[0]])
    return None


def _follows(force: np.ndarray, other: np.ndarray) -> bool:
    """Whether a channel rises with the force (:data:`WITNESS_CORRELATION`)."""
    both = np.isfinite(force) & np.isfinite(other)
    if both.sum() < 3 or not (np.ptp(force[both]) > 0 and np.ptp(other[both]) > 0):
        return False
    ranks = [np.argsort(np.argsort(values[both])) for values in (force, other)]
    return bool(np.corrcoef(*ranks)[0, 1] >= WITNESS_CORRELATION)


def reading_step(channel: np.ndarray) -> float:
    """Resolution of a quantised reading: its smallest change between samples [channel's unit].

    Zero for a channel that never changes.

    Examples
    --------
    >>> reading_step(np.array([2.53, 2.53, 2.54, 2.52, 2.53]))  # doctest: +ELLIPSIS
    0.0099...
    """
    steps = np.abs(np.diff(channel[np.isfinite(channel)]))
    steps = steps[steps > 0]
    return float(steps.min()) if steps.size else 0.0


def channel_tolerance(channel: np.ndarray, share_of_range: float = 0.005) -> float:
    """How far a channel's reading may move and still be still [channel's unit]: five
    times its noise, `share_of_range` of its range, or :data:`RESOLUTION_STEPS` steps of
    its resolution, whichever is largest."""
    return max(5.0 * noise_level(channel), share_of_range * np.ptp(channel),
               RESOLUTION_STEPS * reading_step(channel))


def _frozen_since(channel: np.ndarray, position: int, tolerance: float) -> int:
    """The first sample of the constant stretch of `channel` that holds `position`."""
    moved = np.flatnonzero(np.abs(channel[:position] - channel[position]) > tolerance)
    return int(moved[-1]) + 1 if moved.size else 0


def find_removal(oriented_force: np.ndarray, oriented_channel: np.ndarray,
                 others: Sequence[np.ndarray] = ()) -> Removal | None:
    """Where a displacement channel stops following the specimen, or None.

    Parameters
    ----------
    oriented_force : numpy.ndarray
        Force in the direction of the load [N], up to the fracture: the channel
        may run backwards or jump while the force rises to its maximum, and
        freeze while it rises or, past the maximum, falls.
    oriented_channel : numpy.ndarray
        The channel's reading in the direction of the load [any unit], same samples.
    others : sequence of numpy.ndarray
        The file's other displacement channels, same samples [any unit]: the
        channel has frozen where it stands still while one of them moves.

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
    Removal(position=60, reason='runs backwards', cause='taken off or slipped')
    """
    whole = np.asarray(oriented_force, dtype=float)
    reading = np.asarray(oriented_channel, dtype=float)
    peak = int(np.argmax(whole))
    below = np.flatnonzero(whole[:peak] < LOADED * whole[peak])
    start = int(below[-1]) + 1 if below.size else 0
    while True:
        found = _misbehaviour(whole, reading, others, start, peak)
        if found is None:
            return None
        resumed = _seated(whole, reading, start, peak, *found)
        if resumed is None:
            break
        start = resumed
    position, reason, tolerance = found
    if reason == "freezes":
        position = _frozen_since(reading, position, tolerance)
    if reason == "jumps" and _decade(reading, position):
        return Removal(position=int(position), reason=reason, cause=DECADE_CAUSE)
    return Removal(position=int(position), reason=reason)
