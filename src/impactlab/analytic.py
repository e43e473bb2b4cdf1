"""The paper's closed forms for a rigid rod with a spherical tip hitting a flat, corrected.

Source: H. Ghaednia, D. B. Marghitu, R. L. Jackson, "Permanent deformation during the oblique impact
with friction", Archive of Applied Mechanics 86 (2016) 121-134, doi:10.1007/s00419-015-1108-2,
Eqs. 1-13, 28, 29. The printed Eqs. 6, 10, 11, 12 and 13 contain errors; the forms here are derived
from the rigid-body impulse relations in ``docs/analytic.md`` (errata: ``docs/paper/errata.md``).

Conventions (SI throughout, angles in radians): origin at the first contact point O, x horizontal
and positive towards the centre of mass C, y up; ``angle`` is the angle between the rod axis and the
flat; the rod starts with no spin and no tangential velocity and drops with vertical speed ``v_i``.
Lever arms from C to O: ``a = (L/2) cos(angle)``, ``b = (L/2) sin(angle) + R``; ``k^2 = I_C/m``.
P is the normal contact impulse. In gross sliding the tip slides towards -x and friction gives
the tangential impulse ``P_x = mu P``; then the tip velocity is ``v_O = (K_x P, v_i + K_y P)``.

Validity: rigid rod, constant angle during contact (the rod turns by about 1.6 deg at 20 deg and
0.9 deg at 45 deg in the paper's impacts, see docs/analytic.md), initial tangential velocity and
spin zero, impulse-ratio friction (paper Eq. 7),
gross sliding (``mu < mu_c``). Gravity during the contact is neglected by the paper's equations;
:func:`invert` can include it (``gravity=True``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Protocol

import numpy as np

from impactlab._validation import check_finite, check_nonnegative, check_positive

#: Standard gravity [m/s^2].
G0 = 9.80665

DOI = "10.1007/s00419-015-1108-2"

__all__ = [
    "DOI",
    "G0",
    "InversionResult",
    "Measured",
    "RodLike",
    "RodProperties",
    "alpha",
    "critical_friction",
    "friction_from_velocities",
    "impact_duration",
    "impulse_coefficients",
    "invert",
    "lever_arms",
    "mean_force_momentum",
    "mean_force_rigid",
    "sliding_length",
]


# --------------------------------------------------------------------------------------------
# The rod
# --------------------------------------------------------------------------------------------


class RodLike(Protocol):
    """Anything with the rod's ``mass`` [kg], ``length`` [m] (or ``L``, as ``impactlab.bodies.Rod``;
    the centre of mass sits L/2 from the tip sphere's centre along the axis, paper Eq. 1),
    ``tip_radius`` [m] and ``inertia`` I_C [kg m^2] about the centre of mass (``None`` means the
    slender-rod value m L^2 / 12)."""

    @property
    def mass(self) -> Any: ...

    @property
    def tip_radius(self) -> Any: ...


@dataclass(frozen=True)
class RodProperties:
    """The rigid-body data the closed forms need (duck-compatible with ``impactlab.bodies.Rod``).

    Parameters
    ----------
    mass : m [kg], > 0.
    length : L [m], > 0; the centre of mass lies L/2 from the tip sphere's centre (paper Eq. 1).
    tip_radius : R [m], > 0, radius of curvature of the tip.
    inertia : I_C [kg m^2] about the centre of mass, > 0; ``None`` gives the slender-rod value
        m L^2 / 12 (the paper gives none; see docs/analytic.md for the sensitivity of T to it).
    """

    mass: float
    length: float
    tip_radius: float
    inertia: float | None = None

    def __post_init__(self) -> None:
        m = check_positive("mass", self.mass, "kg")
        L = check_positive("length", self.length, "m")
        object.__setattr__(self, "mass", m)
        object.__setattr__(self, "length", L)
        object.__setattr__(self, "tip_radius", check_positive("tip_radius", self.tip_radius, "m"))
        i = m * L * L / 12.0 if self.inertia is None else self.inertia
        object.__setattr__(self, "inertia", check_positive("inertia", i, "kg m^2"))

    @property
    def inertia_ratio(self) -> float:
        """I_C / (m L^2) (1/12 for a slender rod)."""
        assert self.inertia is not None
        return float(self.inertia) / (self.mass * self.length**2)


def _rod_values(rod: RodLike | None) -> tuple[Any, Any, Any, Any]:
    """(mass, length, tip_radius, inertia) of ``rod`` as float arrays, validated."""
    if rod is None:
        from impactlab.paper.data import PAPER_ROD

        return _rod_values(PAPER_ROD)
    length = getattr(rod, "length", None)
    if length is None:
        length = getattr(rod, "L", None)  # impactlab.bodies.Rod names it L
    try:
        raw = (rod.mass, length, rod.tip_radius, getattr(rod, "inertia", None))
    except AttributeError as exc:
        raise ValueError(
            f"rod must have mass, length (or L), tip_radius and inertia attributes ({exc})"
        ) from None
    if raw[1] is None:
        raise ValueError("rod must have a length (or L) attribute")
    m = _arr("rod.mass", raw[0], low=0.0, low_open=True)
    L = _arr("rod.length", raw[1], low=0.0, low_open=True)
    R = _arr("rod.tip_radius", raw[2], low=0.0, low_open=True)
    inertia = m * L * L / 12.0 if raw[3] is None else _arr("rod.inertia", raw[3], low=0.0,
                                                            low_open=True)
    return m, L, R, inertia


def _arr(
    name: str,
    value: Any,
    *,
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    high_open: bool = False,
) -> Any:
    """``value`` as a float64 array (0-d for scalars); ValueError naming ``name`` if it is not a
    finite real or lies outside [low, high] (open ends where asked)."""
    try:
        x = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number or array, got {value!r}") from None
    bad = ~np.isfinite(x)
    if bad.any():
        first = x.ravel()[np.flatnonzero(bad.ravel())[0]]
        raise ValueError(f"{name} must be finite, got {first!r}")
    if low is not None:
        out = x <= low if low_open else x < low
        if out.any():
            op = ">" if low_open else ">="
            raise ValueError(f"{name} must be {op} {low:g}, got {x.ravel()[np.argmax(out)]!r}")
    if high is not None:
        out = x >= high if high_open else x > high
        if out.any():
            op = "<" if high_open else "<="
            raise ValueError(f"{name} must be {op} {high:g}, got {x.ravel()[np.argmax(out)]!r}")
    return x


def _out(x: Any) -> Any:
    """Return a Python float for 0-d results, the array otherwise."""
    x = np.asarray(x)
    return float(x) if x.ndim == 0 else x


_HALF_PI = 0.5 * math.pi


def _angle(value: Any) -> Any:
    return _arr("angle", value, low=0.0, high=_HALF_PI)


# --------------------------------------------------------------------------------------------
# Closed forms (vectorised)
# --------------------------------------------------------------------------------------------


def lever_arms(angle: Any, length: Any, tip_radius: Any) -> tuple[Any, Any]:
    """Lever arms (a, b) [m] from the centre of mass C to the contact point O (paper Eq. 1).

    ``a = (L/2) cos(angle)`` (horizontal), ``b = (L/2) sin(angle) + R`` (vertical).
    ``angle`` in radians, [0, pi/2]. Broadcasts over arrays.
    """
    th = _angle(angle)
    L = _arr("length", length, low=0.0, low_open=True)
    R = _arr("tip_radius", tip_radius, low=0.0, low_open=True)
    return _out(0.5 * L * np.cos(th)), _out(0.5 * L * np.sin(th) + R)


_MEASURES = ("slip", "travel")


def _travel(measure: str) -> bool:
    if measure not in _MEASURES:
        raise ValueError(f"measure must be 'slip' or 'travel', got {measure!r}")
    return measure == "travel"


def _coefficients(
    th: Any, mu: Any, m: Any, L: Any, R: Any, inertia: Any, travel: bool = False
) -> tuple[Any, ...]:
    """Unvalidated core: a, b, k^2, K_x, K_y, alpha, mu_c (arrays). With ``travel`` K_x and alpha
    refer to the tip sphere's centre (the contact patch) instead of the material point O."""
    a = 0.5 * L * np.cos(th)
    b = 0.5 * L * np.sin(th) + R
    k2 = inertia / m
    ab = a * b
    if travel:  # lever arm of the sphere centre S: b - R
        bs = b - R
        kx_num = mu * (k2 + b * bs) - a * bs
    else:
        kx_num = mu * (k2 + b * b) - ab
    ky_num = k2 + a * a - mu * ab
    K_x = kx_num / (m * k2)
    K_y = ky_num / (m * k2)
    alpha_ = kx_num / ky_num
    mu_c = ab / (k2 + b * b)
    return a, b, k2, K_x, K_y, alpha_, mu_c


