"""GW Instek oscilloscope CSV: the settings above the samples give their names and units."""

import numpy as np
import pytest

from pipeline.errors import LayoutError
from pipeline.ingest import open_log, read_table

#: The settings of a real GDS-1072A-U export, as it writes them (each row ends in a comma).
SETTINGS = ("Memory Length,4000,\nTrigger Level,1.67899e+00,\nSource,CH1,\nProbe,10.0X,\n"
            "Vertical Units,V,\nVertical Scale,2.00000e+00,\nVertical Position,-4.00000e+00,\n"
            "Horizontal Units,S,\nHorizontal Scale,1.00000e-04,\n"
            "Horizontal Position,4.0000000e-04,\nHorizontal Mode,Main,\n"
            "Sampling Period,4.00000e-07,\nFirmware,V1.14,\nTime, ,\nMode,{mode},\n"
            "Waveform Data,\n")
TIME = -4e-4 + 4e-7 * np.arange(30)
VALUE = np.where(np.arange(30) % 4, 3.28, 3.36)


def detail_mode() -> str:
    rows = "".join(f"{time:.6e},{value:.2e},\n" for time, value in zip(TIME, VALUE, strict=True))
    return SETTINGS.format(mode="Detail") + rows


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_the_samples_named_and_united_by_the_settings(write, reader):
    found = reader(write("A0000CH1.CSV", detail_mode()), kind="engagement",
                   columns={"force": "CH1"}, units={"force": "kN"})
    table, meta = found if reader is read_table else (found.read(0, 30)[0], found.metadata)
    assert meta.layout == "gwinstek" and meta.first_data_line == 17
    # "S" is the scope's second, not a siemens
    np.testing.assert_allclose(table["time"], TIME, rtol=0, atol=1e-15)
    np.testing.assert_allclose(table["force"], 1e3 * VALUE)
    assert (meta.preamble["Source"], meta.preamble["Sampling Period"]) == ("CH1", "4.00000e-07")
    assert [(c.name, c.unit) for c in meta.columns if c.role] == [("Time", "s"), ("CH1", "kN")]


def test_raw_codes_of_the_fast_mode_are_refused(write):
    text = SETTINGS.format(mode="Fast") + "-45,\n-45,\n-46,\n"
    with pytest.raises(LayoutError, match="Fast mode") as caught:
        read_table(write("DS0000.CSV", text), kind="engagement")
    assert caught.value.row == 16 and "Detail mode" in caught.value.hint


def test_raw_codes_of_an_older_firmware_writing_no_mode_are_refused(write):
    # a real GDS export of firmware V1.14: no Mode setting, one code a row; read as the
    # time in seconds, the channel dropped as empty
    settings = SETTINGS.replace("Time, ,\nMode,{mode},\n", "")
    with pytest.raises(LayoutError, match="one number a row") as caught:
        read_table(write("DS0000.CSV", settings + "-1,\n-1,\n0,\n1,\n2,\n"), kind="engagement")
    assert caught.value.row == 14 and "Detail mode" in caught.value.hint
