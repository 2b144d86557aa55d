"""Rendering report figures: deterministic SVG, and a user's matplotlib session untouched."""

from __future__ import annotations

import subprocess
import sys


def test_rendering_leaves_the_users_matplotlib_session_alone():
    """The report neither chooses a backend nor loads pyplot (a notebook keeps its own)."""
    code = (
        "import sys, matplotlib; matplotlib.use('svg')\n"
        "from matplotlib.figure import Figure\n"
        "from pipeline.report import build, render\n"
        "figure = Figure(); figure.subplots().plot([0, 1], [1, 2])\n"
        "assert render.svg(figure).startswith('<svg')\n"
        "print(matplotlib.get_backend(), 'matplotlib.pyplot' in sys.modules)\n"
    )
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           check=True)
    assert found.stdout.split() == ["svg", "False"]
