"""chainbench: test-bench data analysis for chain-drive laboratories."""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("chainbench")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"
