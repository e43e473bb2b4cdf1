"""Candidate models on a Dask cluster: each model's chain is one task (the models are
independent), so a large set of models spreads over the workers; each task still evaluates its
walkers in the compiled batch on its worker's cores."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["map_on_dask"]


def map_on_dask(
    scheduler: Any, fn: Callable[..., Any], calls: Sequence[tuple[Any, ...]]
) -> list[Any]:
    """``[fn(*args) for args in calls]`` on Dask: ``scheduler`` is a ``distributed.Client`` or
    a scheduler address (``"tcp://host:8786"``; a client is opened and closed here)."""
    from distributed import Client

    own = not isinstance(scheduler, Client)
    client = Client(scheduler, timeout=60, set_as_default=False) if own else scheduler
    try:
        futures = [client.submit(fn, *args, pure=False) for args in calls]
        return list(client.gather(futures))
    finally:
        if own:
            client.close()
