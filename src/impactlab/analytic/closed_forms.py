"""The paper's closed forms for a rigid rod with a spherical tip, corrected (vectorised).

Source: H. Ghaednia, D. B. Marghitu, R. L. Jackson, Archive of Applied Mechanics 86 (2016)
121-134, doi:10.1007/s00419-015-1108-2, Eqs. 1-13, 28, 29 (the printed Eqs. 6, 10-13 contain
errors; derivation in ``docs/analytic.md``). The impulse relations are those of
:mod:`impactlab.bodies.impulse` (:func:`~impactlab.bodies.impulse_response`,
:func:`~impactlab.bodies.critical_ratio`) with the rod at rest tangentially and no spin;
Eq. 12's forms also take the tip's incoming tangential velocity ``vt_in`` (docs/analytic.md).

Signs: ``angle`` [rad] in [0, pi/2]; ``v_i`` [m/s] the tip's vertical velocity before impact
(negative, y up); ``delta_p`` [m] the permanent dent depth and a measured sliding length [m] are
magnitudes >= 0 (the paper prints both negative). The sliding length returned by
:func:`sliding_length` is the slip along +x, negative in gross sliding, as the engine's.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from impactlab._validation import check_gravity
from impactlab.analytic._inputs import (
    HALF_PI,
    arr,
    drop_speed,
    finite,
    gravity_flag,
    magnitude,
    out,
    rod_values,
)
from impactlab.analytic._inputs import angle as _angle
from impactlab.analytic._inputs import travel as _travel
from impactlab.bodies import Rod, critical_ratio, impulse_response
from impactlab.bodies import lever_arms as _lever_arms

#: Standard gravity [m/s^2].
G0 = 9.80665

#: The paper's DOI.
DOI = "10.1007/s00419-015-1108-2"

#: An angle this close to pi/2 [rad] (4 units in the last place) is 90 deg: the lever arm
#: a = (L/2) cos(angle) is taken as 0 there, not the 6e-17 L/2 of cos(pi/2) in floating point.
VERTICAL_ROUNDOFF = 4.0 * float(np.spacing(HALF_PI))
#: A |alpha| at or below this is zero within round-off (the closed forms give about 2e-16 at
#: 90 deg without the rule above): ``impact_duration`` refuses it as it refuses alpha = 0.
ALPHA_ROUNDOFF = 1e-12
#: What a mean force's closed form allows where F over- or underflows (never inf or 0).
_FORCE_ALLOWED = "a duration > 0 s at which F is finite and > 0; check the units (SI: s)"

__all__ = [
    "ALPHA_ROUNDOFF",
    "DOI",
    "G0",
    "alpha",
    "critical_friction",
    "friction_from_velocities",
    "impact_duration",
    "impulse_coefficients",
    "lever_arms",
    "mean_force_momentum",
    "mean_force_rigid",
    "sliding_length",
]


def coefficients(
    th: Any, mu: Any, m: Any, L: Any, R: Any, inertia: Any, travel: bool = False
) -> tuple[Any, ...]:
    """Unvalidated core: a, b, k^2, K_x, K_y, alpha, mu_c (arrays). With ``travel`` K_x and alpha
    refer to the tip sphere's centre (the contact patch) instead of the material point O."""
    a, b = _arms(0.5 * L, R, th)
    k2 = inertia / m
    kx_num, ky_num = impulse_response(a, b, k2, mu)
    if travel:  # lever arm of the sphere centre S: b - R
        bs = b - R
        kx_num = mu * (k2 + b * bs) - a * bs
    K_x = kx_num / (m * k2)
    K_y = ky_num / (m * k2)
    alpha_ = kx_num / ky_num
    mu_c = critical_ratio(a, b, k2)
    return a, b, k2, K_x, K_y, alpha_, mu_c


def _arms(half_length: Any, tip_radius: Any, th: Any) -> tuple[Any, Any]:
    """Unvalidated lever arms (a, b) [m]; at 90 deg within round-off cos(angle) ~ 6e-17 is no
    lever arm: a = 0 there (alpha and mu_c are 0)."""
    a, b = _lever_arms(half_length, tip_radius, th)
    return np.where(np.abs(th - HALF_PI) <= VERTICAL_ROUNDOFF, 0.0, a), b


