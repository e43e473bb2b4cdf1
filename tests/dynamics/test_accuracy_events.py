"""Event location of the compiled core (``integrator.locate``, Illinois method on the dense
output) returns the crossing, not the end of the step.

The regression this guards: the iteration once stopped as soon as two iterates were within
1e-14 of each other, even when both lay on the g <= 0 side (a regula-falsi approach from one
side, here a slightly convex event function): it then returned the far end of the bracket,
theta = 1, and the separation was taken at the end of the step (seen as a contact duration 2 %
too long on a sphere of the accuracy sample).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact.kernels import NPARAM
from impactlab.dynamics.core.integrator import locate
from impactlab.dynamics.kernels.layout import EV_SEP, FR_IMPULSE, NS, S_Y

#: A sphere (L/2 = 0 at pi/2: delta = -y[S_Y]); the constants tuple, C_* order.
SPHERE_C = (0.0, 1.0, 1.0, 1.0, 0.0, 0.5 * math.pi, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0)
SPHERE_C += (math.inf, math.inf)
#: Receding on the unloading branch with delta_r = 0.25 (mode tuple, M_* order).
RECEDING = (1.0, 1.0, 0.25, 1.0, 0.0, 0.0, 0.0, 1.0)


@pytest.mark.parametrize("eps", [1e-6, 1e-8, 1e-10, -1e-8])
def test_separation_located_at_the_crossing(eps: float) -> None:
    # dense output over h = 1: y_Y(theta) = -0.5 + 0.5 theta + eps theta^2, so that
    # g_sep = delta_r - delta = -0.25 + 0.5 theta + eps theta^2 crosses zero near 0.5
    Q = np.zeros((NS, 4))
    Q[S_Y, 0] = 0.5
    Q[S_Y, 1] = eps
    y0 = np.zeros(NS)
    y0[S_Y] = -0.5
    K = np.zeros((7, NS))  # not read: the dense output is Q
    g1 = 0.25 + eps
    args = (np.zeros(NPARAM), FR_IMPULSE, SPHERE_C, RECEDING, y0, K, 1.0, Q, np.empty(NS))
    theta = locate(EV_SEP, -0.25, g1, 0, *args)
    root = 0.5 / (0.5 + math.sqrt(0.25 + eps))  # the root of eps t^2 + t / 2 - 1/4, stably
    assert abs(theta - root) < 1e-12, (theta, root)
