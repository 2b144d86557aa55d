"""chainbench: test-bench data analysis for chain-drive laboratories."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("chainbench")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"


def __getattr__(name: str):
    """``pipeline.run_campaign``, imported on first use (it pulls in every stage)."""
    if name == "run_campaign":
        from pipeline.campaign import run_campaign

        return run_campaign
    raise AttributeError(f"module 'pipeline' has no attribute {name!r}")
