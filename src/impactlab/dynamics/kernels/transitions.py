"""Mode transitions at events: the turning point of the normal contact (start of an unloading
branch), reloading, the return to the loading curve, stick/slip switches, and the restart of
the integration after a switch.

Normal contact history (docs/engine/index.md): loading curve until v_n = 0; there delta_m,
delta_r and R_r of the Hertzian unloading branch are fixed once; reloading below delta_m stays on
that branch; reaching delta_m again returns to the loading curve.
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.history_kernels import contact_radius as _contact_radius
from impactlab.contact.kernels import (
    P_ESTAR,
    P_R,
    loading_force,
    residual_depth,
    unloading_radius,
)
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.friction import (
    frictional,
    mindlin_state_at_reload,
    mindlin_state_at_turn,
    switch_friction,
)
from impactlab.dynamics.kernels.layout import (
    EV_FRIC,
    EV_RELOAD,
    EV_VN,
    FR_MINDLIN,
    M_AF,
    M_COMP,
    M_FM,
    M_PHASE,
    M_SIR,
    NS,
    S_Q,
)
from impactlab.dynamics.kernels.rhs import rhs_events_cold
from impactlab.dynamics.kernels.status import ST_NAN, ST_OK
from impactlab.dynamics.kernels.tuples import mode_with, state_tuple


@njit_internal
def without_switch(c):
    """The constants tuple without the law-switch event (passed once: later reloading happens
    beyond it)."""
    return (
        c[0],
        c[1],
        c[2],
        c[3],
        c[4],
        c[5],
        c[6],
        c[7],
        c[8],
        c[9],
        c[10],
        c[11],
        c[12],
        c[13],
        math.inf,
        c[15],
        c[16],
    )


@njit_internal
def unloading_branch(law, p, fric, md, delta):
    """(status, mode) on the unloading branch from the turning point ``delta`` [m] of the
    loading curve: delta_m, delta_r, R_r and (Mindlin) the contact-radius factor."""
    Fm = loading_force(law, p, delta)
    dri = residual_depth(law, p, delta, Fm)
    if not (math.isfinite(Fm) and math.isfinite(dri) and dri >= 0.0 and dri < delta):
        return ST_NAN, md
    rr = unloading_radius(p[P_ESTAR], delta, Fm, dri)
    af = md[M_AF]
    if fric == FR_MINDLIN:
        a_unl = _contact_radius(law, p, delta, math.inf, dri, rr)
        a_load = _contact_radius(law, p, delta, delta, 0.0, p[P_R])
        af = a_load / a_unl if a_unl > 0.0 else 1.0
    return ST_OK, (1.0, delta, dri, rr, md[M_FM], md[M_COMP], md[M_SIR], af)


@njit_internal
def switch_mode(ev, law, p, fric, c, md, y, evq):
    """(status, mode) after the event ``ev`` (EV_VN, EV_RELOAD or EV_FRIC) at state ``y``;
    converts the Mindlin state ``y[S_Q]`` in place. ``evq``: the quantities evaluated at ``y``
    in the old mode."""
    delta, _a, _b, _Fn, Ft, _vn, _vs, kt = evq
    mindlin_elastic = fric == FR_MINDLIN and md[M_FM] == 0.0
    if ev == EV_VN:
        if md[M_COMP] != 0.0:  # turning point: the contact starts to shrink
            if md[M_PHASE] == 0.0:
                status, md = unloading_branch(law, p, fric, md, delta)
                if status != ST_OK:
                    return status, md
            md = mode_with(md, M_COMP, 0.0)
            if mindlin_elastic:
                # from the force to the elastic displacement
                y[S_Q] = mindlin_state_at_turn(law, p, c, md, delta, Ft, kt)
        else:  # local minimum of delta: reloading on the unloading branch
            md = mode_with(md, M_COMP, 1.0)
            if mindlin_elastic:
                y[S_Q] = Ft
    elif ev == EV_RELOAD:
        md = mode_with(md, M_PHASE, 0.0)
        if mindlin_elastic:
            y[S_Q] = mindlin_state_at_reload(law, p, c, md, delta, Ft, kt)
    elif ev == EV_FRIC:
        fm, y[S_Q] = switch_friction(fric, c, md, y, evq)
        md = mode_with(md, M_FM, fm)
    return ST_OK, md


@njit(cache=True, error_model="numpy")
def restart(law, p, fric, c, md, y, K):
    """Restart the integration at ``y`` after a switch: the derivative into ``K[0]``; returns
    (mode, event tuple). A restart can find the friction state already outside its domain (e.g.
    the friction cap drops with a jump of the loading curve): switch at once, at the same
    instant."""
    r, gold, evq = rhs_events_cold(law, p, fric, c, md, state_tuple(y))
    for _ in range(3):
        if not (frictional(fric) and gold[EV_FRIC] > 0.0):
            break
        fm, y[S_Q] = switch_friction(fric, c, md, y, evq)
        md = mode_with(md, M_FM, fm)
        r, gold, evq = rhs_events_cold(law, p, fric, c, md, state_tuple(y))
    for i in range(NS):
        K[0, i] = r[i]
    return md, gold