def impulse_coefficients(
    angle: Any, mu: Any, rod: RodLike | None = None, *, measure: str = "slip"
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
    mu_ = _arr("mu", mu, low=0.0)
    m, L, R, inertia = _rod_values(rod)
    _, _, _, K_x, K_y, _, _ = _coefficients(th, mu_, m, L, R, inertia, _travel(measure))
    return _out(K_x), _out(K_y)


def alpha(angle: Any, mu: Any, rod: RodLike | None = None, *, measure: str = "slip") -> Any:
    """alpha = K_x / K_y = [mu (k^2 + b^2) - a b] / [k^2 + a^2 - mu a b] (paper Eq. 13, corrected).

    Dimensionless. Negative in gross sliding (mu < mu_c), zero at mu = mu_c, positive beyond (where
    the tip sticks and Eq. 12 does not apply). ``angle`` [rad], ``mu`` >= 0; broadcasts.
    ``measure="travel"``: the ratio for the contact patch's travel (see
    :func:`impulse_coefficients`); it changes sign below mu_c, where rolling outweighs slip.
    """
    th = _angle(angle)
    mu_ = _arr("mu", mu, low=0.0)
    m, L, R, inertia = _rod_values(rod)
    return _out(_coefficients(th, mu_, m, L, R, inertia, _travel(measure))[5])


def critical_friction(angle: Any, rod: RodLike | None = None) -> Any:
    """mu_c = a b / (k^2 + b^2): the tip slides throughout the impact for mu < mu_c and sticks from
    the start for mu >= mu_c (rod at rest tangentially, constant angle). Dimensionless; broadcasts.
    """
    th = _angle(angle)
    m, L, R, inertia = _rod_values(rod)
    return _out(_coefficients(th, 0.0, m, L, R, inertia)[6])


def sliding_length(
    delta_p: Any,
    v_i: Any,
    duration: Any,
    angle: Any,
    mu: Any,
    rod: RodLike | None = None,
    *,
    measure: str = "slip",
) -> Any:
    """Signed sliding length L_s = alpha (delta_p - v_i T) [m] (paper Eq. 12 with its sign fixed).

    Paper convention: ``delta_p`` <= 0 [m] (final tip height: the dent is below the surface),
    ``v_i`` < 0 [m/s], ``duration`` T > 0 [s]; the result is negative (the tip slides towards -x) in
    gross sliding. ValueError in the sticking regime (mu >= mu_c), where L_s = 0 physically.
    ``measure="travel"`` gives the contact patch's travel instead of the slip (gravity neglected).
    """
    dp = _arr("delta_p", delta_p, high=0.0)
    vi = _arr("v_i", v_i, high=0.0, high_open=True)
    T = _arr("duration", duration, low=0.0, low_open=True)
    th = _angle(angle)
    mu_ = _arr("mu", mu, low=0.0)
    m, L, R, inertia = _rod_values(rod)
    *_, al, mu_c = _coefficients(th, mu_, m, L, R, inertia, _travel(measure))
    _check_sliding(mu_, mu_c, th)
    return _out(al * (dp - vi * T))


def impact_duration(
    delta_p: Any, L_s: Any, v_i: Any, alpha_: Any, *, gravity: bool = False, g: float = G0
) -> Any:
    """Impact duration T [s] from the measured dent: Eq. 12 solved for T.

        T = (|L_s| / |alpha| + |delta_p|) / |v_i|                 (gravity neglected, the paper)
        (g/2) T^2 + |v_i| T = |L_s| / |alpha| + |delta_p|         (gravity=True)

    Signs: the dent depth and the sliding length enter by magnitude (the paper's negative values
    and plain magnitudes both work); so does ``v_i`` (the drop speed, != 0). ``alpha_`` must be
    negative (gross sliding); ``alpha_ >= 0`` means the tip sticks and raises ValueError.
    """
    dp = np.abs(_arr("delta_p", delta_p))
    ls = np.abs(_arr("L_s", L_s))
    vi = np.abs(_arr("v_i", v_i))
    al = _arr("alpha", alpha_)
    if (vi == 0).any():
        raise ValueError("v_i must be non-zero (the drop speed), got 0.0")
    if (ls == 0).any():
        raise ValueError("L_s must be non-zero: in gross sliding any normal impulse makes the tip "
                         "slide, so a zero sliding length cannot be inverted")
    if (al >= 0).any():
        raise ValueError(
            f"alpha must be < 0 (gross sliding), got {al.ravel()[np.argmax(al.ravel() >= 0)]!r}: "
            "alpha >= 0 means mu >= mu_c, the tip sticks and Eq. 12 cannot give the duration"
        )
    g_ = check_nonnegative("g", g, "m/s^2")
    return _out(_duration(dp, ls, vi, np.abs(al), gravity, g_))


def _duration(dp: Any, ls: Any, vi: Any, abs_alpha: Any, gravity: bool, g: float) -> Any:
    c = ls / abs_alpha + dp
    if not gravity or g == 0.0:
        return c / vi
    # stable root of (g/2) T^2 + vi T - c = 0
    return 2.0 * c / (vi + np.sqrt(vi * vi + 2.0 * g * c))


def friction_from_velocities(
    dv_cx: Any, dv_cy: Any, *, duration: Any = None, g: float = G0
) -> Any:
    """Friction coefficient from the centre-of-mass velocity changes (paper Eq. 28) [-].

    mu = |dv_Cx| / |dv_Cy|. With ``duration`` T [s] the gravity impulse is removed from the
    vertical change: mu = |dv_Cx| / (dv_Cy + g T) (``dv_cy`` upward positive, as measured).
    """
    dx = _arr("dv_cx", dv_cx)
    dy = _arr("dv_cy", dv_cy)
    if duration is not None:
        T = _arr("duration", duration, low=0.0)
        dy = dy + check_nonnegative("g", g, "m/s^2") * T
    if (dy == 0).any():
        raise ValueError("dv_cy must be non-zero (no normal impulse means no friction estimate)")
    return _out(np.abs(dx) / np.abs(dy))


def mean_force_momentum(
    duration: Any, mass: Any, dv_cy: Any, *, gravity: bool = False, g: float = G0
) -> Any:
    """Mean normal contact force [N] from the centre-of-mass momentum change (paper Eq. 29).

    F T = m dv_Cy (the paper), or F T = m dv_Cy + m g T with ``gravity=True`` (the measured change
    of the centre-of-mass velocity includes the gravity impulse, which the contact must overcome).
    """
    T = _arr("duration", duration, low=0.0, low_open=True)
    m = _arr("mass", mass, low=0.0, low_open=True)
    dv = _arr("dv_cy", dv_cy)
    g_ = check_nonnegative("g", g, "m/s^2")
    return _out(m * dv / T + (m * g_ if gravity else 0.0))


def mean_force_rigid(
    duration: Any, e: Any, v_i: Any, K_y: Any, *, gravity: bool = False, g: float = G0
) -> Any:
    """Mean normal contact force [N] from the rigid-body identity (no centre-of-mass data needed).

    The tip's normal velocity goes from v_i to -e v_i: (1 + e)|v_i| = K_y P (- g T with gravity,
    which acts on C only and does not turn the rod), so F = (1 + e)|v_i| / (K_y T), or
    F = [(1 + e)|v_i| + g T] / (K_y T) with ``gravity=True``. ``e`` in [0, 1], ``K_y`` > 0 [1/kg].
    """
    T = _arr("duration", duration, low=0.0, low_open=True)
    e_ = _arr("e", e, low=0.0, high=1.0)
    vi = np.abs(_arr("v_i", v_i))
    Ky = _arr("K_y", K_y, low=0.0, low_open=True)
    g_ = check_nonnegative("g", g, "m/s^2")
    return _out(((1.0 + e_) * vi + (g_ * T if gravity else 0.0)) / (Ky * T))


def _check_sliding(mu: Any, mu_c: Any, th: Any) -> None:
    stick = np.asarray(mu >= mu_c)
    if stick.any():
        i = int(np.argmax(stick.ravel()))
        mu_v = float(np.broadcast_to(mu, stick.shape).ravel()[i])
        mc = float(np.broadcast_to(mu_c, stick.shape).ravel()[i])
        ang = math.degrees(float(np.broadcast_to(th, stick.shape).ravel()[i]))
        raise ValueError(
            f"sticking regime: mu = {mu_v:.4g} >= mu_c = {mc:.4g} at angle = {ang:.4g} deg, so "
            "alpha >= 0 and the tip does not slide; the inversion of Eq. 12 needs gross sliding "
            "(mu < mu_c), it gives no duration here"
        )


# --------------------------------------------------------------------------------------------
# Inversion with uncertainty
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Measured:
    """A measured value and its standard deviation (same unit, ``sigma`` >= 0)."""

    value: float
    sigma: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "value", check_finite("value", self.value))
        object.__setattr__(self, "sigma", check_nonnegative("sigma", self.sigma))