def lever_arms(half_length: Any, tip_radius: Any, angle: Any) -> tuple[Any, Any]:
    """Lever arms (a, b) [m] from the first contact point O to the centre of mass C (paper
    Eq. 1): a = half_length cos(angle), b = half_length sin(angle) + tip_radius.

    ``half_length`` >= 0 [m] (L/2 for a rod, 0 for a sphere), ``tip_radius`` > 0 [m],
    ``angle`` [rad] in [0, pi/2]; each under the input rule of the other closed forms (a
    string with units, ``"20 deg"``, a pint Quantity; a bare angle is radians), ValueError
    naming the parameter otherwise; broadcasts. Within 4 units in the last place of pi/2
    the angle is 90 deg and a = 0. (``impactlab.bodies.lever_arms`` is the unchecked core.)
    """
    h = arr("half_length", half_length, unit="m", low=0.0)
    R = arr("tip_radius", tip_radius, unit="m", low=0.0, low_open=True)
    a, b = _arms(h, R, _angle(angle))
    return out(a), out(b)


def impulse_coefficients(
    angle: Any, mu: Any, rod: Rod | None = None, *, measure: str = "slip"
) -> tuple[Any, Any]:
    """Tip-velocity coefficients (K_x, K_y) [1/kg] in gross sliding: v_Ox = K_x P,
    v_Oy = v_i + K_y P, with P the normal impulse and P_x = mu P (paper Eqs. 8-9, corrected).

        K_x = [mu (k^2 + b^2) - a b] / (m k^2)
        K_y = [k^2 + a^2 - mu a b] / (m k^2)

    ``measure="travel"`` gives K_x for the tip sphere's centre, which the contact patch (and so the
    dent) follows: K_x = [mu (k^2 + b (b - R)) - a (b - R)] / (m k^2) (not in the paper; see
    docs/analytic.md). The default ``"slip"`` is the material point O, as the paper.

    ``angle`` [rad] in [0, pi/2], ``mu`` >= 0; ``rod`` defaults to the paper's rod. K_x < 0 means
    the tip slides towards -x (gross sliding, mu < mu_c); K_y > 0 throughout the sliding regime.
    """
    th = _angle(angle)
    mu_ = arr("mu", mu, low=0.0)
    m, L, R, inertia = rod_values(rod)
    _, _, _, K_x, K_y, _, _ = coefficients(th, mu_, m, L, R, inertia, _travel(measure))
    return out(K_x), out(K_y)


def alpha(angle: Any, mu: Any, rod: Rod | None = None, *, measure: str = "slip") -> Any:
    """alpha = K_x / K_y = [mu (k^2 + b^2) - a b] / [k^2 + a^2 - mu a b] (paper Eq. 13, corrected).

    Dimensionless. Negative in gross sliding (mu < mu_c), zero at mu = mu_c, positive beyond (where
    the tip sticks and Eq. 12 does not apply). ``angle`` [rad], ``mu`` >= 0; broadcasts.
    ``measure="travel"``: the ratio for the contact patch's travel (see
    :func:`impulse_coefficients`); it changes sign below mu_c, where rolling outweighs slip.
    """
    th = _angle(angle)
    mu_ = arr("mu", mu, low=0.0)
    m, L, R, inertia = rod_values(rod)
    return out(coefficients(th, mu_, m, L, R, inertia, _travel(measure))[5])


def critical_friction(angle: Any, rod: Rod | None = None) -> Any:
    """mu_c = a b / (k^2 + b^2): the tip slides throughout the impact for mu < mu_c and sticks from
    the start for mu >= mu_c (rod at rest tangentially, constant angle). Dimensionless; broadcasts.
    """
    th = _angle(angle)
    m, L, R, inertia = rod_values(rod)
    return out(coefficients(th, 0.0, m, L, R, inertia)[6])


