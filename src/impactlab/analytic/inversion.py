"""Impact duration T and mean force F from a measured oblique impact, with uncertainties (paper
Sec. 5.2, doi:10.1007/s00419-015-1108-2): Eq. 12 solved for T, Eq. 29 or the rigid-body identity
for F; first-order propagation (numerical Jacobian) and Monte Carlo."""

from __future__ import annotations

import dataclasses
import functools
import math
import warnings
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any

import numpy as np

from impactlab._validation import (
    ImplausibleInputWarning,
    check_gravity,
    check_seed,
    warn_implausible,
)
from impactlab.analytic._compliance import check_compliance
from impactlab.analytic._conditioning import (
    CONDITION_LIMIT,
    REVERSAL_SIGMAS,
    check_coefficients,
    check_conditioning,
    check_direction,
    check_duration,
    check_finite_result,
    check_mc_duration,
)
from impactlab.analytic._correlation import check_correlation, linear_sigmas, sign_flipped
from impactlab.analytic._inputs import HALF_PI, gravity_flag, rod_values
from impactlab.analytic._inputs import travel as _travel
from impactlab.analytic._measurements import (
    check_momentum,
    check_plausible,
    check_rod,
    measurements,
)
from impactlab.analytic.closed_forms import G0, check_sliding, coefficients, duration_from_dent
from impactlab.analytic.monte_carlo import (
    MC_REJECTED_WARNING,
    REVERSAL_LEAN,
    SPREAD_ROUNDING,
    monte_carlo,
    point_distribution,
)
from impactlab.analytic.result import InversionResult, Measured
from impactlab.bodies import Rod

__all__ = [
    "CONDITION_LIMIT",
    "MC_REJECTED_WARNING",
    "MIN_STEP",
    "REVERSAL_LEAN",
    "REVERSAL_SIGMAS",
    "SPREAD_ROUNDING",
    "invert",
]

Value = float | Measured | tuple[float, float]

#: The smallest step of the central differences, relative to the value: 1e-4 sigma below it
#: would round away (``value + h == value``, a 0/0 derivative); at it the derivative keeps
#: about 7 digits.
MIN_STEP = 1e-9


def _core(
    x: Mapping[str, Any],
    m: float,
    L: float,
    R: float,
    inertia: float,
    gravity: bool,
    g: float,
    travel: bool = False,
) -> tuple[Any, Any, Any, Any, Any]:
    """(T, F, valid, stuck, past) for arrays of inputs (magnitudes; ``dv_cy`` and ``vt_in`` may
    be absent); ``stuck`` marks alpha >= 0: the sticking regime (mu >= mu_c), or a patch's
    travel that turns; ``past`` marks vt_in >= |alpha| |v_i| outside it: the pole of Eq. 12,
    where the tip need not slide towards -x."""
    th, mu = x["angle"], x["mu"]
    *_, K_y, al, mu_c = coefficients(th, mu, m, L, R, inertia, travel)
    vi, dp, ls = x["v_i"], x["delta_p"], x["sliding_length"]
    stuck = (mu >= mu_c) | (al >= 0) if travel else mu >= mu_c
    valid = (th >= 0) & (th <= HALF_PI) & (mu >= 0) & ~stuck & (vi > 0) & (dp >= 0) & (ls > 0)
    with np.errstate(all="ignore"):
        # the tip's incoming tangential velocity vt_in <= 0 (docs/analytic.md, Sec. 5)
        if "vt_in" in x:
            vi_t = vi - x["vt_in"] / np.abs(al)
            past = ~stuck & (vi > 0) & (vi_t <= 0)
        else:
            vi_t, past = vi, np.zeros_like(stuck)
        valid = valid & (vi_t > 0)
        T = duration_from_dent(dp, ls, vi_t, np.abs(al), gravity, g)
        if "dv_cy" in x:
            valid = valid & (x["dv_cy"] > 0)
            F = m * x["dv_cy"] / T + (m * g if gravity else 0.0)
        else:
            e = x["e"]
            valid = valid & (e >= 0) & (e <= 1)
            F = ((1.0 + e) * vi + (g * T if gravity else 0.0)) / (K_y * T)
    valid = valid & np.isfinite(T) & np.isfinite(F) & (T > 0)
    return T, F, valid, stuck, past


