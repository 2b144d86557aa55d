"""The campaign lock: exclusive across processes, released when its holder dies."""

from __future__ import annotations

import os
import subprocess
import sys
import time

import pytest

from pipeline.store.lock import CampaignBusyError, campaign_lock, remove_stale_temporaries

HOLD = """
import sys, time
from pathlib import Path
from pipeline.store.lock import campaign_lock
with campaign_lock(Path(sys.argv[1])):
    print("locked", flush=True)
    time.sleep(60)
"""


def hold_in_subprocess(output):
    process = subprocess.Popen([sys.executable, "-c", HOLD, str(output)], stdout=subprocess.PIPE,
                               text=True)
    assert process.stdout.readline().strip() == "locked"
    return process


def test_second_holder_is_refused_with_the_first_ones_pid(tmp_path):
    process = hold_in_subprocess(tmp_path)
    try:
        with pytest.raises(CampaignBusyError, match=f"process {process.pid}"):
            with campaign_lock(tmp_path):
                pass
    finally:
        process.kill()
        process.wait()


def test_lock_is_released_when_the_holder_is_killed(tmp_path):
    process = hold_in_subprocess(tmp_path)
    process.kill()
    process.wait()
    deadline = time.monotonic() + 5
    while True:  # the kernel releases the flock as the process's files close
        try:
            with campaign_lock(tmp_path):
                break
        except CampaignBusyError:
            assert time.monotonic() < deadline
            time.sleep(0.05)


def test_lock_is_reentrant_after_release(tmp_path):
    with campaign_lock(tmp_path):
        pass
    with campaign_lock(tmp_path):
        assert (tmp_path / ".lock").read_text() == str(os.getpid())


def test_stale_temporaries_are_removed_and_results_kept(tmp_path):
    (tmp_path / ".T1.nc.abc123.tmp").write_bytes(b"half")
    (tmp_path / "T1.nc").write_bytes(b"whole")
    removed = remove_stale_temporaries(tmp_path)
    assert [path.name for path in removed] == [".T1.nc.abc123.tmp"]
    assert [path.name for path in tmp_path.iterdir() if path.name != ".lock"] == ["T1.nc"]
