"""Paper 003's contact geometry fitted to measured segment loads: s and beta recovered honestly.

The virtual segment-load bench runs three operating points (chain forces of
50, 100 and 150 kN) per campaign, with the bench's default noise: 0.5 kN on
every channel at 1 kHz (strain-gauge bridges and a load cell of some 500 kN
range), 30 seatings per run. Expected ratios are Paper 003's closed forms,
eqs. (1)-(4), written out with ``math`` here.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.segment_load import condition_segment_load
from pipeline.errors import FitError
from pipeline.fit.segment_load import FRICTION_CLAIM, contact_ratios, fit_segment_load
from pipeline.simulate.segment_load import SegmentLoadTruth, simulate_segment_load

SEEDS = range(20)
LEVELS = (50e3, 100e3, 150e3)
TRUTH = SegmentLoadTruth()
#: Chain 34x126 (Paper 003, section 3) [m].
CHAIN = {"r_outer": 52e-3, "d": 34e-3, "groove_width": 45e-3}


def closed_form(beta: float, s: float, eps_n: float = 0.0, chain=CHAIN) -> tuple[float, float]:
    """F_K / F and F_P / F of Paper 003, eqs. (1)-(4)."""
    k = chain["r_outer"] - chain["d"] / 2 * (1 - math.cos(math.pi / 2 - beta + eps_n))
    half = math.acos(s / (2 * k))
    return 1 / (2 * math.sin(half)), 1 / (2 * math.tan(half))


def conditioned(truth: SegmentLoadTruth, seed: int):
    log = simulate_segment_load(truth, seed=seed)
    return condition_segment_load(log["time"], log["F"], log["F_K1"], log["F_K2"], log["F_P"])


@pytest.fixture(scope="module")
def campaigns() -> list[tuple[pd.DataFrame, pd.DataFrame]]:
    """Per seed: the operating points' medians, and the seatings of the first run."""
    found = []
    for seed in SEEDS:
        runs = [conditioned(TRUTH.with_(chain_force=(level,)), 10 * seed + number)
                for number, level in enumerate(LEVELS)]
        found.append((pd.DataFrame([run.point() for run in runs]), runs[0].valid))
    return found


def test_point_medians_within_one_percent_of_truth(campaigns):
    k_ratio, p_ratio = closed_form(TRUTH.beta, TRUTH.s)
    for points, _ in campaigns:
        assert np.allclose(points["F_K/F"], k_ratio, rtol=0.01)
        assert np.allclose(points["F_P/F"], p_ratio, rtol=0.01)


def test_s_recovered_within_2_percent_and_covered(campaigns):
    fits = [fit_segment_load(points, CHAIN, beta=TRUTH.beta, s=55e-3) for points, _ in campaigns]
    assert all(fit.parameter == "s" and fit.dof == 5 for fit in fits)
    assert all(fit.value == pytest.approx(TRUTH.s, rel=0.02) for fit in fits)
    assert sum(fit.covers(TRUTH.s) for fit in fits) >= 18  # 95 % intervals: >= 90 % of 20
    assert all(fit.ci_low < fit.value < fit.ci_high and fit.stderr > 0 for fit in fits)


def test_beta_recovered_within_2_percent_and_covered(campaigns):
    fits = [fit_segment_load(points, CHAIN, beta=math.radians(45), s=TRUTH.s, vary="beta")
            for points, _ in campaigns]
    assert all(fit.parameter == "beta" for fit in fits)
    assert all(fit.value == pytest.approx(TRUTH.beta, rel=0.02) for fit in fits)
    assert sum(fit.covers(TRUTH.beta) for fit in fits) >= 18


def test_fit_per_seating(campaigns):
    fits = [fit_segment_load(events, CHAIN, beta=TRUTH.beta, s=TRUTH.s)
            for _, events in campaigns]
    assert all(fit.dof == 2 * len(events) - 1 for fit, (_, events) in zip(fits, campaigns,
                                                                          strict=True))
    assert all(fit.value == pytest.approx(TRUTH.s, rel=0.02) for fit in fits)
    assert sum(fit.covers(TRUTH.s) for fit in fits) >= 18


def exact(beta: float, s: float, eps_n: float = 0.0, side: bool = True) -> pd.DataFrame:
    """Two 'operating points' whose ratios are the closed forms, with stated errors."""
    k_ratio, p_ratio = closed_form(beta, s, eps_n)
    rows = pd.DataFrame({"F_K/F": [k_ratio] * 2, "F_K/F_stderr": [1e-3, 2e-3]})
    return rows.assign(**{"F_P/F": p_ratio, "F_P/F_stderr": [1e-3, 2e-3]}) if side else rows


@pytest.mark.parametrize("beta_deg, s_mm, eps_n_deg", [(50, 60, 0), (80, 45, 0), (50, 70, 6),
                                                       (65, 52, 3)])
