"""Property-based test of one tensile run, file to result and dataset, on odd and broken logs.

Logs of the virtual bench with random settings (noise, 0 to 4 cycles, dwell,
sampling, gauge resolution) are perturbed (NaN samples, a flat force, the sign
convention flipped to compression-negative, gauges reading against the load, a
saturated gauge, a time step backwards, a gauge or the time dropped, very few
rows), written in a random layout and units, and processed by
:func:`pipeline.runs.process_tensile_run` through a one-run run sheet (random
gauge length, number of cycles asked for, fit window). The outcome is a result
whose specimen E0 is finite and positive and whose dataset gives it back
(:meth:`~pipeline.results.TensileResult.from_dataset`), or a
:class:`~pipeline.errors.ChainbenchError`: never another exception.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from pipeline.errors import ChainbenchError
from pipeline.results import TensileResult
from pipeline.runs import process_tensile_run
from pipeline.runsheet import load_run_sheet
from pipeline.simulate.export import FORCE_UNITS, LAYOUTS, LENGTH_UNITS, SUFFIXES, write_table
from pipeline.simulate.tensile import TensileTruth, simulate_tensile

BOUNDED = settings(max_examples=60, deadline=None,
                   suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

SHEET = """
[campaign]
id = "fuzz"

[chains.c18]
catalog = "18x64"

[[runs]]
id = "T1"
kind = "tensile"
file = "{file}"
chain = "c18"
gauge_length_mm = {gauge_length_mm}
"""

PERTURBATIONS = ("nan samples", "nan stretch", "flat force", "compression negative",
                 "gauges reversed", "saturated gauge", "time backwards", "one gauge", "no time",
                 "few rows")


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("runs")


@st.composite
def tensile_logs(draw):
    """A canonical tensile table (SI) from the virtual bench, perturbed; and what was done."""
    cycles = draw(st.sampled_from([0, 1, 2, 3, 3, 4]))
    truth = TensileTruth.for_chain(
        "18x64",
        n_cycles=max(cycles, 1),
        sample_rate=draw(st.sampled_from([0.5, 1.0, 2.0, 5.0])),
        loading_rate=draw(st.sampled_from([500.0, 1000.0, 5000.0, 20_000.0])),
        dwell=draw(st.sampled_from([0.0, 2.0, 20.0])),
        hold=draw(st.sampled_from([0.0, 1.0, 5.0])),
        force_noise=draw(st.sampled_from([0.0, 50.0, 1000.0, 10_000.0])),
        gauge_noise=draw(st.sampled_from([0.0, 2e-6, 5e-5, 5e-4])),
        gauge_resolution=draw(st.sampled_from([0.0, 1e-5, 1e-4])),
        bending=draw(st.sampled_from([0.0, 0.05, 0.5])),
    )
    table = simulate_tensile(truth, seed=draw(st.integers(0, 2**32 - 1)))
    if cycles == 0:  # the preload hold only
        table = table[table["time"] <= truth.hold]
    done = draw(st.sets(st.sampled_from(PERTURBATIONS), max_size=draw(st.sampled_from([0, 1, 3]))))
    rows = len(table)
    if "nan samples" in done or "nan stretch" in done:
        column = draw(st.sampled_from(["force", "gauge_1", "gauge_2"]))
        length = draw(st.integers(4, 12)) if "nan stretch" in done else 1
        for start in draw(st.lists(st.integers(0, max(rows - 1, 0)), max_size=5)):
            table.loc[table.index[start : start + length], column] = np.nan
    if "flat force" in done:
        table["force"] = truth.preload + np.random.default_rng(0).normal(0, 10.0, rows)
    if "compression negative" in done:
        table[["force", "gauge_1", "gauge_2"]] *= -1
    if "gauges reversed" in done:  # wired against the load
        table[["gauge_1", "gauge_2"]] *= -1
    if "saturated gauge" in done:
        level = table["gauge_1"].quantile(draw(st.floats(0.0, 1.0)))  # NaN if all NaN
        table["gauge_1"] = table["gauge_1"].clip(upper=level)
    if "time backwards" in done and rows > 2:
        at = draw(st.integers(1, rows - 1))
        table.loc[table.index[at], "time"] = table["time"].iloc[at - 1] - 1.0
    if "one gauge" in done:
        table = table.drop(columns="gauge_2")
    if "no time" in done:
        table = table.drop(columns="time")
    if "few rows" in done:
        start = draw(st.integers(0, max(rows - 1, 0)))
        table = table.iloc[start : start + draw(st.integers(1, 12))]
    return table.reset_index(drop=True), sorted(done)


@BOUNDED
@given(case=tensile_logs(), layout=st.sampled_from(LAYOUTS),
       force_unit=st.sampled_from(FORCE_UNITS), length_unit=st.sampled_from(LENGTH_UNITS),
       language=st.sampled_from(["pl", "de"]), gauge_length_mm=st.sampled_from([300, 896.5]),
       cycles=st.sampled_from([None, None, 1, 2, 3, 4]),
       window=st.sampled_from([None, None, None, (0.0, 90.0), (30.0, 50.0), (10.0, 300.0)]))
def test_a_tensile_run_gives_a_positive_E0_or_a_typed_error(
    folder, case, layout, force_unit, length_unit, language, gauge_length_mm, cycles, window
):
    table, done = case
    name = f"T1{SUFFIXES[layout]}"
    write_table(table, folder / name, layout=layout, force_unit=force_unit,
                length_unit=length_unit, language=language,
                preamble=[("Machine", "Amsler 50 t")])
    text = SHEET.format(file=name, gauge_length_mm=gauge_length_mm)
    if cycles is not None:
        text += f"cycles = {cycles}\n"
    if window is not None:
        text += f"fit_window = {{force_low_kN = {window[0]}, force_high_kN = {window[1]}}}\n"
    (folder / "campaign.toml").write_text(text, encoding="utf-8")
    sheet = load_run_sheet(folder)
    assert not sheet.invalid_runs
    try:
        result = process_tensile_run(sheet, sheet.runs[0], "0" * 64)
    except ChainbenchError as error:
        event(f"{type(error).__name__} ({', '.join(done) or 'no perturbation'})")
        return
    event("E0")
    E0 = result.specimen.E0
    assert math.isfinite(E0) and E0 > 0, (E0, done)
    back = TensileResult.from_dataset(result.to_dataset())
    np.testing.assert_equal(back.specimen.as_dict(), result.specimen.as_dict())
    np.testing.assert_equal(back.strength.as_dict(), result.strength.as_dict())
