"""The one display layer: how a result field is shown to a person (``print(result)``, Jupyter's
``_repr_html_`` and every ``impactlab`` command).

- :func:`display_unit` maps a field (its name and SI unit, from ``impactlab.schema`` or the
  result's own unit table) to its display unit and scale: dent-scale lengths in um, other
  lengths in mm, times in ms, angles in deg, moduli in GPa, stresses in MPa, SI otherwise;
- :func:`format_number` writes every number the same way (5 significant digits, fixed notation
  from 1e-4 to 1e7, scientific outside: never ``1.094e+04`` next to ``10940``);
- :func:`field_row` / :func:`field_rows` turn a field into a ``(name, text, unit)`` row (with
  ``± sigma`` when there is one), and :func:`text_table` / :func:`html_table` lay rows out.

The machine-readable counterpart (JSON of ``{"value", "unit", "sigma"}``) is
``impactlab._json.to_json``; it stays in SI. This module imports nothing of impactlab (layer
L0): callers pass the SI unit of each field (``impactlab.schema`` for the engine's fields).
"""

from __future__ import annotations

import html
import math
from collections.abc import Iterable, Mapping
from typing import Any, NamedTuple

__all__ = [
    "Display",
    "display_unit",
    "field_row",
    "field_rows",
    "flag_names",
    "format_number",
    "format_value",
    "html_table",
    "text_table",
]


class Display(NamedTuple):
    """A display unit (``"um"``) and the factor from the SI value to it (``1e6``)."""

    unit: str
    scale: float


#: Display unit of a field, by its SI unit (pint spelling as in ``impactlab.schema``).
BY_SI_UNIT: dict[str, Display] = {
    "m": Display("mm", 1e3),
    "s": Display("ms", 1e3),
    "rad": Display("deg", 180.0 / math.pi),
    "Pa": Display("MPa", 1e-6),
    "1": Display("-", 1.0),
    "": Display("-", 1.0),
    "-": Display("-", 1.0),
    "N s": Display("N s", 1.0),
    "N*s": Display("N s", 1.0),
    "kg*m^2": Display("kg m^2", 1.0),
}

_UM = Display("um", 1e6)
_GPA = Display("GPa", 1e-9)

#: Fields shown in another unit than their SI unit's default: dent-scale lengths (um) and
#: elastic moduli (GPa).
BY_NAME: dict[str, Display] = {
    **{
        name: _UM
        for name in (
            "delta_max",
            "delta_p",
            "dent_depth",
            "delta_r",
            "delta_y",
            "delta_c",
            "delta_c_jackson_green",
            "sliding_length",
            "sequence_sliding_length",
            "slip",
            "slip_path",
            "contact_travel",
            "scar_length",
            "penetration",
            "contact_x",
            "x_start",
            "x_end",
            "x_min",
            "x_max",
            "contact_radius",
            "L_s",
            "pileup",
            "switch_interference",
            "max_interference",
            "calibrated_max_interference",
            "full_contact_interference",
            "pole_interference",
            "a_p",
        )
    },
    **{name: _GPA for name in ("E", "E_star", "G_star")},
    "wall_time": Display("s", 1.0),
    "first_task": Display("s", 1.0),
    "throughput": Display("impacts/s", 1.0),
}


def display_unit(name: str, si_unit: str) -> Display:
    """The display unit of field ``name`` whose SI unit is ``si_unit`` (unknown SI units are
    shown as they are); a material input ``body_E``, ``flat_E`` as ``E``."""
    own = name if name in BY_NAME else name.removeprefix("body_").removeprefix("flat_")
    if own in BY_NAME and si_unit not in ("", "1", "-"):
        return BY_NAME[own]
    return BY_SI_UNIT.get(si_unit, Display(si_unit, 1.0))


