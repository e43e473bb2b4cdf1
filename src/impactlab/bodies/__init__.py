"""Impacting bodies: a rod with a hemispherical tip and a sphere, their contact geometry and the
rigid-body impulse at the contact point (SI units throughout).

- :class:`Rod`, :class:`Sphere` (``Body`` is either) and :data:`PAPER_ROD`, the paper's rod;
- :func:`lever_arms`: the lever arms (a, b) from the contact point to the centre of mass;
- :func:`rigid_impulse`: instantaneous impact with Newton restitution and Coulomb friction;
  :func:`impulse_response` and :func:`critical_ratio` are its closed-form core, shared with
  ``impactlab.analytic``;
- ``BP_*``, ``KIND_*``, ``NB``: the layout of ``Body.to_params`` for the compiled engine
  (``impactlab.bodies.layout``).
"""

from __future__ import annotations

from impactlab.bodies.geometry import lever_arms
from impactlab.bodies.impulse import (
    RigidImpulse,
    critical_ratio,
    impulse_response,
    rigid_impulse,
)
from impactlab.bodies.layout import (
    BP_GSTAR,
    BP_HALF_LENGTH,
    BP_INERTIA,
    BP_KIND,
    BP_MASS,
    BP_RADIUS,
    KIND_ROD,
    KIND_SPHERE,
    NB,
)
from impactlab.bodies.rod import PAPER_ROD, Rod
from impactlab.bodies.sphere import Sphere

#: Either body type.
Body = Rod | Sphere

__all__ = [
    "BP_GSTAR",
    "BP_HALF_LENGTH",
    "BP_INERTIA",
    "BP_KIND",
    "BP_MASS",
    "BP_RADIUS",
    "KIND_ROD",
    "KIND_SPHERE",
    "NB",
    "PAPER_ROD",
    "Body",
    "RigidImpulse",
    "Rod",
    "Sphere",
    "critical_ratio",
    "impulse_response",
    "lever_arms",
    "rigid_impulse",
]
