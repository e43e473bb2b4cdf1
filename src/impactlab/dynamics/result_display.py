"""The one display path of a one-impact result (``ImpactResult``) and a drop (``DropResult``):
``repr(result)`` (one line), ``print(result)``, Jupyter's ``_repr_html_`` and the summary tables
of ``impactlab simulate`` / ``impactlab drop`` all show ``result.summary()`` (SI values) through
``impactlab._display`` (display units from the SI units of ``impactlab.schema``, one number
format).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, ClassVar

from impactlab._display import field_rows, html_table, text_table

__all__ = ["ResultDisplay"]


class ResultDisplay:
    """Mixin of the result classes: ``__repr__`` (one line, ``REPR_FIELDS``), ``__str__`` (a
    text table), ``_repr_html_`` (the same rows as HTML) and ``_rows``, from the class's
    ``summary()``, its ``display_units()`` (field -> SI unit), ``detail_rows()`` (rows after
    the summary's) and ``warnings``."""

    def summary(self) -> dict[str, Any]:
        """The fields a person reads first, by name (SI values; text for flags and names)."""
        raise NotImplementedError

    def display_units(self) -> Mapping[str, str]:
        """SI unit of each numeric field of ``summary()``."""
        raise NotImplementedError

    def detail_rows(self) -> list[tuple[str, str, str]]:
        """``(label, text, unit)`` rows shown after the summary (none by default)."""
        return []

    #: The fields of the one-line ``repr``, in order (each class names its own).
    REPR_FIELDS: ClassVar[tuple[str, ...]] = ()

    def __repr__(self) -> str:
        """One line: the headline fields in SI (``print(result)``: the whole table)."""
        units = self.display_units()
        parts = []
        for name in self.REPR_FIELDS:
            value = getattr(self, name)
            unit = units.get(name, "1")
            if isinstance(value, float):
                parts.append(f"{name}={value:.6g}" + ("" if unit == "1" else f" {unit}"))
            else:
                parts.append(f"{name}={value!r}")
        flags = getattr(self, "flags", 0)
        if flags:
            parts.append(f"flags={flags!r}")
        return f"{type(self).__name__}({', '.join(parts)})"

    def _rows(self) -> list[tuple[str, str, str]]:
        """The summary's rows (display units), the detail rows and one row per warning."""
        rows = field_rows(self.summary(), self.display_units())
        rows.extend(self.detail_rows())
        rows.extend(("warning", text, "") for text in getattr(self, "warnings", ()))
        return rows

    def __str__(self) -> str:
        return text_table(type(self).__name__, self._rows())

    def _repr_html_(self) -> str:
        return html_table(type(self).__name__, self._rows())
