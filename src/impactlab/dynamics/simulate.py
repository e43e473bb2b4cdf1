"""``simulate``: one impact of a rod or sphere on a flat (``simulate_batch``, for many, is in
``impactlab.dynamics.simulate_many``); ``rerun`` of a recorded one.

The Python layer only validates the input (``impactlab.dynamics.checks``), looks up the cached
compiled representations of the contact law and the body (``impactlab.dynamics.models``) and
wraps the engine's output; the impact itself runs in the compiled core
(``impactlab.dynamics.core``). Plain inputs (numbers in SI, bools, registered law and friction
names) take a fast path, ``_fast``: checked inline, with a setup cached per (body, flat, law,
friction) (``models.engine_setup``); anything else, and anything the checks would refuse or warn
about, goes through the full checks (``checks.check_impact``), with the same results.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from typing import Any, overload

import numpy as np

from impactlab._validation import check_flag
from impactlab.bodies import Rod, Sphere, lever_arms
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.contact.brittle import brittle_pressure
from impactlab.dynamics.checks import ImpactInputs, check_impact, impact_rtol
from impactlab.dynamics.core.driver import impact
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.flex_simulate import check_simulate_keywords, simulate_flexible
from impactlab.dynamics.input_checks import (
    PLAUSIBLE_SPEED,
    check_constant_angle,
    contact_reach,
    friction_rtol_max,
    given_body,
    velocity_from,
)
from impactlab.dynamics.kernels import layout as L
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.kernels.inputs import IN_OK, input_problem
from impactlab.dynamics.keyword_hints import split_velocity
from impactlab.dynamics.models import (
    body_params,
    check_recorded_model_flat,
    engine_setup,
    kernel_params,
)
from impactlab.dynamics.outcome import engine_result, impact_result, slip_jam, status_error
from impactlab.dynamics.partial_slip import checked_cells, simulate_partial_slip
from impactlab.dynamics.provenance import SIMULATE_DROP, from_record, record_function
from impactlab.dynamics.results import ImpactResult
from impactlab.dynamics.time_limit import renamed_keywords
from impactlab.friction import DEFAULT_MU, PARTIAL_SLIP_CELLS, FrictionKind
from impactlab.materials import AISI_1010, G0, Material


@overload
def simulate(
    body: FlexibleRod, flat: Material = ..., *, velocity: Any = ..., **kwargs: Any
) -> DropResult: ...
@overload
def simulate(
    body: Rod | Sphere, flat: Material = ..., *, velocity: Any = ..., **kwargs: Any
) -> ImpactResult: ...
def simulate(
    body: Rod | Sphere | FlexibleRod,
    flat: Material = AISI_1010,
    *,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    mu: float = DEFAULT_MU,
    angle: Any = None,
    velocity: Any = None,
    spin: Any = 0.0,
    law_params: Mapping[str, Any] | None = None,
    gravity: Any = True,
    constant_angle: bool = False,
    rtol: float | None = None,
    history: bool = True,
    speed: Any = None,
    partial_slip_cells: int = PARTIAL_SLIP_CELLS,
    incidence: Any = None,
    **drop_options: Any,
) -> ImpactResult | DropResult:
    """Simulate one impact from first touch (delta = 0) to separation (SI units); for a
    FlexibleRod the whole drop, a ``DropResult`` (``impactlab.dynamics.drop``; its options
    ``rate``, ``stop``, ``time_limit`` pass through; ``t_max``, ``time_limit``'s name before
    0.3, is read as it with a DeprecationWarning).

    A quantity (angle, velocity, spin, gravity, a law parameter with a unit) is a number in SI
    (a bare angle is radians), a string with units (``"20 deg"``, ``"1.41 m/s"``) or a pint
    Quantity of any registry; ``mu`` and ``rtol`` are plain numbers (no strings, no bools).

    Parameters
    ----------
    body, flat : Rod or Sphere, Material
        The impacting rigid body; the flat's material (default AISI 1010, the paper's flat): a
        Material, a library name (``"al-6061-t6"``), a material by values
        (``"E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"``) or a TOML file
        (``impactlab.get_material``).
    law, friction : str
        Contact-law name (``impactlab.law_names()``) or a built ContactModel; friction model
        (``impactlab.friction.friction_names()``).
    mu : float
        Friction coefficient, >= 0 (default ``impactlab.friction.DEFAULT_MU``).
    angle : float or str
        Rod axis to the flat, in (0, pi/2] rad; tip lowest, centre of mass at +x of the tip.
        A bare number above pi/2 is refused (up to 10 deg past it as a rod leaning past the
        normal, the mirror of pi - angle; up to 90 with a degrees hint too; above pi with the
        degrees hint); a sphere takes none (refused, as is ``constant_angle=True`` for it).
    velocity, spin : pair, float
        (vx, vy) of the centre of mass at first touch [m/s] (the contact point must approach);
        angular velocity [rad/s], counter-clockwise positive.
    speed, incidence : float or str
        Instead of ``velocity``: the speed of the centre of mass [m/s] and its angle to the
        flat's normal (a bare number is radians, ``"30 deg"`` works), in (-90, 90) deg;
        vx = speed sin(incidence) (positive incidence: towards +x), vy = -speed cos(incidence).
        Give ``velocity`` or both of these, never both (``checks.velocity_from``).
    law_params : mapping, optional
        Law parameters (see ``impactlab laws``).
    gravity : bool, float or str
        True (9.80665 m/s^2), False, or a value [m/s^2].
    constant_angle, history : bool
        Freeze the lever arms at the initial angle (the paper's assumption); keep the time
        history (needed for ``dent()`` and the plots).
    rtol : float, optional
        Relative tolerance in [1e-13, 1e-3] (default ``DEFAULT_RTOL`` = 2e-7; 3e-8 for
        ``friction="partial_slip"``, which takes at most 1e-5; ``"mindlin"`` at most 1e-4).
    partial_slip_cells : int
        Cells of ``friction="partial_slip"`` over the largest contact radius, in [4, 64]
        (default ``PARTIAL_SLIP_CELLS`` = 16; more converge e_t near normal incidence, at a
        cost about proportional); another value is refused for other friction models and
        for a drop (a FlexibleRod's cells are compiled, 16 per end).

    Returns
    -------
    ImpactResult
        e, delta_p, sliding_length, duration, mean_force, histories, dent(), dois() and
        ``flags``/``warnings``: an impact that gained energy, or that gravity dominates (m g T
        above a tenth of the normal impulse) and leaves the flat, is flagged, never plain
        success; one that gravity brings to rest on the flat (a sphere or a vertical rod at
        1e-9 m/s) is refused ("no separation within the step limit ... ends at rest on the
        flat").

    ValueError names the parameter for a bad input; ``ImplausibleInputWarning`` (likely a unit
    mistake) for a speed of the centre of mass or contact point above 100 m/s.

    Examples
    --------
    >>> import math, impactlab as il
    >>> r = il.simulate(il.Rod.paper(), law="ghaednia", friction="coulomb", mu=0.2,
    ...                 angle=math.radians(20), velocity=(0.0, -1.41))
    >>> round(r.e, 2)
    0.42
    """
    split = [k for k in ("vx", "vy") if k in drop_options]
    check_simulate_keywords(k for k in drop_options if k not in split)  # before what they hide
    if split and velocity is None and speed is None:  # simulate_batch's names, given here
        raise ValueError(split_velocity("simulate", split))
    if velocity is None or speed is not None or incidence is not None:
        velocity = velocity_from(velocity, speed, incidence)
    if not isinstance(body, Rod | Sphere | FlexibleRod):
        raise ValueError(
            f"body must be an impactlab Rod, Sphere or FlexibleRod, {given_body(body)}"
        )
    cells = partial_slip_cells
    if not (type(cells) is int and cells == PARTIAL_SLIP_CELLS):  # checked unless the default
        cells = checked_cells(cells, friction, isinstance(body, FlexibleRod) or bool(drop_options))
    if isinstance(body, FlexibleRod) or drop_options:  # the flexible drop: a DropResult
        args = {"law": law, "friction": friction, "mu": mu, "angle": angle, "velocity": velocity}
        args |= {"spin": spin, "law_params": law_params, "gravity": gravity, "rtol": rtol}
        # the drop records itself (``input``: a call of simulate_drop, its options in full)
        return simulate_flexible(body, flat, constant_angle=constant_angle, history=history,
                                 **args, **drop_options)  # fmt: skip
    r = _fast(body, flat, law, friction, mu, angle, velocity, spin, law_params, gravity,
              constant_angle, rtol, history)  # fmt: skip
    if r is not None:
        return r
    if isinstance(body, Sphere):
        check_constant_angle(constant_angle, body)  # True refused, as an angle is
    x = check_impact(
        body,
        flat,
        law=law,
        friction=friction,
        mu=mu,
        angle=angle,
        velocity=velocity,
        spin=spin,
        law_params=law_params,
        gravity=gravity,
        constant_angle=constant_angle,
        rtol=rtol,
    )
    if x.friction.kind is FrictionKind.PARTIAL_SLIP:  # the partial-slip engine (slipcore)
        r = simulate_partial_slip(x, check_flag("history", history), cells)
        extra = {"partial_slip_cells": cells}  # in the record (``input``), for ``rerun``
    else:
        r, extra = _run_one(x, check_flag("history", history)), None
    # what was simulated, checked, for ImpactResult.input (the fast path records the same)
    r.__dict__["_call"] = (x.body, x.flat, law, law_params, x.gravity, x.constant_angle, x.rtol,
                           extra)  # fmt: skip
    return r


#: Types of the plain numbers ``_fast`` takes (not bool, str, Quantity or 0-d arrays).
_PLAIN = frozenset((float, int, np.float64))
#: Largest plain number ``_fast`` takes (a larger int is left to the full checks).
_BIG = 1e300


def _plain_number(x: Any) -> float | None:
    """``x`` as a float when it is a plain number (``_PLAIN``) below ``_BIG`` in magnitude,
    else None (NaN: None)."""
    return float(x) if type(x) in _PLAIN and -_BIG < x < _BIG else None


def _fast(
    body: Any,
    flat: Any,
    law: Any,
    friction: Any,
    mu: Any,
    angle: Any,
    velocity: Any,
    spin: Any,
    law_params: Any,
    gravity: Any,
    constant_angle: Any,
    rtol: Any,
    history: Any,
) -> ImpactResult | None:
    """``simulate`` of plain, valid inputs that draw no warning: a Rod or a Sphere, registered
    law and friction names (not partial slip), no law_params, finite Python or numpy floats and
    ints in SI, bools; the same result as the full path (``check_impact`` and ``_run_one``),
    from setups cached per (body, flat, law, friction) (``models.engine_setup``).

    None sends the call through the full path, which raises any error or warning: this one
    raises only the engine status's error, as ``_run_one`` does.
    """
    kind = type(body)
    if not (
        (kind is Rod or kind is Sphere)
        and type(law) is str
        and type(friction) is str
        and law_params is None
        and (type(velocity) is tuple or type(velocity) is list)
        and len(velocity) == 2
        and type(constant_angle) is bool
        and type(history) is bool
    ):
        return None
    if kind is Rod:
        th = _plain_number(angle)
    elif angle is None and constant_angle is False:  # a sphere has no angle: one given, or
        th = 0.5 * math.pi  # constant_angle=True, goes to the full path, which refuses it
    else:
        return None
    plain_gravity = gravity is True or gravity is False
    g = (G0 if gravity else 0.0) if plain_gravity else _plain_number(gravity)
    tol = L.DEFAULT_RTOL if rtol is None else _plain_number(rtol)
    vx, vy, w, m = (_plain_number(v) for v in (*velocity, spin, mu))
    if th is None or g is None or tol is None or vx is None or vy is None or w is None:
        return None
    if tol > friction_rtol_max(friction):  # the full path refuses it, naming the model
        return None
    if m is None or not (abs(vx) <= PLAUSIBLE_SPEED and abs(vy) <= PLAUSIBLE_SPEED):
        return None
    if m == 0.0 and friction != "coulomb":  # the full path warns: the model has no effect
        return None
    if input_problem(kind is Rod, th, vx, vy, w, contact_reach(body), m, g, tol) != IN_OK:
        return None  # the full path words the error
    th_out = th if kind is Rod else math.nan
    if w == 0.0:  # the contact point's normal velocity is vy (checks._approach)
        vn = vy
        if not (vy < 0.0 and math.hypot(vx, vy) <= PLAUSIBLE_SPEED):
            return None
    else:
        a, b = lever_arms(body.half_length, body.tip_radius, th)
        vn = vy - w * a
        if not (
            vn < 0.0 and max(math.hypot(vx, vy), math.hypot(vx + w * b, vn)) <= PLAUSIBLE_SPEED
        ):
            return None
    setup = engine_setup(body, flat, law, friction)
    if setup is None:
        return None
    _, _, model, fric, kp, bp, refs, refs_mu = setup
    out = np.empty(L.N_OUT)
    status, hist, nh = impact(
        model.law_id, kp, fric.friction_id, bp, th, vx, vy, w, m, g, constant_angle, tol, history,
        False, out,
    )  # fmt: skip
    if status != S.ST_OK:
        jam = slip_jam(body, th, fric, m, (vx, vy), w)
        raise status_error(int(status), model, vn=vn, gravity=g, jam=jam)
    hist = hist[:nh] if history else None
    rod = (body.half_length, body.tip_radius) if kind is Rod else None
    r = engine_result(
        out, hist, model, fric, refs_mu if m > 0.0 else refs, m, th_out, (vx, vy), w, rod,
        brittle_pressure(body.material, flat),
    )  # fmt: skip
    r.__dict__["_call"] = (body, flat, law, None, g, constant_angle, tol, None)  # as the full path
    return r


def _run_one(x: ImpactInputs, history: bool) -> ImpactResult:
    """Run the compiled impact for the checked inputs ``x``; ValueError on an engine status."""
    out = np.empty(L.N_OUT)
    vx, vy = x.velocity
    status, hist, nh = impact(
        x.model.law_id,
        kernel_params(x.model),
        x.friction.friction_id,
        body_params(x.body, x.flat),
        x.angle,
        vx,
        vy,
        x.spin,
        x.mu,
        x.gravity,
        x.constant_angle,
        x.rtol,
        history,
        False,
        out,
    )
    if status != S.ST_OK:
        jam = slip_jam(x.body, x.angle, x.friction, x.mu, x.velocity, x.spin)
        raise status_error(int(status), x.model, vn=x.vn, gravity=x.gravity, jam=jam)
    return impact_result(x, out, hist[:nh] if history else None)


def rerun(
    record: Mapping[str, Any] | ImpactResult | DropResult, **changes: Any
) -> ImpactResult | DropResult:
    """Run a recorded impact or drop again: ``record`` is a result (an ``ImpactResult`` or a
    ``DropResult``), its ``to_dict()`` (or its ``input``, or the JSON of ``impactlab simulate
    --json`` or ``impactlab drop --json``, read with ``json.load``), run by the function it
    names (``simulate``, or ``simulate_drop`` for a drop of a rigid or flexible rod);
    ``changes`` override its arguments (``rerun(r, mu=0.3)``; a new ``velocity`` or ``speed``
    and ``incidence`` replace the recorded velocity: ``vx=``/``vy=`` are refused, with the
    recorded pair). ValueError when the record is not one,
    or is not a mapping (a file name: ``rerun(json.load(open(path)))``; JSON text:
    ``rerun(json.loads(text))``; ``impactlab simulate --from FILE`` reads a file)."""
    if isinstance(record, ImpactResult | DropResult):  # its record: what to_dict() holds
        record = record.to_dict()
    if isinstance(record, str) and record.lstrip().startswith("{"):
        text = " ".join(record.split())
        shown = text if len(text) <= 40 else f"{text[:40]}..."
        raise ValueError(
            f"record must be a result's to_dict() or its JSON read back, got JSON text "
            f"{shown!r}: read it first, rerun(json.loads(text))"
        )
    if isinstance(record, str | os.PathLike):
        raise ValueError(
            f"record must be a result's to_dict() or its JSON read back, got the file name "
            f"{os.fspath(record)!r}: load it first, rerun(json.load(open({os.fspath(record)!r})))"
            ", or run 'impactlab simulate --from FILE'"
        )
    if not isinstance(record, Mapping):
        raise ValueError(
            "record must be a result's to_dict() or its JSON read back (a mapping), got "
            f"{type(record).__name__}"
        )
    args = from_record(record)
    changes = renamed_keywords("rerun", changes)  # t_max=: time_limit (a DeprecationWarning)
    split = [k for k in ("vx", "vy") if k in changes]
    if split:  # simulate_batch's names: the recorded velocity is one pair
        v = args.get("velocity")
        recorded = "" if v is None else f" ({', '.join(f'{float(c):g}' for c in v)}) m/s"
        batch = "simulate_drops" if record_function(record) == SIMULATE_DROP else "simulate_batch"
        raise ValueError(
            f"{split_velocity('rerun', split, batch)}: velocity=(vx, vy) replaces the recorded "
            f"velocity{recorded}"
        )
    if {"speed", "incidence"} & set(changes):
        args.pop("velocity", None)
    if str(changes.get("friction", "partial_slip")) != "partial_slip":
        args.pop("partial_slip_cells", None)  # the recorded partial_slip's, not the new model's
    if (
        "friction" in changes
        and "rtol" not in changes
        and args.get("rtol") == impact_rtol(args.get("friction"))
    ):  # the recorded model's default (a record cannot tell it from a given one): the new one's
        args.pop("rtol")
    check_recorded_model_flat(args.get("law"), args.get("flat"), changes)
    args |= changes
    if record_function(record) == SIMULATE_DROP:
        return simulate_drop(args.pop("body"), **args)
    return simulate(args.pop("body"), **args)


__all__ = ["rerun", "simulate"]
