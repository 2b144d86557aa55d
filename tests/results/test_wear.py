"""The wear run file: what the stages gave, stored and read back unchanged, in SI units.

A noise-free linear log relative to its first reading, 0.5 um/h per pitch of a
19.05 mm chain for 200 h, has a wear rate, a life to a limit (limit / rate) and
a pin wear (growth / 2 K_e, Paper 004 eq. (2)) that can be written down by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.wear import wear_from_elongation
from pipeline.fit.wear import compare_pin_wear, fit_wear, pitch_growth_limit, predict_life
from pipeline.results import RESULT_TYPES, result_from_dataset
from pipeline.results.wear import LimitOutcome, WearResult
from pipeline.theory.pin_criterion import check_pin

HOUR = 3600.0
PITCH = 0.01905
RATE = 0.5e-6 / HOUR
TIME = np.arange(41) * 5 * HOUR
#: A pin for the hand calculation: F = 5 kN, [sigma_T] = 800 MPa, K_e = 0.8, z = 20.
PIN = {"pin_wear_coefficient": 0.8, "pin_force": 5e3, "pin_allowable_stress": 800e6,
       "pin_support_factor": 1.0}


@pytest.fixture(scope="module")
def result() -> WearResult:
    log = wear_from_elongation(TIME, RATE * TIME, pitches=1, pitch=PITCH, reference="first")
    fit = fit_wear(log)
    limits = {}
    for name, limit in (("eq3", {"teeth": 20}), ("lab", {"limit_percent": 1.5})):
        value, source = pitch_growth_limit(PITCH, "first", **limit)
        life = predict_life(fit, **limit)
        limits[name] = LimitOutcome(value, source, life, compare_pin_wear(
            life, teeth=20, wear_coefficient=PIN["pin_wear_coefficient"]))
    check = check_pin(5.72e-3, PITCH, 20, PIN["pin_force"], 18e-3, 17e-3,
                      PIN["pin_allowable_stress"], PIN["pin_wear_coefficient"])
    logged = pd.DataFrame({"load": np.full(TIME.size, 4e3)})
    attrs = {"kind": "wear", "run_id": "W1", "chain": "c12B", "abscissa": "time",
             "reference": "first", "channel": "elongation", "section_pitches": 1,
             "pitch": PITCH, "sprocket_teeth": 20}
    return WearResult.of(fit, limits, (check, PIN), logged, attrs, ["read"], ["decided"])


def test_registered_for_its_kind():
    assert RESULT_TYPES["wear"] is WearResult


def test_values_are_the_hand_calculation(result):
    assert result.fit["wear_rate"] == pytest.approx(RATE, rel=1e-9)
    assert math.isnan(result.fit["run_in"]) and result.attrs["model"] == "linear"
    # eq. (3), relative to the first reading: delta_t1 = t (2 / z - 0.004)
    limit = PITCH * (2 / 20 - 0.004)
    eq3 = result.limits.loc["eq3"]
    assert eq3["limit_elongation"] == pytest.approx(limit)
    assert eq3["life"] == pytest.approx(limit / RATE, rel=1e-9)
    assert result.limits.loc["lab", "life"] == pytest.approx(0.015 * PITCH / RATE, rel=1e-9)
    # the pin wear at the lab's limit: (growth / 2) K_e, within delta_d = (delta_t1 / 2) K_e
    assert result.limits.loc["lab", "limit_pin_wear"] == pytest.approx(0.015 * PITCH / 2 * 0.8)
    assert result.limits.loc["lab", "limit_pin_within"] == 1
    growth = RATE * TIME[-1]
    assert result.fit["growth_measured"] == pytest.approx(growth, rel=1e-9)
    assert result.pin["pin_allowed_wear"] == pytest.approx(limit / 2 * 0.8)
    assert result.pin["pin_wear_measured"] == pytest.approx(growth / 2 * 0.8, rel=1e-9)
    assert result.pin["pin_wear_share"] == pytest.approx(growth / limit, rel=1e-9)
    # eq. (5) with K = 1: d_k = cbrt(4 F (2 l1 - l) / (pi [sigma_T]))
    d_k = (4 * 5e3 * (2 * 18e-3 - 17e-3) / (math.pi * 800e6)) ** (1 / 3)
    assert result.pin["pin_critical_diameter"] == pytest.approx(d_k)
    assert result.pin["pin_passes"] == int(5.72e-3 >= d_k + limit / 2 * 0.8)


def test_curve_runs_past_the_last_life_through_the_fit(result):
    curve = result.curve
    assert curve["curve_tau"].iloc[0] == 0
    assert curve["curve_tau"].iloc[-1] > result.limits["life_ci_high"].max()
    np.testing.assert_allclose(curve["curve_elongation"], RATE * curve["curve_tau"],
                               atol=1e-9 * PITCH)


def test_run_file_round_trip(result):
    dataset = result.to_dataset()
    assert dataset["life"].attrs["units"] == "s"
    assert dataset["wear_rate"].attrs["units"] == "m s-1"
    assert dataset["life_ci_low"].attrs["confidence_level"] == 0.95
    back = result_from_dataset(dataset)
    assert isinstance(back, WearResult)
    pd.testing.assert_frame_equal(back.readings, result.readings)
    pd.testing.assert_frame_equal(back.curve, result.curve)
    pd.testing.assert_frame_equal(back.limits, result.limits, check_dtype=False)
    assert back.fit == pytest.approx(result.fit, nan_ok=True)
    assert back.pin == pytest.approx(result.pin, nan_ok=True)
    assert back.ingest_warnings == ("read",) and back.warnings == ("decided",)
    assert back.attrs == {key: value for key, value in dataset.attrs.items()
                          if key not in ("ingest_warnings", "warnings")}
