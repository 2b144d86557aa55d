"""Robust statistics of per-event values (:mod:`pipeline.statistics`)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pipeline.statistics import MedianStatistics, median_stderr


def test_statistics_of_five_values_by_hand():
    found = MedianStatistics.of(np.array([1.0, 2.0, 3.0, 4.0, 100.0]), stderr_ringing=0.5)
    events = math.sqrt(math.pi / 2) * 1.4826 * 1.0 / math.sqrt(5)  # MAD of |v - 3| is 1
    assert (found.median, found.iqr, found.mad, found.count) == (3.0, 2.0, 1.0, 5)
    assert found.stderr_events == pytest.approx(events, rel=1e-15)
    assert found.stderr == pytest.approx(math.hypot(events, 0.5), rel=1e-15)


def test_no_values_give_nan_and_no_count():
    found = MedianStatistics.of(np.array([]))
    assert found.count == 0 and math.isnan(found.median) and math.isnan(found.stderr)


def test_median_stderr_over_arrays():
    assert median_stderr(np.array([1.0, 2.0]), np.array([4, 16])) == pytest.approx(
        math.sqrt(math.pi / 2) * 1.4826 * np.array([0.5, 0.5]), rel=1e-15)
