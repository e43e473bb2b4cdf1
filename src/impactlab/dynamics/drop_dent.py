"""A drop's predicted dent: the dent model of a single impact (``dynamics.dent``) over every
contact of the tip.

Each recorded instant of the tip's contacts leaves the residual cap of the law's unloading from
its interference at the tip's x; the dent is the lower envelope of them all, so a contact that
presses deeper into an earlier dent overwrites it and a shallower one leaves it as it was
(the ``DentRecord``s' rule). The law is the drop's own, its rate factor included. The other
end's contacts, when any, leave their marks elsewhere on the flat (its ``dents`` records).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab.dynamics.dent import dent_map
from impactlab.dynamics.history import DentMap

__all__ = ["drop_dent"]


def drop_dent(result: Any, *, nx: int = 241, ny: int = 121, margin: float = 0.15) -> DentMap:
    """The tip's dent of the ``DropResult`` ``result`` as a height map (``DentMap``, SI);
    ValueError without its history."""
    history, law = result.history, result._law
    if history is None or law is None:
        raise ValueError("dent() needs the history: run simulate_drop(..., history=True)")
    law_id, params = law
    surface = dent_map(
        law_id,
        np.asarray(params, dtype=np.float64),
        np.asarray(history["penetration_0"]),
        np.asarray(history["end_x_0"]),
        nx=nx,
        ny=ny,
        margin=margin,
    )
    return DentMap(*surface)
