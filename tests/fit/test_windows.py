"""The window model's free-phase residuals against each event's least squares, one by one."""

import numpy as np
import pytest

from pipeline.fit.windows import FreePhaseResiduals, Ringing, WindowGeometry

GEO = WindowGeometry(start=0.0, rate=20_000.0, period=0.05, pre=20, width=200)
RINGING = Ringing(omega_n=2_000.0, zeta=0.03)
EVENTS = 12
SPACING = 300  # samples between the events' windows


def onsets(rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Onsets [s] between samples, impact 2 from 60 to 62 samples after impact 1."""
    first = (np.arange(EVENTS) * SPACING + 40 + rng.uniform(0.1, 0.9, EVENTS)) / GEO.rate
    return first, first + (60 + np.arange(EVENTS) % 3) / GEO.rate


def design(onset1: float, onset2: float, ringing: Ringing) -> tuple[np.ndarray, int]:
    """One event's design matrix, its strikes' columns masked before their onsets, and
    the window's first sample."""
    start = int(GEO.first_sample(np.array([onset1]))[0]) - GEO.pre
    basis = GEO.basis(ringing.pole)
    basis[: GEO.pre, 6:8] = 0.0
    basis[: int(GEO.first_sample(np.array([onset2]))[0]) - start, 8:10] = 0.0
    return basis, start


@pytest.mark.parametrize("seed", [1, 2])
def test_residuals_are_each_events_least_squares(seed):
    rng = np.random.default_rng(seed)
    y = rng.normal(size=EVENTS * SPACING + GEO.width)
    onset1, onset2 = onsets(rng)
    expected = []
    for first, second in zip(onset1, onset2, strict=True):
        basis, start = design(first, second, RINGING)
        window = y[start: start + GEO.width]
        coef = np.linalg.lstsq(basis, window, rcond=None)[0]
        expected.append(window - basis @ coef)
    got = FreePhaseResiduals(y, onset1, onset2, GEO)(RINGING)
    np.testing.assert_allclose(got, np.concatenate(expected), rtol=0, atol=1e-9)


def test_a_log_of_the_model_leaves_no_residual():
    rng = np.random.default_rng(3)
    y = np.zeros(EVENTS * SPACING + GEO.width)
    onset1, onset2 = onsets(rng)
    for first, second in zip(onset1, onset2, strict=True):
        basis, start = design(first, second, RINGING)
        y[start: start + GEO.width] = basis @ rng.uniform(-1e3, 1e3, 10)
    residuals = FreePhaseResiduals(y, onset1, onset2, GEO)
    assert np.max(np.abs(residuals(RINGING))) < 1e-6
    assert np.max(np.abs(residuals(Ringing(1.05 * RINGING.omega_n, RINGING.zeta)))) > 1.0
