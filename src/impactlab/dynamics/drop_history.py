"""The time history of a flexible drop (``DropResult.history``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab import schema
from impactlab._validation import did_you_mean
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.history import ColumnAttributes

__all__ = ["DROP_HISTORY_COLUMNS", "DROP_HISTORY_UNITS", "DropHistory"]

#: The column names, in the engine's order (``impactlab.schema.DROP_HISTORY_FIELDS``).
DROP_HISTORY_COLUMNS: tuple[str, ...] = tuple(f.name for f in schema.DROP_HISTORY_FIELDS)
#: SI unit of each column ("1": dimensionless).
DROP_HISTORY_UNITS: dict[str, str] = {f.name: f.unit for f in schema.DROP_HISTORY_FIELDS}
if len(DROP_HISTORY_COLUMNS) != F.N_DROP_HISTORY:  # the schema names every engine column
    raise ImportError("impactlab.schema.DROP_HISTORY_FIELDS does not match the drop's history")


@dataclass(frozen=True, eq=False)
class DropHistory(ColumnAttributes):
    """The time history of a drop (rows: accepted steps and dense points; SI units).

    Columns: ``impactlab.schema.DROP_HISTORY_FIELDS``, by name (``history["normal_force_0"]``)
    or as attributes (``history.normal_force_0``); a quantity of one end of the rod carries
    the end's suffix (``_0`` the tip, ``_1`` the other end: ``schema.end_column``). The names
    before 0.3 (``"fn0"``, ...: ``schema.RENAMED_DROP_HISTORY``) read the same column with a
    DeprecationWarning. ``dir()`` lists the columns; a misspelt one gets the nearest
    (``history.ColumnAttributes``, as ``History`` has it).
    """

    data: np.ndarray = field(repr=False)
    _COLUMNS = DROP_HISTORY_COLUMNS

    def __post_init__(self) -> None:
        a = np.array(self.data, dtype=np.float64, copy=True)
        a.setflags(write=False)
        object.__setattr__(self, "data", a)

    def __len__(self) -> int:
        return int(self.data.shape[0])

    def __getitem__(self, name: str) -> np.ndarray:
        new = schema.RENAMED_DROP_HISTORY.get(name)
        if new is not None:
            schema.warn_renamed(name, new, "drop history column")
            name = new
        try:
            return self.data[:, DROP_HISTORY_COLUMNS.index(name)]
        except ValueError:
            known = ", ".join(DROP_HISTORY_COLUMNS)
            near = did_you_mean(name, DROP_HISTORY_COLUMNS)
            raise KeyError(f"unknown history column {name!r}{near}; known: {known}") from None

    def __getattr__(self, name: str) -> np.ndarray:
        if name.startswith("_") or name == "data":
            raise AttributeError(name)
        try:
            return self[name]
        except KeyError:
            raise self._no_column(name) from None

    @property
    def fields(self) -> tuple[str, ...]:
        """Column names."""
        return DROP_HISTORY_COLUMNS

    @property
    def units(self) -> dict[str, str]:
        """SI unit of each column (``"1"``: dimensionless)."""
        return dict(DROP_HISTORY_UNITS)

    @property
    def normal_force(self) -> np.ndarray:
        """Normal contact force on the tip (end 0) [N] (``normal_force_0``)."""
        return self["normal_force_0"]

    @property
    def penetration(self) -> np.ndarray:
        """Interference delta of the tip (end 0) [m], as an impact's history names it
        (``penetration_0``)."""
        return self["penetration_0"]

    @property
    def tangential_force(self) -> np.ndarray:
        """Tangential contact force on the tip [N] (+x) (``tangential_force_0``)."""
        return self["tangential_force_0"]

    @property
    def tip_x(self) -> np.ndarray:
        """x of the tip's lowest point (below the centre of its sphere) [m] (``end_x_0``)."""
        return self["end_x_0"]

    @property
    def tip_height(self) -> np.ndarray:
        """Height of the tip's lowest point above the undeformed flat [m] (-penetration_0)."""
        return -self["penetration_0"]

    def to_dataframe(self) -> Any:
        """A pandas DataFrame of the columns (SI, units in ``df.attrs["units"]``), as
        ``History.to_dataframe`` of an impact."""
        import pandas as pd  # heavy, needed only here

        df = pd.DataFrame(np.array(self.data), columns=list(DROP_HISTORY_COLUMNS))
        df.attrs["units"] = dict(DROP_HISTORY_UNITS)
        return df

    def __repr__(self) -> str:
        return f"DropHistory({len(self)} rows: {', '.join(DROP_HISTORY_COLUMNS)})"
