"""The values an input of a study may take on its own, and their refusal: the intervals
(:data:`ALLOWED`, SI units, as the single impact requires them), an angle of a rod in (0, 90]
deg (:data:`ANGLE`), and a fixed or grid value converted to SI and checked
(:func:`check_value`). Messages name where the value was given, the offending values (in
display units) and what is allowed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.dynamics.input_checks import PAST_NORMAL, degrees_hint
from impactlab.dynamics.kernels.inputs import MAX_ANGLE, MAX_MU, MAX_SPEED
from impactlab.sweep.inputs import MATERIAL_OVERRIDES, get_input
from impactlab.sweep.magnitudes import check_magnitudes
from impactlab.units import angle_to_rad, is_quantity, magnitude

#: A fixed or axis value: SI float or a category name.
Value = float | str

#: An allowed interval: (low, high, low inclusive, high inclusive, integers only).
Interval = tuple[float, float, bool, bool, bool]
_POSITIVE: Interval = (0.0, math.inf, False, True, False)
_COUNT: Interval = (0.0, math.inf, True, True, True)

#: The values a numeric input may take on its own (SI), as the single impact requires them;
#: inputs not named here take any finite number.
ALLOWED: dict[str, Interval] = {
    "mu": (0.0, MAX_MU, True, True, False),
    "speed": (0.0, MAX_SPEED, False, True, False),
    "vx": (-MAX_SPEED, MAX_SPEED, True, True, False),
    "vy": (-MAX_SPEED, MAX_SPEED, True, True, False),
    "incidence": (-0.5 * math.pi, 0.5 * math.pi, False, False, False),
    **{n: _POSITIVE for n in ("length", "tip_radius", "radius", "mass", "inertia")},
    "n_axial": _COUNT,
    "n_bending": _COUNT,
    "damping": (0.0, 1.0, True, False, False),
    **{
        name: {
            "nu": (-1.0, 0.5, False, False, False),
            "meyer_index": (2.0, 3.0, False, True, False),
        }.get(field, _POSITIVE)
        for side in MATERIAL_OVERRIDES.values()
        for name, field in side.items()
    },
}
#: The angle of a rod (rigid or flexible) to the flat [rad]: (0, pi/2] (``MAX_ANGLE``: +1e-12
#: for 90 deg converted from degrees).
ANGLE: Interval = (0.0, MAX_ANGLE, False, True, False)


def inside(x: float, rule: Interval) -> bool:
    """True when ``x`` lies in the interval ``rule`` (and is an integer where it must be)."""
    lo, hi, lo_in, hi_in, integer = rule
    return (
        (x >= lo if lo_in else x > lo)
        and (x <= hi if hi_in else x < hi)
        and (not integer or x == math.floor(x))
    )


def shown_values(name: str, values: Sequence[float]) -> tuple[list[str], str]:
    """``values`` of input ``name`` as text in its display unit, and the unit ("" for none)."""
    spec = get_input(name)
    field = next((s[name] for s in MATERIAL_OVERRIDES.values() if name in s), name)
    d = display_unit(field, spec.unit)
    return [format_number(v * d.scale) for v in values], "" if d.unit == "-" else d.unit


def rule_text(name: str, rule: Interval) -> str:
    """``"mu must be >= 0"``, ``"angle must lie in (0, 90] deg"`` (bounds in display units)."""
    lo, hi, lo_in, hi_in, integer = rule
    (lo_t, hi_t), unit = shown_values(name, [lo, hi])
    u = f" {unit}" if unit else ""
    if integer:
        return f"{name} must be an integer >= {lo_t}"
    if math.isinf(hi):
        return f"{name} must be {'>=' if lo_in else '>'} {lo_t}{u}"
    return f"{name} must lie in {'[' if lo_in else '('}{lo_t}, {hi_t}{']' if hi_in else ')'}{u}"


def refuse(
    where: str, name: str, values: Sequence[float], bad: Sequence[float], rule: str, note: str = ""
) -> None:
    """ValueError ``"<where>: <rule>, got <bad values> (k of n values)<note>"`` when ``bad`` is
    not empty (values in display units, at most four named)."""
    if not bad:
        return
    texts, unit = shown_values(name, list(bad[:4]))
    got = ", ".join(texts) + (", ..." if len(bad) > 4 else "")
    got += f" {unit}" if unit else ""
    count = f" ({len(bad)} of {len(values)} values)" if len(values) > 1 else ""
    raise ValueError(f"{where}: {rule}, got {got}{count}{note}")


def check_allowed(name: str, values: Sequence[float], where: str) -> None:
    """ValueError naming ``where``, the input, the offending values and the allowed interval
    unless every value of input ``name`` (SI) lies in :data:`ALLOWED`."""
    rule = ALLOWED.get(name)
    if rule is not None:
        refuse(
            where, name, values, [v for v in values if not inside(v, rule)], rule_text(name, rule)
        )


def check_rod_angles(
    angles: Sequence[float], where: str, rule_suffix: str = "", bare: Sequence[Any] = ()
) -> None:
    """ValueError naming ``where``, the offending values and the interval unless every angle
    [rad] of a rod lies in :data:`ANGLE`, (0, 90] deg (``rule_suffix`` ends the rule's text);
    with ``simulate``'s degrees hint for the first of the ``bare`` angles that reads so."""
    rule = rule_text("angle", ANGLE) + rule_suffix
    bad = [a for a in angles if not inside(a, ANGLE)]
    past = any(0.5 * math.pi < a < math.pi for a in bad)  # as simulate says it of one angle
    note = (
        ": an angle past 90 deg leans the rod past the flat's normal, the mirror of a drop at "
        "180 deg - angle with vx (or incidence) and spin negated"
    ) * past
    th = next((float(a) for a in bare if looks_like_degrees(a)), None)
    if th is not None:  # as impactlab.dynamics.input_checks.check_angle says it
        note += degrees_hint(th)
    refuse(where, "angle", angles, bad, rule, note)


def looks_like_degrees(angle: Any) -> bool:
    """A bare number (radians) in (pi/2 + 10 deg, 90]: degrees meant? (refused where given)"""
    return is_number(angle) and 0.5 * math.pi + PAST_NORMAL < angle <= 90.0


def is_number(value: Any) -> bool:
    """A finite int or float (not a bool)."""
    return isinstance(value, float | int) and not isinstance(value, bool) and math.isfinite(value)


def input_value(name: str, value: Any) -> Value:
    """``value`` as a fixed or axis value of input ``name`` (SI float or a category string),
    without the :data:`ALLOWED` interval; a quantity (text with its unit, a pint Quantity of
    any registry) is converted to the input's SI unit, as everywhere in the Python API."""
    spec = get_input(name)
    if spec.kind == "category":
        if not isinstance(value, str) or not value:
            raise ValueError(f"input {name!r} takes a name (string), got {value!r}")
        return value
    if isinstance(value, str) and spec.unit == "rad":  # the angle rule's own message
        value = angle_to_rad(value, name=f"input {name!r}")
    elif isinstance(value, str) or is_quantity(value):
        value = magnitude(f"input {name!r}", value, spec.unit)
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        kind = "a plain number" if spec.unit in ("1", "") else f"a number in {spec.unit}"
        raise ValueError(f"input {name!r} must be {kind}, got {value!r}")
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"input {name!r} must be finite, got {x!r}")
    return x


def check_value(name: str, value: Any) -> Value:
    """A fixed value for input ``name`` (SI float or a category string), inside
    :data:`ALLOWED`."""
    x = input_value(name, value)
    if name == "angle" and isinstance(x, float) and looks_like_degrees(value):
        check_rod_angles([x], f"input {name!r}", bare=[value])
    if isinstance(x, float):
        check_allowed(name, [x], f"input {name!r}")
        check_magnitudes(name, [x], f"input {name!r}")
    return x