def test_exact_ratios_give_the_geometry(beta_deg, s_mm, eps_n_deg):
    beta, s, eps_n = math.radians(beta_deg), s_mm / 1e3, math.radians(eps_n_deg)
    rows = exact(beta, s, eps_n)
    by_s = fit_segment_load(rows, CHAIN, beta=beta, s=50e-3, eps_n=eps_n)
    assert by_s.value == pytest.approx(s, rel=1e-8) and by_s.chi2_reduced < 1e-12
    by_beta = fit_segment_load(rows, CHAIN, beta=math.radians(60), s=s, eps_n=eps_n,
                               vary="beta")
    assert by_beta.value == pytest.approx(beta, rel=1e-8)
    assert by_s.dof == 3 and not by_s.scaled
    assert np.allclose(by_s.points[["F_K/F_residual", "F_P/F_residual"]], 0, atol=1e-10)


def test_model_beside_measured_and_declared():
    beta, s = math.radians(50), 62e-3
    fit = fit_segment_load(exact(beta, s), CHAIN, beta=beta, s=55e-3)
    k_ratio, p_ratio = closed_form(beta, s)
    declared_k, declared_p = closed_form(beta, 55e-3)
    assert (fit.fitted.contact_force, fit.fitted.side_force) == pytest.approx((k_ratio, p_ratio))
    assert fit.fitted.friction_increase == pytest.approx(2 * k_ratio - 1)
    assert (fit.declared.contact_force, fit.declared.side_force) == pytest.approx(
        (declared_k, declared_p), rel=1e-12)
    assert fit.declared.s == 55e-3 and fit.fitted.beta == beta
    assert fit.measured["F_K/F"] == pytest.approx(k_ratio, rel=1e-12)
    assert fit.measured["friction_increase"] == pytest.approx(2 * k_ratio - 1, rel=1e-12)
    # weighted mean of errors 1e-3 and 2e-3: 1 / sqrt(1e6 + 0.25e6)
    assert fit.measured["F_K/F_stderr"] == pytest.approx(1 / math.sqrt(1.25e6))
    frame = fit.points
    assert np.allclose(frame["F_K/F_normalized"], (frame["F_K/F"] - k_ratio)
                       / frame["F_K/F_stderr"], atol=1e-8)


def test_interval_is_students_t_with_the_birge_ratio():
    beta, errors = math.radians(50), 1e-3
    rows = pd.DataFrame({"F_K/F": [0.62, 0.64, 0.66], "F_K/F_stderr": [errors] * 3})
    fit = fit_segment_load(rows, CHAIN, beta=beta, s=60e-3)
    # equal errors: the fitted F_K / F is the mean, 0.64; the error sigma / (slope sqrt(n))
    assert fit.fitted.contact_force == pytest.approx(0.64, rel=1e-9)
    step = 1e-6
    slope = (closed_form(beta, fit.value + step)[0] - closed_form(beta, fit.value - step)[0]) \
        / (2 * step)
    chi2_reduced = sum(((x - 0.64) / errors) ** 2 for x in (0.62, 0.64, 0.66)) / 2
    assert fit.dof == 2 and fit.scaled and fit.chi2_reduced == pytest.approx(chi2_reduced)
    raw = errors / (slope * math.sqrt(3))
    assert fit.stderr == pytest.approx(raw * math.sqrt(chi2_reduced), rel=1e-4)
    half = fit.ci_high - fit.value
    assert half == pytest.approx(4.302653 * fit.stderr, rel=1e-6)  # t(0.975, 2 dof)
    single = fit_segment_load(rows.iloc[:1], CHAIN, beta=beta, s=60e-3)
    assert single.dof == 0 and not single.scaled
    assert single.ci_high - single.value == pytest.approx(1.959964 * single.stderr, rel=1e-6)


def test_edge_contact_keeps_an_honest_error():
    # s = c, the bound of the range: the error is that of a point just inside it
    beta, groove = math.radians(80), CHAIN["groove_width"]
    at_edge = pd.DataFrame({"F_K/F": [closed_form(beta, groove)[0]], "F_K/F_stderr": [1e-3]})
    inside = at_edge.assign(**{"F_K/F": closed_form(beta, groove + 1e-4)[0]})
    edge = fit_segment_load(at_edge, CHAIN, beta=beta, s=50e-3)
    near = fit_segment_load(inside, CHAIN, beta=beta, s=50e-3)
    assert edge.value == pytest.approx(groove, rel=1e-9)
    assert edge.stderr == pytest.approx(near.stderr, rel=0.01)
    assert edge.ci_low == groove and edge.ci_high == pytest.approx(groove + 1.959964
                                                                   * edge.stderr)


def test_friction_increase_against_the_paper_claim():
    # docs/models/paper-003-tooth-segments.md: at s = 70 mm, beta = 50 deg the increase is
    # 46.0 % with eps_n = 0 and 50.6 % with eps_n = 6 deg, against the claimed "over 50 %"
    beta, s = math.radians(50), 70e-3
    below = fit_segment_load(exact(beta, s), CHAIN, beta=beta, s=s)
    above = fit_segment_load(exact(beta, s, math.radians(6)), CHAIN, beta=beta, s=s,
                             eps_n=math.radians(6))
    assert FRICTION_CLAIM == 0.5
    assert below.measured["friction_increase"] == pytest.approx(0.460, abs=5e-4)
    assert above.measured["friction_increase"] == pytest.approx(0.506, abs=5e-4)
    assert "below it" in below.claim_note() and "above it" in above.claim_note()
    assert "46.0 %" in below.claim_note() and "over 50 %" in below.claim_note()