def format_number(x: Any, digits: int = 5) -> str:
    """``x`` with ``digits`` significant digits, fixed notation for 1e-4 <= |x| < 1e7 (trailing
    zeros dropped), scientific outside; ints, bools and text as they are."""
    if isinstance(x, bool) or (not isinstance(x, int | float) and not hasattr(x, "__float__")):
        return str(x)
    if isinstance(x, int):
        return str(x)
    x = float(x)
    if not math.isfinite(x):
        return str(x)
    if x == 0.0:
        return "0"
    exp = math.floor(math.log10(abs(float(f"{x:.{digits - 1}e}"))))
    if -4 <= exp < 7:
        text = f"{x:.{max(digits - 1 - exp, 0)}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text
    mantissa, power = f"{x:.{digits - 1}e}".split("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return f"{mantissa}e{int(power)}"


def format_value(value: Any, sigma: Any = None, digits: int = 5) -> str:
    """``value`` (a number, a pair or a text) as text, with ``± sigma`` when sigma is given
    and > 0 (2 significant digits)."""
    if value is None:
        return "-"
    if isinstance(value, list | tuple):
        return "(" + ", ".join(format_number(v, digits) for v in value) + ")"
    text = format_number(value, digits)
    if sigma is not None and isinstance(sigma, int | float) and sigma > 0:
        text += f" ± {format_number(sigma, 2)}"
    return text


def _scaled(value: Any, scale: float) -> Any:
    if isinstance(value, bool) or scale == 1.0:
        return value
    if isinstance(value, list | tuple):
        return [_scaled(v, scale) for v in value]
    if isinstance(value, float):
        return value * scale
    return value


def field_row(
    name: str, value: Any, si_unit: str | None, sigma: Any = None
) -> tuple[str, str, str]:
    """One ``(name, text, unit)`` row: a float (or a pair of floats) with an SI unit in its
    display unit, anything else as text (mappings as ``key value, ...``, lists one per line)."""
    if isinstance(value, Mapping):
        return name, ", ".join(f"{k} = {format_value(v)}" for k, v in value.items()) or "-", ""
    is_number = isinstance(value, float) or (
        isinstance(value, list | tuple) and value and all(isinstance(v, float) for v in value)
    )
    if isinstance(value, list | tuple) and not is_number:
        lines = [field_row("", v, None)[1] if isinstance(v, Mapping) else str(v) for v in value]
        short = all(len(t) <= 24 and "\n" not in t for t in lines)  # names: one line
        return name, (", " if short else "\n").join(lines) or "-", ""
    if si_unit is None or not is_number:
        return name, "-" if value is None else format_value(value), ""
    d = display_unit(name, si_unit)
    sig = None if sigma is None else sigma * d.scale
    return name, format_value(_scaled(value, d.scale), sig), d.unit


def field_rows(
    data: Mapping[str, Any],
    si_units: Mapping[str, str],
    sigmas: Mapping[str, float] | None = None,
) -> list[tuple[str, str, str]]:
    """Rows of every field of ``data`` (SI units of its quantities in ``si_units``; fields
    without one are shown as text)."""
    sigmas = sigmas or {}
    return [field_row(k, v, si_units.get(k), sigmas.get(k)) for k, v in data.items()]


def flag_names(flags: Any) -> str:
    """The names of the bits set in ``flags`` (an ``enum.IntFlag`` such as
    ``impactlab.flags.ResultFlag``), lower case, comma-separated; ``"none"`` for none."""
    names = [str(f.name).lower() for f in type(flags) if f.value and flags & f.value]
    return ", ".join(names) or "none"


def text_table(title: str, rows: Iterable[tuple[str, str, str]]) -> str:
    """Rows as aligned plain text under ``title`` (the ``__str__`` of results)."""
    rows = list(rows)
    if not rows:
        return title
    w = max(len(r[0]) for r in rows)
    return "\n".join(
        [title] + [f"  {a:<{w}}  {b} {c if c != '-' else ''}".rstrip() for a, b, c in rows]
    )


def html_table(title: str, rows: Iterable[tuple[str, str, str]]) -> str:
    """A three-column (quantity, value, unit) HTML table."""
    body = "".join(
        f"<tr><td>{html.escape(a)}</td><td style='text-align:right'>{html.escape(b)}</td>"
        f"<td>{html.escape(c)}</td></tr>"
        for a, b, c in rows
    )
    return (
        f"<table><thead><tr><th>{html.escape(title)}</th><th>value</th><th>unit</th></tr>"
        f"</thead><tbody>{body}</tbody></table>"
    )
