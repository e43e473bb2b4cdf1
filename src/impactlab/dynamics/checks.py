"""All the inputs of one impact at once (:func:`check_impact`, for simulate, simulate_batch,
run_arrays and the reference implementation), checked and in SI: each input by
``dynamics.input_checks``, then every bound together by ``dynamics.kernels.inputs``."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from impactlab._validation import check_finite, check_flag, warn_implausible
from impactlab.bodies import Rod, Sphere, lever_arms
from impactlab.contact import ContactModel
from impactlab.contact.names import Law
from impactlab.dynamics.input_checks import (
    check_angle,
    check_body,
    check_flat,
    check_friction_rtol,
    check_mu,
    check_rtol,
    check_spin,
    check_velocity,
    contact_reach,
    gravity_value,
    warn_fast,
)
from impactlab.dynamics.kernels.inputs import IN_OK, input_problem
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, PARTIAL_SLIP_RTOL
from impactlab.dynamics.models import contact_model
from impactlab.friction import FrictionKind, FrictionModel, get_friction
from impactlab.materials import G0, ContactPair, Material


@dataclass(frozen=True)
class ImpactInputs:
    """The checked inputs of one impact (SI): the body, the flat, the contact model, the
    friction model, mu, angle [rad], velocity (vx, vy) [m/s], spin [rad/s], gravity [m/s^2],
    rtol, constant_angle and the contact point's initial normal velocity ``vn`` (< 0)."""

    body: Rod | Sphere
    flat: Material
    model: ContactModel
    friction: FrictionModel
    mu: float
    angle: float
    velocity: tuple[float, float]
    spin: float
    gravity: float
    rtol: float
    constant_angle: bool
    vn: float


def _approach(body: Rod | Sphere, th: float, vx: float, vy: float, w: float) -> float:
    """The contact point's normal velocity (ValueError unless < 0); warns on a fast impact."""
    a, b = lever_arms(body.half_length, body.tip_radius, th)
    vn = vy - w * a
    if not vn < 0.0:  # the command line names its options in it: cli.drop.approach_worded
        rule = "vy" if isinstance(body, Sphere) else "vy - spin * (L/2) cos(angle)"
        raise ValueError(
            f"velocity: the contact point does not approach the flat (its normal velocity "
            f"{rule} = {float(vn)!r} m/s must be < 0)"
        )
    tip = math.hypot(vx + w * b, vn)
    warn_fast("the impact speed", max(math.hypot(vx, vy), tip))
    return vn


#: Plain Python numbers of the fast path of ``check_impact`` (bool is not one of them).
_PLAIN = (float, int)


def _plain(value: Any) -> bool:
    """True for a finite plain Python float or int (never a bool, string or Quantity)."""
    return type(value) in _PLAIN and math.isfinite(value)


def _plain_inputs(
    body: Any,
    flat: Any,
    angle: Any,
    velocity: Any,
    spin: Any,
    mu: Any,
    gravity: Any,
    rtol: Any,
    constant_angle: Any,
) -> tuple[float, float, float, float, float, float, float] | None:
    """(angle, vx, vy, spin, mu, gravity, rtol) when every input is a plain, valid value (a
    Rod with a finite angle in (0, pi/2], a tuple of two numbers, ...); None sends the inputs
    through the full checks (units, messages). The same values as the full checks."""
    if not (
        type(body) is Rod
        and isinstance(flat, Material)
        and type(velocity) is tuple
        and len(velocity) == 2
        and _plain(angle)
        and _plain(velocity[0])
        and _plain(velocity[1])
        and _plain(spin)
        and _plain(mu)
        and type(constant_angle) is bool
        and (gravity is True or gravity is False)
        and (rtol is None or _plain(rtol))
    ):
        return None
    g = G0 if gravity else 0.0
    r = DEFAULT_RTOL if rtol is None else float(rtol)
    th, vx, vy, w, m = (float(v) for v in (angle, *velocity, spin, mu))
    if input_problem(True, th, vx, vy, w, contact_reach(body), m, g, r) != IN_OK:
        return None
    return th, vx, vy, w, m, g, r


def check_brake_meyer(body: Rod | Sphere, flat: Material, law: Any, law_params: Any) -> None:
    """ValueError, naming the material it comes from, for Brake's law (``law`` its name)
    taking the Meyer index n of the pair's material that yields first (none in
    ``law_params``) when n lies outside (2, 3): a Material allows n = 3, where the plastic term
    of Brake's Eq. 24, weighted by 1 - sech((3 - n) x), vanishes and the loading force falls
    back towards zero as the interference grows (the law refuses it when built; this says
    whose n it is, before anything is built)."""
    if not (isinstance(law, str) and law == Law.BRAKE):
        return
    if isinstance(law_params, Mapping) and "meyer_index" in law_params:
        return  # the law's own check names the parameter given
    weaker = ContactPair(body.material, flat).weaker
    n = weaker.meyer_index
    if not 2.0 < n < 3.0:
        whose = "the flat" if weaker is flat else "the body's material"
        raise ValueError(
            f"meyer_index = {n!r} of {whose} {weaker.name!r} (the material that yields first, "
            "whose index Brake's law takes) must lie in (2, 3) for Brake's Eq. 24: at n = 3 "
            "its plastic term, weighted by 1 - sech((3 - n) x), vanishes; give the material an "
            "index below 3 (its n= key, e.g. 'n=2.2', or meyer_index), or another law (in "
            "Python also law_params={'meyer_index': ...})"
        )


