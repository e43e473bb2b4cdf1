"""Impact duration T and mean force F from a measured oblique impact, with uncertainties (paper
Sec. 5.2, doi:10.1007/s00419-015-1108-2): Eq. 12 solved for T, Eq. 29 or the rigid-body identity
for F; first-order propagation (numerical Jacobian) and Monte Carlo."""

from __future__ import annotations

import math
from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

import numpy as np

from impactlab._validation import check_nonnegative
from impactlab.analytic._inputs import HALF_PI, rod_values
from impactlab.analytic._inputs import travel as _travel
from impactlab.analytic.closed_forms import G0, check_sliding, coefficients, duration_from_dent
from impactlab.analytic.result import InversionResult, Measured, measured
from impactlab.bodies import Rod

__all__ = ["invert"]

Value = float | Measured | tuple[float, float]

_CONVENTION = "the paper's tables print it negative, impactlab takes the magnitude"


def _core(
    x: Mapping[str, Any],
    m: float,
    L: float,
    R: float,
    inertia: float,
    gravity: bool,
    g: float,
    travel: bool = False,
) -> tuple[Any, Any, Any]:
    """(T, F, valid) for arrays of inputs (magnitudes; ``dv_cy`` may be absent)."""
    th, mu = x["angle"], x["mu"]
    *_, K_y, al, mu_c = coefficients(th, mu, m, L, R, inertia, travel)
    vi, dp, ls = x["v_i"], x["delta_p"], x["L_s"]
    valid = (th >= 0) & (th <= HALF_PI) & (mu >= 0) & (mu < mu_c) & (vi > 0) & (dp >= 0) & (ls > 0)
    if travel:  # the patch's travel must keep its (negative) direction
        valid = valid & (al < 0)
    with np.errstate(all="ignore"):
        T = duration_from_dent(dp, ls, vi, np.abs(al), gravity, g)
        if "dv_cy" in x:
            valid = valid & (x["dv_cy"] > 0)
            F = m * x["dv_cy"] / T + (m * g if gravity else 0.0)
        else:
            e = x["e"]
            valid = valid & (e >= 0) & (e <= 1)
            F = ((1.0 + e) * vi + (g * T if gravity else 0.0)) / (K_y * T)
    valid = valid & np.isfinite(T) & np.isfinite(F) & (T > 0)
    return T, F, valid


def _measurements(
    angle: Value,
    v_i: Value,
    mu: Value,
    delta_p: Value,
    sliding_length: Value,
    e: Value | None,
    dv_cy: Value | None,
) -> dict[str, Measured]:
    """The checked inputs keyed by the paper's symbols (``v_i`` as its magnitude)."""
    meas: dict[str, Measured] = {
        "angle": measured("angle", angle),
        "v_i": measured("v_i", v_i),
        "mu": measured("mu", mu),
        "delta_p": measured("delta_p", delta_p),
        "L_s": measured("sliding_length (L_s)", sliding_length),
    }
    if e is not None:
        meas["e"] = measured("e", e)
    if dv_cy is not None:
        meas["dv_cy"] = measured("dv_cy", dv_cy)
    if e is None and dv_cy is None:
        raise ValueError(
            "e or dv_cy is required: F needs the restitution coefficient (rigid-body "
            "identity) or the centre-of-mass velocity change (Eq. 29)"
        )
    if meas["delta_p"].value < 0.0:
        raise ValueError(
            f"delta_p must be >= 0 (the permanent dent depth, a magnitude in m), got "
            f"{meas['delta_p'].value!r}: {_CONVENTION}"
        )
    if meas["L_s"].value < 0.0:
        raise ValueError(
            f"sliding_length (L_s) must be > 0 (the length of the sliding scar, a "
            f"magnitude in m), got {meas['L_s'].value!r}: {_CONVENTION}"
        )
    for k in ("v_i", "delta_p", "L_s"):  # the drop speed; -0.0 -> 0.0
        meas[k] = Measured(abs(meas[k].value), meas[k].sigma)
    th = meas["angle"].value
    if not 0.0 < th < HALF_PI:
        raise ValueError(
            f"angle must lie in (0, pi/2) rad, got {th!r} rad "
            f"({math.degrees(th):.4g} deg); pass radians"
        )
    if meas["v_i"].value == 0.0:
        raise ValueError("v_i must be non-zero (the drop speed), got 0.0")
    if meas["mu"].value < 0.0:
        raise ValueError(f"mu must be >= 0, got {meas['mu'].value!r}")
    if meas["L_s"].value == 0.0:
        raise ValueError(
            "sliding_length (L_s) must be non-zero: in gross sliding any normal "
            "impulse makes the tip slide, so a zero sliding length cannot be inverted"
        )
    if "e" in meas and not 0.0 <= meas["e"].value <= 1.0:
        raise ValueError(f"e must lie in [0, 1], got {meas['e'].value!r}")
    if "dv_cy" in meas and meas["dv_cy"].value <= 0.0:
        raise ValueError(
            f"dv_cy must be > 0 (upward change of the centre-of-mass velocity), got "
            f"{meas['dv_cy'].value!r}"
        )
    return meas


