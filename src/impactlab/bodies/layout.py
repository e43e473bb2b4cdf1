"""Layout of the float64 body parameter vector (``Body.to_params``) read by the compiled engine.

Imports nothing: the compiled core (``impactlab.dynamics.core``) reads these indices.
"""

from __future__ import annotations

BP_KIND = 0  #: 0 = rod, 1 = sphere
BP_HALF_LENGTH = 1  #: distance C -> centre of the tip sphere, L/2 [m] (0 for a sphere)
BP_RADIUS = 2  #: tip (sphere) radius R [m]
BP_MASS = 3  #: mass m [kg]
BP_INERTIA = 4  #: moment of inertia about the centre of mass I_C [kg m^2]
BP_GSTAR = 5  #: effective shear modulus G* of the pair (body, flat) [Pa] (Mindlin friction)
NB = 6  #: length of the vector

KIND_ROD = 0  #: ``BP_KIND`` of a rod
KIND_SPHERE = 1  #: ``BP_KIND`` of a sphere

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
]
