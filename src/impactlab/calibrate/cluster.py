"""Candidate models on a Dask cluster: each model's chain is one task (the models are
independent), so a large set of models spreads over the workers; each task still evaluates its
walkers in the compiled batch on its worker's cores."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["CONNECT_TIMEOUT", "map_on_dask"]

#: Seconds to wait for a scheduler given by its address (a cluster answers in well under this).
CONNECT_TIMEOUT = 20.0


def _check_reachable(address: Any) -> None:
    """OSError when nothing accepts a connection at a TCP scheduler ``address`` (a socket
    fails at once where a Client would retry until its timeout, and leave a client that
    complains as it is collected)."""
    import socket

    from distributed.comm.addressing import parse_address, parse_host_port

    scheme, location = parse_address(str(address))
    if scheme in ("tcp", "tls", "ws", "wss"):
        host, port = parse_host_port(location)
        socket.create_connection((host, port), timeout=CONNECT_TIMEOUT).close()


def map_on_dask(
    scheduler: Any, fn: Callable[..., Any], calls: Sequence[tuple[Any, ...]]
) -> list[Any]:
    """``[fn(*args) for args in calls]`` on Dask: ``scheduler`` is a ``distributed.Client`` or
    a scheduler address (``"tcp://host:8786"``; a client is opened and closed here). ValueError
    naming the address when no scheduler answers there within CONNECT_TIMEOUT."""
    from distributed import Client

    own = not isinstance(scheduler, Client)
    if own:
        try:
            _check_reachable(scheduler)
            client = Client(scheduler, timeout=CONNECT_TIMEOUT, set_as_default=False)
        except (OSError, TimeoutError, ValueError, TypeError) as exc:
            why = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            raise ValueError(
                f"cannot reach the Dask scheduler {scheduler!r} ({why}); is it running at that "
                "address?"
            ) from None
    else:
        client = scheduler
    try:
        futures = [client.submit(fn, *args, pure=False) for args in calls]
        return list(client.gather(futures))
    finally:
        if own:
            client.close()
