"""Loading the stages into a command-line process: once, frozen out of the collector."""

import subprocess
import sys

#: Run in a fresh process: load the stages twice, report the collector's state.
LOAD_TWICE = """
import gc, sys
from pipeline.cli._stages import load_stages
before = gc.get_freeze_count()
first = load_stages()
frozen = gc.get_freeze_count()
second = load_stages()
print(before, frozen, gc.get_freeze_count(), gc.isenabled(), first is second,
      first is sys.modules["pipeline.campaign"])
"""


def test_the_stages_are_loaded_once_and_frozen_with_the_collector_left_on():
    done = subprocess.run([sys.executable, "-c", LOAD_TWICE], capture_output=True, text=True,
                          check=True)
    before, frozen, after, enabled, same, loaded = done.stdout.split()
    assert int(before) == 0
    assert int(frozen) > 100_000  # every object the import created
    assert int(after) == int(frozen)  # the second call imports nothing and freezes nothing
    assert (enabled, same, loaded) == ("True", "True", "True")
