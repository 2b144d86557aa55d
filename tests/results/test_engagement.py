"""The engagement result: a run file gives back the result it was written from.

The result is made here from numbers chosen by hand (an impact extraction of
four events, one excluded), so that the round trip is tested apart from the
detection and extraction, which have their own tests.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest

from pipeline.fit import impact, windows
from pipeline.fit.impact import ImpactResult
from pipeline.fit.windows import Ringing
from pipeline.results import EngagementResult, result_from_dataset
from pipeline.statistics import MedianStatistics
from pipeline.store.netcdf import read_dataset, write_atomic

N_U1 = np.array([1010.0, 990.0, 1000.0, np.nan])
N_U2 = np.array([3050.0, 2950.0, 3000.0, np.nan])


def extraction() -> ImpactResult:
    """Four seatings 0.05 s apart at 20 kN; the last one clipped."""
    events = pd.DataFrame({
        "event_time": [0.10, 0.15, 0.20, 0.25], "impact2_time": [0.125, 0.175, 0.225, 0.275],
        "tau": [0.025] * 4, "baseline": [2e4, 2e4 + 1, 2e4 + 2, np.nan],
        "N_u1": N_U1, "N_u1_stderr": [5.0, 5.0, 5.0, np.nan],
        "N_u2": N_U2, "N_u2_stderr": [6.0, 6.0, 6.0, np.nan],
        "peak1": 0.954 * N_U1, "peak2": 0.954 * N_U2, "residual_rms": [3.0, 3.1, 2.9, np.nan],
        "status": ["ok", "ok", "ok", "clipped"]})
    ok = events["status"] == "ok"
    statistics = {name: MedianStatistics.of(events.loc[ok, name].to_numpy(), stderr_ringing=2.0)
                  for name in ("N_u1", "N_u2", "peak1", "peak2", "baseline", "tau")}
    excluded = {reason: int(reason == "clipped") for reason in impact.EXCLUSIONS}
    ringing = Ringing(omega_n=900.0, zeta=0.03, omega_n_stderr=1.5, zeta_stderr=0.002,
                      correlation=0.25, n_events=3)
    return ImpactResult(events, ringing, statistics, excluded, (None, 2.5e4),
                        messages=("measured speed 3 % off the run sheet's; detection goes on",
                                  "second message"))


@pytest.fixture
def result() -> EngagementResult:
    detected = SimpleNamespace(seating_period=0.05, omega=15.7, source="force")
    table = pd.DataFrame({"time": np.arange(1000) / 1e4, "force": 2e4 + np.arange(1000.0)})
    signal = table["time"].to_numpy(), table["force"].to_numpy(), 1
    return EngagementResult.of(detected, extraction(), signal,
                               {"run_id": "E1", "kind": "engagement", "wheel": "w8"},
                               ["line 7: a repeated time stamp"])


def test_the_run_file_gives_the_result_back(result, tmp_path):
    back = EngagementResult.from_dataset(read_dataset(write_atomic(result.to_dataset(),
                                                                   tmp_path / "E1.nc")))
    assert back.attrs == result.attrs
    np.testing.assert_array_equal(back.time, result.time)
    np.testing.assert_array_equal(back.force, result.force)
    assert (back.signal_decimation, back.seating_period, back.omega_measured,
            back.event_source, back.ingest_warnings) == (1, 0.05, 15.7, "force",
                                                         ("line 7: a repeated time stamp",))
    pd.testing.assert_frame_equal(back.impact.events, result.impact.events)
    assert back.impact.ringing == result.impact.ringing
    assert back.impact.statistics == result.impact.statistics
    assert back.impact.excluded == result.impact.excluded
    assert back.impact.clip_levels == (None, 2.5e4)
    assert back.impact.messages == result.impact.messages  # a message may hold "; "
    assert back.impact.comparison == "amplitude"


def test_the_statistics_the_campaign_reads_are_the_medians(result):
    back = result_from_dataset(result.to_dataset())
    # the medians over the three valid events: 1000 N and 3000 N, counted 3
    assert back.impact.statistics["N_u1"].median == 1000.0
    assert back.impact.statistics["N_u2"].median == 3000.0
    assert back.impact.statistics["N_u1"].count == 3
    # MAD 10 N: sqrt(pi / 2) 1.4826 10 / sqrt(3) from the events, 2 N shared: in quadrature
    events = math.sqrt(math.pi / 2) * 1.4826 * 10 / math.sqrt(3)
    assert back.impact.statistics["N_u1"].stderr == pytest.approx(math.hypot(events, 2.0))


def test_the_run_file_has_the_documented_layout_and_settings(result):
    dataset = result.to_dataset()
    # docs/outputs.md, "Engagement run file": per event, and the run's statistics beside
    assert {name for name in dataset.data_vars if dataset[name].dims == ("event",)} == {
        "event_time", "impact2_time", "tau", "baseline", "N_u1", "N_u1_event_stderr", "N_u2",
        "N_u2_event_stderr", "peak1", "peak2", "residual_rms", "status"}
    assert dataset["N_u1_event_stderr"].values[:3].tolist() == [5.0, 5.0, 5.0]
    assert dataset["N_u1_stderr"].dims == () and dataset["N_u1_median"].attrs["units"] == "N"
    assert dataset["omega_n"].attrs["units"] == "rad s-1"
    assert int(dataset["excluded_clipped"]) == 1 and int(dataset["events_total"]) == 4
    assert math.isnan(float(dataset["clip_level_low"]))
    assert float(dataset["clip_level_high"]) == 2.5e4
    assert dataset.attrs["signal_decimation"] == 1
    # the extraction's settings, as the extraction's modules define them
    assert dataset.attrs["event_window_pre"] == windows.WINDOW_PRE
    assert dataset.attrs["event_window_guard"] == windows.WINDOW_GUARD
    assert dataset.attrs["max_onset_shift"] == windows.MAX_ONSET_SHIFT
    assert dataset.attrs["residual_outlier"] == impact.RESIDUAL_OUTLIER
    assert dataset.attrs["ringing_events_max"] == impact.RINGING_EVENTS


