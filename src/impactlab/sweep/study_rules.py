"""Study-level rules decided when a study is built, beside those of
:func:`impactlab.sweep.dimensions.check_kinematics`: the inputs each body takes, what the bodies
of a study need, and the values a sampled distribution can draw.

- Each body takes the inputs it has (:data:`IGNORED_BY`): in a study of several bodies (a
  ``body`` grid axis) a rod's length, tip radius and inertia are no sphere's, a sphere's radius
  no rod's, and a flexible rod's inertia follows its beam; the engine adapter leaves them unset
  for the bodies that do not take them (:func:`unset_ignored`), as a sphere ignores the angle.
  An input that no body of the study takes is refused, and so is a body that lacks what it
  needs (a sphere without ``radius``): every case of it would fail. A rod of another tip radius
  than the paper's without ``mass`` keeps the paper's rod's mass, with a warning (one of
  another length is refused: ``study_bodies``).
- A distribution is checked by the values its draws can take: its quantiles at the smallest
  and the largest uniform the draws use short of 1 (2^-54 and 1 - 2^-53: a normal reaches
  about 8.3 standard deviations), against the input's allowed values as a grid's values are
  (:data:`~impactlab.sweep.dimensions.ALLOWED`, the angle of a rod, vy < 0 without spin).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab._validation import warn_implausible
from impactlab.bodies import PAPER_ROD
from impactlab.contact import get_law, law_names
from impactlab.dynamics.input_checks import degrees_hint
from impactlab.sweep.dimensions import (
    ALLOWED,
    ANGLE,
    Axis,
    Interval,
    Sample,
    Value,
    rule_text,
    shown_values,
)
from impactlab.sweep.distributions import Distribution, Uniform
from impactlab.sweep.flexible import FLEXIBLE_BODY
from impactlab.sweep.value_rules import looks_like_degrees

__all__ = [
    "IGNORED_BY",
    "UNIFORM_EXTREMES",
    "check_law_params",
    "check_study_rules",
    "unset_ignored",
]

#: The inputs of other bodies that a body leaves unset in a study of several bodies.
IGNORED_BY: dict[str, tuple[str, ...]] = {
    "rod": ("radius",),
    "sphere": ("length", "tip_radius", "inertia"),
    FLEXIBLE_BODY: ("radius", "inertia"),
}
#: The smallest uniform of the draws and the largest short of 1 (``distributions.uniforms``).
UNIFORM_EXTREMES = np.array([2.0**-54, 1.0 - 2.0**-53])
#: The rule of vy when no spin can turn the contact point towards the flat.
_APPROACH: Interval = (-np.inf, 0.0, True, False, False)


def unset_ignored(cases: Mapping[str, np.ndarray], body: str) -> Mapping[str, np.ndarray]:
    """``cases`` (input -> 1-D array) with the inputs that ``body`` does not take unset (NaN)."""
    ignored = [k for k in IGNORED_BY.get(body, ()) if k in cases and not np.isnan(cases[k]).all()]
    if not ignored:
        return cases
    n = len(cases[ignored[0]])
    return {**cases, **{k: np.full(n, np.nan) for k in ignored}}


def check_study_rules(
    fixed: Mapping[str, Value], axes: Sequence[Axis], sample: Sample | None
) -> None:
    """ValueError (one line, naming the input and the body or the distribution) for an input
    no body of the study takes, a body that lacks what it needs, and a sampled distribution
    that can draw values the input does not allow."""
    grid = {a.name: a.values for a in axes}
    sampled = {} if sample is None else dict(sample.inputs)
    given = set(fixed) | set(grid) | set(sampled)
    bodies = [str(b) for b in grid.get("body", (fixed.get("body", "rod"),))]
    if "inertia" in given and "rod" not in bodies:
        raise ValueError(
            f"inertia: only a rigid rod takes it, and the study's bodies are "
            f"{', '.join(bodies)} (a flexible rod's follows its beam, a sphere's its radius and "
            "mass); leave it out"
        )
    if "sphere" in bodies and "radius" not in given:
        raise ValueError(
            "radius: body 'sphere' needs it (every case of the sphere would fail); set radius "
            "in [fixed], [grid] or [sample]"
        )
    _warn_paper_mass(fixed, grid, sampled, bodies)
    spin_zero = "spin" not in grid and "spin" not in sampled and not fixed.get("spin", 0.0)
    for name, dist in sampled.items():
        rules = [ALLOWED.get(name)]
        if name == "angle" and {"rod", FLEXIBLE_BODY} & set(bodies):
            rules.append(ANGLE)
        if name == "vy" and spin_zero:
            rules.append(_APPROACH)
        for rule in rules:
            if rule is not None:
                _check_draws(name, dist, rule)


def _warn_paper_mass(
    fixed: Mapping[str, Value],
    grid: Mapping[str, Sequence[Value]],
    sampled: Mapping[str, Distribution],
    bodies: Sequence[str],
) -> None:
    """ImplausibleInputWarning for a rod whose tip radius (fixed, on the grid or sampled) is
    not the paper's rod's, without ``mass``: it keeps the paper's rod's mass (``impactlab
    simulate`` asks for the mass instead). The paper's own tip radius does not warn; another
    length without ``mass`` is refused (``study_bodies``)."""
    given = (fixed, grid, sampled)
    if any("mass" in s for s in given) or not {"rod", FLEXIBLE_BODY} & set(bodies):
        return
    values = grid.get("tip_radius", (fixed.get("tip_radius", PAPER_ROD.tip_radius),))
    other = [float(v) for v in values
             if not math.isclose(float(v), PAPER_ROD.tip_radius, rel_tol=1e-9)]  # fmt: skip
    if not other and "tip_radius" not in sampled:
        return
    which = f"tip_radius = {other[0]:.10g} m" if other else "a sampled tip_radius"
    warn_implausible(
        f"mass: the study's rod takes another tip radius than the paper's ({which}, the "
        f"paper's {PAPER_ROD.tip_radius:g} m) but keeps the paper's rod's mass "
        f"({PAPER_ROD.mass:.4g} kg); give mass in [fixed], [grid] or [sample] for a rod other "
        "than the paper's"
    )


def _check_draws(name: str, dist: Distribution, rule: Interval) -> None:
    """ValueError unless every value ``dist`` can draw for input ``name`` lies in ``rule``: it
    names the bound the draws break (low or high, and its value) and how to keep the
    distribution inside it, with the degrees hint a grid or fixed angle gets (``_degrees``)."""
    what = (
        "the contact point must approach the flat (vy < 0 m/s with spin = 0)"
        if rule is _APPROACH
        else rule_text(name, rule)
    )
    if rule[4]:
        raise ValueError(
            f"sample input {name!r}: {what}, and a {dist.kind} distribution draws any number; "
            "put it on the [grid]"
        )
    low, high = (float(v) for v in dist.ppf(UNIFORM_EXTREMES))
    for lower in (True, False):
        x, other = (low, high) if lower else (high, low)
        if not _past(x, rule, lower):
            continue
        (low_t, high_t, bound), unit = shown_values(name, [low, high, rule[0 if lower else 1]])
        u = f" {unit}" if unit else ""
        key = "low" if lower else "high"
        closed = rule[2] if lower else rule[3]  # the bound itself is allowed
        side = ("at least" if lower else "at most") if closed else ("above" if lower else "below")
        if _past(other, rule, lower):  # every value it draws lies past the bound
            drawn = f"from {low_t} to {high_t}{u}"
            fix = (
                f"keep low and high {side} {bound}{u}"
                if isinstance(dist, Uniform)
                else f"move it inside: every value it draws lies {'below' if lower else 'above'} "
                f"{bound}{u}"
            )
        else:
            drawn = f"{'down' if lower else 'up'} to {low_t if lower else high_t}{u}"
            fix = (
                f"keep {key} {side} {bound}{u}"
                if isinstance(dist, Uniform)
                else f"truncate it: {key} = {bound}{u}"
                if closed
                else f"truncate it: {key} {side} {bound}{u}"
            )
        raise ValueError(
            f"sample input {name!r}: {what}, but its {dist.kind} distribution draws values "
            f"{drawn}; {fix}{_degrees(name, dist, lower)}"
        )


def _past(x: float, rule: Interval, lower: bool) -> bool:
    """True when ``x`` lies past the low (``lower``) or the high bound of ``rule``."""
    lo, hi, lo_in, hi_in, _ = rule
    if lower:
        return not (x >= lo if lo_in else x > lo)
    return not (x <= hi if hi_in else x < hi)


def _degrees(name: str, dist: Distribution, lower: bool) -> str:
    """The degrees hint of a grid or fixed angle (``value_rules.check_rod_angles``) for an
    angle distribution whose draws pass 90 deg: its first parameter that reads as degrees (a
    uniform's low, a normal's mean); "" otherwise."""
    if name != "angle" or lower:
        return ""
    params = [v for k, v in dist.to_dict().items() if k != "dist"]
    th = next((float(v) for v in params if looks_like_degrees(v)), None)
    return "" if th is None else degrees_hint(th)


def check_law_params(
    law_params: Mapping[str, Any] | None, laws: Sequence[Value | None]
) -> dict[str, float]:
    """Numbers in each parameter's unit, each a parameter of every (registered) law of the
    study: a number, or, for a parameter with a unit, a string with units or a pint Quantity
    (``"105 HB"``, ``"1030 MPa"``), as ``simulate``'s ``law_params`` takes it (None: none)."""
    if law_params is None:
        return {}
    if not isinstance(law_params, Mapping):
        raise ValueError(
            "law_params must be a mapping of a contact law's parameter names to values (or "
            f"None), got {type(law_params).__name__} {law_params!r}"
        )
    given = {str(k): v for k, v in law_params.items()}
    known_laws = [str(law) for law in laws if law in law_names()]
    for law in known_laws:
        known = sorted(p.name for p in get_law(law).parameters)
        unknown = sorted(set(given) - set(known))
        if unknown:
            raise ValueError(
                f"[law_params] {', '.join(map(repr, unknown))} is not a parameter of contact law "
                f"{law!r}; its parameters: {', '.join(known) or 'none'} (see `impactlab laws`)"
            )
    lp, texts = {}, {}
    for k, v in given.items():
        if isinstance(v, bool) or not isinstance(v, int | float):
            if not known_laws:  # no law to say the parameter's unit
                raise ValueError(f"law parameter {k!r} must be a number, got {v!r}")
            texts[k] = v
        else:
            lp[k] = float(v)  # a number: checked with the law's other rules (below)
    for law in known_laws if texts else ():  # in the parameter's unit ("105 HB": kgf/mm^2)
        try:
            lp |= get_law(law).parameter_values(texts)
        except ValueError as exc:
            raise ValueError(f"[law_params] of contact law {law!r}: {exc}") from None
    return {k: lp[k] for k in given}
