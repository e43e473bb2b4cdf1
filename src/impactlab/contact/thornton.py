"""Thornton (1997): elastic-perfectly plastic sphere with a limiting contact pressure p_y.

Loading: Hertz until the Hertz peak pressure p_0 = 2 E* a/(pi R) reaches p_y, i.e. until
delta_y = R (pi p_y / (2 E*))^2 (F_y = Hertz at delta_y); beyond it the pressure is capped at
p_y while a^2 = R delta still holds, so F = F_y + pi p_y (a^2 - a_y^2)
= F_y + pi p_y R (delta - delta_y).
Unloading: Hertzian with the radius R_p that keeps the contact radius a_m = sqrt(R delta_m):
R_p = 4 E* a_m^3 / (3 F_m), delta_r = delta_m - a_m^2/R_p = delta_m - 3 F_m / (4 E* a_m); R_r
from continuity then equals R_p.

Default p_y = C(nu) S_y with Green's C(nu) = 1.295 exp(0.736 nu): the Hertz peak pressure at
first yield (von Mises), so Thornton's yield onset coincides with Jackson-Green's delta_c.

Closed forms (derived in docs/laws/thornton.md) for a body of mass m hitting the flat at V:
V_y^2 = pi^5 p_y^5 R^3 / (30 E*^4 m) and, for V >= V_y with s = V_y/V,
e^2 = (6 sqrt3 / 5) (1 - s^2/6) [s / (s + 2 sqrt(6/5 - s^2/5))]^(1/2).

Reference: C. Thornton, Coefficient of restitution for collinear collisions of elastic-
perfectly plastic spheres, J. Appl. Mech. 64 (1997) 383-386, doi:10.1115/1.2787319.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab._validation import check_array_finite, check_positive
from impactlab.contact import kernels as k
from impactlab.contact._common import jg_C, jg_critical, pair_constants
from impactlab.contact.base import ContactLaw, Parameter
from impactlab.contact.names import Law
from impactlab.materials import ContactPair


def thornton_yield_interference(E_star: float, radius: float, p_y: float) -> float:
    """delta_y = R (pi p_y / (2 E*))^2 [m]: Hertz peak pressure equals p_y."""
    E = check_positive("E_star", E_star, "Pa")
    R = check_positive("radius", radius, "m")
    py = check_positive("p_y", p_y, "Pa")
    return R * (math.pi * py / (2.0 * E)) ** 2


def thornton_yield_velocity(E_star: float, radius: float, mass: float, p_y: float) -> float:
    """Impact speed at which Thornton's law just reaches p_y [m/s], for a body of ``mass`` [kg]
    whose spherical tip of ``radius`` [m] hits a rigidly supported flat (E_star [Pa], p_y [Pa]).

    From 1/2 m V_y^2 = (2/5) F_y delta_y: V_y = sqrt(pi^5 p_y^5 R^3 / (30 E*^4 m)). For a solid
    sphere (m = 4/3 pi R^3 rho) this is Thornton's V_y = 1.56 sqrt(p_y^5 / (E*^4 rho)).
    """
    E = check_positive("E_star", E_star, "Pa")
    R = check_positive("radius", radius, "m")
    m = check_positive("mass", mass, "kg")
    py = check_positive("p_y", p_y, "Pa")
    return math.sqrt(math.pi**5 * py**5 * R**3 / (30.0 * E**4 * m))


def thornton_restitution(v_ratio: Any) -> Any:
    """Thornton's coefficient of restitution e(V/V_y) (1 for V <= V_y); float or array.

    e = sqrt(6 sqrt3 / 5) sqrt(1 - s^2/6) [s / (s + 2 sqrt(6/5 - s^2/5))]^(1/4), s = V_y/V.
    """
    try:
        r = check_array_finite("v_ratio", v_ratio)
    except (TypeError, ValueError) as exc:
        if "v_ratio" in str(exc):
            raise
        raise ValueError(
            f"v_ratio must be a number or an array of numbers, got {v_ratio!r}"
        ) from None
    if np.any(r < 0.0):
        raise ValueError(f"v_ratio must be >= 0, got min {float(r.min())!r}")
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(r > 1.0, 1.0 / np.where(r > 1.0, r, 1.0), 1.0)
        e = (
            math.sqrt(6.0 * math.sqrt(3.0) / 5.0)
            * np.sqrt(1.0 - s * s / 6.0)
            * (s / (s + 2.0 * np.sqrt(6.0 / 5.0 - s * s / 5.0))) ** 0.25
        )
    e = np.where(r > 1.0, e, 1.0)
    if np.ndim(v_ratio) == 0:
        return float(e)
    return e


class Thornton(ContactLaw):
    law = Law.THORNTON
    title = "Thornton 1997 elastic-perfectly plastic"
    reference = "Thornton, J. Appl. Mech. 64 (1997) 383-386"
    validity = (
        "elastic-perfectly plastic sphere, Hertzian pressure truncated at p_y, a^2 = R delta "
        "kept after yield (small deformations); hard limit delta = R"
    )
    parameters = (
        Parameter(
            "limit_pressure_ratio",
            math.nan,
            "1",
            "p_y / S_y, Thornton's limiting contact pressure over the yield strength",
            default_note="C(nu) = 1.295 exp(0.736 nu) (first yield, Green 2005)",
        ),
    )

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> dict[str, float]:
        E, R, Sy, nu = pair_constants(p)
        ratio = values["limit_pressure_ratio"]
        if math.isnan(ratio):
            ratio = jg_C(nu)
        ratio = check_positive("limit_pressure_ratio", ratio)
        py = ratio * Sy
        dy = R * (math.pi * py / (2.0 * E)) ** 2
        if dy >= R:
            raise ValueError(
                f"limit_pressure_ratio = {ratio!r} puts Thornton's yield beyond delta = R"
            )
        p[k.P_TH_PY] = py
        p[k.P_DY] = dy
        p[k.P_FY] = float(k.hertz_force(E, R, dy))
        p[k.P_DSW] = dy
        p[k.P_DLIM] = R
        return {
            "p_y": py,
            "limit_pressure_ratio": ratio,
            "delta_y": dy,
            "F_y": float(p[k.P_FY]),
            "delta_c_jackson_green": jg_critical(E, R, Sy, nu)[0],
        }
