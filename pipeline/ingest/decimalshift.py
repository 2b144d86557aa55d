"""Values a power of ten off their neighbours: decimal marks a spreadsheet has mangled.

A machine export opened in a spreadsheet whose locale takes the file's decimal
mark for a thousands separator, and saved again, comes back with some values
moved by a power of ten and others not (a Bluehill export re-saved through
Excel: ``0,9966``, ``10,114``, ``10,285``, ``1,063``, ``10,786``: the second,
third and fifth were 1.0114, 1.0285 and 1.0786). Read as written, such a column
gives a wrong stiffness without any error, so the readers look for it.

A column is reported when its values step by a factor within 5 % of a power of
ten, up at least once and down at least once, where each such step is also
far larger than the column's typical step (:data:`OUTLIER_FACTOR` x the median
step). A real signal does not jump tenfold and back: a specimen breaking drops
once, and noise about zero makes small steps, not outlying ones. A column longer
than a spreadsheet holds (:data:`SPREADSHEET_ROWS`) was not saved by one, and is
not looked at: a long log costs nothing more to read.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

#: How many times the median step a step must be to count as a jump.
OUTLIER_FACTOR = 20.0
#: The most rows a spreadsheet holds (Excel, LibreOffice Calc).
SPREADSHEET_ROWS = 1_048_576
#: How close to a power of ten the ratio of a jump's two values must be (5 %).
_TOLERANCE = math.log10(1.05)


def decimal_shifts(values: np.ndarray) -> tuple[int, int]:
    """The steps of `values` that move them by a power of ten, and the first one.

    Parameters
    ----------
    values : numpy.ndarray
        One column, in any unit; NaN allowed.

    Returns
    -------
    count : int
        How many steps move a value by a factor within 5 % of 10, 100, ... (up or
        down) and are outliers; 0 unless there is at least one up and one down, and
        0 for a column of more than :data:`SPREADSHEET_ROWS` values.
    first : int
        The index of the value after the first such step (-1 when `count` is 0).

    Examples
    --------
    >>> decimal_shifts(np.array([0.95, 0.97, 0.99, 10.1, 10.3, 1.05, 1.07, 10.9, 1.11, 1.13]))
    (4, 3)
    >>> decimal_shifts(np.array([9.0, 9.1, 9.2, 9.3, 9.4, 0.94, 0.0, 0.01]))  # a break: down only
    (0, -1)
    """
    if not 4 <= values.size <= SPREADSHEET_ROWS:
        return 0, -1
    every = max(1, (values.size - 1) // 100_000)
    sample = np.abs(values[1::every] - values[:-1:every])  # every n-th step
    sample = sample[sample > 0]  # NaN and flat stretches say nothing of the typical step
    if not sample.size:
        return 0, -1
    jumps = _steps_over(values, OUTLIER_FACTOR * float(np.median(sample)))
    before, after = values[jumps], values[jumps + 1]
    with np.errstate(all="ignore"):  # zeros, and ratios past float's range: no shift
        ratio = after / before
    usable = np.isfinite(ratio) & (ratio > 0)  # of one sign, neither zero
    jumps, exponent = jumps[usable], np.log10(ratio[usable])
    power = np.round(exponent)
    shifted = (np.abs(exponent - power) < _TOLERANCE) & (power != 0)
    ups, downs = np.count_nonzero(shifted & (power > 0)), np.count_nonzero(shifted & (power < 0))
    if not (ups and downs):
        return 0, -1
    return int(ups + downs), int(jumps[shifted][0]) + 1


def _steps_over(values: np.ndarray, threshold: float) -> np.ndarray:
    """The indices i where ``|values[i + 1] - values[i]| > threshold``."""
    found = []
    for start, steps in step_blocks(values):
        np.abs(steps, out=steps)
        found.append(np.flatnonzero(steps > threshold) + start)
    return np.concatenate(found) if found else np.empty(0, dtype=np.intp)


def step_blocks(values: np.ndarray, block: int = 1 << 16) -> Iterator[tuple[int, np.ndarray]]:
    """The steps ``values[i + 1] - values[i]`` a block at a time, each with the index of
    its first, so that no array of every step is made for a long log. Each block is
    written into one buffer: use it before asking for the next."""
    buffer = np.empty(min(block, max(values.size - 1, 0)))
    for start in range(0, values.size - 1, block):
        stop = min(start + block, values.size - 1)
        yield start, np.subtract(values[start + 1: stop + 1], values[start:stop],
                                 out=buffer[: stop - start])
