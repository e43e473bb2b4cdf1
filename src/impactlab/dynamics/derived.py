"""Derived outputs (``impactlab.schema.register_output``) on the result objects.

A derived output is computed from the engine's outputs (``OUTPUT_FIELDS`` names) when it is
read, so registering one needs no recompilation. ``DerivedOutputs`` gives a one-impact result
(``ImpactResult``, ``DropResult``) its derived outputs as attributes and in ``derived()``; a
batch computes them from its columns (``batch_derived``); the sweep from its chunk's arrays
(``impactlab.sweep.engine``). An engine output that a result does not define (a drop has no
``vn_in``, and its sequence totals are no ``duration``, ``delta_p``, ...) reads as NaN.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.dynamics.kernels.status import REGIME_NAMES
from impactlab.schema import DERIVED_FIELDS, derived_values

_REGIME_CODES = {name: code for code, name in REGIME_NAMES.items()}


def e_gravity_removed(vn_in: Any, vn_out: Any, duration: Any, gravity: float) -> Any:
    """A rigid impact's e with the gravity impulse of its contact removed, as a drop's ``e``
    removes it and as marker tracks extrapolated to the impact measure it:
    (v_n,out + g T) / |v_n,in| (``vn_in``, ``vn_out`` [m/s] of the contact point, ``duration``
    T [s], ``gravity`` g [m/s^2]; floats or arrays). Gravity exerts no moment about the centre
    of mass, so it changes the contact point's normal velocity by g T alone."""
    return (np.asarray(vn_out) + gravity * np.asarray(duration)) / np.abs(vn_in)


def result_output(result: Any, name: str) -> Any:
    """The engine output ``name`` of a one-impact result (a float; NaN where it has none)."""
    if name in ("vx_out", "vy_out"):
        return float(result.velocity_out[0 if name == "vx_out" else 1])
    if name in getattr(type(result), "RENAMED", {}):
        return math.nan  # a drop's sequence total of another meaning (schema.SEQUENCE_FIELDS)
    if name == "regime":
        return float(_REGIME_CODES.get(getattr(result, "regime", ""), math.nan))
    return float(getattr(result, name, math.nan))  # (an engine output is never a derived name)


class DerivedOutputs:
    """Mixin of the one-impact results: the derived outputs as attributes and ``derived()``."""

    def derived(self) -> dict[str, Any]:
        """Every registered derived output (``impactlab.schema.DERIVED_FIELDS``) of this
        result, by name."""
        return derived_values(lambda n: result_output(self, n))

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_") or name not in DERIVED_FIELDS:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        d = DERIVED_FIELDS[name]
        return d.compute(**{n: result_output(self, n) for n in d.needs})


def batch_derived(column: Any, name: str) -> np.ndarray:
    """The derived output ``name`` of a batch whose engine outputs are ``column(name)``."""
    d = DERIVED_FIELDS[name]
    return np.asarray(d.compute(**{n: column(n) for n in d.needs}), dtype=np.float64)


__all__ = ["DerivedOutputs", "batch_derived", "result_output"]
