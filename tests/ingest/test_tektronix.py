"""Tektronix oscilloscope CSV: settings beside the samples, the units from the settings."""

import numpy as np
import pytest

from pipeline.errors import ColumnError
from pipeline.ingest import open_log, read_table

SETTINGS = [
    ("Record Length", "2.500000e+03"), ("Sample Interval", "2.000000e-06"),
    ("Trigger Point", "2.400000000000e+02"), ("", ""), ("", ""), ("", ""),
    ("Source", "CH2"), ("Vertical Units", "V"), ("Vertical Scale", "5.000000e-01"),
    ("Vertical Offset", "-1.200000e-01"), ("Horizontal Units", "s"),
    ("Horizontal Scale", "5.000000e-04"), ("Pt Fmt", "Y"), ("Yzero", "0.000000e+00"),
    ("Probe Atten", "1.000000e+01"), ("Model Number", "TBS1022"),
]
TIME = -0.00048 + 2e-6 * np.arange(40)
VALUE = np.where(np.arange(40) % 3, -0.86, -0.88)


def tbs1022() -> str:
    """A Tektronix TBS1022 export as a lab's: settings in the first two fields of the first
    rows, each sample in the fourth and fifth, every row ending in a delimiter."""
    rows = []
    for index, (time, value) in enumerate(zip(TIME, VALUE, strict=True)):
        key, setting = SETTINGS[index] if index < len(SETTINGS) else ("", "")
        rows.append(f"{key},{setting},,{time:17.12f},{value:10.5f},")
    return "\r\n".join(rows) + "\r\n"


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_the_samples_named_and_united_by_the_settings(write, reader):
    found = reader(write("TEK0000.CSV", tbs1022()), kind="engagement",
                   columns={"force": "CH2"}, units={"force": "kN"})
    table, meta = found if reader is read_table else (found.read(0, 40)[0], found.metadata)
    assert meta.layout == "tektronix"
    np.testing.assert_allclose(table["time"], TIME, rtol=0, atol=1e-15)
    np.testing.assert_allclose(table["force"], 1e3 * VALUE)
    assert (meta.preamble["Source"], meta.preamble["Horizontal Units"]) == ("CH2", "s")
    assert [(c.name, c.unit) for c in meta.columns if c.role] == [("Time", "s"), ("CH2", "kN")]


def test_volts_are_no_force_until_the_run_sheet_says_so(write):
    with pytest.raises(Exception, match="no force column"):
        read_table(write("TEK0000.CSV", tbs1022()), kind="engagement")


def test_a_newer_scopes_time_without_unit_takes_the_settings(write):
    # a real Tektronix MSO3012 export: settings above TIME,CH1,CH2, no units row
    text = ("Model,MSO3012\nFirmware Version,2.40\n\nHorizontal Units,s,\nSample Interval,"
            "4e-08,\nVertical Units,V,\nLabel,,\nTIME,CH1,CH2\n-2.0000e-04,-0.0019,0.0061\n"
            "-1.9996e-04,-0.0018,0.0060\n")
    table, meta = read_table(write("tek0000.csv", text), kind="engagement",
                             columns={"force": "CH1"}, units={"force": "kN"})
    np.testing.assert_allclose(table["time"], [-2.0e-4, -1.9996e-4])
    assert "column 'TIME': unit 's' from the preamble's Horizontal Units" in meta.warnings


def test_a_scopes_vertical_units_are_its_channels_and_told_as_no_force(write):
    # a real TBS1052C export: TIME,CH1 under settings that give both units; CH1 was left
    # without one, and the missing force's hint said nothing of volts
    text = ("Model,TBS1052C\n\nHorizontal Units,S\nSample Interval,0.0008\nVertical "
            "Units,V\nLabel,\nTIME,CH1\n-8.000e-01,-1.32\n-7.992e-01,-0.44\n"
            "-7.984e-01,-1\n")
    with pytest.raises(ColumnError) as caught:
        read_table(write("TEK00000.CSV", text), kind="engagement")
    assert "column 'CH1' is in V, a sensor's signal" in caught.value.hint
    _, meta = read_table(write("TEK00000.CSV", text), kind="engagement",
                         columns={"force": "CH1"}, units={"force": "kN"})
    assert "column 'CH1': unit 'V' from the preamble's Vertical Units" in meta.warnings


def test_a_rohde_schwarz_scopes_singular_horizontal_unit_gives_the_time_its_unit(write):
    # a real RTH1004 (Scope Rider) export: "Horizontal Unit", settings per channel above
    text = ("Model,RTH1004\nSerialNumber,104154\n\nHorizontal Unit,s,\nSample Interval,"
            "1.6e-05,\nProbe Setting,'10:1','10:1'\nVertical Unit,V,V\nVertical Scale,2,2\n"
            "History Index,0,0\n,,\nTIME,CH1,CH2\n"
            + "".join(f"{-0.2 + 1.6e-5 * i:.6f},-0.0862745,0.15686\n" for i in range(8)))
    table, meta = read_table(write("Waveform.csv", text), kind="engagement",
                             columns={"force": "CH1"}, units={"force": "kN"})
    np.testing.assert_allclose(table["time"][:2], [-0.2, -0.199984])
    assert "column 'TIME': unit 's' from the preamble's Horizontal Unit" in meta.warnings


def test_a_unit_in_the_header_wins_over_the_settings(write):
    # a real Siglent export's settings say "us" over a units row that says Second
    text = ("Record Length,Analog:200\nHorizontal Units,us\nSource,CH1\nSecond,Volt\n"
            "-0.0002,0.04\n-0.000198,0.04\n")
    table, meta = read_table(write("SDS00001.csv", text), kind="engagement",
                             columns={"force": "CH1"}, units={"force": "kN"})
    np.testing.assert_allclose(table["time"], [-2e-4, -1.98e-4])
    assert not any("Horizontal Units" in warning for warning in meta.warnings)


def test_an_older_scopes_settings_with_their_units_give_the_time_its_unit(write):
    # a real TDS export (a Kolsky bar record): each setting's unit in the third field, no
    # Horizontal Units
    settings = [('"Record Length"', "50000", '"Points"'), ('"Sample Interval"', "8e-9", "s"),
                ('"Trigger Point"', "10000", '"Samples"'), ('""', "", "")]
    rows = [f"{key},{value},{unit},{time:.8e},{value_v:.8e}" for (key, value, unit), time, value_v
            in zip(settings + [("", "", "")] * 36, TIME, VALUE, strict=True)]
    table, meta = read_table(write("180303_Ch1.csv", "\n".join(rows) + "\n"),
                             kind="engagement", columns={"force": "column 5"},
                             units={"force": "kN"})
    assert meta.layout == "tektronix"
    assert [(c.name, c.unit) for c in meta.columns if c.role] == [("Time", "s"),
                                                                  ("column 5", "kN")]
    np.testing.assert_allclose(table["time"], TIME, rtol=1e-8)
    assert meta.preamble["Sample Interval"] == "8e-9 s"
