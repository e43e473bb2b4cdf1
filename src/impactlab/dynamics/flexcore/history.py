"""The recorded history of the flexible drop: one row per accepted step (and three dense
points inside it), columns ``layout.DROP_HISTORY_FIELDS`` (compiled)."""

from __future__ import annotations

import numpy as np

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.kinematics import mechanical_energy
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.buffers import grown


@njit_internal
def history_row(hist, nh, t, mdl, y, ek, e0):
    """Append the row at time t (state y, evaluated quantities ek; e0: initial energy [J]);
    returns (hist, nh), the array grown when full."""
    c = mdl[2]
    M = mdl[3].shape[0]
    if nh >= hist.shape[0]:
        hist = grown(hist, nh, np.int64(64))
    r = hist[nh]
    r[0] = t
    for k in range(F.NE):
        r[1 + 5 * k] = ek[k, F.EK_DELTA]
        r[2 + 5 * k] = ek[k, F.EK_FN]
        r[3 + 5 * k] = ek[k, F.EK_FT]
        r[4 + 5 * k] = ek[k, F.EK_X]
        r[5 + 5 * k] = c[F.FC_R] - ek[k, F.EK_DELTA]
    r[11] = c[F.FC_D] * c[F.FC_C0] + y[0]
    r[12] = c[F.FC_D] * c[F.FC_S0] + c[F.FC_R] + y[1]
    r[13] = y[2]
    r[14] = ek[0, F.EK_VT]
    iq = 6 + 2 * M
    r[15] = (mechanical_energy(mdl, y) - e0 - y[iq] - y[iq + 1] - y[iq + 2]) / e0
    return hist, nh + 1
