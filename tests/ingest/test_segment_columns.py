"""Segment-load logs through the readers: the chain force and the forces on the two tooth
segments F_K1, F_K2 and the side force F_P, recognised by name and converted to SI."""

from __future__ import annotations

import numpy as np
import pytest

from pipeline.errors import ColumnError, UnitError
from pipeline.ingest import parse_table

ROLES = ["time", "force", "segment_force_1", "segment_force_2", "side_force"]


def test_plain_english_names_in_si():
    text = (b"time [s],chain force [kN],segment force 1 [kN],segment force 2 [kN],"
            b"side force [kN]\n0,0,0,0,0\n0.005,100,32,31.5,40\n0.01,100,32.5,31,40.5\n")
    table, meta = parse_table(text, kind="segment-load", name="s.csv")
    assert list(table.columns) == ROLES
    np.testing.assert_allclose(table["segment_force_1"], [0, 32e3, 32.5e3])  # kN -> N
    np.testing.assert_allclose(table["segment_force_2"], [0, 31.5e3, 31e3])
    np.testing.assert_allclose(table["side_force"], [0, 40e3, 40.5e3])
    roles = {column.name: (column.role, column.si_unit) for column in meta.columns}
    assert roles["segment force 2"] == ("segment_force_2", "N")
    assert roles["side force"] == ("side_force", "N")


def test_the_rigs_short_names_f_k1_f_k2_f_p():
    text = b"Time [s],Force [N],F_K1 [N],F_K2 [N],F_P [N]\n0,0,0,0,0\n1,1000,320,318,400\n"
    table, _ = parse_table(text, kind="segment-load", name="s.csv")
    assert list(table.columns) == ROLES
    np.testing.assert_allclose(table.iloc[1], [1, 1000, 320, 318, 400])


def test_german_names_in_a_european_file():
    text = ("Zeit [ms];Kettenkraft [kN];Segmentkraft 1 [kN];Segmentkraft 2 [kN];"
            "Seitenkraft [kN]\n0;0;0;0;0\n5;100;32,5;31,5;40\n").encode("latin-1")
    table, _ = parse_table(text, kind="segment-load", name="s.csv")
    assert list(table.columns) == ROLES
    np.testing.assert_allclose(table["time"], [0, 0.005])  # ms -> s
    np.testing.assert_allclose(table["segment_force_1"], [0, 32.5e3])
    np.testing.assert_allclose(table["side_force"], [0, 40e3])


def test_polish_names_without_a_side_force():
    text = ("Czas [s];Siła w łańcuchu [kN];Siła segmentu 1 [kN];Siła segmentu 2 [kN]\n"
            "0;0;0;0\n0,005;100;32;31,5\n").encode("cp1250")
    table, _ = parse_table(text, kind="segment-load", name="s.csv")
    assert list(table.columns) == ROLES[:4]
    np.testing.assert_allclose(table["segment_force_2"], [0, 31.5e3])


def test_run_sheet_names_the_segment_channels():
    text = b"t,F,A,B,C\n0,0,0,0,0\n1,100,32,31,40\n"
    table, _ = parse_table(text, kind="segment-load", name="s.csv",
                           columns={"time": "t", "force": "F", "segment_force_1": "A",
                                    "segment_force_2": "B", "side_force": "C"},
                           units={"time": "s", "force": "kN", "segment_force_1": "kN",
                                  "segment_force_2": "kN", "side_force": "kN"})
    np.testing.assert_allclose(table.iloc[1], [1, 100e3, 32e3, 31e3, 40e3])


@pytest.mark.parametrize("header, error, words", [
    (b"time [s],chain force [kN],segment force 1 [kN],side force [kN]", ColumnError,
     "no segment_force_2 column"),
    (b"time [s],chain force [kN],segment force 2 [kN]", ColumnError,
     "no segment_force_1 column"),
    (b"time [s],chain force [kN],segment force 1 [mm],segment force 2 [kN]", UnitError,
     r"unit .mm. is not a unit of segment_force_1 \(N\)"),
])
def test_a_log_without_its_segment_channels_or_with_a_wrong_unit_is_refused(
        header, error, words):
    width = header.count(b",") + 1
    rows = b"".join(b",".join([str(i).encode()] * width) + b"\n" for i in range(3))
    with pytest.raises(error, match=words):
        parse_table(header + b"\n" + rows, kind="segment-load", name="s.csv")
