"""Running extremes and the normal work of an impact, kept in the accumulator array ``acc``
(the ``A_*`` of ``kernels.layout``, and ``A_EEL``) over the accepted steps of the driver
(``driver``) and of the final approach (``approach``)."""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.kernels._jit import njit_no_refcount
from impactlab.dynamics.kernels.friction import frictional, sticking
from impactlab.dynamics.kernels.layout import (
    A_DMAX,
    A_EMIN,
    A_ERISE,
    A_FEX,
    A_FMAX,
    A_OWN,
    A_STICK,
    A_TMAX,
    A_VSNEG,
    A_VSPOS,
    C_MU,
    M_DR,
)
from impactlab.dynamics.kernels.rhs import energy

A_EEL = A_OWN  # stored elastic energy at the start of the current restitution [J]
NA = A_OWN + 1


@njit_no_refcount
def track(acc, law, p, fric, c, md, y, evq, t0, t1, diag):
    """Update ``acc`` over the accepted step [t0, t1] ending at state ``y`` (a tuple, mode
    ``md`` before any switch, quantities ``evq``); False where the forces are not finite."""
    if sticking(fric, md):
        acc[A_STICK] += t1 - t0
    delta, _a, _b, Fn, Ft, _vn, vs, kt = evq
    if not (math.isfinite(Fn) and math.isfinite(Ft)):
        return False
    if Fn > acc[A_FMAX]:
        acc[A_FMAX] = Fn
    if delta > acc[A_DMAX]:
        acc[A_DMAX] = delta
        acc[A_TMAX] = t1
    if vs > acc[A_VSPOS]:
        acc[A_VSPOS] = vs
    if vs < acc[A_VSNEG]:
        acc[A_VSNEG] = vs
    if diag:
        en = energy(law, p, fric, c, md, y, Fn, Ft, delta, kt)
        if en - acc[A_EMIN] > acc[A_ERISE]:
            acc[A_ERISE] = en - acc[A_EMIN]
        if en < acc[A_EMIN]:
            acc[A_EMIN] = en
        if frictional(fric):
            ex = abs(Ft) - c[C_MU] * Fn
            if ex > acc[A_FEX]:
                acc[A_FEX] = ex
    return True


@njit(cache=True, inline="always", error_model="numpy")
def stored(evq, md):
    """Elastic energy stored on the unloading branch of mode ``md`` at the evaluated state
    ``evq`` [J]: int_{delta_r}^{delta} F dd = 0.4 F_n (delta - delta_r) (Hertzian branch).

    The restitution runs on that branch (delta decreases on it, d delta/dt = -v_n exactly), so
    the normal work of a restitution segment is the drop of this energy: the work of restitution
    comes in closed form, not as a small difference of the integrated work (which made e* the
    least accurate output when e is small)."""
    delta = evq[0]
    Fn = evq[3]
    return 0.4 * Fn * (delta - md[M_DR]) if Fn > 0.0 else 0.0
