"""The same impact with the quasi-static FE curves: a one-degree-of-freedom reference.

The sphere (mass m, speed v) is a point mass on the quasi-static indentation curve: loading on
F_load(delta) until it stops at delta_m, then unloading on the curve unloaded from delta_m
(``indent`` run to that maximum) until the force is zero at delta_r, the permanent depth;
the rebound speed follows from the energy given back. m delta'' = -F(delta), integrated by
scipy's ``solve_ivp`` (a reference: tight tolerances, dense events). No inertia or stress
propagation in the bodies: the difference from :func:`impactlab.fe.impact_run.impact` is
what the quasi-static assumption costs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from impactlab.fe.impact_result import renamed_field
from impactlab.fe.result import IndentationResult
from impactlab.fe.run import indent
from impactlab.materials import Material

_OWNER = "fe.impact_quasistatic.QuasiStaticImpact"


@dataclass(frozen=True)
class QuasiStaticImpact:
    """A 1-DOF impact on quasi-static curves (SI; the names of ``fe.ImpactResult``): e,
    rebound_speed [m/s], delta_max: the peak interference delta_m [m], max_force [N], delta_p:
    the permanent depth [m] (the unloading curve's delta_r from delta_m), duration: the
    contact duration [s]; time, penetration, force: the history [s, m, N]; curve_maximum: the
    delta_max of the unloading curve used [m] (delta_m to within the mismatch of the two FE
    runs). The names before 0.3 (``restitution``, ``max_interference``, ``residual_depth``,
    ``contact_duration``, ``interference``) read these with a DeprecationWarning."""

    speed: float
    mass: float
    e: float
    rebound_speed: float
    delta_max: float
    max_force: float
    delta_p: float
    duration: float
    curve_maximum: float
    time: np.ndarray
    penetration: np.ndarray
    force: np.ndarray

    restitution = renamed_field("restitution", "e", _OWNER)
    max_interference = renamed_field("max_interference", "delta_max", _OWNER)
    residual_depth = renamed_field("residual_depth", "delta_p", _OWNER)
    contact_duration = renamed_field("contact_duration", "duration", _OWNER)
    interference = renamed_field("interference", "penetration", _OWNER)


def _interp(x: np.ndarray, y: np.ndarray, origin: float = 0.0) -> Any:
    """F(delta) between the points as a local power law F = c (delta - origin)^n (linear
    interpolation of log F over log(delta - origin)), which is exact for a Hertz-like curve
    where straight chords are not (a chord of delta^1.5 over 10 points per decade is 0.3 %
    high); zero at and below ``origin``, extrapolated linearly past the last point."""
    order = np.argsort(x)
    xs, ys = np.asarray(x, dtype=np.float64)[order], np.asarray(y, dtype=np.float64)[order]
    keep = (xs > origin) & (ys > 0.0)
    xs, ys = xs[keep], ys[keep]
    lx, ly = np.log(xs - origin), np.log(ys)
    slope = (ys[-1] - ys[-2]) / (xs[-1] - xs[-2]) if xs.size > 1 else 0.0

    def f(d: float) -> float:
        if d <= origin:
            return 0.0
        if d >= xs[-1]:
            return float(ys[-1] + slope * (d - xs[-1]))
        if d <= xs[0]:  # below the first point: the first segment's power law
            n = (ly[1] - ly[0]) / (lx[1] - lx[0]) if xs.size > 1 else 1.0
            return float(ys[0] * ((d - origin) / (xs[0] - origin)) ** n)
        return float(np.exp(np.interp(math.log(d - origin), lx, ly)))

    return f


def _zero_of(delta: np.ndarray, force: np.ndarray) -> float:
    """Where the unloading curve's force reaches zero (the last point still carrying force
    and the first one that does not, interpolated linearly), or its smallest delta."""
    order = np.argsort(delta)
    d, f = np.asarray(delta)[order], np.asarray(force)[order]
    pos = f > 1e-9 * float(np.max(f))
    if pos.all():
        return 0.0
    k = int(np.argmax(pos))  # first point carrying force
    if k == 0:
        return 0.0
    return float(d[k - 1] + (d[k] - d[k - 1]) * (0.0 - f[k - 1]) / (f[k] - f[k - 1]))


def one_dof_impact(
    loading_delta: np.ndarray,
    loading_force: np.ndarray,
    unloading_delta: np.ndarray,
    unloading_force: np.ndarray,
    *,
    mass: float,
    speed: float,
    curve_maximum: float,
    unloading_zero: float | None = None,
) -> QuasiStaticImpact:
    """Integrate m delta'' = -F(delta): loading on the loading curve until delta' = 0, then
    unloading on the unloading curve (shifted so that it starts at the reached delta_m)
    until F = 0. Curves in m and N; mass [kg], speed [m/s]; unloading_zero: where the
    unloading force is zero [m] (the FE run's residual depth, exact to the mesh; default: the
    unloading points' own zero crossing, which the coarse last increments only bracket)."""
    f_load = _interp(np.concatenate([[0.0], loading_delta]), np.concatenate([[0.0], loading_force]))
    # the unloading curve is measured from its own maximum: delta_m - (curve_maximum - delta)
    origin = (
        unloading_zero
        if unloading_zero is not None and math.isfinite(unloading_zero)
        else _zero_of(unloading_delta, unloading_force)
    )
    f_unload = _interp(unloading_delta, unloading_force, origin)
    scale = speed / max(float(np.max(loading_delta)), 1e-30)

    def load(_t: float, y: np.ndarray) -> list[float]:
        return [y[1], -f_load(y[0]) / mass]

    def stop(_t: float, y: np.ndarray) -> float:
        return float(y[1])

    stop.terminal = True  # type: ignore[attr-defined]
    stop.direction = -1  # type: ignore[attr-defined]
    t_span = (0.0, 1e3 / scale)
    a = solve_ivp(load, t_span, [0.0, speed], events=stop, rtol=1e-10, atol=1e-16, max_step=1e-6)
    dm = float(a.y_events[0][0][0]) if a.t_events[0].size else float(a.y[0, -1])
    t1 = float(a.t_events[0][0]) if a.t_events[0].size else float(a.t[-1])
    shift = curve_maximum - dm

    def force_unload(d: float) -> float:
        return max(f_unload(d + shift), 0.0)

    def unload(_t: float, y: np.ndarray) -> list[float]:
        return [y[1], -force_unload(y[0]) / mass]

    def zero(_t: float, y: np.ndarray) -> float:
        return force_unload(y[0]) - 1e-9 * max(force_unload(dm), 1e-30)

    zero.terminal = True  # type: ignore[attr-defined]
    zero.direction = -1  # type: ignore[attr-defined]
    b = solve_ivp(
        unload, (t1, t1 + 1e3 / scale), [dm, 0.0], events=zero, rtol=1e-10, atol=1e-16,
        max_step=1e-6,
    )  # fmt: skip
    if b.t_events[0].size:
        dr, vr, t2 = float(b.y_events[0][0][0]), float(b.y_events[0][0][1]), float(b.t_events[0][0])
    else:
        dr, vr, t2 = math.nan, math.nan, math.nan
    t = np.concatenate([a.t, b.t[1:]])
    d = np.concatenate([a.y[0], b.y[0, 1:]])
    f = np.array([f_load(x) for x in a.y[0]] + [force_unload(x) for x in b.y[0, 1:]])
    return QuasiStaticImpact(
        speed=speed,
        mass=mass,
        e=-vr / speed,
        rebound_speed=-vr,
        delta_max=dm,
        max_force=f_load(dm),
        delta_p=dr,
        duration=t2,
        curve_maximum=curve_maximum,
        time=t,
        penetration=d,
        force=f,
    )


def quasi_static_impact(
    flat: Material,
    sphere_material: Material,
    *,
    radius: float,
    speed: float,
    mass: float,
    delta_guess: float,
    **indent_options: Any,
) -> tuple[QuasiStaticImpact, IndentationResult]:
    """The 1-DOF impact on quasi-static FE curves of the same bodies: one ``indent`` run to
    1.25 ``delta_guess`` [m] gives the loading curve and delta_m; a second run to delta_m
    gives the unloading curve from it. Returns the impact and the second run.
    ``indent_options`` go to ``indent`` (sphere, flat_hardening, mesh_level, ...)."""
    first = indent(flat, sphere_material, radius=radius, delta_max=1.25 * delta_guess,
                   **indent_options)[0]  # fmt: skip
    probe = one_dof_impact(
        first.loading_delta,
        first.loading_force,
        first.unloading_delta,
        first.unloading_force,
        mass=mass,
        speed=speed,
        curve_maximum=first.delta_max,
    )
    run = indent(flat, sphere_material, radius=radius, delta_max=probe.delta_max,
                 **indent_options)[0]  # fmt: skip
    res = one_dof_impact(
        run.loading_delta,
        run.loading_force,
        run.unloading_delta,
        run.unloading_force,
        mass=mass,
        speed=speed,
        curve_maximum=run.delta_max,
        unloading_zero=run.residual_depth,
    )
    return res, run