def checked_model(
    body: Rod | Sphere, flat: Material, law: Any, law_params: Mapping[str, Any] | None
) -> ContactModel:
    """The contact model of the checked body and flat (``models.contact_model``), after the
    checks of a law's inputs that a material gives (:func:`check_brake_meyer`: the error names
    the material)."""
    check_brake_meyer(body, flat, law, law_params)
    return contact_model(body, flat, law, law_params)


def _friction_name(friction: Any) -> str:
    """The registered name of ``friction`` ("" for an unknown one: the checks below raise its
    error in their order)."""
    try:
        return str(get_friction(friction).kind.value)
    except (TypeError, ValueError, KeyError):
        return ""


def impact_rtol(friction: Any) -> float:
    """The default tolerance of an impact with ``friction`` (a name or a FrictionModel):
    ``PARTIAL_SLIP_RTOL`` for the partial-slip engine, else ``DEFAULT_RTOL``."""
    partial = _friction_name(friction) == FrictionKind.PARTIAL_SLIP.value
    return PARTIAL_SLIP_RTOL if partial else DEFAULT_RTOL


def warn_unused_friction(friction: Any, mu: float) -> None:
    """ImplausibleInputWarning for a friction model chosen (not Coulomb, the default) with
    mu = 0 (given, or the default): the impact is frictionless and the model has no effect."""
    name = _friction_name(friction)
    if mu == 0.0 and name and name != FrictionKind.COULOMB.value:
        warn_implausible(
            f"friction = {name!r} with mu = 0 is frictionless: the model has no effect (for "
            "friction give mu > 0, e.g. mu=0.3 or --mu 0.3, mu's default being 0; for a "
            "frictionless impact leave friction out)"
        )


def check_impact(
    body: Any,
    flat: Any,
    *,
    law: str | ContactModel,
    friction: str,
    mu: Any,
    angle: Any,
    velocity: Any,
    spin: Any,
    law_params: Mapping[str, Any] | None,
    gravity: Any,
    constant_angle: Any,
    rtol: Any,
) -> ImpactInputs:
    """All the inputs of one impact (``simulate``'s arguments) checked and in SI. The default
    tolerance is ``DEFAULT_RTOL``, ``PARTIAL_SLIP_RTOL`` for the partial-slip engine. A friction
    model other than Coulomb with mu = 0 warns: the impact is frictionless, the model unused."""
    if rtol is None and _friction_name(friction) == FrictionKind.PARTIAL_SLIP.value:
        rtol = PARTIAL_SLIP_RTOL
    fast = _plain_inputs(body, flat, angle, velocity, spin, mu, gravity, rtol, constant_angle)
    if rtol is not None:
        check_friction_rtol(check_rtol(rtol), _friction_name(friction))
    if fast is not None:
        th, vx, vy, w, m, g, r = fast
        warn_unused_friction(friction, m)
        return ImpactInputs(
            body=body,
            flat=flat,
            model=checked_model(body, flat, law, law_params),
            friction=get_friction(friction),
            mu=m,
            angle=th,
            velocity=(vx, vy),
            spin=w,
            gravity=g,
            rtol=r,
            constant_angle=constant_angle,
            vn=_approach(body, th, vx, vy, w),
        )
    body = check_body(body)
    th = check_angle(angle, body)
    vx, vy = check_velocity(velocity)
    w = check_spin(check_finite("spin", spin, "rad/s"), contact_reach(body))
    flat = check_flat(flat)
    m = check_mu(mu)
    warn_unused_friction(friction, m)
    return ImpactInputs(
        body=body,
        flat=flat,
        model=checked_model(body, flat, law, law_params),
        friction=get_friction(friction),
        mu=m,
        angle=th,
        velocity=(vx, vy),
        spin=w,
        gravity=gravity_value(gravity),
        rtol=check_rtol(rtol),
        constant_angle=check_flag("constant_angle", constant_angle),
        vn=_approach(body, th, vx, vy, w),
    )


__all__ = [
    "ImpactInputs",
    "check_brake_meyer",
    "check_impact",
    "checked_model",
    "warn_unused_friction",
]