def test_contact_ratios_are_eqs_1_to_4():
    ratios = contact_ratios(CHAIN, beta=math.radians(80), s=45e-3)
    assert ratios.contact_force == pytest.approx(closed_form(math.radians(80), 45e-3)[0])
    # docs/models/paper-003-tooth-segments.md: psi = 128.45 deg at s = 45 mm, beta = 80 deg
    assert math.degrees(ratios.psi) == pytest.approx(128.45, abs=0.005)


@pytest.mark.parametrize("s, match", [(44e-3, "outside c <= s < 2 k"),
                                      (97e-3, "outside c <= s < 2 k")])
def test_declared_geometry_that_cannot_hold_is_refused(s, match):
    with pytest.raises(FitError, match=match) as error:
        fit_segment_load(exact(math.radians(50), 60e-3), CHAIN, beta=math.radians(50), s=s)
    assert error.value.column == "s" and "run sheet" in error.value.hint


def test_ratio_below_one_half_is_refused():
    rows = pd.DataFrame({"F_K/F": [0.64, 0.48], "F_K/F_stderr": [1e-3, 1e-3]})
    with pytest.raises(FitError, match="below 0.5, which no opening angle gives") as error:
        fit_segment_load(rows, CHAIN, beta=math.radians(50), s=60e-3)
    assert "calibration" in error.value.hint


def test_negative_side_force_ratio_is_refused():
    rows = exact(math.radians(50), 60e-3).assign(**{"F_P/F": -0.4})
    with pytest.raises(FitError, match="F_P/F = -0.4 is below 0") as error:
        fit_segment_load(rows, CHAIN, beta=math.radians(50), s=60e-3)
    assert "sign" in error.value.hint


def test_ratio_needing_s_below_the_groove_is_refused():
    beta = math.radians(50)
    edge, _ = closed_form(beta, CHAIN["groove_width"])  # F_K / F at edge contact, s = c
    rows = pd.DataFrame({"F_K/F": [edge - 0.01], "F_K/F_stderr": [1e-3]})
    with pytest.raises(FitError, match="lies outside what eqs. \\(1\\)-\\(4\\) give for s "
                                       "from 45 mm") as error:
        fit_segment_load(rows, CHAIN, beta=beta, s=60e-3)
    assert error.value.hint


def test_ratio_needing_k_above_r_is_refused():
    s = 60e-3
    # beta = 90 deg gives k = r, the largest contact radius and smallest F_K / F
    least, _ = closed_form(math.radians(90), s)
    rows = pd.DataFrame({"F_K/F": [least - 0.005], "F_K/F_stderr": [1e-3]})
    with pytest.raises(FitError, match="give for beta") as error:
        fit_segment_load(rows, CHAIN, beta=math.radians(50), s=s, vary="beta")
    assert error.value.hint


def test_side_force_ratio_no_geometry_gives_is_refused():
    beta = math.radians(50)
    rows = exact(beta, 60e-3).assign(**{"F_P/F": 0.05})  # F_P/F needs s < c
    edge = closed_form(beta, CHAIN["groove_width"])[1]
    beyond = (edge - 0.05) * math.sqrt(1e6 + 0.25e6)  # errors 1e-3 and 2e-3, weighted
    with pytest.raises(FitError, match=f"measured F_P/F = 0.05 ± .* lies outside .* by "
                                       f"{beyond:.3g} standard errors") as error:
        fit_segment_load(rows, CHAIN, beta=beta, s=60e-3)
    assert error.value.column == "F_P/F" and error.value.hint


@pytest.mark.parametrize("rows, match", [
    (pd.DataFrame({"F_P/F": [0.4], "F_P/F_stderr": [1e-3]}), "no column 'F_K/F'"),
    (pd.DataFrame({"F_K/F": [0.64]}), "have no standard errors"),
    (pd.DataFrame({"F_K/F": [0.64], "F_K/F_stderr": [0.0]}), "no positive standard error"),
    (pd.DataFrame({"F_K/F": [np.nan], "F_K/F_stderr": [1e-3]}), "no measured F_K/F"),
])
def test_bad_measured_rows_are_refused(rows, match):
    with pytest.raises(FitError, match=match) as error:
        fit_segment_load(rows, CHAIN, beta=math.radians(50), s=60e-3)
    assert error.value.hint


def test_unknown_parameter_is_refused():
    with pytest.raises(ValueError, match="vary must be"):
        fit_segment_load(exact(math.radians(50), 60e-3), CHAIN, beta=math.radians(50),
                         s=60e-3, vary="k")
