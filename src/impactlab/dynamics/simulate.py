"""``simulate``: one impact of a rod or sphere on a flat, and ``simulate_batch`` for many.

The Python layer only validates the input (``impactlab.dynamics.checks``), looks up the cached
compiled representations of the contact law and the body (``impactlab.dynamics.models``) and
wraps the engine's output; the impact itself runs in the compiled core
(``impactlab.dynamics.core``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._validation import check_finite, check_nonnegative
from impactlab.bodies import Rod, Sphere
from impactlab.contact import ContactModel
from impactlab.dynamics.batch import run_arrays
from impactlab.dynamics.checks import (
    check_angle,
    check_body,
    check_flat,
    check_rtol,
    check_velocity,
    gravity_value,
)
from impactlab.dynamics.core import layout as L
from impactlab.dynamics.core import status as S
from impactlab.dynamics.core.driver import impact
from impactlab.dynamics.models import body_params, contact_model, kernel_params, references_used
from impactlab.dynamics.results import BatchResult, History, ImpactResult
from impactlab.friction import FrictionModel, get_friction
from impactlab.materials import AISI_1010, Material


def _status_error(status: int, out: np.ndarray, model: ContactModel, law_name: str) -> ValueError:
    if status == S.ST_LAW_LIMIT:
        return ValueError(
            f"the interference exceeded {model.max_interference:.6g} m, the validity limit of "
            f"the {law_name!r} law: lower the impact velocity or choose another law"
        )
    if status == S.ST_NAN:
        return ValueError(
            f"the {law_name!r} contact law returned a non-finite force or unloading branch "
            f"(law not available, or evaluated outside its domain)"
        )
    return ValueError(S.STATUS_MESSAGES.get(status, f"engine status {status}"))


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
        Relative tolerance (default ``DEFAULT_RTOL`` = 3e-8).
    history : bool
        Keep the time history (needed for ``dent()`` and the plots).

    Returns
    -------
    ImpactResult
        Immutable result: e, delta_p, sliding_length, duration, mean_force, histories, dent(),
        references and dois().

    Examples
    --------
    >>> import math, impactlab as il
    >>> r = il.simulate(il.Rod.paper(), law="ghaednia", friction="coulomb", mu=0.2,
    ...                 angle=math.radians(20), velocity=(0.0, -1.41))
    >>> round(r.e, 2)
    0.42
    """
    body = check_body(body)
    flat = check_flat(flat)
    fric = get_friction(friction)
    mu_v = check_nonnegative("mu", mu)
    th = check_angle(angle, body)
    vx, vy = check_velocity(velocity)
    w = check_finite("spin", spin)
    g = gravity_value(gravity)
    r = check_rtol(rtol)
    model = contact_model(body, flat, law, law_params)
    bp = body_params(body, flat)
    a0 = body.half_length * math.cos(th)
    vn = vy - w * a0
    if not vn < 0.0:
        raise ValueError(
            f"velocity: the contact point does not approach the flat (its normal velocity "
            f"vy - spin * (L/2) cos(angle) = {vn!r} m/s must be < 0)"
        )
    out = np.empty(L.N_OUT)
    status, hist, nh = impact(
        model.law_id,
        kernel_params(model),
        fric.friction_id,
        bp,
        th,
        vx,
        vy,
        w,
        mu_v,
        g,
        bool(constant_angle),
        r,
        bool(history),
        False,
        out,
    )
    if status != S.ST_OK:
        raise _status_error(int(status), out, model, model.name)
    return _impact_result(
        out.tolist(),
        History(hist[:nh]) if history else None,
        model,
        fric,
        mu_v,
        th if isinstance(body, Rod) else math.nan,
        (vx, vy),
        w,
    )


#: Engine outputs that are ImpactResult fields of the same name and type (float).
_SCALAR_OUTPUTS = tuple(
    n
    for n in L.OUTPUT_FIELDS
    if n in ImpactResult.__dataclass_fields__ and n not in ("regime", "n_steps")
)


def _impact_result(
    o: list[float],
    history: History | None,
    model: ContactModel,
    fric: FrictionModel,
    mu: float,
    angle: float,
    velocity_in: tuple[float, float],
    spin_in: float,
) -> ImpactResult:
    """The ImpactResult from the engine's output row ``o`` and the inputs."""
    return ImpactResult(
        **{name: o[L.O[name]] for name in _SCALAR_OUTPUTS},
        velocity_out=(o[L.O_VX], o[L.O_VY]),
        regime=S.REGIME_NAMES[int(o[L.O_REG])],
        n_steps=int(o[L.O_NST]),
        law=model.name,
        friction=fric.name,
        mu=mu,
        angle=angle,
        velocity_in=velocity_in,
        spin_in=spin_in,
        history=history,
        references=references_used(model, fric, mu > 0.0),
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
    body = check_body(body)
    flat = check_flat(flat)
    fric = get_friction(friction)
    model = contact_model(body, flat, law, law_params)
    if angle is None:
        if isinstance(body, Rod):
            raise ValueError("angle is required for a Rod (radians, in (0, pi/2])")
        angle = 0.5 * math.pi
    arrays = [
        _as_1d(n, v)
        for n, v in (("mu", mu), ("angle", angle), ("vx", vx), ("vy", vy), ("spin", spin))
    ]
    try:
        b = np.broadcast_arrays(*[np.atleast_1d(a) for a in arrays])
    except ValueError:
        shapes = ", ".join(
            f"{n}: {a.shape}"
            for n, a in zip(("mu", "angle", "vx", "vy", "spin"), arrays, strict=True)
        )
        raise ValueError(f"mu, angle, vx, vy and spin do not broadcast ({shapes})") from None
    mu_a, th_a, vx_a, vy_a, w_a = (np.ascontiguousarray(x, dtype=np.float64) for x in b)
    init = np.ascontiguousarray(np.stack([th_a, vx_a, vy_a, w_a], axis=1))
    out, status = run_arrays(
        model.law_id,
        fric.friction_id,
        model.params,
        body_params(body, flat),
        init,
        mu_a,
        gravity=gravity,
        constant_angle=constant_angle,
        rtol=rtol,
    )
    inputs = {"mu": mu_a, "angle": th_a, "vx": vx_a, "vy": vy_a, "spin": w_a}
    return BatchResult(
        out=out,
        status=status,
        inputs=inputs,
        law=model.name,
        friction=fric.name,
        references=references_used(model, fric, bool(np.any(mu_a > 0.0))),
    )


__all__ = ["simulate", "simulate_batch"]
