"""A drop's e above 1 through the gravity impulse it removes (docs/flexible.md, "Flags").

A drop's ``e`` removes the gravity impulse of the whole sequence, e = -(v_n,out + g T)/v_n,in
(T: first touch to last separation), so e - e_raw = g T/|v_n,in|. For an impact that loses
less than that, e exceeds 1 with no energy gained: a nearly elastic drop at a low speed (the
paper's rod, Hertz, frictionless, vertical: 1.0013 at 1.41 m/s, 1.139 at 0.03 m/s, with e_raw
1 to the tolerance). Such a drop carries GRAVITY_DOMINATED (not ``ok``), in ``simulate_drop``
and ``simulate_drops`` (and so in the sweep stores) alike; the rigid engine's ``e`` keeps the
gravity impulse and has no such case.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab.flags import ENERGY_ROUNDOFF, FLAG_ENERGY_GAIN, FLAG_OTHER_END

__all__ = ["E_RTOL_FACTOR", "e_lifted_by_gravity", "lifted_e_warning"]

#: e and e_raw are ratios of velocities, accurate to about the integration's rtol (e_raw of a
#: lossless drop: 1 - 3.7e-6 at rtol 1e-5); a value above 1 + E_RTOL_FACTOR rtol is above 1
#: (the energy criterion's 100 rtol, a tolerance on energies, let e = 1.0009 pass at rtol 1e-5).
E_RTOL_FACTOR = 10.0


def e_lifted_by_gravity(e: Any, e_raw: Any, flags: Any, rtol: float) -> Any:
    """True where the gravity impulse removed from ``e`` alone lifts it above 1: e > 1 + tol
    while ``e_raw`` <= 1 + tol (tol = E_RTOL_FACTOR rtol + ENERGY_ROUNDOFF), and neither
    ENERGY_GAIN (the energy rose) nor OTHER_END (no bounce of the tip: e of a whole flight, or
    the other end's landing) is among ``flags``. Scalars or arrays (NaN: False)."""
    tol = E_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF
    e = np.asarray(e, dtype=np.float64)
    e_raw = np.asarray(e_raw, dtype=np.float64)
    free = (np.asarray(flags, dtype=np.int64) & (FLAG_ENERGY_GAIN | FLAG_OTHER_END)) == 0
    return free & (e > 1.0 + tol) & (e_raw <= 1.0 + tol)


def lifted_e_warning(e: float, e_raw: float) -> str:
    """The GRAVITY_DOMINATED sentence of a drop flagged by :func:`e_lifted_by_gravity` alone
    (m g T within 0.1 of the normal impulse)."""
    return (
        f"gravity-dominated: e = {e:.6g} exceeds 1 only through the gravity impulse it "
        f"removes: e = -(v_n,out + g T)/v_n,in adds g T/|v_n,in| = {e - e_raw:.3g} (T: first "
        f"touch to last separation) to e_raw = {e_raw:.6g} (gravity kept), more than the "
        "impact lost, with no energy gained; so e is no coefficient of restitution here (read "
        "e_raw, or pass gravity=False)"
    )
