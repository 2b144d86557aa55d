"""The virtual engagement bench: its truth is what its docstring says it is.

Expectations are computed here independently: the closed forms of Paper 000
(``docs/models/paper-000-wheel-impact.md``) for N_u, and an explicit sum over
every strike for the signal.
"""

from __future__ import annotations

import json
import math
import tomllib

import numpy as np
import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.ingest import read_table
from pipeline.runsheet import load_run_sheet
from pipeline.simulate.engagement import (
    EngagementSettings,
    simulate_engagement,
    strike_response,
    write_engagement_csv,
    write_engagement_tdms,
)

QUIET = {"snr": math.inf, "jitter": 0.0}


def closed_form_tensions(s: EngagementSettings) -> tuple[float, float]:
    """Paper 000: v_u1 = w (t-d) sin(psi/2), v_u2 = w (t+d) sin(pi/z + psi/2), eq. (16)."""
    root = math.sqrt(s.k * s.mass_per_length * s.t * s.E0 / s.branch_length)
    v_u1 = s.omega * (s.t - s.d) * math.sin(s.psi / 2)
    v_u2 = s.omega * (s.t + s.d) * math.sin(math.pi / s.z + s.psi / 2)
    return v_u1 * root, v_u2 * root


def explicit_sum(amplitudes, onsets, time, omega_n, zeta):
    omega_d = omega_n * math.sqrt(1 - zeta**2)
    lag = time[:, None] - np.asarray(onsets)[None, :]
    ring = np.where(lag >= 0, np.exp(-zeta * omega_n * lag) * np.sin(omega_d * np.maximum(lag, 0)),
                    0.0)
    return ring @ np.asarray(amplitudes)


def test_defaults_are_paper_000_example():
    s = EngagementSettings()
    n_u1, n_u2 = s.impact_tensions()
    assert (n_u1, n_u2) == pytest.approx(closed_form_tensions(s), rel=1e-12)
    # docs/published-values.md, Paper 000 grid (q = 6.6 kg/m, z = 8, psi = 40 deg): 972 N, 3423 N
    assert round(n_u1) == 972 and round(n_u2) == 3423
    # docs/file-formats.md: "some 150 Hz for an 18x64 chain on a 2 m branch"
    assert s.omega_n / (2 * math.pi) == pytest.approx(math.sqrt(2.26e7 / (2.0 * 6.6 * 2.0))
                                                      / (2 * math.pi))
    assert 140 < s.omega_n / (2 * math.pi) < 160
    assert s.tau == pytest.approx(math.pi / (8 * 20))
    assert s.seating_period == pytest.approx(2 * s.tau)


@pytest.mark.parametrize("k", [2.0, 1.5])
def test_truth_follows_k(k):
    s = EngagementSettings(k=k, z=6, psi=math.radians(30), omega=12.0)
    _, truth = simulate_engagement(s.with_(duration=0.5), seed=0)
    assert (truth["N_u1"], truth["N_u2"]) == pytest.approx(closed_form_tensions(s), rel=1e-12)


@pytest.mark.parametrize("bad", [{"omega": 0.0}, {"damping_ratio": 1.0}, {"snr": -1.0},
                                 {"jitter": -1e-3}, {"d": 0.07}, {"z": 2},
                                 {"sample_rate": 200.0}])
def test_invalid_settings_name_the_parameter(bad):
    (name,) = bad
    with pytest.raises(ValueError, match=name):
        EngagementSettings(**bad)


def test_strike_response_is_the_explicit_superposition():
    time = np.arange(3000) / 1e4
    amplitudes = [1.0, 2.5, -0.7, 3.0]
    onsets = [-0.05, 0.00003, 0.1234567, 0.2999]  # before the log, between samples, at the end
    expected = explicit_sum(amplitudes, onsets, time, 900.0, 0.04)
    assert np.max(np.abs(strike_response(amplitudes, onsets, time, 900.0, 0.04) - expected)) < 1e-12


