"""Real third-party exports (../shared/realdata, never copied here): roles and units."""

import numpy as np
import pandas as pd
import pytest

from pipeline.errors import UnitError
from pipeline.ingest import read_table
from pipeline.units import STANDARD_GRAVITY

pytestmark = pytest.mark.realdata

BLUEHILL = "yadbor__bluer__Specimen_RawData_6.csv"
CCFATIGUE = "EPFL-ENAC__CCFatiguePlatform__TST_2021-10_FA_22.csv"
MTS1 = "ramonbotella__MTS_data_process_Python__sampledatafiletype1.dat"
MTS2 = "ramonbotella__MTS_data_process_Python__sampledatafiletype2.dat"


def roles(meta):
    return {column.name: (column.role, column.unit, column.si_unit) for column in meta.columns}


def test_bluehill(realdata):
    table, meta = read_table(realdata / BLUEHILL)
    assert meta.layout == "machine_export" and len(table) == 18_011
    assert roles(meta) == {
        "Time": ("time", "sec", "s"), "Extension": ("gauge_1", "mm", "m"),
        "Load": ("force", "N", "N"), "Segment ID": (None, None, None),
        "Total Cycle Count": ("cycle_count", None, "1"),
    }
    # first data row: 0.00000,-2.04726,-4.31900 ; last: 360.06000,-2.04555,0.28068
    np.testing.assert_allclose(table.iloc[0][["time", "gauge_1", "force"]],
                               [0.0, -2.04726e-3, -4.319], rtol=1e-12)
    np.testing.assert_allclose(table.iloc[-1][["time", "gauge_1", "force"]],
                               [360.06, -2.04555e-3, 0.28068], rtol=1e-12)
    assert set(np.unique(table["cycle_count"])) == {0.0, 1.0, 2.0}
    assert table["force"].min() < 0  # compression negative
    assert meta.time_monotonic and meta.warnings == []


def test_ccfatigue_needs_units_from_the_run_sheet(realdata):
    with pytest.raises(UnitError) as caught:
        read_table(realdata / CCFATIGUE)
    assert caught.value.column == "Machine_Load" and "run sheet" in caught.value.hint
    table, meta = read_table(realdata / CCFATIGUE, units={"force": "kN", "gauges": "mm"})
    assert meta.encoding == "utf-8-sig" and len(table) == 11_179
    assert list(table.columns) == ["force", "gauge_1", "cycle_count"]
    # first data row: 1,6.136780273,3.102225251
    np.testing.assert_allclose(table.iloc[0], [6136.780273, 3.102225251e-3, 1.0], rtol=1e-12)
    assert table["cycle_count"].nunique() == 373
    assert any("13 empty column(s) dropped" in warning for warning in meta.warnings)


def test_mts_spanish(realdata):
    table, meta = read_table(realdata / MTS1)
    assert (meta.layout, meta.encoding, meta.delimiter, meta.decimal) == (
        "mts", "latin-1", "\t", ",")
    assert roles(meta) == {
        "Tiempo": ("time", "Sec", "s"), "Channel 1 Displacement": ("gauge_1", "mm", "m"),
        "Channel 1 Force": ("force", "kgf", "N"),
        "Channel 1 Recuento": ("cycle_count", "cycles", "1"),
    }
    assert len(table) == 510 and meta.preamble["blocks"] == "10"
    # first point: 10,016357  -0,095496617  -4,1995568  99
    np.testing.assert_allclose(
        table.iloc[0], [10.016357, -4.1995568 * STANDARD_GRAVITY, -0.095496617e-3, 99.0],
        rtol=1e-12)
    assert meta.time_gaps == 9


def test_mts_english(realdata):
    table, meta = read_table(realdata / MTS2)
    assert meta.layout == "mts"
    assert roles(meta)["Axial Fuerza"] == ("force", "kgf", "N")
    assert roles(meta)["Axial Count"] == ("cycle_count", "segments", "1")
    # last point: 100,10043  -0,36483389  -9,5635424  1999 (no line end after it)
    assert len(table) == 510
    np.testing.assert_allclose(
        table.iloc[-1], [100.10043, -9.5635424 * STANDARD_GRAVITY, -0.36483389e-3, 1999.0],
        rtol=1e-12)


def test_last_line_without_line_end_is_kept_and_a_cut_one_dropped(realdata, tmp_path):
    options = {CCFATIGUE: {"units": {"force": "kN", "gauges": "mm"}}}
    for path in sorted(path for path in realdata.iterdir() if path.suffix in (".csv", ".dat")):
        whole, _ = read_table(path, **options.get(path.name, {}))
        body = path.read_bytes().rstrip(b"\r\n")
        last_line = body.rfind(b"\n") + 1
        for end, rows in ((len(body), len(whole)), (last_line + 1, len(whole) - 1)):
            copy = tmp_path / f"copy{path.suffix}"
            copy.write_bytes(body[:end])
            table, meta = read_table(copy, **options.get(path.name, {}))
            pd.testing.assert_frame_equal(table, whole.iloc[:rows], obj=path.name)
            cut = [warning for warning in meta.warnings if "is truncated" in warning]
            assert len(cut) == len(whole) - rows, (path.name, meta.warnings)
