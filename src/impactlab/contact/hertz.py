"""Hertz elastic contact of a sphere on a flat.

F = 4/3 E* sqrt(R) delta^1.5, contact radius a = sqrt(R delta); no yield, no residual depth.
Reference: H. Hertz, J. reine angew. Math. 92 (1882) 156-171, doi:10.1515/crll.1882.92.156;
K. L. Johnson, Contact Mechanics (1985), Sec. 4.2, doi:10.1017/CBO9781139171731.
Validity: small strains, delta << R (enforced: delta <= R). Physically valid only below first
yield, delta_c of Jackson-Green (exposed as the calibrated range).
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.contact import kernels as k
from impactlab.contact._common import jg_critical, pair_constants
from impactlab.contact.base import ContactLaw
from impactlab.contact.names import Law
from impactlab.contact.ranges import calibrated_max
from impactlab.materials import ContactPair


class Hertz(ContactLaw):
    law = Law.HERTZ
    title = "Hertz (elastic)"
    reference = "Hertz, J. reine angew. Math. 92 (1882) 156; Johnson, Contact Mechanics (1985)"
    validity = "elastic, frictionless, delta <= R (small-strain theory: delta << R)"

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> dict[str, float]:
        p[k.P_DY] = math.inf
        p[k.P_FY] = math.inf
        p[k.P_DSW] = math.inf
        E, R, Sy, nu = pair_constants(p)
        dc, fc = jg_critical(E, R, Sy, nu)
        return {
            "delta_c": dc,
            "F_c": fc,
            "calibrated_max_interference": calibrated_max(self.law, dc, R, p),
        }
