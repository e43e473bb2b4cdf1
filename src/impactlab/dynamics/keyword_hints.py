"""The words of a velocity given in a batch's form to a one-impact function: ``simulate``,
``simulate_drop`` and ``rerun`` take it as one pair, ``velocity=(vx, vy)``; ``simulate_batch``
and ``simulate_drops`` take ``vx=`` and ``vy=`` arrays."""

from __future__ import annotations

from collections.abc import Iterable

__all__ = ["split_velocity"]


def split_velocity(function: str, given: Iterable[str], batch: str = "simulate_batch") -> str:
    """The error text of ``function`` given ``vx=`` / ``vy=`` (``given``, in order), the names
    of ``batch``'s arrays: it takes the velocity as one pair, ``velocity=(vx, vy)`` [m/s]."""
    names = " and ".join(f"{k}=" for k in given)
    return (
        f"{function} takes the velocity as one pair, velocity=(vx, vy) [m/s], not {names} (the "
        f"names of the arrays of {batch})"
    )