def _measured(name: str, x: Any) -> Measured:
    if isinstance(x, Measured):
        return x
    if isinstance(x, tuple | list):
        if len(x) != 2:
            raise ValueError(f"{name} must be a number or a (value, sigma) pair, got {x!r}")
        v, s = x
    else:
        v, s = x, 0.0
    try:
        return Measured(v, s)
    except ValueError as exc:
        raise ValueError(f"{name}: {exc}") from None


_INPUTS = ("angle", "v_i", "e", "mu", "delta_p", "L_s", "dv_cy")
_UNITS = {"angle": "rad", "v_i": "m/s", "e": "-", "mu": "-", "delta_p": "m", "L_s": "m",
          "dv_cy": "m/s", "T": "s", "F": "N"}


@dataclass(frozen=True)
class InversionResult:
    """Impact duration and mean normal force inverted from a measured oblique impact (immutable).

    Attributes (SI): ``T`` [s], ``F`` [N] (nominal values); ``sigma_T_linear``, ``sigma_F_linear``
    (first-order propagation, numerical Jacobian); ``T_mc``, ``F_mc`` (Monte Carlo means),
    ``sigma_T_mc``, ``sigma_F_mc`` (Monte Carlo standard deviations), ``T_interval_mc``,
    ``F_interval_mc`` (2.5 and 97.5 percentiles), ``mc_rejected`` (fraction of samples that fell in
    the sticking regime or out of range and were discarded), ``n_samples``, ``seed``; ``alpha``,
    ``K_x``, ``K_y`` [1/kg], ``mu_c``; ``force_method`` ("momentum" for Eq. 29 with dv_cy, else
    "rigid-body identity"); ``F_momentum``, ``F_rigid`` (each None when its input is missing);
    ``gravity``; ``measure`` ("slip" or "travel", what L_s measures); ``inputs`` (name ->
    (value, sigma) in SI, magnitudes as used); ``rod`` (mass, length, tip_radius, inertia);
    ``sensitivity_T``, ``sensitivity_F`` (partial derivatives
    with respect to each input, SI).
    """

    T: float
    F: float
    sigma_T_linear: float
    sigma_F_linear: float
    T_mc: float
    F_mc: float
    sigma_T_mc: float
    sigma_F_mc: float
    T_interval_mc: tuple[float, float]
    F_interval_mc: tuple[float, float]
    mc_rejected: float
    n_samples: int
    seed: int | None
    alpha: float
    K_x: float
    K_y: float
    mu_c: float
    force_method: str
    F_momentum: float | None
    F_rigid: float | None
    gravity: bool
    measure: str
    inputs: Mapping[str, tuple[float, float]] = field(repr=False)
    rod: Mapping[str, float] = field(repr=False)
    sensitivity_T: Mapping[str, float] = field(repr=False)
    sensitivity_F: Mapping[str, float] = field(repr=False)

    def _repr_html_(self) -> str:
        from impactlab._display import html_table

        units = {"T": "s", "F": "N", "K_x": "1/kg", "K_y": "1/kg"}
        rows = [
            (k, f"{v:.6g}", units.get(k.split("_")[-1] if k.startswith("sigma") else k, ""))
            for k, v in self.to_dict().items()
            if isinstance(v, int | float) and not isinstance(v, bool)
        ]
        return html_table("InversionResult", rows)

    def to_dict(self) -> dict[str, Any]:
        """Plain, JSON-ready dictionary (SI units; see the class docstring)."""
        out: dict[str, Any] = {}
        for k in self.__dataclass_fields__:
            v = getattr(self, k)
            if isinstance(v, Mapping):
                v = {kk: (list(vv) if isinstance(vv, tuple) else vv) for kk, vv in v.items()}
            elif isinstance(v, tuple):
                v = list(v)
            out[k] = v
        return out

    def __str__(self) -> str:
        ins = self.inputs

        def pm(name: str, scale: float, unit: str, digits: int = 4) -> str:
            v, s = ins[name]
            txt = f"{v * scale:.{digits}g}"
            return txt + (f" ± {s * scale:.2g}" if s > 0 else "") + (f" {unit}" if unit else "")

        r = self.rod
        lines = [
            "Inversion of the dent (paper Eqs. 12 and 29, corrected; "
            + ("gravity included" if self.gravity else "gravity neglected as in the paper")
            + ("; L_s is the contact patch's travel" if self.measure == "travel" else "") + ")",
            f"  rod: m = {r['mass']:.4g} kg, L = {r['length']:.4g} m, R = "
            f"{r['tip_radius'] * 1e3:.4g} mm, I_C = {r['inertia']:.4g} kg m^2 "
            f"(I_C/(m L^2) = {r['inertia'] / (r['mass'] * r['length'] ** 2):.4g})",
            f"  angle = {pm('angle', 180.0 / math.pi, 'deg')}, v_i = {pm('v_i', 1.0, 'm/s')}, "
            f"mu = {pm('mu', 1.0, '')}"
            + (f", e = {pm('e', 1.0, '')}" if "e" in ins else "")
            + (f", dv_Cy = {pm('dv_cy', 1.0, 'm/s')}" if "dv_cy" in ins else ""),
            f"  delta_p = {pm('delta_p', 1e6, 'um')}, L_s = {pm('L_s', 1e6, 'um')}",
            f"  alpha = {self.alpha:.4g}, mu_c = {self.mu_c:.4g}, K_x = {self.K_x:.4g} 1/kg, "
            f"K_y = {self.K_y:.4g} 1/kg",
            f"  T = {self.T * 1e3:.4g} ms  ± {self.sigma_T_linear * 1e3:.2g} (first order)"
            f"  ± {self.sigma_T_mc * 1e3:.2g} (Monte Carlo, mean {self.T_mc * 1e3:.4g})",
            f"  F = {self.F:.4g} N  ± {self.sigma_F_linear:.2g} (first order)"
            f"  ± {self.sigma_F_mc:.2g} (Monte Carlo, mean {self.F_mc:.4g})  [{self.force_method}]",
        ]
        if self.mc_rejected > 0:
            lines.append(f"  note: {self.mc_rejected:.2%} of the Monte Carlo samples fell in the "
                         "sticking regime or out of range and were discarded")
        return "\n".join(lines)


