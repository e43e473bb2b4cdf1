"""The velocity of a batch of impacts or drops (``simulate_batch``, ``simulate_drops``): given
as ``vx=`` and ``vy=``, as the pair ``velocity=(vx, vy)``, or as ``speed=`` and ``incidence=``,
each a scalar or an array, with the rules ``simulate`` applies to one impact
(``input_checks.velocity_from``: a speed finite and > 0 m/s, an incidence in (-90, 90) deg)
applied to every case, a refused case named by its index.

Quantities follow ``impactlab.units.magnitude`` (a number in SI, a string with units such as
``"30 deg"``, or a pint Quantity of any registry).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._validation import check_array, value_text
from impactlab.dynamics.kernels.inputs import incidence_allowed
from impactlab.units import has_unit, is_quantity

__all__ = ["batch_velocity", "speed_incidence", "velocity_given"]

#: Most refused cases a message lists by index (then the count).
_SHOWN = 3


def velocity_given(value: Any) -> str:
    """A velocity as the user gave it: a string quoted, a Quantity with its unit."""
    quantity = hasattr(value, "magnitude") and hasattr(value, "units")
    return f"{value.magnitude!r} {value.units:~}" if quantity else repr(value)


def batch_velocity(
    vx: Any, vy: Any, speed: Any, incidence: Any, velocity: Any = None
) -> tuple[Any, Any]:
    """(vx, vy) of a batch: as given (vx None: 0), the pair ``velocity`` = (vx, vy) (each a
    scalar or an array, broadcast as vx= and vy= are), or from speed and incidence (scalars or
    arrays, element by element: :func:`speed_incidence`). ValueError when more than one of
    these or none is given."""
    if velocity is not None:
        if vx is not None or vy is not None or speed is not None or incidence is not None:
            given = [k for k, v in (("vx", vx), ("vy", vy), ("speed", speed)) if v is not None]
            given += ["incidence"] if incidence is not None else []
            raise ValueError(
                f"give either velocity=(vx, vy), vx= and vy=, or speed= and incidence=, not "
                f"velocity= with {'= and '.join(given)}= (they say the same thing)"
            )
        return _velocity_pair(velocity)
    if speed is None and incidence is None:
        if vy is None:
            raise ValueError("vy is required (or velocity=(vx, vy), or speed= and incidence=)")
        return (0.0 if vx is None else vx), vy
    if vx is not None or vy is not None:
        raise ValueError("give either vx/vy or speed= and incidence=, not both")
    if speed is None or incidence is None:
        missing = "speed" if speed is None else "incidence"
        raise ValueError(f"speed and incidence go together: {missing} is missing")
    return speed_incidence(speed, incidence)


def speed_incidence(speed: Any, incidence: Any) -> tuple[np.ndarray, np.ndarray]:
    """(vx, vy) = (speed sin(incidence), -speed cos(incidence)) [m/s], element by element;
    ValueError naming the refused cases by index, with the rule, unless every speed is finite
    and > 0 m/s and every incidence in (-90, 90) deg (a bare incidence is radians), and one
    naming both shapes when they do not broadcast; each read as :func:`_column` reads it."""
    v, th = _column("speed", speed, "m/s"), _column("incidence", incidence, "rad")
    try:
        np.broadcast_shapes(v.shape, th.shape)
    except ValueError:
        raise ValueError(
            f"speed and incidence do not broadcast (speed: {v.shape}, incidence: {th.shape}): "
            "give arrays of one length, or a number for either"
        ) from None
    with np.errstate(invalid="ignore"):
        _refuse("speed", v, ~(v > 0.0) | ~np.isfinite(v), "must be finite and > 0 m/s", "m/s")
        bad = ~np.vectorize(incidence_allowed, otypes=[bool])(th)
    if bad.any():
        finite = th[bad & np.isfinite(th)]
        degrees = finite.size and bool(np.all((np.abs(finite) > 0.5 * math.pi) & (finite <= 90)))
        hint = ""
        if degrees and not _has_unit(incidence):
            hint = "; a bare incidence is radians: for degrees pass np.radians(...) or '... deg'"
        rule = "must lie in (-90, 90) deg from the flat's normal"
        _refuse("incidence", np.degrees(th), bad, rule, "deg", hint)
    return v * np.sin(th), -v * np.cos(th)


def _column(name: str, value: Any, unit: str) -> np.ndarray:
    """``speed`` [m/s] or ``incidence`` [rad] as a float array, read as ``simulate_batch``
    reads its columns: a number, an array, a pint Quantity, a string with units, or a list that
    holds Quantities (each element read so, named ``name[i]``; numpy would drop their units);
    ValueError naming ``name`` for what is not a number (``_validation.check_array``)."""
    if isinstance(value, list | tuple) and any(is_quantity(v) for v in value):
        items = [check_array(f"{name}[{i}]", v, unit) for i, v in enumerate(value)]
        return np.array(items, dtype=np.float64)
    return check_array(name, value, unit)


def _has_unit(value: Any) -> bool:
    """Whether ``value``, or an element of a list of them, states its unit."""
    items = value if isinstance(value, list | tuple) else [value]
    return any(has_unit(v) for v in items)


def _refuse(
    name: str, values: np.ndarray, bad: np.ndarray, rule: str, unit: str, hint: str = ""
) -> None:
    """ValueError ``"<name> <rule>, got <value>"`` (one value) or naming the first refused
    cases by index and their count, when any of ``bad`` is True."""
    if not bad.any():
        return

    def text(x: float) -> str:  # an angle as simulate says it, 6 digits in degrees
        return f"{x:.6g} {unit}" if unit == "deg" else value_text(x, unit)

    if values.ndim == 0:
        raise ValueError(f"{name} {rule}, got {text(float(values))}{hint}")
    where = np.flatnonzero(bad.ravel())
    flat = values.ravel()
    shown = ", ".join(f"{name}[{i}] = {text(float(flat[i]))}" for i in where[:_SHOWN])
    more = ", ..." if where.size > _SHOWN else ""
    raise ValueError(
        f"{name} {rule} in every case, got {shown}{more} ({where.size} of {flat.size} cases); "
        f"a batch applies simulate's rules to each case{hint}"
    )


def _velocity_pair(velocity: Any) -> tuple[Any, Any]:
    """The two components of a batch's ``velocity=(vx, vy)``, each a scalar or a 1-D array (or
    one array or Quantity whose first axis has length 2); ValueError otherwise, and for a 2 x 2
    input of lists or one array: two cases' (vx, vy) pairs would read as (vx, vy) arrays."""
    if not isinstance(velocity, str | bytes | Mapping | set | frozenset):
        try:
            if len(velocity) == 2:
                vx, vy = velocity
                if _pairs(velocity, vx, vy):
                    raise ValueError(
                        f"velocity: {' '.join(velocity_given(velocity).split())} could be two "
                        "cases' (vx, vy) pairs or the arrays (vx, vy); pass vx= and vy= (each a "
                        "number or a 1-D array), or velocity=(np.array(vx), np.array(vy))"
                    )
                if all(s is not None and len(s) <= 1 for s in map(_shape, (vx, vy))):
                    return vx, vy
        except TypeError:  # no length: one number
            pass
    raise ValueError(
        f"velocity must be a pair (vx, vy) in m/s, each a number or a 1-D array (or pass vx= "
        f"and vy=), got {velocity_given(velocity)}"
    )


def _pairs(velocity: Any, vx: Any, vy: Any) -> bool:
    """True for a 2 x 2 ``velocity=`` that could be two cases' (vx, vy) pairs: one 2 x 2 array,
    or two lists of two (``velocity=(np.array(vx), np.array(vy))`` states its components)."""
    arrays = [isinstance(v, np.ndarray) or hasattr(v, "magnitude") for v in (velocity, vx, vy)]
    if arrays[0]:
        return _shape(velocity) == (2, 2)
    return _shape(vx) == _shape(vy) == (2,) and not (arrays[1] and arrays[2])


def _shape(value: Any) -> tuple[int, ...] | None:
    """The shape of a number, an array, a Quantity or nested lists (None: ragged lists)."""
    try:
        return tuple(np.shape(value))
    except ValueError:
        return None
