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
from typing import TYPE_CHECKING, Any
from uuid import uuid4

if TYPE_CHECKING:
    from distributed import Client


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
            keys = [f"{function.__name__}-{uuid4().hex}" for _ in self._items]
            self._futures = client.map(_call, self._items, function=function, shared=bundle,
                                       key=keys)

    def results(self) -> list:
        """The results, in the items' order (the first task's error is raised)."""
        if self._futures is None:
            return [self._function(item, **self._shared) for item in self._items]
        return self._client.gather(self._futures)


def _call(item: Any, function: Callable, shared: dict[str, Any]) -> Any:
    """``function(item, **shared)``: one task of :class:`Mapped` on a worker."""
    return function(item, **shared)


def map_tasks(function: Callable, items: Sequence, client: Client | None = None) -> list:
    """``function(item)`` of every item, in order: here, or as dask tasks on `client`."""
    return Mapped(function, items, client).results()