def _core(
    x: Mapping[str, Any], m: float, L: float, R: float, inertia: float, gravity: bool, g: float,
    travel: bool = False,
) -> tuple[Any, Any, Any]:
    """(T, F, valid) for arrays of inputs (magnitudes; ``dv_cy`` may be absent)."""
    th, mu = x["angle"], x["mu"]
    *_, K_y, al, mu_c = _coefficients(th, mu, m, L, R, inertia, travel)
    vi, dp, ls = x["v_i"], x["delta_p"], x["L_s"]
    valid = (th >= 0) & (th <= _HALF_PI) & (mu >= 0) & (mu < mu_c) & (vi > 0) & (dp >= 0) & (ls > 0)
    if travel:  # the patch's travel must keep its (negative) direction
        valid = valid & (al < 0)
    with np.errstate(all="ignore"):
        T = _duration(dp, ls, vi, np.abs(al), gravity, g)
        if "dv_cy" in x:
            valid = valid & (x["dv_cy"] > 0)
            F = m * x["dv_cy"] / T + (m * g if gravity else 0.0)
        else:
            e = x["e"]
            valid = valid & (e >= 0) & (e <= 1)
            F = ((1.0 + e) * vi + (g * T if gravity else 0.0)) / (K_y * T)
    valid = valid & np.isfinite(T) & np.isfinite(F) & (T > 0)
    return T, F, valid