def sliding_length(
    delta_p: Any,
    v_i: Any,
    duration: Any,
    angle: Any,
    mu: Any,
    rod: Rod | None = None,
    *,
    measure: str = "slip",
    vt_in: Any = 0.0,
) -> Any:
    """Sliding length L_s = vt_in T - alpha (delta_p + v_i T) [m] along +x (paper Eq. 12, sign
    fixed; the term vt_in T is not in the paper).

    ``delta_p`` >= 0 [m] is the dent depth (the paper's delta_p <= 0 is the final tip height, so
    its form reads L_s = alpha (delta_p - v_i T)), ``v_i`` the drop velocity [m/s] (sign
    ignored, |v_i| >= 1e-6 m/s, ``MIN_SPEED``, as everywhere in ``impactlab.analytic``;
    v_i = -|v_i| above), ``duration``
    T > 0 [s]. ``vt_in`` [m/s] is the incoming tangential velocity (along +x, signed) of the
    point whose displacement is measured: the contact point for the slip, v_Cx + b omega (spin
    included), the tip sphere's centre for the travel, v_Cx + (b - R) omega; <= 0 (default 0,
    the paper), so that the tip slides towards -x throughout (ValueError for > 0: the sliding
    reverses during the contact, docs/analytic.md). The result is the slip along +x, negative
    in gross sliding (the tip slides towards -x), as the engine's ``sliding_length``.
    ValueError in the sticking regime (mu >= mu_c), where L_s = 0, and for T < delta_p/|v_i|
    (a negative normal impulse). ``measure="travel"`` gives the contact patch's travel instead
    of the slip (gravity neglected).
    """
    dp = magnitude("delta_p", delta_p, "the permanent dent depth")
    vi = -drop_speed(v_i)
    T = arr("duration", duration, unit="s", low=0.0, low_open=True)
    vt = _one_direction(vt_in)
    th = _angle(angle)
    mu_ = arr("mu", mu, low=0.0)
    m, L, R, inertia = rod_values(rod)
    *_, al, mu_c = coefficients(th, mu_, m, L, R, inertia, _travel(measure))
    check_sliding(mu_, mu_c, th)
    _check_impulse(dp, -vi, T)
    ls = al * (-dp - vi * T)
    return out(ls + vt * T if (vt != 0).any() else ls)


def _one_direction(vt_in: Any, bounds: Callable[[Any], tuple[Any, Any]] | None = None) -> Any:
    """``vt_in`` [m/s] as a float array, checked <= 0: for vt_in > 0 the tip first slides
    towards +x and reverses, which Eq. 12 (one sliding direction) does not describe. With
    ``bounds`` (vt_in -> the arrays of T at vt_in = 0 and at vt_in [s]) the error gives the
    bounds of T there (docs/analytic.md)."""
    vt = arr("vt_in", vt_in, unit="m/s")
    if (vt > 0).any():
        i = int(np.argmax((vt > 0).ravel()))
        got = float(vt.ravel()[i])
        text = ""
        if bounds is not None:
            lo, hi = (float(np.broadcast_to(x, vt.shape).ravel()[i]) for x in bounds(vt))
            if math.isfinite(hi) and hi > 0:
                text = f"; T lies between {lo:.4g} s (the value for vt_in = 0) and {hi:.4g} s"
            else:  # vt_in >= |alpha| |v_i|
                text = "; this vt_in is so large that the tip may slide towards +x throughout"
        raise ValueError(
            f"vt_in must be <= 0 m/s (the tip sliding towards -x from the start), got {got!r} "
            "m/s: the tip first slides towards +x and its sliding reverses during the contact, "
            f"which Eq. 12 (one sliding direction) does not describe{text}"
        )
    return vt


def _check_impulse(dp: Any, vi: Any, T: Any) -> None:
    """ValueError where the duration T [s] is shorter than delta_p/|v_i| (magnitudes ``dp``
    [m], ``vi`` [m/s]): the tip would reach the dent's bottom only with a negative normal
    impulse, Q = (|v_i| T - delta_p)/K_y < 0."""
    least = dp / vi
    short = np.asarray(T < least)
    if short.any():
        i = int(np.argmax(short.ravel()))
        t = float(np.broadcast_to(T, short.shape).ravel()[i])
        lo = float(np.broadcast_to(least, short.shape).ravel()[i])
        raise ValueError(
            f"duration must be >= delta_p/|v_i| = {lo:.4g} s (at |v_i| the tip needs that long "
            f"to reach the dent's bottom; a shorter one implies a negative normal impulse), "
            f"got {t!r} s"
        )


