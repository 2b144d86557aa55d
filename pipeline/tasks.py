"""The same work here or as dask tasks: one function mapped over items.

The stages do not know whether they run on a cluster: they hand a function
and its items to :class:`Mapped`, which computes them in this process when
there is no client, or submits them at once to a dask.distributed client and
gathers them when asked. Values every item needs (``shared``) are sent to the
workers once, not with every task.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

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
            scattered = {name: client.scatter(value, broadcast=True, hash=False)
                         for name, value in shared.items()}
            self._futures = client.map(function, self._items, pure=False, **scattered)

    def results(self) -> list:
        """The results, in the items' order (the first task's error is raised)."""
        if self._futures is None:
            return [self._function(item, **self._shared) for item in self._items]
        return self._client.gather(self._futures)


def map_tasks(function: Callable, items: Sequence, client: Client | None = None) -> list:
    """``function(item)`` of every item, in order: here, or as dask tasks on `client`."""
    return Mapped(function, items, client).results()
