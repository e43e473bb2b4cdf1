"""Geometry of a body at first contact: the lever arms from the centre of mass to the contact point.

Convention (the paper's Eq. 1, doi:10.1007/s00419-015-1108-2): the centre S of the tip's sphere
(radius R) lies ``half_length`` = L/2 from the centre of mass C along the rod axis; with the axis
at ``angle`` to the flat, the tip lowest and C at +x of the tip, the first contact point O (the
lowest point of the tip sphere) sees C at

    r_C - r_O = (a, b) = ((L/2) cos(angle), (L/2) sin(angle) + R).

A sphere is the case ``half_length = 0`` (a = 0, b = R).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["lever_arms"]


def lever_arms(half_length: Any, tip_radius: Any, angle: Any) -> tuple[Any, Any]:
    """Lever arms (a, b) [m] from the contact point O to the centre of mass C (paper Eq. 1).

    ``a = half_length cos(angle)`` (horizontal), ``b = half_length sin(angle) + tip_radius``
    (vertical); ``half_length`` and ``tip_radius`` in m, ``angle`` in rad. Broadcasts over
    arrays; no validation (the callers check their inputs).
    """
    return half_length * np.cos(angle), half_length * np.sin(angle) + tip_radius
