"""The contact pair an FE indentation problem stands for (``Problem.pair``): what its delta_c,
F_c and E*/S_y are computed from, and what the contact laws compared with it are built with.

In the FE only a body given a plastic table can yield: the flat always (unless kept elastic),
the sphere only when ``sphere="elastic-plastic"``. So for a rigid or an elastic sphere the
flat's S_y and nu are the pair's, even where the sphere material's C(nu) S_y is the smaller
(a copper sphere on AISI 1010: the FE's first yield is the flat's, at 38 times the copper's
delta_c).
"""

from __future__ import annotations

import dataclasses
import math
import warnings

from impactlab._validation import ImplausibleInputWarning
from impactlab.materials import ContactPair, Material, body_yields_first, first_yield_factor


def _never_yielding(sphere: Material, flat: Material) -> Material:
    """``sphere`` with its yield strength raised so that the flat yields first (twice the
    flat's first-yield pressure C(nu) S_y over the sphere's C(nu); below the sphere's E)."""
    target = 2.0 * first_yield_factor(flat.nu) * flat.yield_strength / first_yield_factor(sphere.nu)
    with warnings.catch_warnings():  # a yield strength no sphere has, on purpose
        warnings.simplefilter("ignore", ImplausibleInputWarning)
        return dataclasses.replace(
            sphere, yield_strength=min(target, math.nextafter(sphere.E, 0.0))
        )


def problem_pair(flat: Material, sphere_material: Material, sphere: str) -> ContactPair:
    """The contact pair (the sphere's material first) of an FE problem whose sphere is
    ``sphere`` ("rigid", "elastic", "elastic-plastic"). A rigid sphere is a material 10^9
    times stiffer than the flat, so that E* is the flat's E / (1 - nu^2) to 1e-9, and never
    the one that yields: its yield strength is the larger of the sphere material's and the
    flat's (its Brinell hardness and Meyer index are the sphere material's). An elastic sphere
    keeps its E and nu (E* is the pair's) and, where it would yield first, gets a yield
    strength at which the flat yields first (the flat's S_y and nu are then the pair's)."""
    if sphere == "rigid":
        m = sphere_material
        sy = max(m.yield_strength, flat.yield_strength)
        with warnings.catch_warnings():  # 10^9 times the flat's E on purpose
            warnings.simplefilter("ignore", ImplausibleInputWarning)
            rigid = Material("rigid", flat.E * 1e9, flat.nu, sy, m.brinell_hardness, m.meyer_index)
        return ContactPair(rigid, flat)
    if sphere == "elastic" and body_yields_first(sphere_material, flat):
        return ContactPair(_never_yielding(sphere_material, flat), flat)
    return ContactPair(sphere_material, flat)


__all__ = ["problem_pair"]
