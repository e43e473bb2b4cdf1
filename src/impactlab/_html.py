"""Notebook reprs: rich HTML (Jupyter's ``_repr_html_``) and short text reprs for the objects a
notebook shows: bodies, materials, contact laws, batches and sweep studies.

Numbers go through the one display layer (``impactlab._display``: display units, number
format). Layer L0: this module imports only ``impactlab._display``; the classes call it from a
one-line ``_repr_html_`` / ``__repr__``. Sweep axes are summarised as name, size, range and unit,
never listed value by value.
"""

from __future__ import annotations

import dataclasses
import html
import math
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from impactlab._display import display_unit, field_row, format_number, html_table

__all__ = [
    "FIELD_UNITS",
    "axis_row",
    "dataclass_html",
    "dataclass_rows",
    "doi_link",
    "grid_html",
    "law_html",
    "law_repr",
    "value_range",
]

#: SI units of the fields of bodies and materials (the dataclasses that have an HTML repr).
FIELD_UNITS: dict[str, str] = {
    "length": "m",
    "overall_length": "m",
    "tip_radius": "m",
    "radius": "m",
    "diameter": "m",
    "mass": "kg",
    "inertia": "kg*m^2",
    "density": "kg/m^3",
    "E": "Pa",
    "yield_strength": "Pa",
    "nu": "1",
    "meyer_index": "1",
    "brinell_hardness": "kgf/mm^2",
    "damping": "1",
    "E_star": "Pa",
    "G_star": "Pa",
}

#: At most this many values of a category axis are named in a summary.
_MAX_NAMED = 4


def _name_of(value: Any) -> Any:
    """A nested object (a body's material) by its name; anything else as it is."""
    name = getattr(value, "name", None)
    return name if isinstance(name, str) and not isinstance(value, str) else value


def dataclass_rows(obj: Any, extra: Mapping[str, Any] | None = None) -> list[tuple[str, str, str]]:
    """``(name, value, unit)`` rows of a dataclass's public fields (units: ``FIELD_UNITS``,
    shown in display units), then ``extra`` (name -> SI value of a derived quantity)."""
    data: dict[str, Any] = {
        f.name: _name_of(getattr(obj, f.name))
        for f in dataclasses.fields(obj)
        if f.repr and not f.name.startswith("_")
    }
    data.update(extra or {})
    rows = []
    for name, value in data.items():
        if isinstance(value, float) and math.isnan(value):
            rows.append((name, "-", ""))
        elif isinstance(value, int) and not isinstance(value, bool):
            rows.append((name, str(value), ""))
        else:
            rows.append(field_row(name, value, FIELD_UNITS.get(name)))
    return rows


def dataclass_html(obj: Any, extra: Mapping[str, Any] | None = None) -> str:
    """The HTML table of a body or a material (``_repr_html_``)."""
    return html_table(type(obj).__name__, dataclass_rows(obj, extra))


def doi_link(doi: str) -> str:
    """A DOI as an HTML link to https://doi.org/ (the text ``doi:...``)."""
    d = html.escape(doi)
    return f"<a href='https://doi.org/{d}'>doi:{d}</a>"


def grid_html(
    title: str, header: Sequence[str], rows: Iterable[Sequence[str]], caption: str = ""
) -> str:
    """A plain HTML table: ``title`` above it, a header row, text cells (escaped)."""
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    body = "".join(
        "<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows
    )
    cap = f"<p>{html.escape(caption)}</p>" if caption else ""
    return (
        f"<div><strong>{html.escape(title)}</strong>{cap}<table><thead><tr>{head}</tr></thead>"
        f"<tbody>{body}</tbody></table></div>"
    )


def law_repr(meta: Mapping[str, Any]) -> str:
    """One line for a contact law (its ``__repr__``), from ``ContactLaw.describe()``."""
    params = ", ".join(p["name"] for p in meta.get("parameters", ())) or "none"
    return (
        f"<contact law {meta['name']!r}: {meta['title']}; doi:{meta['doi']}; parameters: {params}>"
    )


def law_html(meta: Mapping[str, Any]) -> str:
    """A contact law's card (its ``_repr_html_``): title, sources with DOI links, validity,
    calibrated range and the parameter table, from ``ContactLaw.describe()``."""
    refs = "".join(
        f"<li>{html.escape(r['citation'])}" + (f", {doi_link(r['doi'])}" if r.get("doi") else "")
        for r in meta.get("references", ())
    )
    params = [
        (p["name"], p["default_text"], p["unit"], p["description"])
        for p in meta.get("parameters", ())
    ]
    table = (
        grid_html("parameters", ("name", "default", "unit", "meaning"), params) if params else ""
    )
    return (
        f"<div><strong>contact law {html.escape(repr(meta['name']))}</strong>: "
        f"{html.escape(meta['title'])}<ul>{refs}</ul>"
        f"<p>validity: {html.escape(meta['validity'])}<br>"
        f"calibrated range: {html.escape(meta['calibrated_range'])}</p>{table}</div>"
    )


def value_range(name: str, values: Sequence[Any], si_unit: str) -> tuple[str, str]:
    """``(range, unit)`` of an axis's values in display units: ``"5 .. 85"`` and ``"deg"``
    for numbers, the first few names for categories (``"ghaednia, brake"``)."""
    if not all(isinstance(v, int | float) and not isinstance(v, bool) for v in values):
        named = ", ".join(str(v) for v in values[:_MAX_NAMED])
        return named + (f", ... ({len(values)})" if len(values) > _MAX_NAMED else ""), ""
    d = display_unit(name, si_unit)
    lo, hi = min(values) * d.scale, max(values) * d.scale
    text = format_number(lo) if lo == hi else f"{format_number(lo)} .. {format_number(hi)}"
    return text, "" if d.unit == "-" else d.unit


def axis_row(name: str, values: Sequence[Any], si_unit: str) -> tuple[str, str, str, str]:
    """``(name, size, range, unit)``: one dimension of a study, summarised."""
    text, unit = value_range(name, values, si_unit)
    return name, str(len(values)), text, unit
