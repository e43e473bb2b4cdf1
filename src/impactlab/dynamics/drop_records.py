"""The records of a drop's contacts and dents (``DropResult.contacts``, ``DropResult.dents``),
read from the rows of the flexible core's tables (``flexcore.layout``); SI units."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, fields
from typing import Any, TypeVar

import numpy as np

from impactlab import schema
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.result_display import record_repr

__all__ = ["ContactDict", "ContactRecord", "DentRecord"]

_R = TypeVar("_R")


@dataclass(frozen=True, repr=False)
class ContactRecord:
    """One contact of the sequence (SI units): the ``end`` that touched (0 the tip, 1 the other
    end), its ``start`` (from the first touch) and ``duration`` [s], the largest interference
    ``delta_max`` [m] and force ``max_force`` [N], the normal and tangential impulses [N s], the
    signed slip ``sliding_length`` = int v_t dt [m] (an impact's ``sliding_length``: the body
    point at the contact, signed along +x) and ``slip_path`` = int |v_t| dt [m], the contact
    point at touch and at separation [m], its ``dent`` (index into ``DropResult.dents``),
    ``reload`` (True if it started on an existing dent), the dent's ``delta_r`` after it [m], the
    works of its end's normal force and friction [J] (its own, also while the other end touches:
    the contacts' works add up to the drop's) and the time spent sticking [s]. Named as in
    ``to_dict()`` and ``impactlab drop --json`` (``contacts[i]``); the name before 0.3,
    ``slip``, reads ``sliding_length`` with a DeprecationWarning (attribute, ``to_dict()`` key
    and ``from_dict``'s key)."""

    end: int
    start: float
    duration: float
    delta_max: float
    max_force: float
    normal_impulse: float
    tangential_impulse: float
    sliding_length: float
    slip_path: float
    x_start: float
    x_end: float
    dent: int
    reload: bool
    delta_r: float
    work_normal: float
    work_friction: float
    stick_time: float

    @classmethod
    def from_row(cls, row: np.ndarray) -> ContactRecord:
        """From one row of the integrator's contact table (``layout.CR_*``)."""
        return _from_row(cls, row, _CONTACT_COLUMNS)

    def __repr__(self) -> str:
        return record_repr(self)  # display units (result_display)

    @property
    def slip(self) -> float:
        """``sliding_length`` [m] under its name before 0.3 (DeprecationWarning)."""
        schema.warn_renamed("slip", "sliding_length", "ContactRecord field")
        return self.sliding_length

    def to_dict(self) -> dict[str, Any]:
        """The fields by name (SI); the key ``"slip"`` reads ``"sliding_length"`` with a
        DeprecationWarning (it is not among the keys)."""
        return ContactDict(self.__dict__)

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> ContactRecord:
        """A record from ``to_dict()`` or a ``contacts[i]`` of a drop's JSON (a value or its
        ``{"value", "unit"}`` quantity, SI); ``"slip"``, the key before 0.3, is read as
        ``"sliding_length"`` (DeprecationWarning). ValueError naming a missing or unknown key."""
        values = dict(data)
        if "slip" in values and "sliding_length" not in values:
            schema.warn_renamed("slip", "sliding_length", "contact record key")
            values["sliding_length"] = values.pop("slip")
        names = [f.name for f in fields(cls)]
        missing = [n for n in names if n not in values]
        unknown = sorted(set(values) - set(names))
        if missing or unknown:
            raise ValueError(
                f"data: a contact record needs the keys {', '.join(names)}; missing "
                f"{missing or 'none'}, unknown {unknown or 'none'}"
            )
        kinds = {"int": int, "bool": bool, "float": float}
        return cls(**{f.name: kinds[str(f.type)](_plain(values[f.name])) for f in fields(cls)})


class ContactDict(dict[str, Any]):
    """``ContactRecord.to_dict()``: its key before 0.3, ``"slip"``, still reads
    ``"sliding_length"`` with a DeprecationWarning; it is not among its keys (nor in JSON)."""

    def __missing__(self, key: str) -> Any:
        if key != "slip":
            raise KeyError(key)
        schema.warn_renamed("slip", "sliding_length", "contact record key")
        return self["sliding_length"]


def _plain(value: Any) -> Any:
    """A JSON quantity's value (``{"value": x, "unit": "m"}``: x; null: NaN); any other value
    as it is."""
    if isinstance(value, Mapping) and "value" in value:
        value = value["value"]
    return math.nan if value is None else value


@dataclass(frozen=True, repr=False)
class DentRecord:
    """A dent on the flat (SI units): the ``end`` that made it, the x-range of the contact-point
    path over it [m], its largest contact radius [m], delta_m, the permanent depth delta_p
    (= delta_r of its unloading curve) [m], the unloading radius R_r [m], the force F_m at
    delta_m [N] and the number of contacts on it."""

    end: int
    x_min: float
    x_max: float
    contact_radius: float
    delta_max: float
    delta_p: float
    unloading_radius: float
    max_force: float
    n_contacts: int

    @classmethod
    def from_row(cls, row: np.ndarray) -> DentRecord:
        """From one row of the integrator's dent table (``layout.DT_*``)."""
        return _from_row(cls, row, _DENT_COLUMNS)

    def __repr__(self) -> str:
        return record_repr(self)  # display units (result_display)


#: Column of each ContactRecord field in the contact table, in field order.
_CONTACT_COLUMNS = (
    F.CR_END, F.CR_T0, F.CR_DUR, F.CR_DMAX, F.CR_FMAX, F.CR_PN, F.CR_PT, F.CR_SLIP, F.CR_ASLIP,
    F.CR_X0, F.CR_X1, F.CR_DENT, F.CR_RELOAD, F.CR_DR, F.CR_WN, F.CR_WT, F.CR_STICK,
)  # fmt: skip
#: Column of each DentRecord field in the dent table, in field order.
_DENT_COLUMNS = (
    F.DT_END, F.DT_XLO, F.DT_XHI, F.DT_AM, F.DT_DM, F.DT_DR, F.DT_RR, F.DT_FM, F.DT_NC,
)  # fmt: skip


def _from_row(cls: type[_R], row: np.ndarray, columns: tuple[int, ...]) -> _R:
    """An instance of the record class ``cls`` from a table row: each field from its column,
    converted to the field's type (float, int or bool)."""
    kinds = {"int": int, "bool": bool, "float": float}
    values = {
        f.name: kinds[str(f.type)](float(row[j]))
        for f, j in zip(fields(cls), columns, strict=True)  # type: ignore[arg-type]
    }
    return cls(**values)
