"""The checks ``fe.tabulated_law`` makes of a request before any FE run (minutes of CalculiX
each): which body yields in the FE problem asked, the FE problem's own pair (a rigid sphere's
E*/S_y is not the pair's), the maxima against the radius, and that the runs unload."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from impactlab.contact.indentation_data import yielding_body
from impactlab.contact.tabulated import NU_TOLERANCE, RATIO_TOLERANCE
from impactlab.fe.problem import largest_delta_max
from impactlab.fe.problem_pair import problem_pair
from impactlab.materials import ContactPair


def fe_yielding(pair: ContactPair, sphere: str, flat_hardening: Any = None) -> str:
    """The body that yields first in an FE run of ``pair`` whose sphere is ``sphere``
    ("rigid", "elastic", "elastic-plastic"): the flat unless the sphere is elastic-plastic
    and yields first, its C(nu) S_y the smaller (``yielding_body``), or the flat is kept
    elastic (``flat_hardening="elastic"``)."""
    if sphere in ("rigid", "elastic"):
        return "flat"
    if isinstance(flat_hardening, str) and flat_hardening == "elastic":
        return "sphere"
    return yielding_body(pair)


def check_reach(
    pair: ContactPair, radius: float, maxima: Sequence[float], dc: float, default: bool
) -> None:
    """ValueError naming ``maxima_over_delta_c`` (``default``: not given) when its largest
    multiple of delta_c is more than the sphere of ``radius`` [m] allows (a soft flat:
    delta_c is large)."""
    largest = largest_delta_max(radius)
    too_far = [m for m in maxima if m * dc >= largest]
    if too_far:
        keep = [m for m in maxima if m * dc < largest]
        raise ValueError(
            f"maxima_over_delta_c{' (the default)' if default else ''} asks for "
            f"{too_far[0]:g} delta_c = {too_far[0] * dc:.4g} m (delta_c = {dc:.4g} m for "
            f"{pair.body.name} on {pair.flat.name}), too large for radius {radius:g} m: allowed "
            f"delta_max < {largest:.4g} m = {largest / dc:.4g} delta_c; pass "
            f"maxima_over_delta_c below that, e.g. {tuple(keep)}"
        )


def check_unload(unload: Any) -> None:
    """ValueError unless ``unload`` (``indent``'s) is True: a loading-only run has no residual
    depth, which the law needs at every maximum."""
    if not (isinstance(unload, bool | np.bool_) and unload):
        raise ValueError(
            f"unload must be True (the default) for tabulated_law, got {unload!r}: a "
            "loading-only FE run (unload=False) has no residual depth delta_r, which the law "
            "needs at every maximum; leave unload out"
        )


def fe_pair(pair: ContactPair, sphere: str) -> ContactPair:
    """The pair of the FE problem of ``pair`` with a ``sphere`` sphere (``Problem.pair``),
    whose delta_c, F_c and E*/S_y its curves are made dimensionless with; ValueError, before
    any run, where its E*/S_y or nu is not the pair's within the law's tolerances: a rigid
    sphere's E* is the flat's alone, so its curves describe another contact than the pair's,
    which the law would refuse."""
    fe = problem_pair(pair.flat, pair.body, sphere)
    ratio, fe_ratio = pair.E_star / pair.yield_strength, fe.E_star / fe.yield_strength
    off = abs(math.log(fe_ratio / ratio)) > math.log1p(RATIO_TOLERANCE)
    if off or abs(fe.nu - pair.nu) > NU_TOLERANCE:
        raise ValueError(
            f"sphere={sphere!r} makes FE curves of the flat against a rigid sphere, E*/S_y = "
            f"{fe_ratio:.4g} (E* = {fe.E_star / 1e9:.4g} GPa, the flat's alone), while "
            f"{pair.body.name} on {pair.flat.name} has E*/S_y = {ratio:.4g} (E* = "
            f"{pair.E_star / 1e9:.4g} GPa): those curves describe another contact, and the law "
            f"takes curves within {100 * RATIO_TOLERANCE:g} % of the pair's E*/S_y only; leave "
            "sphere='elastic-plastic' (the default) or give sphere='elastic', so that the FE "
            "models the pair's sphere"
        )
    return fe


__all__ = ["check_reach", "check_unload", "fe_pair", "fe_yielding"]