def impact_duration(
    delta_p: Any,
    sliding_length: Any,
    v_i: Any,
    alpha_: Any,
    *,
    vt_in: Any = 0.0,
    gravity: bool = False,
    g: float = G0,
) -> Any:
    """Impact duration T [s] from the measured dent: Eq. 12 solved for T.

        T = (L_s / |alpha| + delta_p) / (|v_i| - vt_in / |alpha|)             (gravity neglected)
        (g/2) T^2 + (|v_i| - vt_in / |alpha|) T = L_s / |alpha| + delta_p      (gravity=True)

    (the paper's form has vt_in = 0). ``delta_p`` >= 0 [m] the dent depth (a negative value,
    the paper's sign, raises ValueError); ``sliding_length`` [m] the length of the scar, or the
    engine's signed ``sliding_length`` (its magnitude enters; != 0); ``v_i`` the drop velocity
    [m/s] (sign ignored, |v_i| >= 1e-6 m/s, ``MIN_SPEED``, as in :func:`invert`). ``alpha_``
    must be negative (gross sliding); ``alpha_ >= 0`` means the tip sticks and raises
    ValueError, as does a |alpha_| at round-off (<= ``ALPHA_ROUNDOFF``: zero, the rod vertical
    or mu at mu_c). ``vt_in`` [m/s] is the
    incoming tangential velocity (along +x, signed, spin included: see :func:`sliding_length`)
    of the point whose displacement is measured, <= 0 (ValueError for > 0, giving the bounds
    of T: the sliding reverses during the contact). A T that over- or underflows (inf, 0) is
    refused, naming the inputs.
    """
    dp = magnitude("delta_p", delta_p, "the permanent dent depth")
    ls = np.abs(arr("sliding_length", sliding_length, unit="m"))  # signed: along +x
    vi = drop_speed(v_i)
    al = arr("alpha_", alpha_)
    if (ls == 0).any():
        raise ValueError(
            "sliding_length must be non-zero: in gross sliding any normal "
            "impulse makes the tip slide, so a zero sliding length cannot be inverted"
        )
    if (al >= 0).any():
        raise ValueError(
            f"alpha_ must be < 0 (gross sliding), got {float(al.ravel()[np.argmax(al >= 0)])!r}: "
            "alpha >= 0 means mu >= mu_c, the tip sticks and Eq. 12 cannot give the duration"
        )
    zero = np.abs(al) <= ALPHA_ROUNDOFF
    if zero.any():
        raise ValueError(
            f"alpha_ must be < 0 beyond round-off (|alpha_| > {ALPHA_ROUNDOFF:g}), got "
            f"{float(al.ravel()[np.argmax(zero.ravel())])!r}: that is alpha = 0 (the rod "
            "vertical, or mu at mu_c), where the tip does not slide and T = L_s/(|alpha| |v_i|) "
            "is undefined"
        )
    g_, gravity = check_gravity("g", g), gravity_flag(gravity)
    ab = np.abs(al)

    def bounds(vt: Any) -> tuple[Any, Any]:
        with np.errstate(all="ignore"):
            hi = duration_from_dent(dp, ls, vi - vt / ab, ab, gravity, g_)
        return duration_from_dent(dp, ls, vi, ab, gravity, g_), hi

    vt = _one_direction(vt_in, bounds)
    with np.errstate(all="ignore"):
        T = duration_from_dent(dp, ls, vi - vt / ab if (vt != 0).any() else vi, ab, gravity, g_)
    given = {"delta_p": (dp, "m"), "sliding_length": (ls, "m"), "v_i": (vi, "m/s")}
    given |= {"alpha_": (al, ""), "vt_in": (vt, "m/s")}
    return out(finite("the duration T", T, "s", given, "a finite T > 0 s; check the units (SI)"))


def duration_from_dent(dp: Any, ls: Any, vi: Any, abs_alpha: Any, gravity: bool, g: float) -> Any:
    """Unvalidated Eq. 12 solved for T [s] from magnitudes (stable root with gravity); ``vi``
    [m/s] is |v_i| - vt_in/|alpha| with an incoming tangential velocity vt_in."""
    c = ls / abs_alpha + dp
    if not gravity or g == 0.0:
        return c / vi
    # stable root of (g/2) T^2 + vi T - c = 0
    return 2.0 * c / (vi + np.sqrt(vi * vi + 2.0 * g * c))


def friction_from_velocities(dv_cx: Any, dv_cy: Any, *, duration: Any = None, g: float = G0) -> Any:
    """Friction coefficient from the centre-of-mass velocity changes (paper Eq. 28) [-].

    mu = |dv_Cx| / dv_Cy. With ``duration`` T [s] the gravity impulse is removed from the
    vertical change: mu = |dv_Cx| / (dv_Cy + g T). ``dv_cx`` [m/s] (sign ignored); ``dv_cy``
    [m/s] the upward change, > 0 (ValueError otherwise: the normal impulse lifts the rod).
    """
    dx = arr("dv_cx", dv_cx, unit="m/s")
    dy = _upward("dv_cy", dv_cy)
    if duration is not None:
        T = arr("duration", duration, unit="s", low=0.0)
        dy = dy + check_gravity("g", g) * T
    return out(np.abs(dx) / dy)


