"""The ``chainbench`` command line: it only wires the pipeline's stages.

:data:`app` (built in :mod:`pipeline.cli.commands`) is the whole command tree.
The entry point, :func:`main`, loads only the ``run`` command when that is the
one asked for, so that a re-run with nothing changed answers before any stage
or numerical library is imported (:mod:`pipeline.store.freshness`).
"""

from __future__ import annotations

import sys


def main() -> None:
    """The ``chainbench`` console script."""
    args = sys.argv[1:]
    if args[:1] == ["run"]:
        from pipeline.cli.run import run_app

        run_app(args=args[1:], prog_name="chainbench run")
        return
    from pipeline.cli.commands import app

    app()


def __getattr__(name: str):
    """``pipeline.cli.app``, the whole command tree, built on first use."""
    if name == "app":
        from pipeline.cli.commands import app

        return app
    raise AttributeError(f"module 'pipeline.cli' has no attribute {name!r}")
