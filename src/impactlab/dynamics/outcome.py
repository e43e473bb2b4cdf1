"""From a compiled impact's output row to an ``ImpactResult``, and the ValueError of a failed
impact: one place for ``simulate`` (the rigid core, its fast path included) and the partial-slip
path (slipcore), which write the same output row (``impactlab.schema.OUTPUT_FIELDS``) and status
codes.

The result is assembled without the dataclass ``__init__`` (``results.assemble_result``): the
flags are completed here exactly as ``ImpactResult.__post_init__`` completes them, with the
law's reference interference and range looked up once per contact model.
"""

from __future__ import annotations

import math
from operator import itemgetter

import numpy as np

from impactlab.bodies import Rod, Sphere
from impactlab.bodies.geometry import lever_arms
from impactlab.bodies.impulse import jam_ratio
from impactlab.contact import ContactModel
from impactlab.contact.brittle import brittle_flags, brittle_pressure
from impactlab.contact.ranges import critical_interference, extrapolation, extrapolation_flags
from impactlab.dynamics.checks import ImpactInputs
from impactlab.dynamics.kernels import layout as L
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.models import references_used
from impactlab.dynamics.results import History, ImpactResult, assemble_result
from impactlab.dynamics.rod_reach import rod_reach_bits
from impactlab.flags import FLAG_LAW_EXTRAPOLATED, ResultFlag
from impactlab.friction import FrictionKind, FrictionModel
from impactlab.references import Reference

__all__ = ["engine_result", "impact_result", "slip_jam", "status_error"]

#: The output-row columns ``engine_result`` reads, in the order it unpacks them.
_ROW = itemgetter(
    L.O_E, L.O_EE, L.O_VX, L.O_VY, L.O_SPIN, L.O_DMAX, L.O_DP, L.O_SL, L.O_CT, L.O_T, L.O_FMEAN,
    L.O_FMAX, L.O_PN, L.O_PT, L.O_ED, L.O_STICK, L.O_REG, L.O_VNIN, L.O_VTIN, L.O_VNOUT,
    L.O_VTOUT, L.O_ANG, L.O_TMAX, L.O_NST, L.O_FLAGS,
)  # fmt: skip

#: id(model) -> (model, delta_ref, delta_ratio_max) of ``_law_flag``, or (model, None, None)
#: where ``contact.ranges.extrapolation_flags`` itself decides (unknown law, delta_ref = 0).
_RANGES: dict[int, tuple[ContactModel, float | None, float | None]] = {}


def _law_flag(model: ContactModel, delta_max: float) -> int:
    """``contact.ranges.extrapolation_flags(model.law_id, model.params, delta_max)`` for a float
    ``delta_max``, with delta_ref and the range's ratio looked up once per model (the same
    float64 division and comparison)."""
    hit = _RANGES.get(id(model))
    if hit is None or hit[0] is not model:
        ref = ratio_max = None
        law_id, params = model.law_id, model.params
        at_zero, limit = extrapolation(law_id, params, 0.0)  # NaN: unknown law or delta_ref 0
        if not math.isnan(at_zero):
            r = critical_interference(law_id, params)
            if type(r) is float and r != 0.0:
                ref, ratio_max = r, limit
        if len(_RANGES) >= 256:
            _RANGES.clear()
        hit = _RANGES[id(model)] = (model, ref, ratio_max)
    _, ref, ratio_max = hit
    if ref is None or ratio_max is None:
        return int(extrapolation_flags(model.law_id, model.params, delta_max))
    return FLAG_LAW_EXTRAPOLATED if delta_max / ref > ratio_max else 0


def slip_jam(
    body: Rod | Sphere,
    angle: float,
    friction: FrictionModel,
    mu: float,
    velocity: tuple[float, float],
    spin: float,
) -> float | None:
    """For the paper's ``impulse_ratio`` friction (F_t = mu F_n throughout, no stick): the ratio
    ``jam_ratio`` (k^2 + a^2) / (a b) of a rod whose slipping contact point is driven into the
    flat by the friction force's moment (Painleve's paradox: ``mu`` at or above that ratio, the
    slip towards -x); None otherwise (another friction model, whose contact point can stick, a
    sphere, a slip the other way, or ``mu`` below it). ``angle`` [rad], ``velocity`` (vx, vy)
    [m/s], ``spin`` [rad/s]."""
    if friction.kind is not FrictionKind.IMPULSE_RATIO or type(body) is not Rod:
        return None
    a, b = (float(x) for x in lever_arms(body.half_length, body.tip_radius, angle))
    if velocity[0] + spin * b > 0.0:
        return None  # friction towards +x: c_n = k^2 + a^2 + mu a b > 0
    jam = jam_ratio(a, b, float(body.inertia) / float(body.mass))  # type: ignore[arg-type]
    return jam if mu >= jam else None


