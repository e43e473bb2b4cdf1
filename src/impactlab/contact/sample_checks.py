"""The checks of a law sampled from Python callables (``registered.sample_law``): the callables
evaluated at each interference [m], ``delta_max`` below the radius, the samples' signs and
order, and the force at the switch against Hertz's.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np

from impactlab.contact.table_input import HERTZ_TOLERANCE, hertz_offset, radius_hint, two
from impactlab.materials import ContactPair

__all__ = ["check_below_radius", "check_hertz_switch", "check_samples", "sample_values"]


def sample_values(what: str, fn: Callable[[float], Any], x: np.ndarray) -> np.ndarray:
    """``fn`` at every point of ``x`` (floats in, one finite float out each)."""
    out = np.empty(x.size)
    for i, xi in enumerate(x):
        try:
            v = float(fn(float(xi)))
        except Exception as exc:  # a user's function: say which call failed
            raise ValueError(f"{what}({float(xi)!r}) raised {type(exc).__name__}: {exc}") from None
        if not math.isfinite(v):
            raise ValueError(f"{what}({float(xi)!r}) returned {v!r}; it must be finite")
        out[i] = v
    return out


#: Units a bare length may have been meant in, and their size in m.
_MEANT_UNITS = (("mm", 1e-3), ("um", 1e-6))


def check_below_radius(given: Any, top: float, radius: float, d0: float) -> None:
    """ValueError naming ``delta_max`` (as ``given``: ``top`` [m]) and ``radius`` [m] unless
    ``top`` lies below the radius; for a bare number, the unit it may have been meant in."""
    if top < radius:
        return
    shown = f"{top:.4g} m" if isinstance(given, int | float) else f"{given!r} ({top:.4g} m)"
    meant = next((u for u, size in _MEANT_UNITS if d0 < top * size < radius), None)
    hint = ""
    if isinstance(given, int | float):
        hint = " (a bare number is m" + (f": '{top:g} {meant}'?)" if meant else ")")
    raise ValueError(f"delta_max = {shown} must be smaller than radius = {radius:.4g} m{hint}")


def check_samples(
    name: str, grid: np.ndarray, forces: np.ndarray, residual: np.ndarray, default: bool
) -> None:
    """ValueError naming the callable, the value it returned and the interference [m] of the
    sample where ``forces`` (``loading`` at ``grid``) are not > 0 or decrease, or where
    ``residual`` (``unloading`` at ``grid``) is not in [0, delta_max) or not 0 at the first
    sample (the elastic limit: ``switch_interference``, by default the pair's delta_c)."""
    start = "the pair's delta_c" if default else "switch_interference"
    d, f, r = grid, forces, residual
    bad = np.flatnonzero(~(f > 0.0))
    if bad.size:
        i = int(bad[0])
        raise ValueError(
            f"law {name!r}: F = loading(delta) must be > 0 N from {start} to delta_max, got "
            f"{f[i]:.4g} N at delta = {d[i]:.4g} m"
        )
    bad = np.flatnonzero(np.diff(f) < 0.0)
    if bad.size:
        i = int(bad[0]) + 1
        raise ValueError(
            f"law {name!r}: F = loading(delta) must not decrease with delta, got "
            f"{two(f[i - 1], f[i], 'N')} at delta = {two(d[i - 1], d[i], 'm')}"
        )
    if r[0] != 0.0:
        raise ValueError(
            f"law {name!r}: delta_r = unloading(delta_max) must be 0 at the elastic limit "
            f"({start}, {d[0]:.4g} m: Hertz, no residual depth), got {r[0]:.4g} m"
        )
    bad = np.flatnonzero(~((r >= 0.0) & (r < d)))
    if bad.size:
        i = int(bad[0])
        raise ValueError(
            f"law {name!r}: delta_r = unloading(delta_max) must lie in [0, delta_max), got "
            f"{r[i]:.4g} m at delta_max = {d[i]:.4g} m"
        )


def check_hertz_switch(
    name: str, pair: ContactPair, radius: float, d0: float, f0: float, default: bool
) -> None:
    """ValueError unless the callable's force ``f0`` [N] at the switch ``d0`` [m], where the
    sampled law leaves Hertz, lies within ``HERTZ_TOLERANCE`` of Hertz's (``f0`` > 0:
    ``check_samples``)."""
    hertz, off = hertz_offset(pair, radius, d0, f0)
    if abs(off) <= HERTZ_TOLERANCE:
        return
    which = ", by default the pair's Jackson-Green delta_c" if default else ""
    raise ValueError(
        f"law {name!r}: F(switch_interference = {d0:.4g} m{which}) is {f0:.4g} N, "
        f"{100 * off:+.1f} % from Hertz's {hertz:.4g} N for this pair and radius = "
        f"{radius:.4g} m (the law is Hertz up to the switch: within "
        f"{100 * HERTZ_TOLERANCE:g} % needed): give switch_interference=<where F leaves Hertz>"
        + radius_hint(off, radius, pair)
    )


class ForceDepartsWarning(UserWarning):
    """A law sampled from a loading callable departs from it by more than the tabulated law's
    own accuracy (``TABLE_FIT_TOLERANCE``), though within the ``tolerance`` it was given: where
    F/F_Hertz rises the law does not follow the callable (it keeps F/F_Hertz from rising, or no
    impact would be without an energy gain), or the samples are too few."""


def warn_force_departs(name: str, check: np.ndarray, f_err: np.ndarray, limit: float) -> None:
    """A :class:`ForceDepartsWarning` where the sampled law's force departs from the callable's
    (``f_err``, relative, at the interferences ``check`` [m]) by more than ``limit``."""
    i = int(np.argmax(np.abs(f_err)))
    if not abs(f_err[i]) > limit:
        return
    warnings.warn(
        f"law {name!r}: its force departs from the loading callable's by {float(f_err[i]):+.3g} "
        f"(relative) at delta = {float(check[i]):.4g} m, more than {limit:g} (the tabulated "
        "law's own accuracy), within the tolerance given: where F/F_Hertz rises, the law keeps "
        "it from rising (an impact would gain energy), so this law is not the callable there; "
        "check the callable, or give more points",
        ForceDepartsWarning,
        stacklevel=3,
    )