def test_log_matches_strikes_and_baseline_after_settling():
    # a log long enough to compare after the pre-log strikes died out
    s = EngagementSettings(duration=1.0, sample_rate=4000.0, snr=math.inf, jitter=3e-4,
                           amplitude_scatter=0.05)
    table, truth = simulate_engagement(s, seed=9)
    time, force = table["time"].to_numpy(), table["force"].to_numpy()
    settle = 20 / (truth["zeta"] * truth["omega_n"])  # 0.72 s
    late = time > settle
    first = truth["seating_origin"]
    baseline = s.pretension + s.polygon_amplitude * np.cos(
        2 * np.pi * (time - first) / truth["seating_period"])
    strikes = explicit_sum(np.concatenate([truth["N_u1_event"], truth["N_u2_event"]]),
                           np.concatenate([truth["event_time"], truth["impact2_time"]]), time,
                           truth["omega_n"], truth["zeta"])
    assert np.max(np.abs(force - baseline - strikes)[late]) < 1e-4 * truth["N_u2"]
    assert np.std(truth["N_u1_event"] / truth["N_u1"]) == pytest.approx(0.05, rel=0.5)
    assert np.allclose(truth["impact2_time"] - truth["event_time"], math.pi / (s.z * s.omega))
    assert truth["baseline_event"] == pytest.approx(s.pretension + s.polygon_amplitude * np.cos(
        2 * np.pi * (truth["event_time"] - first) / truth["seating_period"]))


def test_noise_level_and_determinism():
    s = EngagementSettings(duration=0.5, snr=10.0)
    a, truth = simulate_engagement(s, seed=3)
    b, _ = simulate_engagement(s, seed=3)
    c, _ = simulate_engagement(s.with_(snr=math.inf), seed=3)
    assert a.equals(b)
    assert truth["noise_std"] == pytest.approx(truth["N_u1"] / 10)
    assert np.std(a["force"] - c["force"]) == pytest.approx(truth["noise_std"], rel=0.05)


def test_angle_channel_marks_impact_1():
    s = EngagementSettings(duration=0.5, **QUIET)
    table, truth = simulate_engagement(s, seed=2)
    assert list(table.columns) == ["time", "force", "angle"]
    angle = np.interp(truth["event_time"], table["time"], np.unwrap(table["angle"]))
    pitch = 2 * np.pi / s.z
    offsets = np.mod(angle - truth["impact_angle"] + pitch / 2, pitch) - pitch / 2
    assert np.max(np.abs(offsets)) < 1e-9
    assert table["angle"].between(0, 2 * np.pi).all()
    no_angle, _ = simulate_engagement(s.with_(with_angle=False), seed=2)
    assert list(no_angle.columns) == ["time", "force"]


def test_clipping_saturates_and_is_recorded():
    s = EngagementSettings(duration=1.0, amplitude_scatter=0.1, clip_level=23.8e3, snr=20.0)
    table, truth = simulate_engagement(s, seed=1)
    free, _ = simulate_engagement(s.with_(clip_level=None), seed=1)
    assert table["force"].max() == 23.8e3
    assert np.array_equal(table["force"], np.minimum(free["force"], 23.8e3))
    assert 0 < truth["clipped_event"].sum() < truth["clipped_event"].size


@pytest.mark.parametrize("writer, suffix", [(write_engagement_csv, "csv"),
                                            (write_engagement_tdms, "tdms")])
def test_written_logs_read_back_through_ingest(tmp_path, writer, suffix):
    table, _ = simulate_engagement(EngagementSettings(duration=0.3), seed=5)
    path = writer(table, tmp_path / f"run.{suffix}")
    back, metadata = read_table(path, kind="engagement")
    assert list(back.columns) == ["time", "force", "angle"]
    assert np.allclose(back.to_numpy(), table[back.columns].to_numpy(), rtol=1e-12, atol=1e-12)
    if suffix == "tdms":  # time from the waveform properties, no time channel
        assert any("waveform" in column.name for column in metadata.columns)


def test_cli_writes_a_campaign_the_run_sheet_accepts(tmp_path):
    result = CliRunner().invoke(app, [
        "simulate", "engagement", "--out", str(tmp_path), "--teeth", "6", "8", "--omega", "10",
        "20", "--duration", "0.4", "--sample-rate", "5000", "--format", "csv", "--k", "1.5",
        "--json"])
    assert result.exit_code == 0, result.output
    printed = json.loads(result.stdout)
    assert [row["id"] for row in printed["rows"]] == ["E6-40-10", "E6-40-20", "E8-40-10",
                                                       "E8-40-20"]
    sheet = load_run_sheet(tmp_path / "campaign.toml")
    assert len(sheet.runs) == 4
    raw = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))
    assert raw["wheels"]["w8_40"] == {"teeth": 8, "apex_angle_deg": 40}
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))["runs"]
    expected = closed_form_tensions(EngagementSettings(z=8, omega=20.0, k=1.5))
    assert (truth["E8-40-20"]["N_u1"], truth["E8-40-20"]["N_u2"]) == pytest.approx(expected)
    back, _ = read_table(tmp_path / "E8-40-20.csv", kind="engagement")
    assert len(back) == 2001