def _upward(name: str, value: Any) -> Any:
    """The measured upward change of the centre-of-mass velocity [m/s] as a float array;
    ValueError naming ``name`` unless it is > 0 (the contact's normal impulse lifts the rod, the
    ``dv_cy`` of :func:`invert`)."""
    dy = arr(name, value, unit="m/s")
    bad = dy <= 0
    if bad.any():
        raise ValueError(
            f"{name} must be > 0 (the upward change of the centre-of-mass velocity over the "
            f"impact, m/s), got {float(dy.ravel()[np.argmax(bad.ravel())])!r} m/s"
        )
    return dy


def mean_force_momentum(
    duration: Any, mass: Any, dv_cy: Any, *, gravity: bool = False, g: float = G0
) -> Any:
    """Mean normal contact force [N] from the centre-of-mass momentum change (paper Eq. 29).

    F T = m dv_Cy (the paper), or F T = m dv_Cy + m g T with ``gravity=True`` (the measured change
    of the centre-of-mass velocity includes the gravity impulse, which the contact must overcome).
    ``duration`` T > 0 [s], ``mass`` > 0 [kg], ``dv_cy`` [m/s] the upward change, > 0; a
    force that over- or underflows (a duration of 1e-320 s: inf) is refused.
    """
    T = arr("duration", duration, unit="s", low=0.0, low_open=True)
    m = arr("mass", mass, unit="kg", low=0.0, low_open=True)
    dv = _upward("dv_cy", dv_cy)
    g_, gravity = check_gravity("g", g), gravity_flag(gravity)
    with np.errstate(all="ignore"):
        F = m * dv / T + (m * g_ if gravity else 0.0)
    given = {"duration": (T, "s"), "mass": (m, "kg"), "dv_cy": (dv, "m/s")}
    return out(finite("the mean force F", F, "N", given, _FORCE_ALLOWED))


def mean_force_rigid(
    duration: Any, e: Any, v_i: Any, K_y: Any, *, gravity: bool = False, g: float = G0
) -> Any:
    """Mean normal contact force [N] from the rigid-body identity (no centre-of-mass data needed).

    The tip's normal velocity goes from v_i to -e v_i: (1 + e)|v_i| = K_y P (- g T with gravity,
    which acts on C only and does not turn the rod), so F = (1 + e)|v_i| / (K_y T), or
    F = [(1 + e)|v_i| + g T] / (K_y T) with ``gravity=True``. ``e`` in [0, 1], ``K_y`` > 0 [1/kg],
    ``v_i`` [m/s] sign ignored, |v_i| >= 1e-6 m/s (``MIN_SPEED``, as :func:`invert`); a force
    that over- or underflows (a duration of 1e-320 s: inf) is refused.
    """
    T = arr("duration", duration, unit="s", low=0.0, low_open=True)
    e_ = arr("e", e, low=0.0, high=1.0)
    vi = drop_speed(v_i)
    Ky = arr("K_y", K_y, unit="1/kg", low=0.0, low_open=True)
    g_, gravity = check_gravity("g", g), gravity_flag(gravity)
    with np.errstate(all="ignore"):
        F = ((1.0 + e_) * vi + (g_ * T if gravity else 0.0)) / (Ky * T)
    given = {"duration": (T, "s"), "e": (e_, ""), "v_i": (vi, "m/s"), "K_y": (Ky, "1/kg")}
    return out(finite("the mean force F", F, "N", given, _FORCE_ALLOWED))


def check_sliding(mu: Any, mu_c: Any, th: Any) -> None:
    """ValueError (naming mu, mu_c and the angle) where mu >= mu_c: the tip sticks."""
    stick = np.asarray(mu >= mu_c)
    if stick.any():
        i = int(np.argmax(stick.ravel()))
        mu_v = float(np.broadcast_to(mu, stick.shape).ravel()[i])
        mc = float(np.broadcast_to(mu_c, stick.shape).ravel()[i])
        ang = math.degrees(float(np.broadcast_to(th, stick.shape).ravel()[i]))
        vertical = " (the rod stands vertical: no lever arm, mu_c = 0)" if mc == 0.0 else ""
        raise ValueError(
            f"sticking regime: mu = {mu_v:.4g} >= mu_c = {mc:.4g} at angle = {ang:.4g} deg"
            f"{vertical}, so alpha >= 0 and the tip does not slide; the inversion of Eq. 12 "
            "needs gross sliding (mu < mu_c), it gives no duration here"
        )
