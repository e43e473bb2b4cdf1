"""``simulate``: one impact of a rod or sphere on a flat, and ``simulate_batch`` for many.

The Python layer only validates the input, looks up (cached) compiled representations of the
contact law and the body, and wraps the engine's output; the impact itself runs in
``impactlab.dynamics.engine``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._validation import check_finite, check_nonnegative
from impactlab.bodies import Rod, Sphere
from impactlab.contact.base import ContactModel
from impactlab.contact.registry import get_law
from impactlab.dynamics import engine as _e
from impactlab.dynamics.results import BatchResult, History, ImpactResult
from impactlab.friction import get_friction
from impactlab.materials import AISI_1010, G0, ContactPair, Material

_MODEL_CACHE: dict[tuple[Any, ...], ContactModel] = {}
_PARAMS_CACHE: dict[int, tuple[ContactModel, np.ndarray]] = {}


def kernel_params(model: ContactModel) -> np.ndarray:
    """A writable C-contiguous copy of ``model.params`` for the compiled engine (one numba
    specialisation for every caller: read-only arrays would compile a second one)."""
    hit = _PARAMS_CACHE.get(id(model))
    if hit is not None and hit[0] is model:
        return hit[1]
    p = np.require(np.array(model.params, dtype=np.float64), np.float64, ["C", "W"])
    if len(_PARAMS_CACHE) > 512:
        _PARAMS_CACHE.clear()
    _PARAMS_CACHE[id(model)] = (model, p)
    return p
_BODY_CACHE: dict[tuple[int, int], tuple[Any, Any, np.ndarray]] = {}


def _check_body(body: Any) -> Rod | Sphere:
    if not isinstance(body, Rod | Sphere):
        raise ValueError(f"body must be an impactlab Rod or Sphere, got {type(body).__name__}")
    return body


def _check_flat(flat: Any) -> Material:
    if not isinstance(flat, Material):
        raise ValueError(f"flat must be an impactlab Material, got {type(flat).__name__}")
    return flat


def _body_params(body: Rod | Sphere, flat: Material) -> np.ndarray:
    key = (id(body), id(flat))
    hit = _BODY_CACHE.get(key)
    if hit is not None and hit[0] is body and hit[1] is flat:
        return hit[2]
    bp = np.require(body.to_params(flat), np.float64, ["C", "W"])
    if len(_BODY_CACHE) > 256:
        _BODY_CACHE.clear()
    _BODY_CACHE[key] = (body, flat, bp)
    return bp


def contact_model(body: Rod | Sphere, flat: Material, law: str | ContactModel,
                  law_params: Mapping[str, float] | None = None) -> ContactModel:
    """The (cached) ContactModel of ``law`` for ``body`` on ``flat``.

    ``law`` is a registered law name or a ready ContactModel (then ``law_params`` must be
    empty and its radius must equal the body's tip radius).
    """
    R = body.tip_radius
    if isinstance(law, ContactModel):
        if law_params:
            raise ValueError("law_params cannot be combined with a ready ContactModel")
        if abs(law.radius - R) > 1e-12 * R:
            raise ValueError(
                f"law: the ContactModel's radius ({law.radius!r} m) differs from the body's tip "
                f"radius ({R!r} m); build the model with radius={R!r}"
            )
        return law
    if not isinstance(law, str):
        raise ValueError(f"law must be a law name or a ContactModel, got {type(law).__name__}")
    params = dict(law_params or {})
    key = (law, body.material, flat, R, tuple(sorted(params.items())))
    try:
        model = _MODEL_CACHE.get(key)
    except TypeError:  # unhashable parameter values
        raise ValueError(f"law_params values must be numbers, got {params!r}") from None
    if model is None:
        model = get_law(law).build(ContactPair(body.material, flat), R, **params)
        if len(_MODEL_CACHE) > 512:
            _MODEL_CACHE.clear()
        _MODEL_CACHE[key] = model
    return model


def gravity_value(gravity: bool | float) -> float:
    """True -> standard gravity 9.80665 m/s^2, False -> 0, a number -> that value (>= 0)."""
    if gravity is True:
        return G0
    if gravity is False or gravity is None:
        return 0.0
    return check_nonnegative("gravity", gravity, "m/s^2")


def _check_rtol(rtol: float | None) -> float:
    if rtol is None:
        return _e.DEFAULT_RTOL
    r = check_finite("rtol", rtol)
    if not 1e-13 <= r <= 1e-3:
        raise ValueError(f"rtol must lie in [1e-13, 1e-3], got {r!r}")
    return r


def check_angle(angle: Any, body: Rod | Sphere) -> float:
    """Validate the rod angle (radians, in (0, pi/2]); ignored (pi/2) for a sphere."""
    if isinstance(body, Sphere):
        if angle is not None:
            check_finite("angle", angle)
        return 0.5 * math.pi
    if angle is None:
        raise ValueError("angle is required for a Rod: the rod axis to the flat, in radians, "
                         "in (0, pi/2]")
    th = check_finite("angle", angle)
    if th > 0.5 * math.pi + 1e-12:
        hint = ""
        if th <= 90.0 + 1e-9:
            hint = (f"; {th!r} looks like degrees: pass math.radians({th!r}) = "
                    f"{math.radians(th):.6g} rad")
        raise ValueError(f"angle must be in radians in (0, pi/2], got {th!r}{hint}")
    if th <= 0.0:
        raise ValueError(f"angle must be in radians in (0, pi/2], got {th!r}")
    return th


def _check_velocity(velocity: Any) -> tuple[float, float]:
    try:
        vx, vy = velocity
    except (TypeError, ValueError):
        raise ValueError(f"velocity must be a pair (vx, vy) in m/s, got {velocity!r}") from None
    return check_finite("velocity[0] (vx)", vx), check_finite("velocity[1] (vy)", vy)


def _status_error(status: int, out: np.ndarray, model: ContactModel, law_name: str) -> ValueError:
    if status == _e.ST_LAW_LIMIT:
        return ValueError(
            f"the interference exceeded {model.max_interference:.6g} m, the validity limit of "
            f"the {law_name!r} law: lower the impact velocity or choose another law"
        )
    if status == _e.ST_NAN:
        return ValueError(
            f"the {law_name!r} contact law returned a non-finite force or unloading branch "
            f"(law not available, or evaluated outside its domain)"
        )
    return ValueError(_e.STATUS_MESSAGES.get(status, f"engine status {status}"))


def simulate(
    body: Rod | Sphere,
    flat: Material = AISI_1010,
    *,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    mu: float = 0.0,
    angle: float | None = None,
    velocity: tuple[float, float],
    spin: float = 0.0,
    law_params: Mapping[str, float] | None = None,
    gravity: bool | float = True,
    constant_angle: bool = False,
    rtol: float | None = None,
    history: bool = True,
) -> ImpactResult:
    """Simulate one impact from first touch (delta = 0) to separation (SI units).

    Parameters
    ----------
    body : Rod or Sphere
        The impacting rigid body.
    flat : Material
        The flat's material (default AISI 1010, the paper's flat).
    law : str or ContactModel
        Contact-law name (``impactlab.law_names()``) or a built ContactModel.
    friction : str
        ``"impulse_ratio"`` (paper Eq. 7), ``"coulomb"`` or ``"mindlin"``.
    mu : float
        Friction coefficient, >= 0.
    angle : float
        Rod axis to the flat [rad], in (0, pi/2]; tip lowest, centre of mass at +x of the tip
        (ignored for a sphere).
    velocity : tuple of float
        (vx, vy) of the centre of mass at first touch [m/s]; the contact point must approach.
    spin : float
        Angular velocity [rad/s], counter-clockwise positive.
    law_params : mapping, optional
        Law parameters (see ``impactlab laws``).
    gravity : bool or float
        True (9.80665 m/s^2), False, or a value [m/s^2].
    constant_angle : bool
        Freeze the lever arms at the initial angle (the paper's assumption).
    rtol : float, optional
        Relative tolerance (default ``engine.DEFAULT_RTOL``).
    history : bool
        Keep the time history (needed for ``dent()`` and the plots).

    Returns
    -------
    ImpactResult
        Immutable result: e, delta_p, sliding_length, duration, mean_force, histories, dent().

    Examples
    --------
    >>> import math, impactlab as il
    >>> r = il.simulate(il.Rod.paper(), law="ghaednia", friction="coulomb", mu=0.2,
    ...                 angle=math.radians(20), velocity=(0.0, -1.41))
    >>> round(r.e, 2)
    0.42
    """
    body = _check_body(body)
    flat = _check_flat(flat)
    fric = get_friction(friction)
    mu_v = check_nonnegative("mu", mu)
    th = check_angle(angle, body)
    vx, vy = _check_velocity(velocity)
    w = check_finite("spin", spin)
    g = gravity_value(gravity)
    r = _check_rtol(rtol)
    model = contact_model(body, flat, law, law_params)
    bp = _body_params(body, flat)
    a0 = body.half_length * math.cos(th)
    vn = vy - w * a0
    if not vn < 0.0:
        raise ValueError(
            f"velocity: the contact point does not approach the flat (its normal velocity "
            f"vy - spin * (L/2) cos(angle) = {vn!r} m/s must be < 0)"
        )
    out = np.empty(_e.N_OUT)
    status, hist, nh = _e.impact(model.law_id, kernel_params(model), fric.friction_id, bp, th,
                                 vx, vy, w, mu_v, g, bool(constant_angle), r, bool(history),
                                 False, out)
    if status != _e.ST_OK:
        raise _status_error(int(status), out, model, model.name)
    o = out.tolist()
    return ImpactResult(
        e=o[_e.O_E],
        e_energy=o[_e.O_EE],
        velocity_out=(o[_e.O_VX], o[_e.O_VY]),
        spin_out=o[_e.O_W],
        delta_max=o[_e.O_DMAX],
        delta_p=o[_e.O_DP],
        sliding_length=o[_e.O_SL],
        contact_travel=o[_e.O_CT],
        duration=o[_e.O_T],
        mean_force=o[_e.O_FMEAN],
        max_force=o[_e.O_FMAX],
        normal_impulse=o[_e.O_PN],
        tangential_impulse=o[_e.O_PT],
        energy_dissipated=o[_e.O_ED],
        stick_time=o[_e.O_STICK],
        regime=_e.REGIME_NAMES[int(o[_e.O_REG])],
        law=model.name,
        friction=fric.name,
        mu=mu_v,
        angle=th if isinstance(body, Rod) else math.nan,
        velocity_in=(vx, vy),
        spin_in=w,
        vn_in=o[_e.O_VNIN],
        vt_in=o[_e.O_VTIN],
        vn_out=o[_e.O_VNOUT],
        vt_out=o[_e.O_VTOUT],
        angle_out=o[_e.O_ANG],
        t_max=o[_e.O_TMAX],
        n_steps=int(o[_e.O_NST]),
        history=History(hist[:nh]) if history else None,
        _law_id=model.law_id,
        _law_params=model.params,
    )


def _as_1d(name: str, value: Any) -> np.ndarray:
    a = np.asarray(value, dtype=np.float64)
    if a.ndim > 1:
        raise ValueError(f"{name} must be a scalar or a 1-D array, got shape {a.shape}")
    return a


def simulate_batch(
    body: Rod | Sphere,
    flat: Material = AISI_1010,
    *,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    mu: Any = 0.0,
    angle: Any = None,
    vx: Any = 0.0,
    vy: Any,
    spin: Any = 0.0,
    law_params: Mapping[str, float] | None = None,
    gravity: bool | float = True,
    constant_angle: bool = False,
    rtol: float | None = None,
) -> BatchResult:
    """Many impacts of one body, law and friction model, in parallel on all cores.

    ``mu``, ``angle`` [rad], ``vx``, ``vy`` [m/s] and ``spin`` [rad/s] are scalars or 1-D arrays,
    broadcast against each other. Invalid cases (NaN input, an angle outside (0, pi/2], a
    receding contact point, the law's validity exceeded, ...) are flagged in
    ``BatchResult.status`` and never stop the batch.
    """
    from impactlab.dynamics.batch import run_arrays

    body = _check_body(body)
    flat = _check_flat(flat)
    fric = get_friction(friction)
    model = contact_model(body, flat, law, law_params)
    if angle is None:
        if isinstance(body, Rod):
            raise ValueError("angle is required for a Rod (radians, in (0, pi/2])")
        angle = 0.5 * math.pi
    arrays = [_as_1d(n, v) for n, v in
              (("mu", mu), ("angle", angle), ("vx", vx), ("vy", vy), ("spin", spin))]
    try:
        b = np.broadcast_arrays(*[np.atleast_1d(a) for a in arrays])
    except ValueError:
        shapes = ", ".join(f"{n}: {a.shape}" for n, a in
                           zip(("mu", "angle", "vx", "vy", "spin"), arrays, strict=True))
        raise ValueError(f"mu, angle, vx, vy and spin do not broadcast ({shapes})") from None
    mu_a, th_a, vx_a, vy_a, w_a = (np.ascontiguousarray(x, dtype=np.float64) for x in b)
    init = np.ascontiguousarray(np.stack([th_a, vx_a, vy_a, w_a], axis=1))
    out, status = run_arrays(model.law_id, fric.friction_id, model.params,
                             _body_params(body, flat), init, mu_a, gravity=gravity,
                             constant_angle=constant_angle, rtol=rtol)
    inputs = {"mu": mu_a, "angle": th_a, "vx": vx_a, "vy": vy_a, "spin": w_a}
    return BatchResult(out=out, status=status, inputs=inputs, law=model.name,
                       friction=fric.name)


__all__ = ["check_angle", "contact_model", "gravity_value", "simulate", "simulate_batch"]
