"""Verification of the ``partial_slip`` friction model: cases, reference values and
the sphere runs behind the tests (tests/dynamics/test_partial_slip*.py) and the verification
page (``partial_slip_page``).

Reference values ("exact M-D") are the exact Mindlin-Deresiewicz solution of the same impact,
computed by an independent fixed-step method-of-dimensionality-reduction (MDR) solution: 600
elements, 20 000 velocity-Verlet steps, converged to ~1e-5 in e_t. They are a solution of the
continuous model, not of the discretised one; rounded to 5 digits here. The MDR program and its
results (``research/partial_slip/``: ``mdr.py``, ``results/*.json``, ``RESULTS.md``) are in the
git history, last in commit 98a4405. ``NU_EXACT`` (nu = 0.1-0.45, small psi1) comes from the
same method in ``impactlab.verification.partial_slip_mdr`` (3200 elements, 6 digits), which
reproduces ``MBF_EXACT`` and ``KGS_EXACT`` to 4e-5.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab.bodies import Sphere
from impactlab.dynamics import simulate
from impactlab.dynamics.checks import check_impact
from impactlab.dynamics.partial_slip import simulate_partial_slip
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material
from impactlab.verification.data.kharaz2001 import KGS_ET, KGS_OMEGA

__all__ = [
    "ALUMINA",
    "GLASS",
    "KGS_EXACT",
    "KGS_SPEED",
    "MBF_EXACT",
    "NU_EXACT",
    "THORNTON_EXACT",
    "SphereCase",
    "kharaz_case",
    "kharaz_rms",
    "kharaz_run",
    "mbf_case",
    "nu_case",
    "psi_velocity",
    "rigid_coulomb",
    "thornton_case",
]

# Kharaz, Gorham & Salman, Powder Technol. 120 (2001) 281, doi:10.1016/S0032-5910(01)00283-2:
# 5 mm alumina spheres on a thick soda-lime glass anvil, 3.9 m/s, mu = 0.092. Elastic constants
# as tabulated for this experiment by Di Renzo & Di Maio (2004, doi:10.1016/j.ces.2003.09.037)
# and reused by the MFIX DEM05 case and Lethe; the yield strengths are placeholders (the Hertz
# law does not use them).
ALUMINA = Material("alumina (Kharaz 2001)", E=380e9, nu=0.23, yield_strength=5e9, density=4000.0)
GLASS = Material(
    "soda-lime glass (Kharaz 2001)", E=70e9, nu=0.25, yield_strength=3e9, density=2500.0
)
KGS_SPEED = 3.9
KGS_MU = 0.092
#: MBF's solid sphere: steel on steel, nu = 0.3 (chi = 1.441), mu = 0.3, |v_n| = 1 m/s.
STEEL_NU30 = Material("steel nu=0.30", E=200e9, nu=0.30, yield_strength=1e9, density=7800.0)

#: Kharaz case, exact M-D: theta [deg], e_t = v_x,out / v_x,in, rebound spin [rad/s].
KGS_EXACT = np.array(
    [
        [1.0, 0.78473, -14.65],
        [2.0, 0.77407, -30.75],
        [4.0, 0.74965, -68.11],
        [6.0, 0.72151, -113.53],
        [10.0, 0.63643, -246.22],
        [15.0, 0.59041, -413.44],
        [20.0, 0.59221, -543.94],
        [30.0, 0.68130, -621.46],
        [40.0, 0.78072, -549.71],
        [60.0, 0.89377, -358.80],
    ]
)
#: MBF solid sphere, exact M-D: psi1, psi2 (MBF's sign: < 0 = contact point rebounds backwards),
#: e_t, normalised spin -omega R / (mu |v_n|).
MBF_EXACT = np.array(
    [
        [0.05, 0.01094, 0.77678, 0.03388],
        [0.65455, 0.03179, 0.72816, 0.54014],
        [1.375, -0.32121, 0.64754, 1.47120],
        [2.25, -1.01238, 0.58573, 2.82961],
        [3.125, -1.41585, 0.58484, 3.93850],
        [4.0, -1.43651, 0.61168, 4.71534],
        [4.875, -0.88971, 0.66214, 5.0],
        [5.75, -0.01471, 0.71355, 5.0],
        [7.5, 1.73529, 0.78039, 5.0],
        [9.5, 3.73529, 0.82663, 5.0],
    ]
)

#: Steel spheres (E = 200 GPa, 7800 kg/m^3, R = 5 mm) on the same steel, mu = 0.3, |v_n| = 1 m/s,
#: Hertz, nu = 0.1-0.45, exact M-D by ``partial_slip_mdr`` (3200 elements): nu, psi1, e_t, psi2
#: (MBF's sign, as ``MBF_EXACT``); nine psi1 for each nu: the verification page's accuracy table.
# fmt: off
NU_EXACT = np.array(
    [
        [0.10, 0.01, 0.818423, 0.003645], [0.10, 0.03, 0.817668, 0.010855],
        [0.10, 0.05, 0.816919, 0.017961], [0.10, 0.1, 0.815071, 0.035275],
        [0.10, 0.2, 0.811450, 0.068015], [0.10, 0.4, 0.804084, 0.125718],
        [0.10, 1, 0.770943, 0.198301], [0.10, 2.25, 0.628748, -0.673610],
        [0.10, 4, 0.606447, -1.509744], [0.20, 0.01, 0.804441, 0.003155],
        [0.20, 0.03, 0.803341, 0.009351], [0.20, 0.05, 0.802248, 0.015393],
        [0.20, 0.1, 0.799542, 0.029840], [0.20, 0.2, 0.794171, 0.055919],
        [0.20, 0.4, 0.782831, 0.095964], [0.20, 1, 0.738112, 0.083391],
        [0.20, 2.25, 0.607355, -0.842078], [0.20, 4, 0.606383, -1.510637],
        [0.30, 0.01, 0.779744, 0.002291], [0.30, 0.03, 0.778273, 0.006719],
        [0.30, 0.05, 0.776803, 0.010940], [0.30, 0.1, 0.773120, 0.020592],
        [0.30, 0.2, 0.765658, 0.035960], [0.30, 0.4, 0.749953, 0.049934],
        [0.30, 1, 0.697230, -0.059695], [0.30, 2.25, 0.585730, -1.012376],
        [0.30, 4, 0.611678, -1.436512], [0.40, 0.01, 0.740690, 0.000924],
        [0.40, 0.03, 0.738814, 0.002575], [0.40, 0.05, 0.736936, 0.003964],
        [0.40, 0.1, 0.732233, 0.006282], [0.40, 0.2, 0.722769, 0.005938],
        [0.40, 0.4, 0.703611, -0.014944], [0.40, 1, 0.648653, -0.229716],
        [0.40, 2.25, 0.565238, -1.173753], [0.40, 4, 0.628187, -1.205384],
        [0.45, 0.01, 0.714569, 0.000010], [0.45, 0.03, 0.712516, -0.000186],
        [0.45, 0.05, 0.710465, -0.000669], [0.45, 0.1, 0.705348, -0.003128],
        [0.45, 0.2, 0.695159, -0.013389], [0.45, 0.4, 0.675099, -0.054861],
        [0.45, 1, 0.621728, -0.323952], [0.45, 2.25, 0.556270, -1.244373],
        [0.45, 4, 0.645161, -0.967742],
    ]
)
# fmt: on
#: Thornton's representation, AISI 201 sphere (R = 5 mm) on AISI 1010, mu = 0.3, exact M-D:
#: (law, |v_n| [m/s]) -> rows Psi, e_t, Omega = 2 omega R / (mu (1 + e) |v_n|) (magnitude).
THORNTON_EXACT = {
    ("hertz", 1.0): np.array(
        [
            [0.1, 0.77439, 0.0564],
            [1.24, 0.69506, 0.9453],
            [2.6667, 0.58722, 2.75186],
            [4.6667, 0.60530, 4.60484],
            [6.6667, 0.7, 5.0],
            [14.0, 0.85714, 5.0],
        ]
    ),
    ("thornton", 0.5): np.array(
        [
            [0.1, 0.53065, 0.11734],
            [1.24, 0.79758, 0.62749],
            [2.6667, 0.76649, 1.55675],
            [4.6667, 0.66225, 3.9404],
            [6.6667, 0.7, 5.0],
            [14.0, 0.85714, 5.0],
        ]
    ),
}


@dataclass(frozen=True)
class SphereCase:
    """A sphere impact family: body, flat, law, mu and the normal speed |v_n| [m/s]."""

    body: Sphere
    flat: Material
    law: str
    mu: float
    vn: float

    @property
    def eta(self) -> float:
        """4 G*/E*: full-stick tangential over normal tangent stiffness."""
        pair = ContactPair(self.body.material, self.flat)
        return 4.0 * pair.G_star / pair.E_star

    @property
    def chi(self) -> float:
        """Maw-Barber-Fawcett's chi = (eta/2)(1 + m R^2 / I)."""
        b = self.body
        return 0.5 * self.eta * (1.0 + self.mass * b.radius**2 / b.inertia)

    @property
    def mass(self) -> float:
        """The sphere's mass [kg]."""
        return float(self.body.inertia / (0.4 * self.body.radius**2))

    def run(
        self, vt: float, friction: str = "partial_slip", vn: float | None = None,
        n_cells: int | None = None,
    ) -> dict[str, float]:  # fmt: skip
        """One impact (no gravity) with tangential velocity ``vt`` and normal speed ``vn``
        (default the case's) [m/s]: e, e_t, spin [rad/s] and the slip velocity out [m/s].
        ``n_cells``: the ``partial_slip`` cells (default ``PARTIAL_SLIP_CELLS``, as
        ``simulate``)."""
        vn = self.vn if vn is None else vn
        if n_cells is None:
            r = simulate(
                self.body, self.flat, law=self.law, friction=friction, mu=self.mu,
                velocity=(vt, -vn), gravity=False, history=False,
            )  # fmt: skip
        else:
            if friction != "partial_slip":
                raise ValueError(f"n_cells = {n_cells} needs friction='partial_slip', not "
                                 f"{friction!r}")  # fmt: skip
            x = check_impact(
                self.body, self.flat, law=self.law, friction=friction, mu=self.mu, angle=None,
                velocity=(vt, -vn), spin=0.0, law_params=None, gravity=False,
                constant_angle=False, rtol=None,
            )  # fmt: skip
            r = simulate_partial_slip(x, False, n_cells)
        vx = r.velocity_out[0]
        vslip = vx + r.spin_out * self.body.radius
        return {"e": r.e, "et": vx / vt, "spin": r.spin_out, "vslip": vslip}


