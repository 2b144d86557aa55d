"""The same work here or as dask tasks (:mod:`pipeline.tasks`)."""

from __future__ import annotations

import threading
import time

import pytest

from pipeline.tasks import Mapped, map_tasks, submit

distributed = pytest.importorskip("distributed")


def _scaled(value: int, *, factor: int, offset: int = 0) -> int:
    return value * factor + offset


def _inverse(value: int) -> float:
    return 1 / value


#: Holds the tasks of the queueing test until the scheduler's state is read.
_RELEASE = threading.Event()


def _held(value: int, **shared: int) -> int:
    _RELEASE.wait(timeout=30)
    return value + sum(shared.values())


def _scheduler_counts(dask_scheduler) -> tuple[int, int]:
    """Tasks queued on the scheduler, and tasks it has handed to workers."""
    processing = sum(len(worker.processing) for worker in dask_scheduler.workers.values())
    return len(dask_scheduler.queued), processing


def test_here_every_item_in_order_with_the_shared_arguments():
    assert Mapped(_scaled, [3, 1, 2], factor=10, offset=1).results() == [31, 11, 21]
    assert map_tasks(abs, [-2, 5]) == [2, 5]
    assert Mapped(_scaled, [], factor=2).results() == []


def test_here_nothing_is_computed_until_asked():
    calls = []
    mapped = Mapped(calls.append, [1, 2])
    assert calls == []
    mapped.results()
    assert calls == [1, 2]


def test_on_a_cluster_the_same_results_computed_by_the_workers():
    with distributed.Client(processes=False, n_workers=2, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        mapped = Mapped(_scaled, list(range(20)), client, factor=3, offset=2)
        assert mapped.results() == [3 * value + 2 for value in range(20)]
        executed = sum(client.run(lambda dask_worker: dask_worker.state.executed_count
                                  ).values())
        assert executed == 20


def test_on_a_cluster_the_first_error_is_raised():
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        with pytest.raises(ZeroDivisionError):
            Mapped(_inverse, [1, 0], client).results()


def test_on_a_cluster_the_tasks_wait_on_the_scheduler_for_a_free_worker():
    # Five shared values scattered one by one would be five dependencies: the scheduler
    # would then hand every task to a worker at once, and one worker could sit idle at
    # the end while the other works through its share.
    shared = {name: index for index, name in enumerate("abcde")}
    _RELEASE.clear()
    with distributed.Client(processes=False, n_workers=2, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        try:
            mapped = Mapped(_held, list(range(20)), client, **shared)
            deadline = time.monotonic() + 10
            while sum(counts := client.run_on_scheduler(_scheduler_counts)) < 20:
                assert time.monotonic() < deadline, counts
                time.sleep(0.01)
            queued, processing = counts
            assert processing <= 4 and queued >= 16  # at most two per one-thread worker
        finally:
            _RELEASE.set()
        assert mapped.results() == [value + 10 for value in range(20)]


def _difference(first: int, second: int, *, scale: int = 1) -> int:
    return (first - second) * scale


def _scheduler_calls(dask_scheduler) -> list[tuple[str, list[type]]]:
    """The function of every task the scheduler holds, and the types of its arguments."""
    return [(task.run_spec.func.__name__, [type(argument) for argument in task.run_spec.args])
            for task in dask_scheduler.tasks.values() if task.run_spec is not None]


def test_submit_passes_results_of_other_tasks_in_their_places():
    with distributed.Client(processes=False, n_workers=2, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        seven, two = submit(client, abs, -7), submit(client, abs, 2)
        assert submit(client, _difference, seven, 3, scale=two).result() == 8  # (7 - 3) * 2
        assert submit(client, sum, [seven, two, 1]).result() == 10
        assert submit(client, _difference, 5, second=seven, priority=3).result() == -2


def test_the_scheduler_is_sent_bytes_not_the_functions_and_values_of_a_task():
    # The scheduler unpickles what it is sent: a task naming the stages' functions would
    # make it import them; a pickled call is only bytes and a list of other tasks.
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        first = submit(client, _difference, 4, 1)
        second = submit(client, _difference, first, 1)
        assert second.result() == 2
        calls = client.run_on_scheduler(_scheduler_calls)
    assert len(calls) == 2
    assert all(function == "_pickled_call" and arguments[0] is bytes
               for function, arguments in calls)


def test_submit_keeps_a_tasks_error():
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        with pytest.raises(ZeroDivisionError):
            submit(client, _inverse, 0).result()