def invert(
    *,
    angle: float | Measured | tuple[float, float],
    v_i: float | Measured | tuple[float, float],
    mu: float | Measured | tuple[float, float],
    delta_p: float | Measured | tuple[float, float],
    L_s: float | Measured | tuple[float, float],
    e: float | Measured | tuple[float, float] | None = None,
    dv_cy: float | Measured | tuple[float, float] | None = None,
    rod: RodLike | None = None,
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
    delta_p : permanent dent depth [m]; sign ignored (the paper writes -22e-6).
    L_s : sliding length [m], non-zero; sign ignored (the paper writes -1400e-6).
    e : coefficient of restitution of the tip's normal velocity, in [0, 1]. Needed for F when
        ``dv_cy`` is not given (rigid-body identity F T = (1 + e)|v_i| / K_y).
    dv_cy : measured change of the centre-of-mass vertical velocity over the impact [m/s], upward
        positive; when given, F comes from Eq. 29 (F T = m dv_Cy) and the rigid-body identity is
        reported alongside as ``F_rigid``.
    rod : any object with ``mass``, ``length``, ``tip_radius``, ``inertia`` (e.g.
        ``impactlab.bodies.Rod`` or :class:`RodProperties`); default: the paper's rod with
        I_C = m L^2 / 12 (``impactlab.paper.data.PAPER_ROD``).
    gravity : include gravity during the contact (adds g T^2 / 2 to Eq. 12 and the gravity impulse
        to Eq. 29); False reproduces the paper's equations.
    measure : what ``L_s`` measures: ``"slip"`` (default, the paper: displacement of the rod's
        material point at the contact) or ``"travel"`` (displacement of the contact patch, i.e. of
        the tip sphere's centre, which is what a dent's length records; see docs/analytic.md).
    n_samples, seed : Monte Carlo sample count (>= 100) and seed (reproducible by default).

    Returns an :class:`InversionResult` with T, F, their first-order and Monte Carlo uncertainties,
    alpha, K_x, K_y, mu_c and the inputs used. Raises ValueError naming the offending parameter for
    invalid inputs and for the sticking regime (mu >= mu_c), where the dent does not fix T.

    Example: ``invert(angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=-22e-6,
    L_s=-1400e-6).T`` is about 4.11e-3 s.
    """
    meas: dict[str, Measured] = {
        "angle": _measured("angle", angle),
        "v_i": _measured("v_i", v_i),
        "mu": _measured("mu", mu),
        "delta_p": _measured("delta_p", delta_p),
        "L_s": _measured("L_s", L_s),
    }
    if e is not None:
        meas["e"] = _measured("e", e)
    if dv_cy is not None:
        meas["dv_cy"] = _measured("dv_cy", dv_cy)
    if e is None and dv_cy is None:
        raise ValueError("e or dv_cy is required: F needs the restitution coefficient (rigid-body "
                         "identity) or the centre-of-mass velocity change (Eq. 29)")
    # magnitudes for the signed-by-convention quantities
    for k in ("v_i", "delta_p", "L_s"):
        meas[k] = Measured(abs(meas[k].value), meas[k].sigma)
    th = meas["angle"].value
    if not 0.0 < th < _HALF_PI:
        raise ValueError(f"angle must lie in (0, pi/2) rad, got {th!r} rad "
                         f"({math.degrees(th):.4g} deg); pass radians")
    if meas["v_i"].value == 0.0:
        raise ValueError("v_i must be non-zero (the drop speed), got 0.0")
    if meas["mu"].value < 0.0:
        raise ValueError(f"mu must be >= 0, got {meas['mu'].value!r}")
    if meas["L_s"].value == 0.0:
        raise ValueError("L_s must be non-zero: in gross sliding any normal impulse makes the tip "
                         "slide, so a zero sliding length cannot be inverted")
    if "e" in meas and not 0.0 <= meas["e"].value <= 1.0:
        raise ValueError(f"e must lie in [0, 1], got {meas['e'].value!r}")
    if "dv_cy" in meas and meas["dv_cy"].value <= 0.0:
        raise ValueError(f"dv_cy must be > 0 (upward change of the centre-of-mass velocity), got "
                         f"{meas['dv_cy'].value!r}")
    if isinstance(n_samples, bool) or not isinstance(n_samples, int | np.integer) \
            or n_samples < 100:
        raise ValueError(f"n_samples must be an integer >= 100, got {n_samples!r}")
    g_ = check_nonnegative("g", g, "m/s^2")
    travel = _travel(measure)
    m_a, L_a, R_a, I_a = _rod_values(rod)
    if any(np.ndim(v) for v in (m_a, L_a, R_a, I_a)):
        raise ValueError("rod properties must be scalars for invert()")
    m, L, R, inertia = float(m_a), float(L_a), float(R_a), float(I_a)

    _, _, _, K_x, K_y, al, mu_c = (float(v) for v in _coefficients(
        th, meas["mu"].value, m, L, R, inertia, travel))
    _check_sliding(np.float64(meas["mu"].value), np.float64(mu_c), np.float64(th))
    if travel and al >= 0:
        raise ValueError(
            f"measure='travel': at mu = {meas['mu'].value:.4g} and angle = {math.degrees(th):.4g} "
            "deg the contact patch does not move towards -x (rolling outweighs slip, "
            f"alpha_travel = {al:.3g} >= 0), so its travel cannot give the duration"
        )

    nominal = {k: np.float64(v.value) for k, v in meas.items()}
    T0, F0, ok = _core(nominal, m, L, R, inertia, gravity, g_, travel)
    if not bool(ok):  # pragma: no cover - guarded by the checks above
        raise ValueError("the inputs give no valid inversion")
    T0, F0 = float(T0), float(F0)

    # first order: central differences with steps scaled to each sigma (or value)
    names = [k for k in meas if meas[k].sigma > 0]
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
        Ts, Fs, _ = _core(xs, m, L, R, inertia, gravity, g_, travel)
        Ts, Fs = np.broadcast_to(Ts, (2,)), np.broadcast_to(Fs, (2,))
        sens_T[k] = float((Ts[1] - Ts[0]) / (hi - lo))
        sens_F[k] = float((Fs[1] - Fs[0]) / (hi - lo))
    sT_lin = math.sqrt(sum((sens_T[k] * meas[k].sigma) ** 2 for k in names))
    sF_lin = math.sqrt(sum((sens_F[k] * meas[k].sigma) ** 2 for k in names))

    # Monte Carlo
    rng = np.random.default_rng(seed)
    n = int(n_samples)
    samples = {k: (v.value + v.sigma * rng.standard_normal(n)) if v.sigma > 0
               else np.full(n, v.value) for k, v in meas.items()}
    Ts, Fs, ok = (np.broadcast_to(v, (n,)) for v in _core(samples, m, L, R, inertia,
                                                            gravity, g_, travel))
    rejected = 1.0 - float(np.mean(ok))
    Tv, Fv = Ts[ok], Fs[ok]
    if Tv.size < 2:
        raise ValueError("almost all Monte Carlo samples fall in the sticking regime or out of "
                         "range: the uncertainties are too large for this inversion")
    T_mc, F_mc = float(np.mean(Tv)), float(np.mean(Fv))
    sT_mc = float(np.std(Tv, ddof=1)) if names else 0.0
    sF_mc = float(np.std(Fv, ddof=1)) if names else 0.0
    T_int = (float(np.percentile(Tv, 2.5)), float(np.percentile(Tv, 97.5)))
    F_int = (float(np.percentile(Fv, 2.5)), float(np.percentile(Fv, 97.5)))

    F_rig = None
    if "e" in meas:
        F_rig = float(((1.0 + meas["e"].value) * meas["v_i"].value
                       + (g_ * T0 if gravity else 0.0)) / (K_y * T0))
    F_mom = None
    if "dv_cy" in meas:
        F_mom = float(m * meas["dv_cy"].value / T0 + (m * g_ if gravity else 0.0))

    return InversionResult(
        T=T0, F=F0, sigma_T_linear=sT_lin, sigma_F_linear=sF_lin,
        T_mc=T_mc, F_mc=F_mc, sigma_T_mc=sT_mc, sigma_F_mc=sF_mc,
        T_interval_mc=T_int, F_interval_mc=F_int, mc_rejected=rejected,
        n_samples=n, seed=seed, alpha=al, K_x=K_x, K_y=K_y, mu_c=mu_c,
        force_method="momentum" if "dv_cy" in meas else "rigid-body identity",
        F_momentum=F_mom, F_rigid=F_rig, gravity=bool(gravity), measure=measure,
        inputs=MappingProxyType({k: (v.value, v.sigma) for k, v in meas.items()}),
        rod=MappingProxyType({"mass": m, "length": L, "tip_radius": R, "inertia": inertia}),
        sensitivity_T=MappingProxyType(sens_T), sensitivity_F=MappingProxyType(sens_F),
    )


#: Units of the inputs and outputs of :func:`invert` (SI), for printing.
UNITS: Mapping[str, str] = MappingProxyType(_UNITS)
