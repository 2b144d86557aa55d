"""The tensile result: a run file gives back the result it was written from.

The runs are the demo campaigns' (``raw/``): a cyclic test and a single pull to
fracture. Their values are tested against the truth elsewhere; here the result
must come back from its netCDF file unchanged, with the layout of
docs/outputs.md.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pipeline.results import TensileResult, result_from_dataset
from pipeline.runs import process_tensile_run
from pipeline.runsheet import load_run_sheet
from pipeline.store.netcdf import read_dataset, write_atomic

ROOT = Path(__file__).parents[2]


def processed(campaign: str, run_id: str) -> TensileResult:
    folder = ROOT / "raw" / campaign
    if not folder.is_dir():
        pytest.skip(f"demo campaign {folder} is absent")
    sheet = load_run_sheet(folder)
    (run,) = [run for run in sheet.runs if run.id == run_id]
    return process_tensile_run(sheet, run, "0" * 64)


@pytest.fixture(scope="module")
def cyclic() -> TensileResult:
    return processed("stiffness-demo", "T18-A")


@pytest.fixture(scope="module")
def pull() -> TensileResult:
    return processed("pull-demo", "P18-C")


def through_file(result: TensileResult, folder: Path) -> TensileResult:
    return TensileResult.from_dataset(read_dataset(write_atomic(result.to_dataset(),
                                                                folder / "run.nc")))


def assert_same(back: TensileResult, result: TensileResult) -> None:
    assert back.attrs == result.attrs
    for name in ("samples", "fits", "cycles", "channels"):
        pd.testing.assert_frame_equal(getattr(back, name), getattr(result, name))
    np.testing.assert_equal(back.specimen.as_dict(), result.specimen.as_dict())
    np.testing.assert_equal(back.strength.as_dict(), result.strength.as_dict())
    for name in ("single_pull", "fracture", "gauge_length", "gauge_disagreement", "warnings",
                 "ingest_warnings"):
        np.testing.assert_equal(getattr(back, name), getattr(result, name))


@pytest.mark.parametrize("name", ["cyclic", "pull"])
def test_the_run_file_gives_the_result_back(name, request, tmp_path):
    result = request.getfixturevalue(name)
    assert_same(through_file(result, tmp_path), result)


def test_a_cyclic_run_and_a_pull_to_fracture_are_what_their_logs_hold(cyclic, pull):
    # stiffness-demo: three cycles, loading and unloading fitted; pull-demo P18-C: one
    # loading up to a fracture, its time stamp repeated once (raw/pull-demo/campaign.toml)
    assert cyclic.fits.index.tolist() == [(cycle, branch) for cycle in (1, 2, 3)
                                          for branch in ("loading", "unloading")]
    assert (cyclic.single_pull, cyclic.fracture, cyclic.specimen.n_cycles) == (False, None, 2)
    assert pull.single_pull and pull.fracture is not None and pull.specimen.n_cycles == 1
    assert any("repeated time stamp" in text for text in pull.ingest_warnings)
    assert any(text.startswith("fracture at") for text in pull.warnings)


def test_fracture_sources_and_warnings_with_semicolons_come_back(cyclic, tmp_path):
    # None <-> -1 for "no fracture", a figure read on another channel, a warning holding "; "
    changed = replace(cyclic, fracture=1234,
                      strength=replace(cyclic.strength, sources={"at fracture": "Weg 2"}),
                      warnings=("preload not used; set preload_kgf", "second"))
    back = through_file(changed, tmp_path)
    assert back.fracture == 1234
    assert back.strength.sources == {"at fracture": "Weg 2"}
    assert back.warnings == ("preload not used; set preload_kgf", "second")
    assert through_file(cyclic, tmp_path).fracture is None


def test_the_run_file_has_the_documented_layout(cyclic):
    dataset = cyclic.to_dataset()
    # docs/outputs.md, "Tensile run file"
    assert set(dataset.dims) == {"sample", "gauge", "strain_gauge", "cycle", "branch",
                                 "channel"}
    assert dataset["fit_E0"].dims == ("cycle", "branch")
    assert dataset["specimen_E0"].attrs["units"] == "N"
    assert int(dataset["fracture_sample"]) == -1
    assert dataset["sample_branch"].attrs["flag_meanings"].split()[1] == "loading"
    for name in ("fit_E0_ci_low", "fit_E0_ci_high", "specimen_E0_ci_low", "specimen_E0_ci_high"):
        assert dataset[name].attrs["confidence_level"] == 0.95
        assert "95 % interval" in dataset[name].attrs["long_name"]
    # the settings the fit applied, written by the code that applied them
    assert dataset.attrs["confidence_level"] == 0.95
    assert dataset.attrs["fit_window"].startswith("automatic per branch")
    assert dataset.attrs["kind"] == "tensile" and dataset.attrs["run_id"] == "T18-A"


def test_a_fit_window_of_the_run_sheet_is_recorded(tmp_path):
    folder = ROOT / "raw" / "stiffness-demo"
    if not folder.is_dir():
        pytest.skip(f"demo campaign {folder} is absent")
    header, *entries = (folder / "campaign.toml").read_text(encoding="utf-8").split(
        "\n[[runs]]\n")
    (entry,) = [entry for entry in entries if 'id = "T18-A"' in entry]
    target = tmp_path / "campaign"
    target.mkdir()
    (target / "T18-A.csv").write_bytes((folder / "T18-A.csv").read_bytes())
    (target / "campaign.toml").write_text(
        f"{header}\n[[runs]]\n{entry.rstrip()}\n"
        "fit_window = {force_low_kN = 20, force_high_kN = 60}\n", encoding="utf-8")
    sheet = load_run_sheet(target)
    result = process_tensile_run(sheet, sheet.runs[0], "0" * 64)
    assert result.attrs["fit_window"] == "fixed force window 20 to 60 kN for every branch"
    assert result.fits["window_low"].tolist() == pytest.approx([20e3] * len(result.fits))
    assert result.fits["window_high"].tolist() == pytest.approx([60e3] * len(result.fits))


def test_the_kind_names_the_type(cyclic):
    assert isinstance(result_from_dataset(cyclic.to_dataset()), TensileResult)
    with pytest.raises(KeyError):
        result_from_dataset(cyclic.to_dataset().assign_attrs(kind="bending"))
