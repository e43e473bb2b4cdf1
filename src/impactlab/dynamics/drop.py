"""``simulate_drop``: the drop of a flexible rod (or, as its rigid limit, a rigid rod) on a flat,
the whole contact sequence from the first touch of the tip until the rod leaves the flat for good
(SI units; the model: docs/flexible.md).

The Python layer validates the input, builds the contact model with the package's one builder
(``impactlab.dynamics.models``), the modal basis of the body (``impactlab.bodies``) and, for a
rate-dependent flat, iterates the self-consistent rate factor (``impactlab.contact.rate``); the
drop itself runs in the compiled integrator ``impactlab.dynamics.flexcore``
(``impactlab.dynamics.drop_run``: the call, and its output row as a ``DropResult``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from impactlab import schema
from impactlab._validation import check_finite, check_flag, refuse_unknown_keywords
from impactlab.bodies import Rod, lever_arms
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.layout import BP_GSTAR
from impactlab.contact import ContactModel
from impactlab.contact.brittle import brittle_pressure
from impactlab.contact.rate import (
    RateFactor,
    RateLaw,
    RateLimit,
    check_rate_flat,
    get_rate_law,
    rate_materials,
    self_consistent_factor,
)
from impactlab.contact.rate_factor import warn_no_dent
from impactlab.contact.registry import get_law
from impactlab.dynamics.checks import check_brake_meyer, warn_unused_friction
from impactlab.dynamics.drop_body import body_model
from impactlab.dynamics.drop_checks import (
    DROP_FRICTION,
    MIN_APPROACH_SPEED,
    STOP_MODES,
    DropError,
    check_body,
    check_friction,
    check_stop,
    drop_rtol,
    status_error,
)
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.drop_run import DropRun as _Run
from impactlab.dynamics.drop_run import assemble_drop_result as _result
from impactlab.dynamics.drop_run import first_contact_radius as _first_contact_radius
from impactlab.dynamics.drop_run import run_drop as _run
from impactlab.dynamics.drop_run import slip_cell_widths as _cell_widths
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.input_checks import (
    check_angle,
    check_flat,
    check_spin,
    check_velocity,
    contact_reach,
    gravity_value,
    velocity_from,
    warn_fast,
)
from impactlab.dynamics.kernels.layout import MU_NEGLIGIBLE
from impactlab.dynamics.keyword_hints import split_velocity
from impactlab.dynamics.models import (
    body_params,
    build_contact_model,
    contact_model,
    references_used,
)
from impactlab.dynamics.provenance import SIMULATE_DROP
from impactlab.dynamics.time_limit import DEFAULT_TIME_LIMIT, takes_renamed
from impactlab.friction import (
    COULOMB,
    DEFAULT_MU,
    MINDLIN,
    PARTIAL_SLIP,
    PARTIAL_SLIP_CELLS,
)
from impactlab.materials import AISI_1010, Material

__all__ = [
    "DEFAULT_TIME_LIMIT",
    "DROP_FRICTION",
    "MIN_APPROACH_SPEED",
    "STOP_MODES",
    "DropError",
    "simulate_drop",
]

#: Contact laws without plasticity: a rate-dependent flat is refused with them.
ELASTIC_LAWS = frozenset({"hertz"})


def _rate_model(
    rate_law: RateLaw | None,
    law: str | ContactModel,
    body: Rod,
    flat: Material,
    law_params: Mapping[str, float] | None,
    run: Any,
    vn0: float,
) -> tuple[ContactModel, RateFactor | None]:
    """The contact model, with the flat's yield strength raised by the self-consistent rate
    factor when there is a rate law (``impactlab.contact.rate``; a factor that would raise a
    yield strength above its E is refused in one line, ``rate_factor.RateLimit``)."""
    if rate_law is None:
        return contact_model(body, flat, law, law_params), None
    if not isinstance(law, str):
        raise ValueError("rate needs the law as a name (the flat's yield strength is rebuilt)")
    # the law's name and parameters first: their errors do not depend on the rate factor
    get_law(law).parameter_values({} if law_params is None else law_params)
    if law.strip().lower() in ELASTIC_LAWS:
        raise ValueError(
            f"rate {rate_law.name!r}: the {law!r} law is elastic (no yield strength for the rate "
            "to raise); pass rate=None, or an elastic-plastic law"
        )
    check_rate_flat(rate_law, flat)

    def build(k: float) -> ContactModel:
        body_k, flat_k = rate_materials(body.material, flat, k)
        try:
            return build_contact_model(law, body_k, flat_k, body.tip_radius, law_params)
        except ValueError as exc:
            raise ValueError(
                f"rate {rate_law.label!r}: with the flat's yield strength and hardness raised by "
                f"the rate factor k = {k:.4g}, the {law!r} law rejects the pair: {exc}"
            ) from None

    def contact_radius(k: float) -> float:
        model = build(k)
        return _first_contact_radius(run(model), model)

    limit = RateLimit.of(body.material, flat)
    factor = self_consistent_factor(contact_radius, rate_law, vn0, limit=limit)
    return build(factor.k), factor


#: What simulate_drop says of a keyword of ``simulate`` it does not take (others: the nearest).
_NOTES = {"partial_slip_cells": f"a drop's partial slip has {PARTIAL_SLIP_CELLS} compiled cells"
          " per end", "constant_angle": "a drop follows the rod's rotation"}  # fmt: skip


@takes_renamed  # t_max=, time_limit's name before 0.3 (a DeprecationWarning)
@refuse_unknown_keywords(_NOTES)
def simulate_drop(
    body: FlexibleRod | Rod,
    flat: Material = AISI_1010,
    *,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    mu: float = DEFAULT_MU,
    angle: Any = None,
    velocity: Any = None,
    spin: Any = 0.0,
    gravity: Any = True,
    rate: str | RateLaw | None = None,
    rtol: float | None = None,
    history: bool = True,
    law_params: Mapping[str, float] | None = None,
    stop: str = "sequence",
    time_limit: Any = DEFAULT_TIME_LIMIT,
    speed: Any = None,
    incidence: Any = None,
    vx: Any = None,
    vy: Any = None,
) -> DropResult:
    """Simulate the drop of ``body`` on ``flat`` from the first touch of its tip (end 0, at
    delta = 0, undeformed, modes at rest) until it leaves the flat for good (SI units).

    body: a FlexibleRod, or a rigid Rod (the rigid limit: no modes); flat: the flat's material;
    law: a registered law name (or a ContactModel; no ``rate`` then); friction: ``"coulomb"``,
    ``"impulse_ratio"``, ``"mindlin"`` or ``"partial_slip"`` (set at every touch, as in the
    rigid engine; partial slip: cells over the contact radius of a Mindlin pre-pass); mu >= 0;
    angle [rad] in (0, pi/2]; velocity (vx, vy) of the centre of mass at first touch [m/s], or
    instead ``speed`` [m/s] and ``incidence`` [rad], its angle to the flat's normal (vx = speed
    sin(incidence), vy = -speed cos(incidence); the rule and errors of ``impactlab.simulate``,
    ``checks.velocity_from``; ``vx=``/``vy=``, ``simulate_drops``' arrays, are refused with a
    ValueError that says so); spin [rad/s]; gravity: True, False or a value [m/s^2]; rate:
    None or ``"none"``, ``"cowper-symonds"``, ``"johnson-cook"``, a RateLaw
    (``RateLaw.custom``) or the text a result's ``rate`` shows (``contact.rate.get_rate_law``;
    the flat's yield strength raised by the self-consistent rate factor); rtol: relative
    tolerance (default 1e-7); history: keep the time history (``DropResult.history``; default
    True, as ``impactlab.simulate``: a result can draw its figures; pass False for many drops
    in a loop: the paper's drops keep about 4,800 rows, 0.6 MB, and take about 1.5 times as
    long with them, 12 ms against 7.5 ms); law_params: the law's parameters; stop:
    ``"sequence"`` (stop when the tip is clear until the other end could land: that is a new
    impact, ``next_end`` / ``next_time``) or ``"flight"`` (go on through the other end's
    impacts until the rod flies off); time_limit [s]: the longest simulated time after the first
    touch (default ``DEFAULT_TIME_LIMIT``, 0.5 s; ``t_max=``, its name before 0.3, is read as
    it with a DeprecationWarning until 0.4).

    Returns a DropResult: every contact, the dents, the totals, the energy balance, the
    history if asked, the references and ``input``, the record of this call
    (``dynamics.provenance``: ``impactlab.rerun`` runs it again). ValueError for invalid input
    (the checks of ``impactlab.simulate``; history True or False; rtol up to 1e-5,
    ``input_checks.DROP_RTOL_MAX``) or a failed integration (``DropError``); an
    ImplausibleInputWarning for an impact speed above 100 m/s.
    """
    if vx is not None or vy is not None:  # simulate_drops' names: one drop takes a pair
        given = [k for k, v in (("vx", vx), ("vy", vy)) if v is not None]
        raise ValueError(split_velocity("simulate_drop", given, "simulate_drops"))
    body = check_body(body)  # first: a sphere is refused before what a rod's drop needs
    velocity = velocity_from(velocity, speed, incidence)
    bm = body_model(body)
    flat = check_flat(flat)
    fric, mu_v = check_friction(friction, mu)
    warn_unused_friction(fric.name, mu_v)
    if angle is None:
        raise ValueError(
            f"angle is required for the drop of a {type(body).__name__}: the rod axis to the "
            "flat at the first touch, in radians (or with a unit), in (0, pi/2]"
        )
    th = check_angle(angle, bm.rigid)
    vx, vy = check_velocity(velocity)
    w = check_spin(check_finite("spin", spin, "rad/s"), contact_reach(bm.rigid))
    g = gravity_value(gravity)
    options = (drop_rtol(rtol, fric), *check_stop(stop, time_limit))
    record_history = check_flag("history", history)
    vn0 = vy - w * bm.rigid.half_length * math.cos(th)
    if not vn0 < 0.0:
        raise ValueError(
            f"velocity: the tip does not approach the flat (its normal velocity "
            f"vy - spin * (L/2) cos(angle) = {float(vn0)!r} m/s must be < 0)"
        )
    if -vn0 < MIN_APPROACH_SPEED:
        raise ValueError(
            f"velocity: the tip's normal approach speed |vy - spin * (L/2) cos(angle)| = "
            f"{-float(vn0):.3g} m/s is below {MIN_APPROACH_SPEED:g} m/s, the smallest the drop "
            f"integrates (its Hertzian depth and time scales underflow); give a larger |vy|"
        )
    _, b = lever_arms(bm.rigid.half_length, bm.rigid.tip_radius, th)  # as simulate warns
    warn_fast("the impact speed", max(math.hypot(vx, vy), math.hypot(vx + w * b, vn0)))

    gstar = float(body_params(bm.rigid, flat)[BP_GSTAR])
    mu_run = 0.0 if mu_v < MU_NEGLIGIBLE else mu_v  # frictionless, as in the rigid engine
    fid = COULOMB if (fric.friction_id == PARTIAL_SLIP and mu_run == 0.0) else fric.friction_id

    def run(model: ContactModel, record: bool = False) -> _Run:
        widths = (math.nan, math.nan)
        max_steps = F.DROP_MAX_STEPS
        if fid == PARTIAL_SLIP:  # the cells span the contact radius of a Mindlin pre-pass
            pre = _run(bm, model, (th, vx, vy, w), (MINDLIN, mu_run, gstar, widths), g,
                       (*options, False))  # fmt: skip
            widths = _cell_widths(pre, model)
            pre_steps = int(pre.out[F.O_N_STEPS])
            max_steps = max(F.PARTIAL_MIN_STEPS, F.PARTIAL_STEP_FACTOR * pre_steps)
        return _run(bm, model, (th, vx, vy, w), (fid, mu_run, gstar, widths), g,
                    (*options, record), max_steps)  # fmt: skip

    check_brake_meyer(bm.rigid, flat, law, law_params)
    rate_law = get_rate_law(rate)
    model, factor = _rate_model(rate_law, law, bm.rigid, flat, law_params, run, vn0)
    r = run(model, record_history)
    if r.status != F.ST_OK:
        raise status_error(r.status, model, r.out)
    refs = references_used(model, fric, mu_run > 0.0) + bm.references
    if rate_law is not None:
        refs += rate_law.references
    inputs = {"friction": fric.name, "mu": mu_v, "angle": th, "velocity_in": (vx, vy)}
    inputs |= {"spin_in": w, "gravity": g, "rtol": options[0]}
    name = rate_law.label if rate_law is not None else None
    limit = brittle_pressure(bm.rigid.material, flat)
    result = _result(r, bm, model, inputs, (name, factor), tuple(dict.fromkeys(refs)), limit)
    if rate_law is not None and factor is not None:  # a rate law that removes the dent: say so
        onsets = (contact_model(bm.rigid, flat, law, law_params).yield_onset[0],
                  model.yield_onset[0])  # fmt: skip
        warn_no_dent(rate_law, factor, flat.yield_strength, onsets, result.dent_depth,
                     result.delta_max)  # fmt: skip
    # what was simulated, checked, for DropResult.input (``dynamics.provenance``)
    drop_options = {"rate": rate_law, "stop": stop, "time_limit": options[1]}
    call = (body, flat, law, law_params, g, None, options[0], drop_options, SIMULATE_DROP)
    object.__setattr__(result, "_call", call)
    return result


def __getattr__(name: str) -> Any:
    """``DEFAULT_T_MAX``, ``DEFAULT_TIME_LIMIT``'s name before 0.3 (a DeprecationWarning)."""
    if name == "DEFAULT_T_MAX":
        schema.warn_renamed("DEFAULT_T_MAX", "DEFAULT_TIME_LIMIT", "constant")
        return DEFAULT_TIME_LIMIT
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
