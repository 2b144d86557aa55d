"""The campaign lock: exclusive across processes and within one, released when its holder dies."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
import time

import pytest

from pipeline.store import layout
from pipeline.store.lock import (
    PID_NAME,
    CampaignBusyError,
    campaign_lock,
    remove_stale_temporaries,
)

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


def kill(process):
    process.kill()  # SIGKILL on POSIX, TerminateProcess on Windows: no clean-up runs
    process.wait()
    process.stdout.close()


def acquire_within(output, seconds: float = 5.0) -> None:
    """Take and release the lock, retrying while the OS has not yet released a dead holder's."""
    deadline = time.monotonic() + seconds
    while True:
        try:
            with campaign_lock(output):
                return
        except CampaignBusyError:
            assert time.monotonic() < deadline
            time.sleep(0.05)


def test_second_holder_is_refused_with_the_first_ones_pid(tmp_path):
    process = hold_in_subprocess(tmp_path)
    try:
        with pytest.raises(CampaignBusyError, match=f"process {process.pid}\\)") as caught:
            with campaign_lock(tmp_path):
                pytest.fail("entered a lock another process holds")
        assert caught.value.hint == "wait for it to finish, then run again"
    finally:
        kill(process)


def test_refusal_without_a_known_holder_names_no_process(tmp_path):
    process = hold_in_subprocess(tmp_path)
    try:
        (tmp_path / PID_NAME).unlink()
        with pytest.raises(CampaignBusyError, match="another chainbench run is writing") as caught:
            with campaign_lock(tmp_path):
                pass
        assert "process" not in caught.value.message
    finally:
        kill(process)


def test_lock_is_released_when_the_holder_is_killed(tmp_path):
    process = hold_in_subprocess(tmp_path)
    kill(process)
    acquire_within(tmp_path)  # the OS releases the lock as the process's files close


def test_killed_holders_pid_file_does_not_block_and_is_replaced(tmp_path):
    process = hold_in_subprocess(tmp_path)
    kill(process)
    assert (tmp_path / PID_NAME).read_text() == str(process.pid)  # left behind by the kill
    acquire_within(tmp_path)
    with campaign_lock(tmp_path):
        assert (tmp_path / PID_NAME).read_text() == str(os.getpid())


def test_second_lock_in_the_same_process_is_refused(tmp_path):
    with campaign_lock(tmp_path):
        with pytest.raises(CampaignBusyError, match=f"process {os.getpid()}\\)"):
            with campaign_lock(tmp_path):
                pytest.fail("the lock is reentrant")
        refused = []

        def other_thread():
            try:
                with campaign_lock(tmp_path):
                    pass
            except CampaignBusyError as error:
                refused.append(error)

        thread = threading.Thread(target=other_thread)
        thread.start()
        thread.join()
        assert len(refused) == 1
    with campaign_lock(tmp_path):  # neither refusal disturbed the first hold's release
        pass


def test_lock_is_reentrant_after_release(tmp_path):
    with campaign_lock(tmp_path):
        assert (tmp_path / layout.LOCK).exists()
        assert (tmp_path / PID_NAME).read_text() == str(os.getpid())
    assert not (tmp_path / PID_NAME).exists()
    with campaign_lock(tmp_path):
        assert (tmp_path / PID_NAME).read_text() == str(os.getpid())


def test_lock_is_released_when_the_block_raises(tmp_path):
    with pytest.raises(RuntimeError, match="boom"):
        with campaign_lock(tmp_path):
            raise RuntimeError("boom")
    with campaign_lock(tmp_path):
        pass


def test_output_folder_is_created(tmp_path):
    output = tmp_path / "processed" / "c1"
    with campaign_lock(output):
        assert output.is_dir()


def test_stale_temporaries_are_removed_and_results_kept(tmp_path):
    (tmp_path / ".T1.nc.abc123.tmp").write_bytes(b"half")
    (tmp_path / "T1.nc").write_bytes(b"whole")
    removed = remove_stale_temporaries(tmp_path)
    assert [path.name for path in removed] == [".T1.nc.abc123.tmp"]
    assert [path.name for path in tmp_path.iterdir() if path.name != layout.LOCK] == ["T1.nc"]