def kharaz_case() -> SphereCase:
    """Kharaz-Gorham-Salman: 5 mm alumina sphere on glass, 3.9 m/s, mu = 0.092 (Hertz)."""
    return SphereCase(Sphere(radius=2.5e-3, material=ALUMINA), GLASS, "hertz", KGS_MU, KGS_SPEED)


def kharaz_run(theta_deg: float, friction: str = "partial_slip") -> dict[str, float]:
    """The Kharaz impact at incidence ``theta_deg`` from the normal."""
    th = math.radians(theta_deg)
    return kharaz_case().run(KGS_SPEED * math.sin(th), friction, KGS_SPEED * math.cos(th))


def mbf_case(mu: float = 0.3, vn: float = 1.0) -> SphereCase:
    """Maw-Barber-Fawcett's solid sphere: steel (nu = 0.3) on steel, R = 5 mm, Hertz."""
    return SphereCase(Sphere(radius=5e-3, material=STEEL_NU30), STEEL_NU30, "hertz", mu, vn)


def nu_case(nu: float) -> SphereCase:
    """A steel sphere (E = 200 GPa, Poisson's ratio ``nu``, R = 5 mm) on the same steel, mu = 0.3,
    |v_n| = 1 m/s, Hertz: the cases of ``NU_EXACT`` (``nu_case(0.3)`` is ``mbf_case()``)."""
    if not 0.0 <= nu < 0.5:
        raise ValueError(f"nu = {nu}: Poisson's ratio must be in [0, 0.5)")
    mat = Material(f"steel nu={nu:g}", E=200e9, nu=nu, yield_strength=1e9, density=7800.0)
    return SphereCase(Sphere(radius=5e-3, material=mat), mat, "hertz", 0.3, 1.0)


