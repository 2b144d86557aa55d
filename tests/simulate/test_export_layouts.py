"""The log writer: each layout reads back (with plain pandas) to the same SI table."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.simulate.export import format_numbers, write_table
from pipeline.simulate.tensile import TensileTruth, simulate_tensile
from pipeline.units import to_si


@pytest.fixture(scope="module")
def log() -> pd.DataFrame:
    return simulate_tensile(TensileTruth.for_chain("18x64", sample_rate=1.0), seed=2)


def assert_same(read: pd.DataFrame, log: pd.DataFrame, units: list[str]) -> None:
    """Columns of `read` (in `units`) equal the SI `log` to the written precision."""
    assert len(read) == len(log)
    for column, unit, name in zip(read.columns, units, ["time", "force", "gauge_1", "gauge_2"],
                                  strict=True):
        si = to_si(read[column].to_numpy(dtype=float), unit)
        scale = np.max(np.abs(log[name]))
        np.testing.assert_allclose(si, log[name], rtol=0, atol=1e-8 * scale, err_msg=column)


@pytest.mark.parametrize(("force_unit", "length_unit"),
                         [("kN", "mm"), ("N", "um"), ("lbf", "in"), ("tf", "m")])
def test_plain_csv(tmp_path, log, force_unit, length_unit):
    path = write_table(log, tmp_path / "run.csv", force_unit=force_unit, length_unit=length_unit)
    first = path.read_text(encoding="utf-8").splitlines()[0]
    assert first == (f"time [s],force [{force_unit}],gauge1 [{length_unit}],"
                     f"gauge2 [{length_unit}]")
    assert_same(pd.read_csv(path), log, ["s", force_unit, length_unit, length_unit])


@pytest.mark.parametrize(
    ("language", "encoding", "header"),
    [
        ("pl", None, "Czas [s];Siła [kgf];Wydłużenie 1 [mm];Wydłużenie 2 [mm]"),
        ("de", None, "Zeit [s];Kraft [kgf];Weg 1 [mm];Weg 2 [mm]"),
        ("pl", "utf-8-sig", "Czas [s];Siła [kgf];Wydłużenie 1 [mm];Wydłużenie 2 [mm]"),
    ],
)
def test_european_csv(tmp_path, log, language, encoding, header):
    path = write_table(log, tmp_path / "run.csv", layout="european", language=language,
                       encoding=encoding, force_unit="kgf")
    raw = path.read_bytes()
    expected = encoding or {"pl": "cp1250", "de": "latin-1"}[language]
    assert raw.startswith(b"\xef\xbb\xbf") == (encoding == "utf-8-sig")
    assert raw.decode(expected).splitlines()[0].lstrip("\ufeff") == header
    assert b"." not in raw.split(b"\n", 1)[1]  # decimal comma throughout
    read = pd.read_csv(path, sep=";", decimal=",", encoding=expected)
    assert_same(read, log, ["s", "kgf", "mm", "mm"])


def test_machine_export(tmp_path, log):
    preamble = [("Text Inputs", 'Specimen label,"T18-1"'), ("General", "Machine,bench")]
    path = write_table(log, tmp_path / "run.csv", layout="machine", force_unit="kN",
                       preamble=preamble)
    lines = path.read_bytes().split(b"\r\n")
    assert lines[:5] == [b'Text Inputs : Specimen label,"T18-1"', b"General : Machine,bench", b"",
                         b"Time,Extension 1,Extension 2,Load", b"(sec),(mm),(mm),(kN)"]
    read = pd.read_csv(path, skiprows=[0, 1, 2, 4])
    assert_same(read[["Time", "Load", "Extension 1", "Extension 2"]], log,
                ["s", "kN", "mm", "mm"])


def test_xlsx(tmp_path, log):
    path = write_table(log, tmp_path / "run.xlsx", layout="xlsx", force_unit="daN")
    read = pd.read_excel(path, sheet_name=0, engine="openpyxl")
    assert list(read.columns) == ["time [s]", "force [daN]", "gauge1 [mm]", "gauge2 [mm]"]
    assert_same(read, log, ["s", "daN", "mm", "mm"])


def test_single_gauge_machine_export_is_named_extension(tmp_path, log):
    path = write_table(log.drop(columns="gauge_2"), tmp_path / "one.csv", layout="machine")
    assert path.read_text(encoding="ascii").splitlines()[0] == "Time,Extension,Load"


def test_numbers_are_fixed_point_and_trimmed():
    assert format_numbers(np.array([0.00001, 2.5, -40.0])).tolist() == ["0.00001", "2.5", "-40"]
    assert format_numbers(np.array([1.25, np.nan]), ",").tolist() == ["1,25", ""]


@pytest.mark.parametrize(
    ("settings", "words"),
    [({"layout": "tdms"}, "layout"), ({"force_unit": "kp"}, "force_unit"),
     ({"length_unit": "ft"}, "length_unit"), ({"layout": "european", "language": "fr"},
                                               "language")],
)
def test_bad_settings_raise(tmp_path, log, settings, words):
    with pytest.raises(ValueError, match=words):
        write_table(log, tmp_path / "x.csv", **settings)
