"""The same work here or as dask tasks: one function mapped over items.

The stages do not know whether they run on a cluster: they hand a function
and its items to :class:`Mapped`, which computes them in this process when
there is no client, or submits them at once to a dask.distributed client and
gathers them when asked. Values every item needs (``shared``) are sent to the
workers once, not with every task, and as one value: a group of tasks with few
dependencies is one the dask scheduler keeps queued and hands to whichever worker
is free, where tasks with several (each scattered value is one) are assigned to
workers as they are submitted, and a worker can sit idle at the end while the
other works through its share.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any
from uuid import uuid4

if TYPE_CHECKING:
    from distributed import Client, Future


class Mapped:
    """``function(item, **shared)`` for every item, in the items' order.

    Parameters
    ----------
    function : callable
        A module-level function (picklable, for the workers).
    items : sequence
        Its first argument, one task each.
    client : distributed.Client, optional
        Submit the tasks now, to this cluster; default: compute them in this
        process when :meth:`results` is called.
    **shared
        Keyword arguments every call gets (on a cluster: scattered once to
        every worker).

    Examples
    --------
    >>> Mapped(pow, [2, 3], exp=2).results()
    [4, 9]
    """

    def __init__(self, function: Callable, items: Sequence, client: Client | None = None,
                 **shared: Any) -> None:
        self._function, self._items, self._shared = function, list(items), shared
        self._client, self._futures = client, None
        if client is not None and self._items:
            bundle = client.scatter([shared], broadcast=True, hash=False)[0]
            calls = [_pickled(_call, (item, function, bundle), {}) for item in self._items]
            self._futures = client.map(
                _pickled_call, [call for call, _ in calls], [inputs for _, inputs in calls],
                key=[f"{function.__name__}-{uuid4().hex}" for _ in calls], pure=False)

    def results(self) -> list:
        """The results, in the items' order (the first task's error is raised)."""
        if self._futures is None:
            return [self._function(item, **self._shared) for item in self._items]
        return self._client.gather(self._futures)


def _call(item: Any, function: Callable, shared: dict[str, Any]) -> Any:
    """``function(item, **shared)``: one task of :class:`Mapped` on a worker."""
    return function(item, **shared)


@dataclass(frozen=True)
class _Input:
    """Where the result of another task goes in a pickled call: the `index`-th future
    handed to dask beside it."""

    index: int


def submit(client: Client, function: Callable, *args: Any, priority: int = 0,
           **kwargs: Any) -> Future:
    """``client.submit(function, *args, **kwargs)``, the call pickled here, as bytes.

    Futures among the arguments (alone, or in a list) stay dask's: the task waits
    for them and gets their results in their place. A task's key is its function's
    name and a unique suffix, and it is never taken for another with the same
    arguments (``pure=False``).

    Parameters
    ----------
    client : distributed.Client
        The cluster to run the task on.
    function : callable
        A module-level function (the workers import its module).
    *args, **kwargs
        Its arguments.
    priority : int
        dask's priority of the task (higher first).

    Examples
    --------
    >>> from distributed import Client
    >>> with Client(processes=False, n_workers=1, dashboard_address=":0") as client:
    ...     total = submit(client, sum, [submit(client, abs, -2), 3])
    ...     total.result()
    5
    """
    call, inputs = _pickled(function, args, kwargs)
    return client.submit(_pickled_call, call, inputs, priority=priority, pure=False,
                         key=f"{function.__name__}-{uuid4().hex}")


def _pickled(function: Callable, args: Sequence, kwargs: dict[str, Any]
             ) -> tuple[bytes, list[Future]]:
    """``function(*args, **kwargs)`` pickled, each future among the arguments (alone, or in
    a list) replaced by its place in the list of futures returned beside it."""
    from distributed import Future
    from distributed.protocol.pickle import dumps

    inputs: list[Future] = []

    def placed(value: Any) -> Any:
        if isinstance(value, Future):
            inputs.append(value)
            return _Input(len(inputs) - 1)
        if isinstance(value, list):
            return [placed(item) for item in value]
        return value

    call = (function, [placed(value) for value in args],
            {name: placed(value) for name, value in kwargs.items()})
    return dumps(call), inputs


def _pickled_call(call: bytes, results: list[Any]) -> Any:
    """A task of :func:`submit` on a worker: the call unpickled, with `results` (those of
    the futures it named) in their places."""

    def filled(value: Any) -> Any:
        if isinstance(value, _Input):
            return results[value.index]
        if isinstance(value, list):
            return [filled(item) for item in value]
        return value

    from distributed.protocol.pickle import loads

    function, args, kwargs = loads(call)
    return function(*map(filled, args), **{name: filled(value) for name, value in kwargs.items()})


def map_tasks(function: Callable, items: Sequence, client: Client | None = None) -> list:
    """``function(item)`` of every item, in order: here, or as dask tasks on `client`."""
    return Mapped(function, items, client).results()
