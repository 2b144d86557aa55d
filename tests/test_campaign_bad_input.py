"""Bad input at campaign level: every broken file fails alone, clearly, and raw/ stays as it was.

Each file of the broken-file corpus (``tests/data/bad``) becomes a run of one
campaign beside a good run: the good run is processed, each broken run fails
with a typed chainbench error that names its file (never an internal error),
the exit code is non-zero, and the campaign folder is byte-for-byte unchanged.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.errors import ChainbenchError

BAD = Path(__file__).parent / "data" / "bad"
runner = CliRunner()


def run_entry(run_id: str, file: str) -> str:
    return (f'\n[[runs]]\nid = "{run_id}"\nkind = "tensile"\nfile = "{file}"\n'
            f'chain = "c18x64"\ngauge_length_mm = 900\ncycles = 3\n')


@pytest.fixture(scope="module")
def campaign(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("raw") / "bad-input"
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(folder), "--specimens", "1",
                                 "--campaign", "bad-input"])
    assert result.exit_code == 0, result.output
    sheet = folder / "campaign.toml"
    text = sheet.read_text()
    for number, path in enumerate(sorted(BAD.iterdir())):
        shutil.copy(path, folder / path.name)
        text += run_entry(f"bad-{number}", path.name)
    sheet.write_text(text)
    return folder


def snapshot(folder: Path) -> dict[str, bytes]:
    return {path.name: path.read_bytes() for path in sorted(folder.iterdir())}


def test_each_broken_file_fails_alone_with_a_typed_error(campaign, tmp_path):
    before = snapshot(campaign)
    result = process_campaign(campaign, tmp_path)
    assert snapshot(campaign) == before
    assert list(result.run_files) == ["T18-1"]  # the good run
    files = {f"bad-{n}": path.name for n, path in enumerate(sorted(BAD.iterdir()))}
    failed = {failure.run_id: failure for failure in result.failures}
    assert set(failed) == set(files)  # warnings-only defects still fail later: too few cycles
    for run_id, failure in failed.items():
        assert isinstance(failure.error, ChainbenchError), failure.message
        assert files[run_id] in failure.message or "cycle" in failure.message, failure.message
        assert failure.error.hint or failure.error.row is not None, failure.message


def test_cli_exits_non_zero_and_lists_every_failure(campaign, tmp_path):
    result = runner.invoke(app, ["run", str(campaign), "--output", str(tmp_path)])
    assert result.exit_code == 1
    for number in range(len(list(BAD.iterdir()))):
        assert f"bad-{number}:" in result.output
    assert "Traceback" not in result.output
