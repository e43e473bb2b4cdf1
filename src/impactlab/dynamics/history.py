"""The parts of an impact's result that hold arrays: its time ``History`` and the predicted
``DentMap`` (SI units, read-only arrays, short reprs), and ``readonly_copy``. Re-exported by
``impactlab.dynamics.results``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from impactlab import schema
from impactlab._validation import did_you_mean
from impactlab.dynamics.export import history_dataframe
from impactlab.dynamics.kernels.layout import HISTORY_FIELDS

__all__ = ["HISTORY_UNITS", "ColumnAttributes", "DentMap", "History", "readonly_copy"]


def readonly_copy(a: Any, dtype: Any = np.float64) -> np.ndarray:
    """A copy of ``a`` (float64 unless ``dtype`` says otherwise) that cannot be written to."""
    out = np.array(a, dtype=dtype, copy=True)
    out.setflags(write=False)
    return out


#: Units of the history columns (from ``impactlab.schema``).
HISTORY_UNITS: dict[str, str] = {f.name: f.unit for f in schema.HISTORY_FIELDS}


class ColumnAttributes:
    """A history's columns (``_COLUMNS``, set by each history class) as attributes: ``dir()``
    lists them (tab completion), and a name that is no attribute gets the nearest column
    (``_validation.did_you_mean``) in its AttributeError, in ``History`` and ``DropHistory``
    alike."""

    _COLUMNS: ClassVar[tuple[str, ...]] = ()

    def __dir__(self) -> list[str]:
        """The attributes with the columns (``history.normal_force``: tab completion)."""
        return sorted({*object.__dir__(self), *self._COLUMNS})

    def _no_column(self, name: str) -> AttributeError:
        """The AttributeError of ``history.name`` for a name that is no column: the nearest
        column, then the columns."""
        near = did_you_mean(name, self._COLUMNS)
        return AttributeError(
            f"'{type(self).__name__}' object has no attribute {name!r}{near}; columns: "
            f"{', '.join(self._COLUMNS)}"
        )


@dataclass(frozen=True, eq=False)
class History(ColumnAttributes):
    """Time history of one impact (rows: accepted steps, dense-output points and events).

    Columns (SI): see ``HISTORY_FIELDS``; each is also an attribute (``history.t``, ...).
    ``phase`` is 0 on the loading curve and 1 on the unloading/reloading curve; ``stick`` is 1
    while the contact point sticks (Coulomb) or has no gross slip (Mindlin).
    """

    data: np.ndarray = field(repr=False)
    _COLUMNS = HISTORY_FIELDS

    def __post_init__(self) -> None:
        object.__setattr__(self, "data", readonly_copy(self.data))

    def __len__(self) -> int:
        return int(self.data.shape[0])

    def __getattr__(self, name: str) -> np.ndarray:
        try:
            j = HISTORY_FIELDS.index(name)
        except ValueError:
            raise self._no_column(name) from None
        return self.data[:, j]

    def __getitem__(self, name: str) -> np.ndarray:
        return self.__getattr__(name)

    @property
    def fields(self) -> tuple[str, ...]:
        """Column names."""
        return HISTORY_FIELDS

    @property
    def units(self) -> dict[str, str]:
        """SI unit of each column (``"1"``: dimensionless)."""
        return dict(HISTORY_UNITS)

    def to_dataframe(self) -> Any:
        """A pandas DataFrame: SI, units in ``.attrs``, categorical phase/stick (``export``)."""
        return history_dataframe(self.data)

    def __repr__(self) -> str:
        return f"History({len(self)} rows: {', '.join(HISTORY_FIELDS)})"


@dataclass(frozen=True, eq=False)
class DentMap:
    """Predicted permanent dent on the flat as a height map (see docs/engine/index.md).

    x, y : grid coordinates on the flat [m]; x along the impact plane from the first contact
        point (positive towards the centre-of-mass side), y across it.
    height : (len(y), len(x)) surface height after the impact [m] (<= 0 inside the dent).
    max_depth : deepest point [m] (equals ``delta_p`` for a single loading).
    length : extent of the dent along x [m]; width : extent across (along y) [m].
    caps_at_contact_radius : residual caps of the surface drawn with the widest contact
        radius as rim (the unloading relation has no concave dent for R_r <= R and puts the rim
        beyond the contact for R_r just above R): their depth is the law's, their width an
        upper bound.
    note : what those bounds mean for this dent ("" when every cap follows the relation).
    """

    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    height: np.ndarray = field(repr=False)
    max_depth: float
    length: float
    width: float
    caps_at_contact_radius: int = 0
    note: str = ""

    def __post_init__(self) -> None:
        for name in ("x", "y", "height"):
            object.__setattr__(self, name, readonly_copy(getattr(self, name)))

    def profile(self) -> tuple[np.ndarray, np.ndarray]:
        """(x, height) along the centre line y = 0."""
        j = int(np.argmin(np.abs(self.y)))
        return self.x, self.height[j]

    def __repr__(self) -> str:
        bounded = ""
        if self.caps_at_contact_radius:
            bounded = f", caps_at_contact_radius={self.caps_at_contact_radius}, note={self.note!r}"
        return (
            f"DentMap(max_depth={self.max_depth:.4g} m, length={self.length:.4g} m, "
            f"width={self.width:.4g} m, grid={self.height.shape[1]}x{self.height.shape[0]}"
            f"{bounded})"
        )
