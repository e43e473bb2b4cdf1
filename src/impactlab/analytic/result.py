"""Inputs and result of the inversion: :class:`Measured` values and :class:`InversionResult`."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from impactlab._display import html_table
from impactlab._validation import check_finite, check_nonnegative

__all__ = ["InversionResult", "Measured", "measured"]

#: Units of the scalar fields of :class:`InversionResult` (for the HTML table).
_UNITS = {
    k: unit
    for unit, keys in (
        ("s", ("duration", "sigma_T_linear", "T_mc", "sigma_T_mc")),
        ("N", ("mean_force", "sigma_F_linear", "F_mc", "sigma_F_mc", "F_momentum", "F_rigid")),
        ("1/kg", ("K_x", "K_y")),
    )
    for k in keys
}


@dataclass(frozen=True)
class Measured:
    """A measured value and its standard deviation (same unit, ``sigma`` >= 0)."""

    value: float
    sigma: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "value", check_finite("value", self.value))
        object.__setattr__(self, "sigma", check_nonnegative("sigma", self.sigma))


def measured(name: str, x: Any, unit: str = "") -> Measured:
    """``x`` (a number, a ``(value, sigma)`` pair or a :class:`Measured`) as :class:`Measured`;
    with a ``unit``, value and sigma may also be strings with units or pint Quantities
    (``impactlab._validation``). ValueError naming ``name``."""
    if isinstance(x, Measured):
        return x
    if isinstance(x, tuple | list):
        if len(x) != 2:
            raise ValueError(f"{name} must be a number or a (value, sigma) pair, got {x!r}")
        v, s = x
    else:
        v, s = x, 0.0
    return Measured(check_finite(name, v, unit), check_nonnegative(f"the sigma of {name}", s, unit))


@dataclass(frozen=True)
class InversionResult:
    """Impact duration and mean normal force inverted from a measured oblique impact (immutable).

    Attributes (SI): ``duration`` T [s], ``mean_force`` F [N] (nominal values);
    ``sigma_T_linear``, ``sigma_F_linear``
    (first-order propagation, numerical Jacobian); ``T_mc``, ``F_mc`` (Monte Carlo means),
    ``sigma_T_mc``, ``sigma_F_mc`` (Monte Carlo standard deviations), ``T_interval_mc``,
    ``F_interval_mc`` (2.5 and 97.5 percentiles), ``mc_rejected`` (fraction of samples that fell in
    the sticking regime or out of range and were discarded), ``n_samples``, ``seed``; ``alpha``,
    ``K_x``, ``K_y`` [1/kg], ``mu_c``; ``force_method`` ("momentum" for Eq. 29 with dv_cy, else
    "rigid-body identity"); ``F_momentum``, ``F_rigid`` (each None when its input is missing);
    ``gravity``; ``measure`` ("slip" or "travel", what the sliding length measures); ``inputs``
    (name -> (value, sigma) in SI, magnitudes as used: ``angle``, ``v_i``, ``mu``, ``delta_p``,
    ``sliding_length``, ``e``, ``dv_cy``); ``rod`` (mass, length, tip_radius, inertia);
    ``sensitivity_T``, ``sensitivity_F`` (partial derivatives with respect to each input, SI).
    """

    duration: float
    mean_force: float
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
        rows = [
            (k, f"{v:.6g}", _UNITS.get(k, ""))
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
            + ("; L_s is the contact patch's travel" if self.measure == "travel" else "")
            + ")",
            f"  rod: m = {r['mass']:.4g} kg, L = {r['length']:.4g} m, R = "
            f"{r['tip_radius'] * 1e3:.4g} mm, I_C = {r['inertia']:.4g} kg m^2 "
            f"(I_C/(m L^2) = {r['inertia'] / (r['mass'] * r['length'] ** 2):.4g})",
            f"  angle = {pm('angle', 180.0 / math.pi, 'deg')}, v_i = {pm('v_i', 1.0, 'm/s')}, "
            f"mu = {pm('mu', 1.0, '')}"
            + (f", e = {pm('e', 1.0, '')}" if "e" in ins else "")
            + (f", dv_Cy = {pm('dv_cy', 1.0, 'm/s')}" if "dv_cy" in ins else ""),
            f"  delta_p = {pm('delta_p', 1e6, 'um')}, "
            f"sliding_length = {pm('sliding_length', 1e6, 'um')}",
            f"  alpha = {self.alpha:.4g}, mu_c = {self.mu_c:.4g}, K_x = {self.K_x:.4g} 1/kg, "
            f"K_y = {self.K_y:.4g} 1/kg",
            f"  T = {self.duration * 1e3:.4g} ms  ± {self.sigma_T_linear * 1e3:.2g} (first order)"
            f"  ± {self.sigma_T_mc * 1e3:.2g} (Monte Carlo, mean {self.T_mc * 1e3:.4g})",
            f"  F = {self.mean_force:.4g} N  ± {self.sigma_F_linear:.2g} (first order)"
            f"  ± {self.sigma_F_mc:.2g} (Monte Carlo, mean {self.F_mc:.4g})  [{self.force_method}]",
        ]
        if self.mc_rejected > 0:
            lines.append(
                f"  note: {self.mc_rejected:.2%} of the Monte Carlo samples fell in the "
                "sticking regime or out of range and were discarded"
            )
        return "\n".join(lines)
