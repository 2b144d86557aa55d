"""The uncertainty rules the weighted fits share (:mod:`pipeline.fit.intervals`)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from pipeline.fit.intervals import birge_ratio, scaled_error, straight_line


def test_errors_are_scaled_by_the_scatter_never_shrunk():
    wide = scaled_error(0.2, chi2=18.0, dof=4, confidence=0.95)
    assert wide.scaled and wide.chi2_reduced == 4.5
    assert wide.stderr == pytest.approx(0.2 * math.sqrt(4.5), rel=1e-15)
    assert wide.quantile == pytest.approx(2.7764451051977987, rel=1e-12)  # t(0.975, 4)
    narrow = scaled_error(0.2, chi2=1.0, dof=4, confidence=0.95)
    assert not narrow.scaled and narrow.stderr == 0.2
    assert narrow.quantile == pytest.approx(1.959963984540054, rel=1e-12)  # normal 97.5 %


def test_no_degree_of_freedom_keeps_the_stated_error():
    error = scaled_error(0.3, chi2=0.0, dof=0, confidence=0.9)
    assert math.isnan(error.chi2_reduced) and not error.scaled and error.stderr == 0.3
    assert birge_ratio(5.0, 0) == 1.0


def test_straight_line_is_the_least_squares_line():
    rng = np.random.default_rng(4)
    x = np.linspace(0.0, 10.0, 12)
    y = 3.0 * x - 2.0 + rng.normal(0.0, 0.5, x.size)
    slope, intercept, r2 = straight_line(x, y)
    expected = stats.linregress(x, y)
    assert slope == pytest.approx(expected.slope, rel=1e-12)
    assert intercept == pytest.approx(expected.intercept, rel=1e-12)
    assert r2 == pytest.approx(expected.rvalue**2, rel=1e-12)
    assert math.isnan(straight_line(x, np.full(x.size, 2.0))[2])
