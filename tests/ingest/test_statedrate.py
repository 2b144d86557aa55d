"""A sample rate or interval stated in the header makes the time of a file without a time
column: a force plate's or a data logger's export, one row a sample."""

import numpy as np
import pytest

from pipeline.errors import ColumnError
from pipeline.ingest import open_log, read_table
from pipeline.ingest.statedrate import stated_rate

#: Force on the plate [N], one row a sample (our numbers).
FZ = (0.0, 10.0, 250.0, 900.0, 400.0, 20.0, 0.0)
#: The run sheet's columns and units for it.
FZ_IN_N = {"columns": {"force": "Fz"}, "units": {"force": "N"}}


def plate(*preamble: str) -> str:
    """A force plate's export (the layout of a Japanese plate's CSV): settings, a blank line,
    the channels' names and one row a sample, no time."""
    rows = "".join(f"{0.1 * i:.2f},{-0.2 * i:.2f},{fz:.1f}\n" for i, fz in enumerate(FZ))
    return "".join(line + "\n" for line in preamble) + "\nFx,Fy,Fz\n" + rows


@pytest.mark.parametrize("preamble, interval", [
    (("サンプリング周波数,1000",), 1e-3),
    (("Sampling frequency (Hz),500",), 2e-3),
    (("Sample rate,2 kHz",), 5e-4),
    (("Sample interval,4 ms",), 4e-3),
    (("Scan rate,100 S/s",), 1e-2),
    (("Logging interval,1 min",), 60.0),
])
def test_the_time_is_built_from_the_stated_rate(write, preamble, interval):
    path = write("plate.csv", plate(*preamble))
    table, meta = read_table(path, kind="engagement", **FZ_IN_N)
    np.testing.assert_allclose(table["time"], interval * np.arange(len(FZ)), rtol=1e-12)
    np.testing.assert_allclose(table["force"], FZ)
    key, value = preamble[0].split(",")
    assert (f"the file has no time column: time is built from the header's {key!r} = {value} "
            f"(one row each {interval:g} s, 0 at the first row)") in meta.warnings
    assert [(column.role, column.unit) for column in meta.columns][0] == ("time", "s")
    rows, _ = open_log(path, **FZ_IN_N).read(2, 5)  # by row ranges too
    np.testing.assert_allclose(rows["time"], interval * np.arange(2, 5), rtol=1e-12)


@pytest.mark.parametrize("preamble", [
    ("Frequency,5 Hz",),  # a fatigue test's loading frequency
    ("Rate,1000",),  # a crosshead rate, or anything
    ("Scan rate,100",),  # a scan rate with no unit: of what?
    ("Sampling rate,fast",),
    ("Sampling rate,0",),
])
def test_no_time_is_built_from_what_is_no_stated_sample_rate(write, preamble):
    path = write("plate.csv", plate(*preamble))
    with pytest.raises(ColumnError, match="no time column found"):
        read_table(path, kind="engagement", **FZ_IN_N)


def test_rates_that_disagree_build_no_time_and_say_so(write):
    path = write("plate.csv", plate("Sampling rate,1000", "Sample interval,0.002"))
    table, meta = read_table(path, kind="engagement", **FZ_IN_N, strict=False)
    assert "time" not in table
    assert ("the header states its sample rate twice, and not alike ('Sampling rate' = 1000 "
            "and 'Sample interval' = 0.002): no time is built from it") in meta.warnings


def test_a_time_column_is_kept_whatever_rate_the_header_states(write):
    text = "Sampling rate,1000\n\nTime (s),Fz\n0,1\n0.5,2\n1.0,3\n"
    table, meta = read_table(write("log.csv", text), kind="engagement", **FZ_IN_N)
    np.testing.assert_allclose(table["time"], [0.0, 0.5, 1.0])
    assert not any("time is built" in warning for warning in meta.warnings)