def thornton_case(law: str, vn: float, mu: float = 0.3) -> SphereCase:
    """Thornton's representation: AISI 201 sphere (R = 5 mm) on AISI 1010."""
    return SphereCase(Sphere(radius=5e-3, material=AISI_201), AISI_1010, law, mu, vn)


def rigid_coulomb(case: SphereCase, vt: float, e: float) -> dict[str, float]:
    """Rigid-body Coulomb (Stronge, doi:10.1017/CBO9780511626432) for a sphere without initial
    spin: slides throughout, or slides then rolls. e_t and spin [rad/s]."""
    b, m = case.body, case.mass
    k = 1.0 + m * b.radius**2 / b.inertia
    pn = m * (1.0 + e) * case.vn
    pt = -case.mu * pn if vt - k * case.mu * pn / m >= 0.0 else -m * vt / k
    vx = vt + pt / m
    return {"et": vx / vt, "spin": b.radius * pt / b.inertia}


def psi_velocity(case: SphereCase, psi: float, e: float) -> float:
    """v_t for Thornton's Psi = 2 tan(theta) / (mu (1 + e))."""
    return psi * case.mu * (1.0 + e) * case.vn / 2.0


def kharaz_rms(friction: str = "partial_slip") -> tuple[float, float]:
    """RMS deviation of e_t and of |spin| [rad/s] from the Kharaz data (all digitised points)."""
    det = [kharaz_run(t, friction)["et"] - v for t, v in KGS_ET]
    dw = [abs(kharaz_run(t, friction)["spin"]) - v for t, v in KGS_OMEGA]
    return float(np.sqrt(np.mean(np.square(det)))), float(np.sqrt(np.mean(np.square(dw))))
