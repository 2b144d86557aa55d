"""netCDF store: round trip, provenance attributes, atomic writes."""

from __future__ import annotations

import json

import numpy as np
import pytest
import xarray as xr

from pipeline import __version__
from pipeline.store.netcdf import (
    provenance_attrs,
    read_attrs,
    read_dataset,
    write_atomic,
    write_text_atomic,
)


def sample() -> xr.Dataset:
    dataset = xr.Dataset(
        {"E0": ("chain", np.array([1.1e7, 2.2e7]), {"units": "N", "long_name": "stiffness"})},
        coords={"chain": ["c13", "c18"]},
    )
    dataset.attrs.update(
        provenance_attrs(
            title="t", source="s", run_sheet_sha256="ab", raw_file="T.csv", raw_sha256="cd",
            run_entry={"id": "T1", "columns": {"gauges": ["g1", "g2"]}},
        )
    )
    return dataset


def test_round_trip_keeps_values_and_attrs(tmp_path):
    path = write_atomic(sample(), tmp_path / "out" / "run.nc")
    back = read_dataset(path)
    xr.testing.assert_identical(back, sample().assign_attrs(back.attrs))
    for key in ("Conventions", "title", "history", "source", "chainbench_version", "raw_file",
                "raw_sha256", "run_sheet_sha256", "created", "run_entry"):
        assert key in back.attrs
    assert back.attrs["Conventions"] == "CF-1.10"
    assert back.attrs["chainbench_version"] == __version__
    assert json.loads(back.attrs["run_entry"])["columns"]["gauges"] == ["g1", "g2"]
    assert back["E0"].attrs["units"] == "N"


def test_read_attrs_gives_the_global_attributes_alone(tmp_path):
    path = write_atomic(sample().assign_attrs(signal_decimation=3), tmp_path / "run.nc")
    attrs = read_attrs(path)
    assert attrs["title"] == "t" and attrs["raw_file"] == "T.csv"
    assert attrs["signal_decimation"] == 3
    assert set(attrs) == set(read_dataset(path).attrs)


def test_failed_write_leaves_no_file(tmp_path, monkeypatch):
    def boom(*args, **kwargs):
        raise RuntimeError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", boom)
    with pytest.raises(RuntimeError):
        write_atomic(sample(), tmp_path / "run.nc")
    assert list(tmp_path.iterdir()) == []


def test_text_write_replaces_whole_file(tmp_path):
    path = tmp_path / "r.csv"
    write_text_atomic("old,longer\n", path)
    write_text_atomic("new\n", path)
    assert path.read_text() == "new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["r.csv"]


def test_outputs_are_readable_by_others(tmp_path):
    netcdf = write_atomic(sample(), tmp_path / "run.nc")
    text = write_text_atomic("a\n", tmp_path / "report.html")
    assert netcdf.stat().st_mode & 0o777 == 0o644
    assert text.stat().st_mode & 0o777 == 0o644
