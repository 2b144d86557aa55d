"""Values a power of ten off their neighbours: decimal marks a spreadsheet mangled."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pipeline.ingest import parse_table
from pipeline.ingest.decimalshift import SPREADSHEET_ROWS, decimal_shifts


def excel_mangled(value: float) -> str:
    """`value` written with a decimal comma, as a spreadsheet re-saves it after reading ','
    as a thousands separator: '1,0114' was read as 10114 and is written '10,114'; a cell
    with fewer than four decimals ('1,063') or a zero before them ('0,9966') is left."""
    text = f"{value:.4f}".rstrip("0").rstrip(".").replace(".", ",")
    whole, _, decimals = text.partition(",")
    if whole != "0" and len(decimals) == 4:
        return f"{int(whole + decimals):,}"
    return text


def test_the_spreadsheet_rule_by_hand():
    assert [excel_mangled(v) for v in (0.9966, 1.0114, 1.063, 1.2)] == [
        "0,9966", "10,114", "1,063", "1,2"]


def test_a_mangled_bluehill_displacement_is_reported_where_it_starts():
    # 0.0166 mm per 0.02 s from 0.8 to 1.4 mm, written as a re-saved Bluehill export
    displacement = np.round(0.8 + 0.0166 * np.arange(37), 4)
    cells = [excel_mangled(value) for value in displacement]
    first = next(i for i, cell in enumerate(cells) if float(cell.replace(",", ".")) > 5)
    lines = ["Time;Displacement;Force", "(s);(mm);(kN)"] + [
        f"{0.02 * i:.2f};{cell};{0.05 + 0.001 * i:.4f}".replace(".", ",")
        for i, cell in enumerate(cells)]
    _, metadata = parse_table("\n".join(lines).encode(), name="resaved.csv")
    shifted = [w for w in metadata.warnings if "tenfold" in w]
    assert len(shifted) == 1 and shifted[0].startswith("gauge_1: ")
    assert f"line {first + 3}" in shifted[0]  # two header lines, 1-based


def test_a_break_drops_once_and_is_not_reported():
    force = np.concatenate([np.linspace(0.0, 9.4, 50), [0.94, 0.0, 0.01, 0.0, 0.02]])
    assert decimal_shifts(force) == (0, -1)


@pytest.mark.parametrize(("size", "found"), [(20, (2, 7)), (SPREADSHEET_ROWS, (2, 7)),
                                             (SPREADSHEET_ROWS + 1, (0, -1))])
def test_a_hundredfold_shift_there_and_back_is_reported_where_a_spreadsheet_could_be(
        size, found):
    # a log longer than a spreadsheet holds was never re-saved by one: not looked at
    values = np.linspace(1.0, 2.0, size)
    values[7] *= 100.0
    assert decimal_shifts(values) == found


@settings(max_examples=200, deadline=None)
@given(amplitude=st.floats(0.1, 1e4), periods=st.floats(0.2, 20.0),
       noise=st.floats(0.0, 0.05), offset=st.floats(-1.0, 1.0), seed=st.integers(0, 2**32 - 1))
def test_smooth_signals_with_noise_are_never_reported(amplitude, periods, noise, offset, seed):
    # sines about and away from zero, with noise up to 5 % of the amplitude: noise about
    # zero may step tenfold, but never far beyond the typical step
    phase = np.linspace(0.0, 2 * np.pi * periods, 2_000)
    rng = np.random.default_rng(seed)
    values = amplitude * (np.sin(phase) + offset + noise * rng.standard_normal(phase.size))
    assert decimal_shifts(values)[0] == 0


@pytest.mark.parametrize("samples", [5, 8, 12, 25])
def test_an_impact_pulse_is_not_reported(samples):
    # a half-sine force pulse of a few samples between quiet stretches
    pulse = 5e3 * np.sin(np.linspace(0.0, np.pi, samples))
    quiet = np.random.default_rng(samples).normal(0.0, 2.0, 200)
    assert decimal_shifts(np.concatenate([quiet, pulse, quiet]))[0] == 0
