"""Inputs and result of the inversion: :class:`Measured` values and :class:`InversionResult`."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from impactlab._display import field_row, field_rows, format_number, html_table
from impactlab._validation import check_finite, check_nonnegative
from impactlab.bodies._checks import INERTIA_MISFIT
from impactlab.units import has_unit, parse_quantity

__all__ = [
    "DOUBT_PHRASES",
    "INPUT_UNITS",
    "MC_INTERVAL",
    "UNRESOLVED_DENT_PHRASES",
    "InversionResult",
    "Measured",
    "doubting",
    "measured",
]

#: The percentiles [%] of the Monte Carlo's interval (``T_interval_mc``, ``F_interval_mc``): the
#: central 95 %.
MC_INTERVAL = (2.5, 97.5)
#: The words of the inversion's warnings that doubt its result (``InversionResult.doubts``,
#: ``ok``; ``impactlab invert --json``'s ``doubts``): a velocity change that no impact gives
#: (dv_cy implying e outside [0, 1]), a duration no rigid-body impact has (the two that
#: ``impactlab analyze`` holds as ``experiment.analysis.IMPOSSIBLE_PHRASES``), a Monte Carlo that
#: discarded more than 5 % of its samples for a dent measure at or below zero (an L_s or delta_p
#: within about 1.6 sigma of zero: T, which rests on it, is not resolved; ``analyze`` too), and a
#: rod whose mass and inertia do not fit (``analyze``'s doubt of the rod).
#: The Monte Carlo's words for samples discarded for a dent measure at or below zero.
UNRESOLVED_DENT_PHRASES = ("drew |sliding_length| <= 0", "drew |delta_p| < 0")
DOUBT_PHRASES = (
    "no impact gives it",
    "far longer than a rigid-body impact",
    *UNRESOLVED_DENT_PHRASES,
    INERTIA_MISFIT,
)
#: Units of the numeric fields of :class:`InversionResult` (for its tables).
_UNITS = {
    k: unit
    for unit, keys in (
        ("s", ("duration", "sigma_T_linear", "T_mc", "sigma_T_mc", "T_median_mc", "T_interval_mc")),
        (
            "N",
            ("mean_force", "sigma_F_linear", "F_mc", "sigma_F_mc", "F_median_mc", "F_interval_mc"),
        ),
        ("N", ("F_momentum", "F_rigid")),
        ("1/kg", ("K_x", "K_y")),
    )
    for k in keys
}
#: SI units of the inputs (``InversionResult.inputs``), by keyword of ``invert``.
INPUT_UNITS = {
    "angle": "rad",
    "v_i": "m/s",
    "mu": "1",
    "e": "1",
    "delta_p": "m",
    "sliding_length": "m",
    "dv_cy": "m/s",
    "vt_in": "m/s",
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
    """``x`` (a number, a ``(value, sigma)`` tuple or a :class:`Measured`) as
    :class:`Measured`; with a ``unit``, value and sigma may also be strings with units or pint
    Quantities (``impactlab._validation``). A bare number is SI, except a bare sigma beside a
    value given with its unit: that sigma is in the value's unit, as on the command line
    (``("45 deg", 0.2)`` is 0.2 deg, ``("22 um", 2)`` 2 um). ValueError naming ``name``, also
    for a list (neither a pair nor several drops: one drop at a time)."""
    if isinstance(x, Measured):
        return x
    if isinstance(x, list):  # one drop: a list is neither a pair nor several drops here
        raise ValueError(
            f"{name} = {x!r} is a list: a (value, sigma) pair is written as a tuple (value, "
            "sigma) or Measured(value, sigma); invert takes one drop, one value per input (for "
            "several drops call it once per drop, or use the closed forms, which broadcast over "
            "arrays: impact_duration, mean_force_rigid, mean_force_momentum)"
        )
    if isinstance(x, tuple):
        if len(x) != 2:
            raise ValueError(f"{name} must be a number or a (value, sigma) pair, got {x!r}")
        v, s = x
    else:
        v, s = x, 0.0
    value = check_finite(name, v, unit)
    if unit and has_unit(v) and _bare_number(s):
        s = float(s) * _unit_of(name, v, unit)  # in the value's unit
    return Measured(value, check_nonnegative(f"the sigma of {name}", s, unit))


def doubting(texts: Iterable[str]) -> tuple[str, ...]:
    """The warnings among ``texts`` that doubt the result (``DOUBT_PHRASES``), in order."""
    return tuple(t for t in texts if any(p in t for p in DOUBT_PHRASES))


def _bare_number(x: Any) -> bool:
    """A real number without a unit (not a bool, a string or a Quantity)."""
    return isinstance(x, int | float | np.integer | np.floating) and not isinstance(x, bool)


def _unit_of(name: str, value: Any, unit: str) -> Any:
    """The unit of ``value`` (a string with units, or a pint Quantity of any registry)."""
    if isinstance(value, str):
        return parse_quantity(name, value, unit).units
    return value.units


@dataclass(frozen=True)
class InversionResult:
    """Impact duration and mean normal force inverted from a measured oblique impact (immutable).

    Attributes (SI): ``duration`` T [s], ``mean_force`` F [N] (nominal values);
    ``sigma_T_linear``, ``sigma_F_linear``
    (first-order propagation, numerical Jacobian); ``T_mc``, ``F_mc`` (Monte Carlo means),
    ``sigma_T_mc``, ``sigma_F_mc`` (Monte Carlo standard deviations; 0 where the spread is
    rounding), ``T_median_mc``, ``F_median_mc`` (Monte Carlo medians), ``T_interval_mc``,
    ``F_interval_mc`` (the central 95 %: 2.5 and 97.5 percentiles, :data:`MC_INTERVAL`; with
    samples in the sticking regime T's mean and standard deviation are unreliable, its median
    and interval are not), ``mc_rejected`` (fraction of samples that fell in
    the sticking regime or out of range, e.g. e outside [0, 1], and were discarded; above 5 %
    a warning names each cause with its share), ``mc_used`` (the number of samples
    kept; 0 where no input has a sigma: nothing is drawn, and the Monte Carlo values are the
    nominal ones), ``n_samples`` (the samples asked for), ``seed``; ``alpha``,
    ``K_x``, ``K_y`` [1/kg], ``mu_c``; ``force_method`` ("momentum" for Eq. 29 with dv_cy, else
    "rigid-body identity"); ``F_momentum``, ``F_rigid`` (each None when its input is missing);
    ``gravity``; ``measure`` ("slip" or "travel", what the sliding length measures); ``inputs``
    (name -> (value, sigma) in SI, magnitudes as used: ``angle``, ``v_i``, ``mu``, ``delta_p``,
    ``sliding_length``, ``e``, ``dv_cy``, and ``vt_in``, signed, where not 0); ``rod`` (mass,
    length, tip_radius, inertia);
    ``sensitivity_T``, ``sensitivity_F`` (partial derivatives with respect to each input, SI);
    ``correlation`` ((name, name) -> coefficient of the inputs as used, as in ``inputs``;
    empty: independent; ``to_dict()``: a list of ``{"inputs": [a, b], "coefficient":
    {"value", "unit"}}``); ``warnings``: the texts of the inversion's ImplausibleInputWarnings
    (as ``impactlab invert --json`` lists them; ``()`` for none); ``doubts``: those of the
    warnings that say no impact gives this result (a dv_cy implying e outside [0, 1], a
    duration no rigid-body impact has) or that the rod's mass and inertia do not fit
    (:data:`DOUBT_PHRASES`, the rule of ``impactlab invert --json`` and ``analyze``); ``ok``
    (property, and in ``to_dict()``): False when there is a doubt: read T and F as numbers no
    measured impact gives. ``print(result)`` and Jupyter's table show the inputs (and their
    correlations), T and F with their uncertainties, the Monte Carlo's medians and 95 %
    intervals (where an input has a sigma), the note on discarded samples, ``ok`` and the
    doubts (where there is one) and the warnings; ``repr`` is one line.
    """

    duration: float
    mean_force: float
    sigma_T_linear: float
    sigma_F_linear: float
    T_mc: float
    F_mc: float
    sigma_T_mc: float
    sigma_F_mc: float
    T_median_mc: float
    F_median_mc: float
    T_interval_mc: tuple[float, float]
    F_interval_mc: tuple[float, float]
    mc_rejected: float
    mc_used: int
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
    warnings: tuple[str, ...] = field(default=(), repr=False)
    correlation: Mapping[tuple[str, str], float] = field(
        default_factory=lambda: MappingProxyType({}), repr=False
    )
    doubts: tuple[str, ...] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "warnings", tuple(str(w) for w in self.warnings))
        object.__setattr__(self, "doubts", doubting(self.warnings))

    @property
    def ok(self) -> bool:
        """False when a warning doubts the result (``doubts``): no impact gives it."""
        return not self.doubts

    def _uncertain(self) -> bool:
        """Whether an input has a sigma (the Monte Carlo ran)."""
        return any(s > 0 for _v, s in self.inputs.values())

    def _correlations(self) -> str:
        """The inputs' correlations in one line (``"(e, dv_cy) 0.94, ..."``)."""
        return ", ".join(f"({a}, {b}) {rho:.2g}" for (a, b), rho in self.correlation.items())

    def _note(self) -> str:
        """The share of Monte Carlo samples discarded, one sentence (``""`` for none)."""
        if not (self._uncertain() and self.mc_rejected > 0):
            return ""
        return (
            f"{self.mc_rejected:.2%} of the {self.n_samples} Monte Carlo samples fell in the "
            "sticking regime or out of range (e.g. e outside [0, 1]) and were discarded "
            f"({self.mc_used} used)"
        )

    def _rows(self) -> list[tuple[str, str, str]]:
        """``(name, text, unit)`` rows in display units: the inputs, T and F (± first order),
        the Monte Carlo's (where an input has a sigma), the coefficients, the note and the
        warnings (the rows of ``impactlab invert``'s table)."""
        uncertain = self._uncertain()
        rows = [field_row(k, float(v), INPUT_UNITS[k], s) for k, (v, s) in self.inputs.items()]
        rows += [("correlation", self._correlations(), "")] if self.correlation else []
        out: dict[str, Any] = {"duration": self.duration, "mean_force": self.mean_force}
        out["force_method"] = self.force_method
        if self.F_momentum is not None and self.F_rigid is not None:  # both inputs given
            out["F_rigid"] = self.F_rigid
        sigmas = {"duration": self.sigma_T_linear, "mean_force": self.sigma_F_linear}
        if uncertain:
            for q in ("T", "F"):
                out |= {f"{q}_mc": getattr(self, f"{q}_mc")}
                out |= {f"{q}_{k}_mc": getattr(self, f"{q}_{k}_mc") for k in ("median", "interval")}
            sigmas |= {"T_mc": self.sigma_T_mc, "F_mc": self.sigma_F_mc}
            out |= {"n_samples": self.n_samples, "mc_used": self.mc_used, "seed": self.seed}
        out |= {"alpha": self.alpha, "mu_c": self.mu_c, "K_x": self.K_x, "K_y": self.K_y}
        out["gravity"] = "included" if self.gravity else "neglected (paper)"
        out["measure"] = self.measure
        rows += field_rows(out, _UNITS, sigmas)
        rows += [("note", self._note(), "")] if self._note() else []
        rows += [("ok", "no", ""), *(("doubt", d, "") for d in self.doubts)] if self.doubts else []
        return rows + [("warning", w, "") for w in self.warnings if w not in self.doubts]

    def _repr_html_(self) -> str:
        title = "InversionResult (paper Eqs. 12, 29)"
        if self._uncertain():
            lo, hi = MC_INTERVAL
            title += (
                ": ± first order; T_mc, F_mc: Monte Carlo mean ± sigma; *_median_mc: median; "
                f"*_interval_mc: 95 % ({lo:g}-{hi:g} percentiles)"
            )
        return html_table(title, self._rows())

    def __repr__(self) -> str:
        """One line: T and F with their first-order sigma, the force method, the Monte Carlo's
        samples used (where it ran) and the number of warnings."""

        def pm(name: str, value: float, sigma: float, unit: str) -> str:
            return f"{name}={value:.6g}" + (f" ± {sigma:.2g}" if sigma > 0 else "") + f" {unit}"

        parts = [
            pm("duration", self.duration, self.sigma_T_linear, "s"),
            pm("mean_force", self.mean_force, self.sigma_F_linear, "N"),
            f"force_method={self.force_method!r}",
        ]
        if self._uncertain():
            parts.append(f"mc_used={self.mc_used} of {self.n_samples}")
        if self.doubts:
            parts.append("ok=False")
        if self.warnings:
            parts.append(f"{len(self.warnings)} warning" + "s" * (len(self.warnings) > 1))
        return f"InversionResult({', '.join(parts)})"

    def to_dict(self) -> dict[str, Any]:
        """Plain, JSON-ready dictionary (SI units; see the class docstring)."""
        out: dict[str, Any] = {}
        for k in self.__dataclass_fields__:
            v = getattr(self, k)
            if k == "correlation":  # pairs: JSON keys are texts, a coefficient a quantity
                v = [
                    {"inputs": list(pair), "coefficient": {"value": rho, "unit": "1"}}
                    for pair, rho in v.items()
                ]
            elif isinstance(v, Mapping):
                v = {kk: (list(vv) if isinstance(vv, tuple) else vv) for kk, vv in v.items()}
            elif isinstance(v, tuple):
                v = list(v)
            out[k] = v
        return out | {"ok": self.ok}

    def __str__(self) -> str:
        ins = self.inputs
        uncertain = any(s > 0 for _v, s in ins.values())

        def pm(name: str, label: str = "") -> str:
            v, s = ins[name]
            _n, text, unit = field_row(name, float(v), INPUT_UNITS[name], s)
            return f"{label or name} = {text}" + (f" {unit}" if unit != "-" else "")

        def out(label: str) -> str:
            unit, k = ("ms", 1e3) if label == "T" else ("N", 1.0)
            value = self.duration if label == "T" else self.mean_force
            text = f"  {label} = {format_number(value * k)} {unit}"
            sigma = getattr(self, f"sigma_{label}_linear")
            sigma_mc = getattr(self, f"sigma_{label}_mc")
            if uncertain and (sigma > 0 or sigma_mc > 0):  # a sigma of 0: an exact output
                lo, hi = (format_number(v * k) for v in getattr(self, f"{label}_interval_mc"))
                mc = format_number(getattr(self, f"{label}_mc") * k)
                median = format_number(getattr(self, f"{label}_median_mc") * k)
                text += (
                    f"  ± {format_number(sigma * k, 2)} (first order)  ± "
                    f"{format_number(sigma_mc * k, 2)} (Monte Carlo, mean {mc}, median "
                    f"{median}, 95 % in [{lo}, {hi}])"
                )
            return text

        r = self.rod
        ratio = r["inertia"] / (r["mass"] * r["length"] ** 2)
        lines = [
            "Inversion of the dent (paper Eqs. 12 and 29, corrected; "
            + ("gravity included" if self.gravity else "gravity neglected as in the paper")
            + ("; L_s is the contact patch's travel" if self.measure == "travel" else "")
            + ")",
            f"  rod: m = {format_number(r['mass'])} kg, L = {format_number(r['length'] * 1e3)} mm,"
            f" R = {format_number(r['tip_radius'] * 1e3)} mm, I_C = {format_number(r['inertia'])}"
            f" kg m^2 (I_C/(m L^2) = {format_number(ratio)})",
            "  "
            + ", ".join(
                [pm("angle"), pm("v_i", "|v_i|"), pm("mu")]
                + [pm(k) for k in ("e", "dv_cy", "vt_in") if k in ins]
            ),
            f"  {pm('delta_p', '|delta_p|')}, {pm('sliding_length', '|L_s|')}",
            *([f"  correlation: {self._correlations()}"] if self.correlation else []),
            f"  alpha = {format_number(self.alpha)}, mu_c = {format_number(self.mu_c)}, "
            f"K_x = {format_number(self.K_x)} 1/kg, K_y = {format_number(self.K_y)} 1/kg",
            out("T"),
            out("F") + f"  [{self.force_method}]",
        ]
        if self.F_momentum is not None and self.F_rigid is not None:  # both inputs given
            rigid = format_number(self.F_rigid)
            lines.append(f"  F from the rigid-body identity (with e): {rigid} N")
        if self._note():
            lines.append(f"  note: {self._note()}")
        if self.doubts:
            lines += ["  ok: no", *(f"  doubt: {d}" for d in self.doubts)]
        lines += [f"  warning: {w}" for w in self.warnings if w not in self.doubts]
        return "\n".join(lines)
