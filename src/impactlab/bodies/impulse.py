"""Instantaneous rigid-body impact at the contact point: Newton restitution, Coulomb friction.

The body (centre of mass C, mass m, I_C = m k^2) touches the flat at O with the lever arms
(a, b) = r_C - r_O of :func:`~impactlab.bodies.lever_arms`; x runs along the flat towards C, y up.
An impulse (P_t, P_n) at O changes the contact point's velocity (v_t, v_n) by

    m k^2 dv_t = (k^2 + b^2) P_t - a b P_n,    m k^2 dv_n = (k^2 + a^2) P_n - a b P_t

(Stronge, *Impact Mechanics* (2000) Ch. 5, doi:10.1017/CBO9780511626432). While the contact point
slips, P_t = q P_n with q = -mu sign(v_t); it sticks when friction can hold it, i.e. when
mu >= mu_c = a b / (k^2 + b^2). The impact ends when v_n = -e v_n0 (Newton's restitution of the
contact point's normal velocity). ``impactlab.analytic`` builds its closed forms (K_x, K_y, alpha,
mu_c) from :func:`impulse_response` and :func:`critical_ratio`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, cast

from impactlab._validation import check_finite, check_nonnegative, check_range
from impactlab.bodies.geometry import lever_arms
from impactlab.bodies.rod import Rod
from impactlab.bodies.sphere import Sphere

__all__ = ["RigidImpulse", "critical_ratio", "impulse_response", "rigid_impulse"]


def impulse_response(a: Any, b: Any, k2: Any, ratio: Any) -> tuple[Any, Any]:
    """(c_t, c_n) [m^2]: m k^2 times the change of the contact point's (v_t, v_n) per unit normal
    impulse when the tangential impulse is ``ratio`` times the normal one (towards +x):

        c_t = ratio (k^2 + b^2) - a b,    c_n = k^2 + a^2 - ratio a b.

    ``a``, ``b`` lever arms [m], ``k2`` = I_C / m [m^2], ``ratio`` dimensionless. Broadcasts; no
    validation. With ``ratio = mu`` these are the numerators of the paper's corrected K_x, K_y.
    """
    ab = a * b
    return ratio * (k2 + b * b) - ab, k2 + a * a - ratio * ab


def critical_ratio(a: Any, b: Any, k2: Any) -> Any:
    """mu_c = a b / (k^2 + b^2): the impulse ratio P_t / P_n that keeps the contact point at rest
    tangentially (dimensionless); a body at rest slips for mu < mu_c and sticks for mu >= mu_c."""
    return a * b / (k2 + b * b)


def jam_ratio(a: float, b: float, k2: float) -> float:
    """The impulse ratio P_t / P_n (towards +x, dimensionless) from which a slipping contact
    point is driven into the flat, c_n = k^2 + a^2 - ratio a b <= 0: (k^2 + a^2) / (a b), inf
    where a b <= 0 (Painleve's paradox; Stewart 2000, doi:10.1137/S0036144599360110)."""
    ab = a * b
    return (k2 + a * a) / ab if ab > 0.0 else math.inf


@dataclass(frozen=True)
class RigidImpulse:
    """Outcome of :func:`rigid_impulse` (SI units).

    ``regime``: "slip" (slips throughout, one direction), "stick" (ends at rest tangentially) or
    "reversal" (stops, then slips the other way); ``normal_impulse``, ``tangential_impulse``
    [N s] (P_n, P_t, P_t towards +x); ``velocity_out`` (vx, vy) [m/s] and ``spin_out`` [rad/s] of
    the centre of mass after the impact; ``contact_velocity_in``, ``contact_velocity_out``
    (v_t, v_n) [m/s] of the contact point; ``mu_effective`` = |P_t / P_n|; ``mu_critical`` =
    a b / (k^2 + b^2).
    """

    regime: str
    normal_impulse: float
    tangential_impulse: float
    velocity_out: tuple[float, float]
    spin_out: float
    contact_velocity_in: tuple[float, float]
    contact_velocity_out: tuple[float, float]
    mu_effective: float
    mu_critical: float


def _slip_rates(a: float, b: float, k2: float, m: float, ratio: float) -> tuple[float, float]:
    """(dv_t/dP_n, dv_n/dP_n) [1/kg] while slipping with P_t = ratio P_n; ValueError on a jam."""
    c_t, c_n = impulse_response(a, b, k2, ratio)
    if c_n <= 0.0:
        raise ValueError(
            f"slipping with the impulse ratio {ratio:g} would not stop the approach "
            "(jam, Painleve's paradox): no rigid-body solution"
        )
    return c_t / (m * k2), c_n / (m * k2)


def rigid_impulse(
    body: Rod | Sphere,
    angle: float,
    velocity: tuple[float, float],
    spin: float = 0.0,
    *,
    e: float,
    mu: float,
) -> RigidImpulse:
    """Rigid-body impact of ``body`` (a ``Rod`` or a ``Sphere``) at its contact point.

    ``angle`` [rad] in [0, pi/2] between the rod axis and the flat (no effect for a sphere),
    ``velocity`` (vx, vy) [m/s] of the centre of mass, ``spin`` [rad/s] counter-clockwise; ``e``
    in [0, 1] is Newton's restitution of the contact point's normal velocity, ``mu`` >= 0 the
    Coulomb coefficient (the quantities may also be strings with units or pint Quantities, as
    everywhere in the Python API). The contact point slips against its tangential velocity
    until it stops; from rest it sticks if mu >= mu_c, else it slips the way the normal impulse
    drives it. The normal impulse grows until v_n = -e v_n0. ValueError if the contact point does
    not approach the flat or the slip jams (Painleve's paradox).
    """
    th = check_range("angle", angle, 0.0, 0.5 * math.pi, unit="rad")
    vx = check_finite("velocity[0]", velocity[0], "m/s")
    vy = check_finite("velocity[1]", velocity[1], "m/s")
    w = check_finite("spin", spin, "rad/s")
    e_ = check_range("e", e, 0.0, 1.0)
    mu_ = check_nonnegative("mu", mu)
    # the constructors always set the mass (Sphere: from the density) and the inertia (Rod:
    # m L^2 / 12 when not given); their fields are typed optional for the constructor only
    m, inertia = float(cast(float, body.mass)), float(cast(float, body.inertia))
    a, b = (float(x) for x in lever_arms(float(body.half_length), float(body.tip_radius), th))
    k2 = inertia / m
    vt0, vn0 = vx + w * b, vy - w * a
    if vn0 >= 0.0:
        raise ValueError(f"the contact point must approach the flat (v_n < 0), got {vn0!r} m/s")
    mu_c = float(critical_ratio(a, b, k2))
    left = (1.0 + e_) * -vn0  # normal velocity change still to come [m/s]
    p_n = p_t = 0.0
    regime = "slip"
    if vt0 != 0.0:  # slip against v_t until it stops or the impact ends
        q = -math.copysign(mu_, vt0)
        k_t, k_n = _slip_rates(a, b, k2, m, q)
        p_n = left / k_n
        if vt0 * k_t < 0.0 and -vt0 / k_t < p_n:  # the slip stops first
            p_n = -vt0 / k_t
            left -= k_n * p_n
        else:
            left = 0.0
        p_t = q * p_n
    if left > 0.0 and mu_ >= mu_c:  # at rest tangentially and friction holds it: stick
        dp = left * (m * (k2 + b * b)) / (k2 + a * a + b * b)
        p_n, p_t, regime = p_n + dp, p_t + mu_c * dp, "stick"
    elif left > 0.0:  # at rest, mu < mu_c (so a b > 0): slips towards -x
        _, k_n = _slip_rates(a, b, k2, m, mu_)
        dp = left / k_n
        regime = "reversal" if p_n > 0.0 else "slip"
        p_n, p_t = p_n + dp, p_t + mu_ * dp
    v_out = (vx + p_t / m, vy + p_n / m)
    w_out = w + (b * p_t - a * p_n) / inertia
    return RigidImpulse(
        regime=regime,
        normal_impulse=p_n,
        tangential_impulse=p_t,
        velocity_out=v_out,
        spin_out=w_out,
        contact_velocity_in=(vt0, vn0),
        contact_velocity_out=(v_out[0] + w_out * b, v_out[1] - w_out * a),
        mu_effective=abs(p_t / p_n),
        mu_critical=mu_c,
    )