def _sensitivities(
    meas: Mapping[str, Measured], nominal: Mapping[str, Any], core: Any
) -> tuple[dict[str, float], dict[str, float]]:
    """dT/dx and dF/dx for every input: central differences with steps scaled to each sigma (or
    value), one-sided at delta_p = 0."""
    sens_T: dict[str, float] = {}
    sens_F: dict[str, float] = {}
    for k in meas:
        v = meas[k].value
        h = 1e-4 * meas[k].sigma if meas[k].sigma > 0 else 1e-6 * max(abs(v), 1e-9)
        if k in ("delta_p",) and v - h < 0:  # one-sided at the boundary
            lo, hi = v, v + h
        else:
            lo, hi = v - h, v + h
        xs: dict[str, Any] = dict(nominal)
        xs[k] = np.array([lo, hi])
        Ts, Fs, _ = core(xs)
        Ts, Fs = np.broadcast_to(Ts, (2,)), np.broadcast_to(Fs, (2,))
        sens_T[k] = float((Ts[1] - Ts[0]) / (hi - lo))
        sens_F[k] = float((Fs[1] - Fs[0]) / (hi - lo))
    return sens_T, sens_F


def _monte_carlo(
    meas: Mapping[str, Measured], n: int, seed: int | None, core: Any, varied: bool
) -> dict[str, Any]:
    """Means, standard deviations, 95 % intervals and the rejected fraction of ``n`` samples."""
    rng = np.random.default_rng(seed)
    samples = {
        k: (v.value + v.sigma * rng.standard_normal(n)) if v.sigma > 0 else np.full(n, v.value)
        for k, v in meas.items()
    }
    Ts, Fs, ok = (np.broadcast_to(v, (n,)) for v in core(samples))
    rejected = 1.0 - float(np.mean(ok))
    Tv, Fv = Ts[ok], Fs[ok]
    if Tv.size < 2:
        raise ValueError(
            "almost all Monte Carlo samples fall in the sticking regime or out of "
            "range: the uncertainties are too large for this inversion"
        )
    return {
        "T_mc": float(np.mean(Tv)),
        "F_mc": float(np.mean(Fv)),
        "sigma_T_mc": float(np.std(Tv, ddof=1)) if varied else 0.0,
        "sigma_F_mc": float(np.std(Fv, ddof=1)) if varied else 0.0,
        "T_interval_mc": (float(np.percentile(Tv, 2.5)), float(np.percentile(Tv, 97.5))),
        "F_interval_mc": (float(np.percentile(Fv, 2.5)), float(np.percentile(Fv, 97.5))),
        "mc_rejected": rejected,
    }


def _scalar_rod(rod: Rod | None) -> tuple[float, float, float, float]:
    m_a, L_a, R_a, I_a = rod_values(rod)
    if any(np.ndim(v) for v in (m_a, L_a, R_a, I_a)):
        raise ValueError("rod properties must be scalars for invert()")
    return float(m_a), float(L_a), float(R_a), float(I_a)


def _nominal_coefficients(
    meas: Mapping[str, Measured], m: float, L: float, R: float, inertia: float, travel: bool
) -> tuple[float, float, float, float]:
    """(K_x, K_y, alpha, mu_c) at the nominal angle and mu; ValueError in the sticking regime
    and where the contact patch's travel does not point towards -x."""
    th = meas["angle"].value
    _, _, _, K_x, K_y, al, mu_c = (
        float(v) for v in coefficients(th, meas["mu"].value, m, L, R, inertia, travel)
    )
    check_sliding(np.float64(meas["mu"].value), np.float64(mu_c), np.float64(th))
    if travel and al >= 0:
        raise ValueError(
            f"measure='travel': at mu = {meas['mu'].value:.4g} and angle = {math.degrees(th):.4g} "
            "deg the contact patch does not move towards -x (rolling outweighs slip, "
            f"alpha_travel = {al:.3g} >= 0), so its travel cannot give the duration"
        )
    return K_x, K_y, al, mu_c


