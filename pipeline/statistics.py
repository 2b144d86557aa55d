"""Robust statistics of a quantity measured once per event: median, spread, standard error.

Used wherever a run's value is the median over its events (strike amplitudes,
segment-force ratios) and wherever a standard error is rebuilt from a stored
MAD and count. The standard error of a median of ``n`` normal values is
``sqrt(pi / 2) sigma / sqrt(n)``, with ``sigma = 1.4826 MAD``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

#: Consistency constant of the MAD for normal values: sigma = 1.4826 MAD.
MAD_TO_SIGMA = 1.4826
#: Efficiency factor of the median: its standard error is sqrt(pi / 2) sigma / sqrt(n).
MEDIAN_EFFICIENCY = math.sqrt(math.pi / 2)


def median_stderr(mad: ArrayLike, count: ArrayLike) -> float | np.ndarray:
    """Standard error of a median from the MAD of `count` values [unit of the MAD].

    Examples
    --------
    >>> round(float(median_stderr(2.0, 100)), 4)
    0.3716
    """
    return MEDIAN_EFFICIENCY * MAD_TO_SIGMA * mad / np.sqrt(count)


@dataclass(frozen=True)
class MedianStatistics:
    """Robust statistics of one quantity over a run's valid events.

    Attributes
    ----------
    median : float
        Median [unit of the quantity].
    iqr : float
        Interquartile range.
    mad : float
        Median absolute deviation (unscaled).
    stderr : float
        Standard error of the median: ``stderr_events`` and ``stderr_ringing``
        added in quadrature.
    count : int
        Valid events.
    stderr_events : float
        From the scatter of the events, ``sqrt(pi/2) 1.4826 MAD / sqrt(count)``.
    stderr_ringing : float
        From the uncertainty of a fitted quantity every event shares (for
        strike amplitudes, the run's omega_n and zeta; 0 where there is none).
    """

    median: float
    iqr: float
    mad: float
    stderr: float
    count: int
    stderr_events: float
    stderr_ringing: float = 0.0

    @classmethod
    def of(cls, values: np.ndarray, stderr_ringing: float = 0.0) -> MedianStatistics:
        """Statistics of `values` (NaN when empty), with the shared part of the error."""
        values = np.asarray(values, dtype=float)
        if values.size == 0:
            return cls(math.nan, math.nan, math.nan, math.nan, 0, math.nan, stderr_ringing)
        median = float(np.median(values))
        q1, q3 = np.percentile(values, [25, 75])
        mad = float(np.median(np.abs(values - median)))
        events = float(median_stderr(mad, values.size))
        return cls(median, float(q3 - q1), mad, math.hypot(events, stderr_ringing),
                   int(values.size), events, stderr_ringing)
