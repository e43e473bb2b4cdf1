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

from impactlab.bodies import layout
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.geometry import lever_arms
from impactlab.bodies.impulse import (
    RigidImpulse,
    critical_ratio,
    impulse_response,
    rigid_impulse,
)
from impactlab.bodies.layout import *  # noqa: F403 - the layout's names, re-exported as they are
from impactlab.bodies.modal import ModalBasis, modal_basis
from impactlab.bodies.rod import PAPER_ROD, Rod
from impactlab.bodies.rod_section import RodSection
from impactlab.bodies.sphere import Sphere

#: Either body type.
Body = Rod | Sphere

__all__ = [
    *layout.__all__,
    "PAPER_ROD",
    "Body",
    "FlexibleRod",
    "ModalBasis",
    "RigidImpulse",
    "Rod",
    "RodSection",
    "Sphere",
    "critical_ratio",
    "impulse_response",
    "lever_arms",
    "modal_basis",
    "rigid_impulse",
]