def _sensitivities(
    meas: Mapping[str, Measured], nominal: Mapping[str, Any], core: Any
) -> tuple[dict[str, float], dict[str, float]]:
    """dT/dx and dF/dx for every input: central differences with steps scaled to each sigma (or
    value), one-sided at delta_p = 0. The step is at least ``MIN_STEP`` of the value (or of 1e-9
    where it is smaller): a sigma below the value's rounding moves nothing."""
    sens_T: dict[str, float] = {}
    sens_F: dict[str, float] = {}
    for k in meas:
        v, sigma = meas[k].value, meas[k].sigma
        scale = max(abs(v), 1e-9)
        h = max(1e-4 * sigma, MIN_STEP * scale) if sigma > 0 else 1e-6 * scale
        if k in ("delta_p",) and v - h < 0:  # one-sided at the boundary
            lo, hi = v, v + h
        else:
            lo, hi = v - h, v + h
        xs: dict[str, Any] = dict(nominal)
        xs[k] = np.array([lo, hi])
        Ts, Fs, *_ = core(xs)
        Ts, Fs = np.broadcast_to(Ts, (2,)), np.broadcast_to(Fs, (2,))
        sens_T[k] = float((Ts[1] - Ts[0]) / (hi - lo))
        sens_F[k] = float((Fs[1] - Fs[0]) / (hi - lo))
    return sens_T, sens_F


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
    with np.errstate(all="ignore"):  # a rod's extreme values: refused below, not warned
        _, _, _, K_x, K_y, al, mu_c = (
            float(v) for v in coefficients(th, meas["mu"].value, m, L, R, inertia, travel)
        )
    check_coefficients(K_x, K_y, al, {"mass": m, "length": L, "tip_radius": R, "inertia": inertia})
    check_sliding(np.float64(meas["mu"].value), np.float64(mu_c), np.float64(th))
    if travel and al >= 0:
        raise ValueError(
            f"measure='travel': at mu = {meas['mu'].value:.4g} and angle = {math.degrees(th):.4g} "
            "deg the contact patch does not move towards -x (rolling outweighs slip, "
            f"alpha_travel = {al:.3g} >= 0), so its travel cannot give the duration"
        )
    return K_x, K_y, al, mu_c


#: The most Monte Carlo samples taken: about 125 bytes a sample, 1.25 GB of arrays.
MAX_SAMPLES = 10_000_000
_MEMORY = "(about 1.2 GB of memory; the mean and 95 % interval settle long before: default 20,000)"


def _options(n_samples: Any, seed: Any, gravity: Any, g: Any, measure: str) -> dict[str, Any]:
    """The inversion's options checked: n_samples (an int in [100, MAX_SAMPLES]), seed (None
    or an int >= 0), gravity (a bool), g [m/s^2] and measure ("slip" or "travel")."""
    if (
        isinstance(n_samples, bool)
        or not isinstance(n_samples, int | np.integer)
        or n_samples < 100
    ):
        raise ValueError(f"n_samples must be an integer >= 100, got {n_samples!r}")
    if n_samples > MAX_SAMPLES:  # refused before any is drawn
        raise ValueError(f"n_samples must be at most {MAX_SAMPLES:,} {_MEMORY}, got {n_samples:,}")
    return {
        "n_samples": int(n_samples),
        "seed": check_seed("seed", seed),
        "gravity": gravity_flag(gravity),
        "g": check_gravity("g", g),
        "travel": _travel(measure),
    }


