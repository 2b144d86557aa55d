"""The papers' published numbers as data: the CSV files, their reading and the tolerance rule."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pipeline.theory import _published

PAPERS = ["000", "001", "002", "003", "004"]


@pytest.mark.parametrize(
    ("model", "published", "tolerance", "expected"),
    [
        (2379.0, 2300.0, 0.04, True),
        (2379.0, 2300.0, 0.005, False),
        (1.5, 1.0, 0.5, True),  # on the boundary: within
        (-1.02, -1.0, 0.03, True),  # relative to |published|
        (10.0, 10.0, 0.0, True),  # tolerance 0: exact
        (math.nan, 1.0, 0.5, False),
    ],
)
def test_within_tolerance(model, published, tolerance, expected):
    assert _published.within_tolerance(model, published, tolerance) is expected


def test_within_tolerance_is_element_wise():
    verdict = _published.within_tolerance([1.0, 2.0], [1.0, 1.0], [0.0, 0.5])
    assert verdict.tolist() == [True, False]


def test_parse_inputs_converts_to_si():
    inputs = _published.parse_inputs("d=18 mm; psi=20,40 deg; omega=20 1/s; k=2; E=2.2e6 kgf/cm^2")
    assert inputs["d"] == pytest.approx(0.018, rel=1e-12)
    np.testing.assert_allclose(inputs["psi"], np.radians([20, 40]), rtol=1e-12)
    assert inputs["omega"] == 20.0 and inputs["k"] == 2.0
    assert inputs["E"] == pytest.approx(2.2e6 * 9.80665e4, rel=1e-12)
    assert _published.parse_inputs("") == {}


def test_parse_inputs_refuses_an_entry_without_a_value():
    with pytest.raises(ValueError, match="name=value"):
        _published.parse_inputs("d 18 mm")


@pytest.mark.parametrize("paper", PAPERS)
def test_csv_rows_are_complete(paper):
    table = _published.read_published(paper)
    assert tuple(table.columns) == _published.CSV_COLUMNS
    for row in table.to_dict("records"):
        assert row["source"].startswith(f"Paper {paper}")
        assert row["unit"] and row["tolerance"] >= 0
        assert row["reproduced"] or row["note"], f"{row['quantity']}: say why not"
        _published.parse_inputs(row["inputs"])


def test_compare_needs_a_model_for_every_row():
    with pytest.raises(KeyError, match="E0_theory_13x50"):
        _published.compare("001", {"E0_exp": lambda inputs: 1.0})


def test_compare_picks_the_longest_matching_model():
    table = _published.compare(
        "000",
        {
            "N_u2": lambda inputs: 1.0,
            "N_u2_over_N_u1": lambda inputs: 2.0,
            "z_of_smallest_N_u2": lambda inputs: 3.0,
            "psi_of_smallest_N_u2": lambda inputs: 4.0,
        },
    ).set_index("quantity")
    assert table.at["N_u2_smallest", "model"] == 1.0
    assert table.at["N_u2_over_N_u1_z8_psi40", "model"] == 2.0
    assert tuple(table.reset_index().columns) == _published.COLUMNS
