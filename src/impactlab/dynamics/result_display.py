"""The one display path of a one-impact result (``ImpactResult``) and a drop (``DropResult``):
``repr(result)`` (one line), ``print(result)``, Jupyter's ``_repr_html_`` and the summary tables
of ``impactlab simulate`` / ``impactlab drop`` all show ``result.summary()`` (SI values) through
``impactlab._display`` (display units from the SI units of ``impactlab.schema``, one number
format).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, ClassVar

from impactlab._display import field_row, field_rows, flag_names, html_table, text_table
from impactlab.flags import ADVISORY_FLAGS
from impactlab.schema import DERIVED_FIELDS
from impactlab.schema.printed import SI_UNITS

__all__ = ["BATCH_ONLY_NAMES", "RESULT_NAMES", "ResultDisplay", "field_hint", "record_repr"]

#: The fields of a drop's record shown by its ``repr``: a contact's are the cells of the
#: drop's contact table (``impactlab drop``).
RECORD_REPR_FIELDS: dict[str, tuple[str, ...]] = {
    "ContactRecord": (
        "end", "start", "duration", "delta_max", "max_force", "normal_impulse",
        "tangential_impulse", "sliding_length", "reload",
    ),
    "DentRecord": (
        "end", "x_min", "x_max", "contact_radius", "delta_max", "delta_p", "unloading_radius",
        "max_force", "n_contacts",
    ),
}  # fmt: skip


def record_repr(record: object) -> str:
    """One line of a drop's contact or dent record in display units with their units
    (``ContactRecord(end 0, start 0 ms, duration 0.33096 ms, delta_max 35.244 um, ...)``)."""
    name = type(record).__name__
    parts = []
    for key in RECORD_REPR_FIELDS[name]:
        _, text, unit = field_row(key, getattr(record, key), SI_UNITS.get(key))
        parts.append(f"{key} {text}" + (f" {unit}" if unit and unit != "-" else ""))
    return f"{name}({', '.join(parts)})"


#: A batch's column (``BatchResult``, ``DropBatchResult``) -> where a one-impact result holds
#: the same quantity (a pair of velocities as one field).
RESULT_NAMES: dict[str, str] = {
    "vx": "velocity_in[0]",
    "vy": "velocity_in[1]",
    "spin": "spin_in",
    "vx_out": "velocity_out[0]",
    "vy_out": "velocity_out[1]",
}

#: A drop batch's column that one ``DropResult`` does not hold -> where to read it instead
#: (``DropResult.BATCH_ONLY``).
BATCH_ONLY_NAMES: dict[str, str] = {
    "t_final": "history.t[-1] of a drop run with its history (sequence_duration ends at the "
    "last separation); per case: simulate_drops(...).t_final",
    "n_jumps": "a cost counter of the integrator beside n_steps; per case: "
    "simulate_drops(...).n_jumps",
}


def field_hint(result: object, name: str, error: AttributeError) -> AttributeError:
    """``error`` (the AttributeError of ``result.name``) with the result's field of a batch's
    column (:data:`RESULT_NAMES`: ``vx_out -> velocity_out[0]``), or where to read a batch's
    column that the result does not hold (its class's ``BATCH_ONLY``: a drop's ``t_final``);
    ``error`` for another name."""
    head = f"{type(result).__name__!r} object has no attribute {name!r} (a batch's column; "
    where = RESULT_NAMES.get(name)
    if where is not None:
        return AttributeError(f"{head}in one result: {name} -> {where})")
    instead = getattr(type(result), "BATCH_ONLY", {}).get(name)
    if instead is not None:
        return AttributeError(f"{head}one result does not hold it: {instead})")
    return error


class ResultDisplay:
    """Mixin of the result classes: ``__repr__`` (one line, ``REPR_FIELDS``), ``__str__`` (a
    text table), ``_repr_html_`` (the same rows as HTML) and ``_rows``, from the class's
    ``summary()``, its ``display_units()`` (field -> SI unit, which the display layer shows
    in its display units: um, ms), ``detail_rows()`` (rows after the summary's) and
    ``warnings``; ``units``: the SI unit of each field."""

    def summary(self) -> dict[str, Any]:
        """The fields a person reads first, by name (SI values; text for flags and names)."""
        raise NotImplementedError

    def display_units(self) -> Mapping[str, str]:
        """The SI unit of each numeric field of ``summary()``, from which ``print(result)``
        and ``_repr_html_`` choose their display units (um, ms: ``impactlab._display``)."""
        raise NotImplementedError

    @property
    def units(self) -> dict[str, str]:
        """The SI unit of each numeric field and derived output (``schema.register_output``)
        by name, ``"1"`` for a plain number (as ``History.units``; the values of the fields
        are SI, whatever ``print(result)`` shows)."""
        derived = {name: d.field.unit for name, d in DERIVED_FIELDS.items()}
        return {**self.display_units(), **derived}

    def detail_rows(self) -> list[tuple[str, str, str]]:
        """``(label, text, unit)`` rows shown after the summary (none by default)."""
        return []

    @staticmethod
    def flag_rows(flags: Any) -> dict[str, str]:
        """The summary's last rows for the result flags ``flags`` (a ``ResultFlag``): ``ok`` = "no:
        <the flags that make it so> (see the warnings)" for a result that is not ok (none for one
        that is, as ``invert`` and ``analyze`` show it), then ``flags``, every flag's name."""
        rows = {}
        invalid = flags & ~ADVISORY_FLAGS
        if invalid:
            rows["ok"] = f"no: {flag_names(invalid)} (see the warnings)"
        return rows | {"flags": flag_names(flags)}

    #: A batch's column that one result does not hold -> where to read it (``field_hint``).
    BATCH_ONLY: ClassVar[Mapping[str, str]] = {}

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