def _forces(
    meas: Mapping[str, Measured], m: float, K_y: float, T0: float, gravity: bool, g: float
) -> tuple[float | None, float | None]:
    """(F_rigid, F_momentum) at the nominal duration ``T0``: the rigid-body identity (with e)
    and Eq. 29 (with dv_cy), each None without its input."""
    F_rig = F_mom = None
    if "e" in meas:  # the rigid-body identity
        e, v = meas["e"].value, meas["v_i"].value
        F_rig = float(((1.0 + e) * v + (g * T0 if gravity else 0.0)) / (K_y * T0))
    if "dv_cy" in meas:  # Eq. 29
        F_mom = float(m * meas["dv_cy"].value / T0 + (m * g if gravity else 0.0))
    return F_rig, F_mom


def invert(
    *,
    angle: Value,
    v_i: Value,
    mu: Value,
    delta_p: Value,
    sliding_length: Value,
    e: Value | None = None,
    dv_cy: Value | None = None,
    vt_in: Value = 0.0,
    correlation: Mapping[tuple[str, str], float] | None = None,
    rod: Rod | None = None,
    gravity: bool = False,
    measure: str = "slip",
    g: float = G0,
    n_samples: int = 20_000,
    seed: int | None = 0,
) -> InversionResult:
    """Impact duration T and mean normal force F from a measured oblique impact (paper Sec. 5.2).

    Each measured input is a number (exact) or a ``(value, sigma)`` pair / :class:`Measured`
    (sigma = standard deviation, same unit; independent unless ``correlation`` says). A number
    is SI; a dimensional value may also be a string with units (``"22 um"``, ``"20 deg"``) or a
    pint Quantity of any registry, and then a bare sigma beside it is in its unit, as on the
    command line (``("45 deg", 0.2)``: 0.2 deg; ``("22 um", 2)``: 2 um); mu and e are plain numbers.

    angle : rod-to-flat angle [rad], in (0, pi/2).
    v_i : vertical tip velocity before the impact [m/s]; sign ignored (the paper writes -1.41);
        |v_i| >= 1e-6 m/s (``MIN_SPEED``).
    mu : friction coefficient over the impact (Eq. 28, e.g. from
        :func:`friction_from_velocities`), >= 0 and < mu_c(angle) (gross sliding).
    delta_p : permanent dent depth [m], a magnitude of at least 1 nm: a negative value is
        refused (the paper prints -22e-6; give 22e-6).
    sliding_length : length L_s of the sliding scar [m], non-zero; sign ignored, as for v_i:
        the magnitude is taken (the paper prints -1400e-6; -1400e-6 and 1400e-6 give the same
        T and F).
    e : coefficient of restitution of the tip's normal velocity, in [0, 1]. Needed for F when
        ``dv_cy`` is not given (rigid-body identity F T = (1 + e)|v_i| / K_y).
    dv_cy : measured change of the centre-of-mass vertical velocity over the impact [m/s], upward
        positive; when given, F comes from Eq. 29 (F T = m dv_Cy) and the rigid-body identity is
        reported alongside as ``F_rigid``.
    vt_in : incoming tangential velocity [m/s], signed along +x (towards the centre of mass), of
        the point whose displacement ``sliding_length`` is: the contact point, v_Cx + b omega
        (spin included; ``analyze``'s ``v_tip_in[0]``), for ``"slip"``; the tip sphere's centre,
        v_Cx + (b - R) omega, for ``"travel"``. Default 0 (the paper: no tangential velocity, no
        spin; left out of ``inputs``). Eq. 12 then reads T = (delta_p + |L_s|/|alpha|) /
        (|v_i| - vt_in/|alpha|), exact for vt_in <= 0 (docs/analytic.md); for vt_in > 0 the
        sliding reverses and T is an upper bound (warned: see below); vt_in >= |alpha| |v_i|
        is refused.
    correlation : correlation coefficients of inputs measured together, (name, name) ->
        coefficient in [-1, 1] by these keywords (``{("e", "dv_cy"): 0.94}``), each an input
        given with a sigma, the matrix positive semi-definite; used in the first-order
        propagation (J C J^T) and the Monte Carlo (correlated draws). Default None: independent.
        A v_i or sliding_length given negative: its magnitude's coefficients change sign.
    rod : an ``impactlab.bodies.Rod``; default the paper's rod (``impactlab.bodies.PAPER_ROD``).
    gravity : include gravity during the contact (adds g T^2 / 2 to Eq. 12 and the gravity impulse
        to Eq. 29); False reproduces the paper's equations.
    measure : what ``sliding_length`` measures: ``"slip"`` (default, the paper: displacement of
        the rod's material point at the contact) or ``"travel"`` (displacement of the contact
        patch, which a dent's length records; see docs/analytic.md).
    n_samples, seed : Monte Carlo sample count (an int >= 100) and seed (None or an int >= 0).

    Bounds: ValueError for a nominal delta_p below 1 nm (no profilometer resolves it) or deeper
    than the rod's tip radius, a sliding length longer than the rod (impossible: most likely a
    unit mistake), the sticking regime (mu >= mu_c), where the dent does not fix T, and a sigma
    of e or the angle wider than a quarter of its range ([0, 1], (0, pi/2)): it spans the
    whole range, or a sigma of delta_p or sliding_length wider than a quarter of the tip radius
    or of the rod's length; the sticking regime is named before a sliding length below 1 nm;
    also a required input given as None, and a rod or inputs whose K_x, K_y, T, F
    or uncertainties over- or underflow (named, never returned as inf, NaN or 0).
    ImplausibleInputWarning for a dent shallower than 0.1 um or deeper than a tenth of the tip
    radius, |v_i| below 1 mm/s, |v_i| or dv_cy above 100 m/s, a nominal duration
    above 0.1 s, or a Monte Carlo median or 95 % interval reaching above it, a rod whose
    I_C / (m L^2) is below 1/240 (``rod: ...``, as ``analyze``), a mu/mu_c at which a
    tangentially compliant contact makes T 10 % or more too long (docs/analytic.md, Sec. 7;
    ``_compliance.COMPLIANCE_THRESHOLD``; advice only), a Monte Carlo that discards more than
    5 % of its samples (``mc_rejected``; ``mc_used`` samples kept), or any sample in the
    sticking regime or at vt_in >= |alpha| |v_i|: T has a heavy tail there, its Monte Carlo
    mean and standard deviation are unreliable, its median and interval are not; a vt_in more
    than 3 sigma above 0 (with T's bounds), or more than 5 % of the samples above 0 that move
    T's median or interval (``REVERSAL_LEAN``); and for an ill-conditioned T: |d ln T/d ln mu|
    or |d ln T/d ln angle| above 10 (``CONDITION_LIMIT``), near mu_c or 90 deg, where
    alpha -> 0.

    Returns an :class:`InversionResult` with ``duration`` and ``mean_force``, their first-order
    and Monte Carlo uncertainties (mean, standard deviation, median, 95 % interval), alpha, K_x,
    K_y, mu_c, the inputs used (magnitudes; the sensitivities are with respect to them) and
    ``warnings``, the texts of the ImplausibleInputWarnings it issued.

    Example: ``invert(angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6,
    sliding_length=1400e-6).duration`` is about 4.11e-3 s.
    """
    inputs = {"angle": angle, "v_i": v_i, "mu": mu, "delta_p": delta_p}

    def compute() -> InversionResult:
        given = {**inputs, "sliding_length": sliding_length, "e": e, "dv_cy": dv_cy}
        meas = measurements({**given, "vt_in": vt_in})
        opt = _options(n_samples, seed, gravity, g, measure)
        flipped = sign_flipped(given) if correlation is not None else frozenset()
        opt["correlation"] = check_correlation(correlation, meas, flipped)
        m, L, R, inertia = _scalar_rod(rod)
        check_rod(m, L, inertia)
        # the sticking regime first: there a sliding length near 0 is what it leaves
        coef = _nominal_coefficients(meas, m, L, R, inertia, opt["travel"])
        check_plausible(meas, L, R)
        check_compliance(meas["mu"].value, coef[3], meas["angle"].value, meas["v_i"].value)
        check_direction(meas, abs(coef[2]), opt["gravity"], opt["g"])
        rod_ = {"mass": m, "length": L, "tip_radius": R, "inertia": inertia}
        return _result(meas, opt, rod_, coef, measure)

    return _recording(compute)


