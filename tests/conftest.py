"""Fixtures shared across the suite."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
DEMOS = ("stiffness-demo", "engagement-demo", "pull-demo", "wear-demo", "roller-demo",
         "segment-load-demo")

if "PYTEST_XDIST_WORKER" in os.environ:
    # pytest-xdist's workers start with COLUMNS=80 and LINES=24, which would fix the CLI
    # console's width when it is first imported; each test sets the width it needs.
    os.environ.pop("COLUMNS", None)
    os.environ.pop("LINES", None)

#: Third-party exports (never copied into the repository); tests skip without them.
REALDATA = ROOT / ".." / "shared" / "realdata"


@pytest.fixture
def realdata() -> Path:
    """The folder of real exports, or skip."""
    if not REALDATA.is_dir():
        pytest.skip("../shared/realdata is absent")
    return REALDATA.resolve()


@pytest.fixture(scope="session")
def processed_demos(tmp_path_factory) -> Path:
    """The demo campaigns processed once per session into a temporary ``processed/``."""
    from pipeline.campaign import process_campaign

    root = tmp_path_factory.mktemp("processed")
    for name in DEMOS:
        folder = ROOT / "raw" / name
        if not folder.is_dir():
            pytest.skip(f"demo campaign {folder} is absent")
        result = process_campaign(folder, root / name)
        assert result.ok, ([failure.message for failure in result.failures], result.report_error)
    return root


def pytest_collection_modifyitems(config, items):
    """Skip the tests marked ``posix_only`` on Windows."""
    if sys.platform != "win32":
        return
    skip = pytest.mark.skip(reason="needs a POSIX system")
    for item in items:
        if item.get_closest_marker("posix_only"):
            item.add_marker(skip)


@pytest.fixture(scope="session")
def simulated(tmp_path_factory):
    """``simulated(kind, *options)``: the folder of a virtual-bench campaign written by
    ``chainbench simulate KIND --out FOLDER *options``, once per session; copy it before
    changing it."""
    from typer.testing import CliRunner

    from pipeline.cli import app

    made: dict[tuple[str, ...], Path] = {}

    def make(kind: str, *options: str) -> Path:
        if (kind, *options) not in made:
            folder = tmp_path_factory.mktemp(kind) / "campaign"
            result = CliRunner().invoke(app, ["simulate", kind, "--out", str(folder), *options])
            assert result.exit_code == 0, result.output
            made[(kind, *options)] = folder
        return made[(kind, *options)]

    return make
