"""Numbers of a calibration read in each input's own unit, as the sweep stores them
(``impactlab.sweep.inputs``: SI, except the Brinell hardness in kgf/mm^2, which may also be
written ``"105 HB"`` or ``"105 HBW"``: a Brinell number is kgf/mm^2), and the near names offered
for a misspelt key (``impactlab._validation.did_you_mean``)."""

from __future__ import annotations

import math
import re
from functools import cache
from typing import Any

from impactlab._validation import did_you_mean
from impactlab.materials.inputs import brinell_text
from impactlab.units import bare_number, magnitude, to_si

__all__ = ["BRINELL_UNIT", "bare", "did_you_mean", "is_number", "to_unit"]

#: The unit of a Brinell hardness (``impactlab.sweep.inputs``): its number HB is in kgf/mm^2.
BRINELL_UNIT = "kgf/mm^2"


def is_number(text: str) -> bool:
    """True when ``float`` reads ``text`` as a number (no unit; its minus sign ``-``)."""
    try:
        float(text)
    except ValueError:
        return False
    return True


def bare(v: Any) -> bool:
    """A plain number, or text that is only a number (no unit; its minus sign may be any dash,
    as in quantity text: ``"\u2212141"``, :func:`impactlab.units.bare_number`)."""
    return bare_number(v) is not None


@cache
def _si_factor(unit: str) -> float:
    """The SI magnitude of one ``unit`` (1 for an SI unit)."""
    return to_si(1.0, unit)


def in_own_unit(value: Any, unit: str) -> bool:
    """True when ``value`` is text written with a unit of its own (``"0.11 mm"``) other than
    ``unit``: a bare number beside it would be read in ``unit``, not in the value's."""
    if not isinstance(value, str):
        return False
    own = re.sub(r"^\s*[-+\u22120-9.eE]+\s*", "", value)  # a Unicode minus too
    try:
        return bool(own) and not math.isclose(_si_factor(own), _si_factor(unit), rel_tol=1e-12)
    except ValueError:
        return True


def to_unit(value: Any, unit: str, *, name: str) -> float:
    """``value`` (a number in ``unit`` or a quantity string, ``"12 um"``) as a number in
    ``unit`` itself, not in its SI base (a Brinell hardness stays in kgf/mm^2, and may be
    written ``"105 HB"``). ValueError naming ``name`` for unparsable text, a wrong dimension or a
    value that is not finite."""
    value = _brinell(value, unit, name)
    if isinstance(value, str) and unit.strip() in ("", "1"):  # a pure number: "0.4", "0.02 1"
        return float(magnitude(name, value, unit))
    x = to_si(value, unit, name=name)  # parses and checks; the SI magnitude
    if _si_factor(unit) == 1.0:
        return x
    number = bare_number(value)
    return number if number is not None else float(magnitude(name, str(value), unit))


def _brinell(value: Any, unit: str, name: str) -> Any:
    """A Brinell hardness written with its symbol HB or HBW (``"105 HB"``, ``"HBW 105"``) as
    ``"105 kgf/mm^2"``; the symbol on another input is refused, naming the input."""
    text = brinell_text(value)  # as a material's HB reads it (impactlab.materials.inputs)
    if text is value:
        return value
    if unit != BRINELL_UNIT:
        raise ValueError(f"{name}: {value!r} is a Brinell hardness (HB), not a quantity of {unit}")
    return text
