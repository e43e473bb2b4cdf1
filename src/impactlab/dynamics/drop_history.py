"""The time history of a flexible drop (``DropResult.history``)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from impactlab.dynamics.flexcore import layout as F

__all__ = ["DropHistory"]


@dataclass(frozen=True, eq=False)
class DropHistory:
    """The time history of a drop: columns ``flexcore.layout.DROP_HISTORY_FIELDS``
    (``history["fn0"]``); the properties name the ones a figure needs."""

    data: np.ndarray = field(repr=False)

    def __post_init__(self) -> None:
        a = np.array(self.data, dtype=np.float64, copy=True)
        a.setflags(write=False)
        object.__setattr__(self, "data", a)

    def __len__(self) -> int:
        return int(self.data.shape[0])

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in F.DROP_HISTORY_FIELDS:
            raise KeyError(f"unknown history column {name!r}; known: {F.DROP_HISTORY_FIELDS}")
        return self.data[:, F.DROP_HISTORY_FIELDS.index(name)]

    @property
    def t(self) -> np.ndarray:
        """Time from the first touch [s]."""
        return self["t"]

    @property
    def normal_force(self) -> np.ndarray:
        """Normal contact force on the tip (end 0) [N]."""
        return self["fn0"]

    @property
    def tangential_force(self) -> np.ndarray:
        """Tangential contact force on the tip [N] (+x)."""
        return self["ft0"]

    @property
    def tip_x(self) -> np.ndarray:
        """x of the tip's lowest point (below the centre of its sphere) [m]."""
        return self["x0"]

    @property
    def tip_height(self) -> np.ndarray:
        """Height of the tip's lowest point above the undeformed flat [m] (-delta)."""
        return -self["delta0"]

    def __repr__(self) -> str:
        return f"DropHistory({len(self)} rows: {', '.join(F.DROP_HISTORY_FIELDS)})"
