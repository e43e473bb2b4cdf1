"""Brake (2015): elastic-plastic contact with strain hardening (the paper's Sec. 3.4).

- Yield (paper Eq. 23, corrected): delta_y = R (pi S_y / (2 E*))^2 / F(nu),
  F(nu) = [max_{z>=0} {-(1 + nu)[1 - (z/a) atan(a/z)] + (3/2) / (1 + (z/a)^2)}]^2,
  the von Mises (= Tresca) stress on the axis below a Hertz contact, maximised over depth z
  (numerically, once per build). The paper prints (1 - nu) and z/r.
- Transition (paper Eq. 24 with sqrt(R) and a = sqrt(2 R delta)), x = (delta - delta_y) /
  (delta_p - delta_y), n_e = n - 2:
  F = sech[(1 + n_e) x] (4/3) E* sqrt(R) delta^1.5 + {1 - sech[(1 - n_e) x]} P0 pi a^n / a_p^(n-2);
  the result is capped at the Hertz force (see below).
- P0 = 1e6 H g (Eq. 25, H a Brinell number in kgf/mm^2, g = 9.80665 m/s^2); default
  H = (2/H_body + 2/H_flat)^-1 as printed.
- delta_p (Eq. 26) in closed form: delta_p = R (3 pi P0 / (2 E*))^2, a_p = sqrt(2 R delta_p),
  independent of the Meyer index n.
- Unloading: delta_r = delta_m [1 - F_m / ((4/3) E* sqrt(R) delta_m^1.5)], R_r from continuity
  (the printed Eq. 27 is dimensionally wrong).

Deviation: for Meyer indices close to 2 the printed Eq. 24 rises up to a few per cent above the
Hertz force just after yield, which would make delta_r negative and let unloading return more
energy than loading took. The loading force is therefore min(Eq. 24, Hertz): identical to
Eq. 24 wherever Eq. 24 <= Hertz (always for the paper's pair with n = 2.2).

Reference: M. R. W. Brake, An analytical elastic plastic contact model with strain hardening
and frictional effects for normal and oblique impacts, Int. J. Solids Struct. 62 (2015)
104-123, doi:10.1016/j.ijsolstr.2015.02.019 (elastic-perfectly plastic predecessor: Brake,
Int. J. Solids Struct. 49 (2012) 3129-3141). See docs/laws/brake.md.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab._validation import check_positive
from impactlab.contact import kernel_arrays as ka
from impactlab.contact import kernels as k
from impactlab.contact._common import pair_constants
from impactlab.contact.base import ContactLaw, Parameter
from impactlab.contact.names import Law
from impactlab.materials import G0, ContactPair


def brake_yield_function(nu: float) -> tuple[float, float]:
    """(F(nu), z/a at the maximum) of Brake's yield function (paper Eq. 23, corrected).

    F(nu) = [max_{z >= 0} g(z/a)]^2, g(s) = -(1 + nu)(1 - s atan(1/s)) + 1.5 / (1 + s^2): the
    axial von Mises stress below a Hertz contact divided by the peak pressure p_0.
    """
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu must lie in (-1, 0.5), got {nu!r}")
    from scipy.optimize import minimize_scalar  # on first use: ``import impactlab`` stays light

    def neg_g(s: float) -> float:
        return -(-(1.0 + nu) * (1.0 - s * math.atan(1.0 / s)) + 1.5 / (1.0 + s * s))

    opt = minimize_scalar(neg_g, bounds=(1e-9, 10.0), method="bounded", options={"xatol": 1e-12})
    g_max = -float(opt.fun)
    g0 = 0.5 - nu  # g at the surface (s -> 0)
    if g0 > g_max:  # the maximum sits at the surface (only for strongly negative nu)
        return g0 * g0, 0.0
    return g_max * g_max, float(opt.x)


def brake_plastic_interference(E_star: float, radius: float, P0: float) -> float:
    """delta_p = R (3 pi P0 / (2 E*))^2 [m]: closed-form root of paper Eq. 26 (any n)."""
    return radius * (3.0 * math.pi * P0 / (2.0 * E_star)) ** 2


def brake_eq26_residual(delta: float, E_star: float, radius: float, P0: float, n: float) -> float:
    """Printed Eq. 26 written as g(delta) = sqrt(2 delta R) - [3 P0/(4 E*) 2^(n/2) pi
    R^((n-1)/2) delta^((n-3)/2)]^(1/(n-2)); its root is delta_p (used by the tests)."""
    rhs = (
        3.0
        * P0
        / (4.0 * E_star)
        * 2.0 ** (n / 2.0)
        * math.pi
        * radius ** ((n - 1.0) / 2.0)
        * delta ** ((n - 3.0) / 2.0)
    ) ** (1.0 / (n - 2.0))
    return math.sqrt(2.0 * delta * radius) - rhs


class Brake(ContactLaw):
    law = Law.BRAKE
    title = "Brake 2015 elastic-plastic with strain hardening, the paper's Sec. 3.4"
    reference = "Brake, Int. J. Solids Struct. 62 (2015) 104-123; paper Eqs. 23-27"
    validity = (
        "elastic-plastic, strain hardening through Meyer's law, frictionless normal contact; "
        "Eq. 24 must be monotone (checked at build); hard limit delta = R/2 (a = sqrt(2 R delta)"
        " reaches R)"
    )
    parameters = (
        Parameter(
            "hardness",
            math.nan,
            "kgf/mm^2",
            "Brinell hardness H in P0 = 1e6 H g (Eq. 25); alternatives: the softer material's "
            "HB, or the harmonic combination (1/H_body + 1/H_flat)^-1",
            default_note="(2/H_body + 2/H_flat)^-1 as printed",
        ),
        Parameter(
            "meyer_index",
            math.nan,
            "1",
            "Meyer's strain-hardening index n (2 < n < 3), n_e = n - 2",
            default_note="meyer_index of the material that yields first",
        ),
    )

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> dict[str, float]:
        E, R, Sy, nu = pair_constants(p)
        hb = values["hardness"]
        if math.isnan(hb):
            if not (pair.body.has_hardness and pair.flat.has_hardness):
                sides = ((pair.body, "body"), (pair.flat, "flat"))
                lacking = [(m, side) for m, side in sides if not m.has_hardness]
                names = list(dict.fromkeys(repr(m.name) for m, _ in lacking))
                missing = " and ".join(names)
                has, it = ("have", "them") if len(names) > 1 else ("has", "it")
                keys = " and ".join(f"{side}_brinell_hardness" for _, side in lacking)
                raise ValueError(
                    f"hardness: Brake's law needs the Brinell hardness of both materials, and "
                    f"{missing} {has} none; give {it} a brinell_hardness in kgf/mm^2 (HB=...; in "
                    f"a sweep study: {keys}), or the combined value as a law parameter, "
                    "law_params={'hardness': ...} in kgf/mm^2 (a [law_params] table in a "
                    "--config file on the command line, or in a study whose only law is brake)"
                )
            hb = 1.0 / (2.0 / pair.body.brinell_hardness + 2.0 / pair.flat.brinell_hardness)
        hb = check_positive("hardness", hb, "kgf/mm^2")
        n = values["meyer_index"]
        if math.isnan(n):
            n = pair.weaker.meyer_index
        if not 2.0 < n < 3.0:
            raise ValueError(f"meyer_index must lie in (2, 3) for Brake's Eq. 24, got {n!r}")
        fnu, z_over_a = brake_yield_function(nu)
        dy = R * (math.pi * Sy / (2.0 * E)) ** 2 / fnu
        P0 = 1.0e6 * hb * G0
        # delta_p must lie below the hard limit R/2, or the plastic branch is never reached
        p0_max = 2.0 * E * math.sqrt(0.5) / (3.0 * math.pi)
        if not P0 < p0_max:
            raise ValueError(
                f"hardness = {hb!r} kgf/mm^2 gives P0 = {P0:.4g} Pa, whose delta_p = R (3 pi P0 "
                f"/ (2 E*))^2 lies beyond the law's hard limit R/2: Brake's plastic branch would "
                f"never be reached; allowed hardness < {p0_max / (1.0e6 * G0):.4g} kgf/mm^2 "
                "(a Brinell number HB, in kgf/mm^2: check the unit)"
            )
        dp = brake_plastic_interference(E, R, P0)
        if not dp > dy:
            raise ValueError(
                f"hardness = {hb!r} kgf/mm^2 gives P0 = {P0:.4g} Pa and delta_p = {dp:.4g} m <= "
                f"delta_y = {dy:.4g} m; Brake's Eq. 24 needs delta_p > delta_y, i.e. P0 > "
                f"{math.sqrt(dy / R) * 2.0 * E / (3.0 * math.pi):.4g} Pa"
            )
        p[k.P_DY] = dy
        p[k.P_FY] = float(k.hertz_force(E, R, dy))
        p[k.P_DSW] = dy
        p[k.P_DLIM] = 0.5 * R
        p[k.P_BR_DP] = dp
        p[k.P_BR_P0] = P0
        p[k.P_BR_N] = n
        p[k.P_BR_AP] = math.sqrt(2.0 * R * dp)
        # Eq. 24 must give a monotone loading curve (it does not for n near 3 or delta_p near
        # delta_y): check on a fine grid from delta_y to the hard limit.
        grid = np.concatenate(
            [
                dy + (dp - dy) * np.linspace(0.0, 40.0, 8001)[1:],
                np.geomspace(dy + 40.0 * (dp - dy), 0.5 * R, 2000),
            ]
        )
        grid = grid[grid <= 0.5 * R]
        f = ka.loading_force_array(k.BRAKE, p, grid)
        if np.any(np.diff(f) < -1e-12 * f[1:]):
            i = int(np.argmax(np.diff(f) < -1e-12 * f[1:]))
            raise ValueError(
                f"meyer_index = {n!r}: Brake's Eq. 24 is not monotone for this pair "
                f"(delta_p/delta_y = {dp / dy:.4g}; the force decreases beyond delta = "
                f"{grid[i]:.4g} m); use a smaller meyer_index or a larger hardness"
            )
        eq24 = np.array([k.brake_eq24_force(p, float(x)) for x in grid])
        fh = k.hertz_force(E, R, 1.0) * grid**1.5
        return {
            "F_nu": fnu,
            "z_over_a_at_yield": z_over_a,
            "delta_y": dy,
            "F_y": float(p[k.P_FY]),
            "hardness_HB": hb,
            "P0": P0,
            "meyer_index": n,
            "delta_p": dp,
            "a_p": float(p[k.P_BR_AP]),
            "max_eq24_over_hertz": float(np.max(eq24 / fh)),
            "switch_interference": dy,
        }
