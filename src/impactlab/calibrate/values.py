"""Numbers of a calibration read in each input's own unit, as the sweep stores them
(``impactlab.sweep.inputs``: SI, except the Brinell hardness in kgf/mm^2), and the near names
offered for a misspelt key (``impactlab._validation.did_you_mean``)."""

from __future__ import annotations

from functools import cache
from typing import Any

from impactlab._validation import did_you_mean
from impactlab.units import magnitude, to_si

__all__ = ["bare", "did_you_mean", "is_number", "to_unit"]


def is_number(text: str) -> bool:
    """True when ``text`` is a plain number (no unit)."""
    try:
        float(text)
    except ValueError:
        return False
    return True


def bare(v: Any) -> bool:
    """A plain number, or text that is only a number (no unit)."""
    return (isinstance(v, int | float) and not isinstance(v, bool)) or (
        isinstance(v, str) and is_number(v)
    )


@cache
def _si_factor(unit: str) -> float:
    """The SI magnitude of one ``unit`` (1 for an SI unit)."""
    return to_si(1.0, unit)


def to_unit(value: Any, unit: str, *, name: str) -> float:
    """``value`` (a number in ``unit`` or a quantity string, ``"12 um"``) as a number in
    ``unit`` itself, not in its SI base (a Brinell hardness stays in kgf/mm^2). ValueError
    naming ``name`` for unparsable text, a wrong dimension or a value that is not finite."""
    x = to_si(value, unit, name=name)  # parses and checks; the SI magnitude
    if _si_factor(unit) == 1.0:
        return x
    if bare(value):
        return float(value)
    return float(magnitude(name, str(value), unit))