def invert(
    *,
    angle: Value,
    v_i: Value,
    mu: Value,
    delta_p: Value,
    sliding_length: Value,
    e: Value | None = None,
    dv_cy: Value | None = None,
    rod: Rod | None = None,
    gravity: bool = False,
    measure: str = "slip",
    g: float = G0,
    n_samples: int = 20_000,
    seed: int | None = 0,
) -> InversionResult:
    """Impact duration T and mean normal force F from a measured oblique impact (paper Sec. 5.2).

    Each measured input is a number (exact) or a ``(value, sigma)`` pair / :class:`Measured`
    (sigma = standard deviation, same unit; inputs are treated as independent). SI units:

    angle : rod-to-flat angle [rad], in (0, pi/2).
    v_i : vertical tip velocity before the impact [m/s]; sign ignored (the paper writes -1.41).
    mu : friction coefficient over the impact (Eq. 28, e.g. from
        :func:`friction_from_velocities`), >= 0 and < mu_c(angle) (gross sliding).
    delta_p : permanent dent depth [m], >= 0 (the paper prints -22e-6; impactlab takes 22e-6).
    sliding_length : length L_s of the sliding scar [m], > 0 (the paper prints -1400e-6).
    e : coefficient of restitution of the tip's normal velocity, in [0, 1]. Needed for F when
        ``dv_cy`` is not given (rigid-body identity F T = (1 + e)|v_i| / K_y).
    dv_cy : measured change of the centre-of-mass vertical velocity over the impact [m/s], upward
        positive; when given, F comes from Eq. 29 (F T = m dv_Cy) and the rigid-body identity is
        reported alongside as ``F_rigid``.
    rod : an ``impactlab.bodies.Rod``; default the paper's rod with I_C = m L^2 / 12
        (``impactlab.bodies.PAPER_ROD``).
    gravity : include gravity during the contact (adds g T^2 / 2 to Eq. 12 and the gravity impulse
        to Eq. 29); False reproduces the paper's equations.
    measure : what ``sliding_length`` measures: ``"slip"`` (default, the paper: displacement of
        the rod's material point at the contact) or ``"travel"`` (displacement of the contact
        patch, i.e. of the tip sphere's centre, which is what a dent's length records; see
        docs/analytic.md).
    n_samples, seed : Monte Carlo sample count (>= 100) and seed (reproducible by default).

    Returns an :class:`InversionResult` with T, F, their first-order and Monte Carlo uncertainties,
    alpha, K_x, K_y, mu_c and the inputs used. Raises ValueError naming the offending parameter for
    invalid inputs and for the sticking regime (mu >= mu_c), where the dent does not fix T.

    Example: ``invert(angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6,
    sliding_length=1400e-6).T`` is about 4.11e-3 s.
    """
    meas = _measurements(angle, v_i, mu, delta_p, sliding_length, e, dv_cy)
    if (
        isinstance(n_samples, bool)
        or not isinstance(n_samples, int | np.integer)
        or n_samples < 100
    ):
        raise ValueError(f"n_samples must be an integer >= 100, got {n_samples!r}")
    g_ = check_nonnegative("g", g, "m/s^2")
    travel = _travel(measure)
    m, L, R, inertia = _scalar_rod(rod)
    K_x, K_y, al, mu_c = _nominal_coefficients(meas, m, L, R, inertia, travel)

    def core(x: Mapping[str, Any]) -> tuple[Any, Any, Any]:
        return _core(x, m, L, R, inertia, gravity, g_, travel)

    nominal = {k: np.float64(v.value) for k, v in meas.items()}
    T0_a, F0_a, ok = core(nominal)
    if not bool(ok):  # pragma: no cover - guarded by the checks above
        raise ValueError("the inputs give no valid inversion")
    T0, F0 = float(T0_a), float(F0_a)
    names = [k for k in meas if meas[k].sigma > 0]
    sens_T, sens_F = _sensitivities(meas, nominal, core)
    sT_lin = math.sqrt(sum((sens_T[k] * meas[k].sigma) ** 2 for k in names))
    sF_lin = math.sqrt(sum((sens_F[k] * meas[k].sigma) ** 2 for k in names))
    mc = _monte_carlo(meas, int(n_samples), seed, core, bool(names))

    F_rig = None
    if "e" in meas:  # the rigid-body identity
        F_rig = float(
            ((1.0 + meas["e"].value) * meas["v_i"].value + (g_ * T0 if gravity else 0.0))
            / (K_y * T0)
        )
    F_mom = None
    if "dv_cy" in meas:  # Eq. 29
        F_mom = float(m * meas["dv_cy"].value / T0 + (m * g_ if gravity else 0.0))
    return InversionResult(
        T=T0,
        F=F0,
        sigma_T_linear=sT_lin,
        sigma_F_linear=sF_lin,
        **mc,
        n_samples=int(n_samples),
        seed=seed,
        alpha=al,
        K_x=K_x,
        K_y=K_y,
        mu_c=mu_c,
        force_method="momentum" if "dv_cy" in meas else "rigid-body identity",
        F_momentum=F_mom,
        F_rigid=F_rig,
        gravity=bool(gravity),
        measure=measure,
        inputs=MappingProxyType({k: (v.value, v.sigma) for k, v in meas.items()}),
        rod=MappingProxyType({"mass": m, "length": L, "tip_radius": R, "inertia": inertia}),
        sensitivity_T=MappingProxyType(sens_T),
        sensitivity_F=MappingProxyType(sens_F),
    )
