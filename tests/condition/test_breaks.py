"""Fracture and channel removal found from the signals alone."""

import numpy as np
import pytest

from pipeline.condition.breaks import (
    DECADE_CAUSE,
    find_fracture,
    find_removal,
    reading_step,
)

#: A 13x50 chain on a 0.9 m gauge: stiffness E0 [N], gauge length [m], force noise [N],
#: gauge noise [m] and gauge resolution [m] as a lab's clip-on extensometer logs them.
E0, GAUGE, FORCE_NOISE, GAUGE_NOISE, RESOLUTION = 1.1e7, 0.9, 50.0, 2e-6, 1e-5


def _loading(seed: int, samples: int = 6000) -> tuple[np.ndarray, np.ndarray]:
    """A first loading from 5 to 34 kN with a quantised extensometer [N], [m]."""
    rng = np.random.default_rng(seed)
    true_force = np.linspace(5e3, 34e3, samples)
    force = true_force + rng.normal(0.0, FORCE_NOISE, samples)
    elongation = true_force / E0 * GAUGE + rng.normal(0.0, GAUGE_NOISE, samples)
    return force, np.round(elongation / RESOLUTION) * RESOLUTION


def test_a_quantised_gauge_flickering_by_a_step_is_not_taken_off():
    # the reading flickers a step up and a step down about its true value; that
    # two-step fall while the force rises is noise, not a gauge running backwards
    flagged = [seed for seed in range(100) if find_removal(*_loading(seed)) is not None]
    assert flagged == []


def test_a_quantised_gauge_that_falls_back_is_taken_off():
    force, channel = _loading(0)
    fallen = channel.copy()
    fallen[4000:] -= 10 * RESOLUTION  # slips back by 0.1 mm and stays there
    removal = find_removal(force, fallen)
    assert removal is not None and removal.reason == "runs backwards"
    assert removal.position == 4000


def test_a_jump_by_ten_is_named_as_a_lost_decimal_mark():
    # a real Bluehill export re-saved by a spreadsheet: 0.9966 mm, then 10.114 for 1.0114
    force, channel = _loading(3)
    shifted = channel.copy()
    shifted[4000:] *= 10.0
    removal = find_removal(force, shifted)
    assert removal is not None and removal.reason == "jumps" and removal.position == 4000
    assert removal.cause == DECADE_CAUSE


def test_a_slip_is_named_as_such():
    force, channel = _loading(4)
    slipped = channel.copy()
    slipped[4000:] += 0.3 * np.ptp(channel)  # the knife edge slips: a step, not a decade
    removal = find_removal(force, slipped)
    assert removal is not None and removal.reason == "jumps" and removal.position == 4000
    assert removal.cause == "taken off or slipped"


def test_reading_step_is_the_resolution_of_a_quantised_reading():
    _, channel = _loading(1)
    assert reading_step(channel) == pytest.approx(RESOLUTION, rel=1e-9)
    assert reading_step(np.zeros(5)) == 0.0


def test_fracture_is_the_last_sample_before_the_sudden_drop():
    force, _ = _loading(2)
    broken = np.concatenate([force, [300.0, 200.0, 250.0, 220.0]])
    assert find_fracture(broken) == force.size - 1
    assert find_fracture(force) is None
