"""The standard-library check that a campaign's outputs are current, and the hash cache."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys

import pytest

from pipeline.store import freshness, layout


@pytest.fixture
def project(tmp_path, monkeypatch):
    """A project with one campaign, its outputs and manifest written, and a re-run record."""
    monkeypatch.chdir(tmp_path)
    campaign = tmp_path / "raw" / "c1"
    campaign.mkdir(parents=True)
    (campaign / "campaign.toml").write_text('[campaign]\nid = "c1-id"\n', encoding="utf-8")
    (campaign / "a.csv").write_text("time [s],force [N]\n0,1\n", encoding="utf-8")
    output = tmp_path / "processed" / "c1-id"
    output.mkdir(parents=True)
    (output / "r1.nc").write_bytes(b"run")
    (output / layout.SUMMARY).write_bytes(b"summary")
    (output / layout.MANIFEST).write_text(
        json.dumps({"input_key": "k1", "outputs": [layout.SUMMARY]}), encoding="utf-8")
    freshness.write_rerun(output, campaign / "campaign.toml", [campaign / "a.csv"],
                          "tables\n", {"campaign": "c1-id"}, 0)
    return campaign, output


def test_nothing_changed_gives_back_what_the_run_printed(project):
    campaign, output = project
    for named in (campaign, campaign / "campaign.toml", campaign.relative_to(os.getcwd())):
        rerun = freshness.current_rerun(named)
        assert rerun is not None and rerun.text == "tables\n" and rerun.exit_code == 0
        assert rerun.output == output and rerun.document == {"campaign": "c1-id"}


def touch_later(path):
    stat = os.stat(path)
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000))


@pytest.mark.parametrize("change", [
    "sheet_bytes", "raw_bytes", "raw_touched", "raw_replaced", "raw_deleted", "run_output_deleted",
    "summary_touched", "manifest_key", "record_missing",
])
def test_any_change_sends_the_run_down_the_full_path(project, change):
    campaign, output = project
    raw = campaign / "a.csv"
    if change == "sheet_bytes":
        (campaign / "campaign.toml").write_text('[campaign]\nid = "c1-id"\n\n', encoding="utf-8")
    elif change == "raw_bytes":
        raw.write_text("time [s],force [N]\n0,2\n", encoding="utf-8")
    elif change == "raw_touched":
        touch_later(raw)
    elif change == "raw_replaced":
        copy = campaign / "b.csv"
        copy.write_bytes(raw.read_bytes())
        os.replace(copy, raw)
    elif change == "raw_deleted":
        raw.unlink()
    elif change == "run_output_deleted":
        (output / "r1.nc").unlink()
    elif change == "summary_touched":
        touch_later(output / layout.SUMMARY)
    elif change == "manifest_key":
        (output / layout.MANIFEST).write_text(
            json.dumps({"input_key": "k2", "outputs": [layout.SUMMARY]}), encoding="utf-8")
    elif change == "record_missing":
        freshness.forget_rerun(output)
    assert freshness.current_rerun(campaign) is None


def test_other_code_sends_the_run_down_the_full_path(project, monkeypatch):
    campaign, _ = project
    monkeypatch.setattr(freshness, "code_fingerprint", lambda: "another")
    assert freshness.current_rerun(campaign) is None


def test_the_output_root_names_the_folder(project, tmp_path):
    campaign, output = project
    assert freshness.current_rerun(campaign, tmp_path / "elsewhere") is None
    assert freshness.current_rerun(campaign, output.parent) is not None


def test_an_unreadable_run_sheet_is_left_to_the_full_path(project):
    campaign, _ = project
    (campaign / "campaign.toml").write_text("[campaign\n", encoding="utf-8")
    assert freshness.campaign_output(campaign) is None
    assert freshness.current_rerun(campaign) is None


def test_sha256_file_matches_hashlib_across_blocks(tmp_path):
    data = bytes(range(256)) * 8193  # a little over 2 MiB: three blocks
    path = tmp_path / "log.bin"
    path.write_bytes(data)
    assert freshness.sha256_file(path) == hashlib.sha256(data).hexdigest()


def test_hash_cache_reads_a_file_once_until_it_changes(tmp_path, monkeypatch):
    data = tmp_path / "log.csv"
    data.write_bytes(b"1,2\n" * 1000)
    expected = hashlib.sha256(data.read_bytes()).hexdigest()
    reads = []
    monkeypatch.setattr(freshness, "sha256_file",
                        lambda path: reads.append(path) or hashlib.sha256(
                            path.read_bytes()).hexdigest())
    cache = freshness.HashCache(tmp_path)
    assert cache.sha256(data) == expected and len(reads) == 1
    cache.save()
    again = freshness.HashCache(tmp_path)
    assert again.sha256(data) == expected and len(reads) == 1  # from the saved cache
    touch_later(data)
    assert again.sha256(data) == expected and len(reads) == 2  # touched: read again
    forced = freshness.HashCache(tmp_path, rehash=True)
    assert forced.sha256(data) == expected and len(reads) == 3


def test_the_check_imports_no_numerical_library(project):
    campaign, _ = project
    code = ("import sys; from pipeline.store.freshness import current_rerun; "
            f"assert current_rerun({str(campaign)!r}) is not None; "
            "heavy = {'numpy', 'pandas', 'xarray', 'lmfit', 'matplotlib', 'dask', 'pydantic'}; "
            "print(sorted(heavy & set(sys.modules)))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True)
    assert done.stdout.strip() == "[]"


def test_a_cache_that_cannot_be_written_is_left_behind_without_a_trace(tmp_path, monkeypatch):
    data = tmp_path / "log.csv"
    data.write_bytes(b"1,2\n")
    cache = freshness.HashCache(tmp_path)
    cache.sha256(data)

    def full(*args):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", full)
    cache.save()  # no error: the next run reads the file again
    assert not (tmp_path / layout.HASHES).exists() and not list(tmp_path.glob(".*.tmp"))
