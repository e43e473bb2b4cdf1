"""Materials and cases shared by the prototype scripts (SI units)."""

from __future__ import annotations

import math

import impactlab as il
import numpy as np
from impactlab.contact import get_law
from impactlab.materials import ContactPair

# Kharaz, Gorham & Salman, Powder Technol. 120 (2001) 281-291, doi:10.1016/S0032-5910(01)00283-2:
# 5 mm alumina (aluminium oxide) spheres on a thick soda-lime glass anvil, 3.9 m/s, mu = 0.092,
# e_n ~ 0.98. Elastic constants as tabulated for this experiment by Di Renzo & Di Maio (2004)
# and reused by the MFIX DEM05 verification case and the Lethe example (alumina E = 380 GPa,
# nu = 0.23, rho = 4000 kg/m^3; glass E = 70 GPa, nu = 0.25). Yield strengths are placeholders
# (not used by the Hertz law).
ALUMINA = il.Material("alumina (Kharaz 2001)", E=380e9, nu=0.23, yield_strength=5e9,
                      density=4000.0)
GLASS = il.Material("soda-lime glass (Kharaz 2001)", E=70e9, nu=0.25, yield_strength=3e9,
                    density=2500.0)
KGS_R = 2.5e-3
KGS_V = 3.9
KGS_MU = 0.092
KGS_EN = 0.98


class Case:
    """A sphere, a flat, a law and mu: everything an impact needs."""

    def __init__(self, body_mat, flat_mat, R, law="hertz", mu=0.092, law_params=None,
                 density=None):
        self.body = il.Sphere(radius=R, material=body_mat, density=density)
        self.flat = flat_mat
        self.R = R
        self.m = self.body.mass
        self.I = self.body.inertia
        pair = ContactPair(body_mat, flat_mat)
        self.Es = pair.E_star
        self.Gs = pair.G_star
        self.model = get_law(law).build(pair, R, **(law_params or {}))
        self.law = law
        self.law_params = dict(law_params or {})
        self.law_id = int(self.model.law_id)
        self.p = np.array(self.model.params, dtype=np.float64)
        self.mu = mu

    @property
    def eta(self):
        """4 G*/E*: ratio of the full-stick tangential to the normal tangent stiffness."""
        return 4.0 * self.Gs / self.Es

    @property
    def chi(self):
        """Maw-Barber-Fawcett's chi = (eta/2) (1 + R^2/k^2) = (eta/2)(1 + m R^2/I)."""
        return 0.5 * self.eta * (1.0 + self.m * self.R**2 / self.I)

    def hertz_time(self, vn):
        """Hertz contact duration for a normal speed vn [s]."""
        return 2.868 * (self.m**2 / (self.R * self.Es**2 * abs(vn))) ** 0.2


def kharaz_case(law="hertz", law_params=None, mu=KGS_MU):
    return Case(ALUMINA, GLASS, KGS_R, law=law, mu=mu, law_params=law_params)


def velocities(V, theta_deg):
    """(vt, vn) of the centre for speed V at theta from the normal (vn < 0)."""
    th = math.radians(theta_deg)
    return V * math.sin(th), -V * math.cos(th)
