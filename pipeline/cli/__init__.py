"""The ``chainbench`` command line: it only wires the pipeline's stages.

:data:`app` (built in :mod:`pipeline.cli.commands`) is the whole command tree.
The entry point, :func:`main`, loads only the ``run`` command when that is the
one asked for, so that a re-run with nothing changed answers before any stage
or numerical library is imported (:mod:`pipeline.store.freshness`).
"""

from __future__ import annotations

import gc
import sys


def main() -> None:
    """The ``chainbench`` console script.

    The process ends with the command, so everything it holds is frozen out of
    the garbage collector's final pass (:func:`gc.freeze`): with the numerical
    libraries loaded, that pass alone takes about 0.3 s.
    """
    try:
        _dispatch(sys.argv[1:])
    finally:
        gc.freeze()


def _dispatch(args: list[str]) -> None:
    """Run the command `args` name (typer ends it with :class:`SystemExit`)."""
    if args[:1] == ["run"]:
        from pipeline.cli.run import run_app

        run_app(args=args[1:], prog_name="chainbench run")
        return
    from pipeline.cli.commands import app

    app(args=args)


def __getattr__(name: str):
    """``pipeline.cli.app``, the whole command tree, built on first use."""
    if name == "app":
        from pipeline.cli.commands import app

        return app
    raise AttributeError(f"module 'pipeline.cli' has no attribute {name!r}")