@pytest.mark.parametrize("preamble, decimal, interval", [
    ({"Abtastrate": "1,5 kHz"}, ",", 1 / 1500),
    ({"Abtastrate": "1,5 kHz"}, ".", None),  # a thousands separator, or a decimal comma?
    ({"Częstotliwość próbkowania": "100 Hz"}, ".", 0.01),
    ({"Sample rate [Hz]": "1000", "Sample interval (ms)": "1"}, ".", 1e-3),  # agreeing
    ({"dt": "0.01"}, ".", None),  # dt with no unit: of what?
    ({"dt": "10 ms"}, ".", 0.01),
    ({"Abtastrate": "1.000 Hz"}, ",", None),  # a thousands point among decimal commas?
    ({"Data rate": "115200 baud"}, ".", None),  # a serial line's, no sampling
    ({"Measuring rate": "0.5 %/s"}, ".", None),  # a strain rate
    ({"Sample rate": "2 kS/s"}, ".", 5e-4),  # no kilosiemens
    ({"Sampling rate [kS/s]": "2"}, ".", 5e-4),
    ({"Scan rate": "1000 Samples/sec/channel"}, ".", 1e-3),
    ({"Sample rate (per channel)": "1000"}, ".", 1e-3),
    ({"Sample rate (max)": "1000"}, ".", None),  # the device's largest, not the one used
    ({"Samples/sec": "500"}, ".", 2e-3),
    ({"Sample interval": "0.5 msec/sample"}, ".", 5e-4),
    ({"Interval": "0.01 s"}, ".", 0.01),  # a physiology recorder's
    ({"Interval": "10"}, ".", None),  # of what?
    ({"Force Sensor Sample rate (Hz)": "1000"}, ".", 1e-3),  # a real logger's
    ({"Sampling fequency [Hz]": "100"}, ".", 0.01),  # a real tribometer's, as it spells it
    ({"Maximum sampling rate (Hz)": "5000"}, ".", None),  # the device's, not the one used
])
def test_stated_rate(preamble, decimal, interval):
    stated = stated_rate(preamble, decimal)
    if interval is None:
        assert stated is None
    else:
        assert stated.interval == pytest.approx(interval, rel=1e-12)


def test_the_run_sheets_sample_rate_builds_the_time_over_the_headers(write):
    path = write("plate.csv", plate("Sampling rate,1000"))
    table, meta = read_table(path, kind="engagement", sample_rate_hz=250.0, **FZ_IN_N)
    np.testing.assert_allclose(table["time"], 4e-3 * np.arange(len(FZ)), rtol=1e-12)
    assert ("the file has no time column: time is built from the run sheet's sample_rate_hz = "
            "250 (one row each 0.004 s, 0 at the first row); the header states 'Sampling "
            "rate' = 1000, which is not used") in meta.warnings
    rows, _ = open_log(path, sample_rate_hz=250.0, **FZ_IN_N).read(3, 7)
    np.testing.assert_allclose(rows["time"], 4e-3 * np.arange(3, 7), rtol=1e-12)


def test_a_run_sheets_sample_rate_for_a_file_with_a_time_column_is_refused(write):
    text = "Time (s),Fz\n0,1\n0.5,2\n1.0,3\n"
    with pytest.raises(ColumnError, match="sample_rate_hz = 100, but the file has a time column"):
        read_table(write("log.csv", text), kind="engagement", sample_rate_hz=100.0, **FZ_IN_N)


def test_the_missing_time_hint_names_the_run_sheets_rate_and_a_rate_not_read(write):
    path = write("plate.csv", plate("Config,data_rate = 2000.0 Hz"))
    with pytest.raises(ColumnError) as caught:
        read_table(path, kind="engagement", **FZ_IN_N)
    assert "sample_rate_hz = ..." in caught.value.hint
    assert ("the header's 'Config' = 'data_rate = 2000.0 Hz' is not read as a sample rate"
            in caught.value.hint)