def _recording(compute: Callable[[], InversionResult]) -> InversionResult:
    """``compute()`` with the texts of its ImplausibleInputWarnings in the result's
    ``warnings`` (what ``impactlab invert --json`` lists). Each is still issued, at the
    caller's line and through the caller's filters, also when ``compute`` raises; any other
    warning is shown as Python shows it."""
    caught: list[warnings.WarningMessage] = []
    texts: list[str] = []
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", ImplausibleInputWarning)
            result = compute()
    finally:
        for w in caught:
            if issubclass(w.category, ImplausibleInputWarning):
                texts.append(str(w.message))
                warn_implausible(texts[-1])
            else:
                warnings.showwarning(w.message, w.category, w.filename, w.lineno, w.file, w.line)
    return dataclasses.replace(result, warnings=tuple(texts))


def _result(
    meas: Mapping[str, Measured],
    opt: Mapping[str, Any],
    rod: Mapping[str, float],
    coef: tuple[float, float, float, float],
    measure: str,
) -> InversionResult:
    """The inversion at the nominal inputs, its sensitivities and its Monte Carlo."""
    m, L, R, inertia = (rod[k] for k in ("mass", "length", "tip_radius", "inertia"))
    core = functools.partial(
        _core,
        m=m,
        L=L,
        R=R,
        inertia=inertia,
        gravity=opt["gravity"],
        g=opt["g"],
        travel=opt["travel"],
    )
    nominal = {k: np.float64(v.value) for k, v in meas.items()}
    T0_a, F0_a, ok, *_ = core(nominal)
    T0 = float(T0_a)
    check_finite_result({"duration": T0, "mean_force": float(F0_a)}, meas, rod)
    if not bool(ok):  # pragma: no cover - guarded by the checks above
        raise ValueError("the inputs give no valid inversion")
    sens_T, sens_F = _sensitivities(meas, nominal, core)
    corr = opt["correlation"]
    sT_lin, sF_lin = linear_sigmas(meas, sens_T, sens_F, corr)
    check_finite_result({"sigma_T_linear": sT_lin, "sigma_F_linear": sF_lin}, meas, rod)
    varied = any(v.sigma > 0 for v in meas.values())
    K_x, K_y, al, mu_c = coef
    check_duration(T0, check_conditioning(meas, sens_T, T0, al, mu_c))
    F_rig, F_mom = _forces(meas, m, K_y, T0, opt["gravity"], opt["g"])
    if "dv_cy" in meas:
        check_momentum(meas, m, K_y, T0, opt["g"] if opt["gravity"] else 0.0)
    mc_args = (meas, opt["n_samples"], opt["seed"], core, abs(al), opt["gravity"], corr)
    mc = monte_carlo(*mc_args) if varied else point_distribution(T0, float(F0_a))
    check_finite_result(mc, meas, rod)
    check_mc_duration(T0, mc, meas, sens_T)
    return InversionResult(
        duration=T0,
        mean_force=float(F0_a),
        sigma_T_linear=sT_lin,
        sigma_F_linear=sF_lin,
        **mc,
        n_samples=opt["n_samples"],
        seed=opt["seed"],
        alpha=al,
        K_x=K_x,
        K_y=K_y,
        mu_c=mu_c,
        force_method="momentum" if "dv_cy" in meas else "rigid-body identity",
        F_momentum=F_mom,
        F_rigid=F_rig,
        gravity=opt["gravity"],
        measure=measure,
        inputs=MappingProxyType({k: (v.value, v.sigma) for k, v in meas.items()}),
        correlation=MappingProxyType(dict(corr)),
        rod=MappingProxyType(dict(rod)),
        sensitivity_T=MappingProxyType(sens_T),
        sensitivity_F=MappingProxyType(sens_F),
    )