def status_error(
    status: int,
    model: ContactModel,
    prefix: str = "",
    vn: float | None = None,
    gravity: float | None = None,
    jam: float | None = None,
) -> ValueError:
    """The ValueError of an impact that ended with engine ``status`` (not ``ST_OK``); ``vn``
    [m/s] and ``gravity`` [m/s^2], where known, explain an impact that never separates or
    chatters under gravity (a slow grazing slide); ``jam``
    (``slip_jam``) one whose interference ran away under friction."""
    if status == S.ST_LAW_LIMIT and jam is not None:
        text = (
            f"the interference exceeded {model.max_interference:.6g} m, the validity limit of "
            f"the {model.name!r} law, because friction drove the tip into the flat: at this "
            f"angle the friction force's moment pushes the slipping contact point in faster "
            f"than the normal force pushes it out once mu >= (k^2 + a^2) / (a b) = "
            f"{jam:.3g} under impulse_ratio's F_t = mu F_n (Painleve's paradox; Stewart 2000, "
            f"doi:10.1137/S0036144599360110): lower mu below {jam:.3g}, or use friction "
            f"'coulomb', whose contact point can stick"
        )
    elif status == S.ST_LAW_LIMIT and model.name == "tabulated":
        ratio = model.max_interference / model.critical_interference
        text = (
            f"the interference exceeded {model.max_interference:.6g} m, where the tabulated "
            f"law's curves end ({ratio:.4g} delta_c of the pair): lower the impact velocity, "
            f"or use curves that reach further (impactlab.fe.tabulated_law's "
            f"maxima_over_delta_c for a pair of one's own; docs/laws/tabulated.md)"
        )
    elif status == S.ST_LAW_LIMIT:
        text = (
            f"the interference exceeded {model.max_interference:.6g} m, the validity limit of "
            f"the {model.name!r} law: lower the impact velocity or choose another law"
        )
    elif status == S.ST_NAN:
        text = (
            f"the {model.name!r} contact law returned a non-finite force or unloading branch "
            f"(law not available, or evaluated outside its domain)"
        )
    elif status == S.ST_NO_SEPARATION and vn is not None:
        text = (
            f"{S.STATUS_MESSAGES[status]}: the contact point approached the flat at "
            f"{-vn:.3g} m/s and the body never left it"
        )
        if gravity:
            text += (
                f" (with gravity {gravity:g} m/s^2 such a slow approach ends at rest on the "
                f"flat): raise the approach speed, or pass gravity=False"
            )
        else:
            text += ": raise the approach speed (or rtol, for a contact this slow)"
    elif status == S.ST_TOO_MANY_EVENTS and vn is not None and gravity:
        text = (
            f"{S.STATUS_MESSAGES[status]}: the contact point approached the flat at "
            f"{-vn:.3g} m/s; a slow or grazing contact that gravity ({gravity:g} m/s^2) keeps "
            f"pressing onto the flat can switch without end: raise the approach speed, or pass "
            f"gravity=False"
        )
    else:
        text = S.STATUS_MESSAGES.get(status, f"engine status {status}")
    return ValueError(prefix + text)


def engine_result(
    out: np.ndarray,
    history: np.ndarray | None,
    model: ContactModel,
    friction: FrictionModel,
    references: tuple[Reference, ...],
    mu: float,
    angle: float,
    velocity: tuple[float, float],
    spin: float,
    rod: tuple[float, float] | None = None,
    brittle_limit: float = math.inf,
) -> ImpactResult:
    """The ``ImpactResult`` of the output row ``out`` and the history rows (None: no history
    kept) of an impact with ``model`` and ``friction`` (``references``: the sources used), from
    the checked inputs mu, angle [rad] (NaN for a sphere), velocity [m/s] and spin [rad/s];
    ``rod``: a rod's (L/2, R) [m], whose reach is checked (``rod_reach``; None: a sphere);
    ``brittle_limit`` [Pa]: the mean contact pressure a brittle member of the pair stands
    (``contact.brittle.brittle_pressure``; inf: none is brittle)."""
    (e, e_energy, vx, vy, spin_out, delta_max, delta_p, sliding_length, contact_travel,
     duration, mean_force, max_force, normal_impulse, tangential_impulse, energy_dissipated,
     stick_time, regime, vn_in, vt_in, vn_out, vt_out, angle_out, t_max, n_steps,
     flags) = _ROW(out.tolist())  # fmt: skip
    bits = int(flags) | _law_flag(model, delta_max)
    if rod is not None:
        bits |= rod_reach_bits(rod[0], rod[1], angle, angle_out, delta_max)
    if brittle_limit < math.inf:
        bits |= brittle_flags(model.law_id, model.params, delta_max, max_force, brittle_limit)
    return assemble_result(
        {  # every ImpactResult field, in field order
            "e": e,
            "e_energy": e_energy,
            "velocity_out": (vx, vy),
            "spin_out": spin_out,
            "delta_max": delta_max,
            "delta_p": delta_p,
            "sliding_length": sliding_length,
            "contact_travel": contact_travel,
            "duration": duration,
            "mean_force": mean_force,
            "max_force": max_force,
            "normal_impulse": normal_impulse,
            "tangential_impulse": tangential_impulse,
            "energy_dissipated": energy_dissipated,
            "stick_time": stick_time,
            "regime": S.REGIME_NAMES[int(regime)],
            "law": model.name,
            "friction": friction.name,
            "mu": mu,
            "angle": angle,
            "velocity_in": velocity,
            "spin_in": spin,
            "vn_in": vn_in,
            "vt_in": vt_in,
            "vn_out": vn_out,
            "vt_out": vt_out,
            "angle_out": angle_out,
            "t_max": t_max,
            "n_steps": int(n_steps),
            "flags": ResultFlag(bits),
            "history": None if history is None else History(history),
            "references": references,
            "_law_id": model.law_id,
            "_law_params": model.params,
            "_call": None,  # simulate() records its checked arguments here
        }
    )


def impact_result(x: ImpactInputs, out: np.ndarray, history: np.ndarray | None) -> ImpactResult:
    """The ``ImpactResult`` of the checked inputs ``x`` from the output row ``out`` and the
    history rows (None: no history kept)."""
    return engine_result(
        out,
        history,
        x.model,
        x.friction,
        references_used(x.model, x.friction, x.mu > 0.0),
        x.mu,
        x.angle if isinstance(x.body, Rod) else math.nan,
        x.velocity,
        x.spin,
        (x.body.half_length, x.body.tip_radius) if isinstance(x.body, Rod) else None,
        brittle_pressure(x.body.material, x.flat),
    )
