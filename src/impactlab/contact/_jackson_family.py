"""Shared set-up of the Jackson-Green family (Ghaednia et al. 2016 and Jackson-Green 2005).

Both laws use the same critical values (paper Eqs. 15 and 17), the same contact-area fit and
the same unloading (paper Eqs. 18-19); they differ in three constants and the hardness model.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.contact import kernel_arrays as ka
from impactlab.contact import kernels as k
from impactlab.contact._common import jg_C, jg_critical, pair_constants, switch_point
from impactlab.contact.names import Law
from impactlab.contact.ranges import calibrated_max
from impactlab.materials import ContactPair


def fill_jackson_family(
    p: np.ndarray,
    pair: ContactPair,
    *,
    k1: float,
    k2: float,
    m: float,
    hardness_model: float,
    published: bool,
    law: Law,
) -> dict[str, float]:
    """Fill slots 4..15 of ``p`` for the Jackson-Green-family law ``law``; return its details
    (the calibrated range from ``contact.ranges``)."""
    law_name = str(law)
    E, R, Sy, nu = pair_constants(p)
    C = jg_C(nu)
    dc, fc = jg_critical(E, R, Sy, nu)
    B = 0.14 * math.exp(23.0 * Sy / E)
    p[k.P_DY] = dc
    p[k.P_FY] = fc
    p[k.P_JG_DC] = dc
    p[k.P_JG_FC] = fc
    p[k.P_JG_C] = C
    p[k.P_JG_B] = B
    p[k.P_JG_K1] = k1
    p[k.P_JG_K2] = k2
    p[k.P_JG_M] = m
    p[k.P_JG_HARD] = hardness_model
    # Validity: the contact radius of the area fit reaches the sphere radius (r = R) at
    # delta^(1+B) = R (1.9 delta_c)^B; beyond it the hardness fits lose their meaning.
    d_full = math.exp((math.log(R) + B * math.log(k.JG_AREA_SWITCH * dc)) / (1.0 + B))
    dlim = min(R, d_full)
    p[k.P_DLIM] = dlim
    d_pub = k.JG_AREA_SWITCH * dc
    failure = (
        f"the {law_name!r} elastic-plastic formula never crosses the Hertz curve for this pair "
        f"(nu={nu!r}, S_y/E*={Sy / E!r}), so no continuous switch exists; use published_switch=1"
    )
    search = (1e-4 * dc, dlim)
    d_sw, jump = switch_point(p, ka.GAP_JACKSON_FAMILY, d_pub, search, published, failure)
    p[k.P_DSW] = d_sw
    return {
        "C": C,
        "B": B,
        "delta_c": dc,
        "F_c": fc,
        "switch_interference": d_sw,
        "switch_ratio": d_sw / dc,
        "switch_force": float(k.loading_force(k.GHAEDNIA, p, d_sw)),
        "published_jump": jump,
        "full_contact_interference": d_full,
        "calibrated_max_interference": calibrated_max(law, dc, dlim, p),
    }
