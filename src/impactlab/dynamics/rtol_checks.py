"""The integrator's relative tolerance: the range every engine takes and the tighter caps of
the models whose results leave the tolerance beyond them (partial slip, Mindlin, a drop);
ValueError, one line, naming the option and the cap."""

from __future__ import annotations

import math
from typing import Any

from impactlab._validation import check_finite
from impactlab.dynamics.kernels.inputs import RTOL_RANGE, rtol_allowed
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL

#: Largest rtol of a drop (``simulate_drop``, ``simulate_drops``, a flexible rod's sweep), of a
#: flexible rod and of a rigid one: up to it the drop's error shrinks with rtol, beyond it the
#: integrator leaves that regime. Over 24 random drops of each of five rods against rtol 1e-10
#: (docs/flexible.md, "Refused results"), the largest energy created grew from 1.1e-4 E0 at
#: 1e-5 to 1e-3 at 3e-5 and 1.2e-2 at 1e-4, and e moved by up to 3.4 % at 3e-5 (the rigid rod).
DROP_RTOL_MAX = 1e-5


def check_rtol(rtol: Any) -> float:
    """The relative tolerance (None: ``DEFAULT_RTOL``), in [1e-13, 1e-3]."""
    if rtol is None:
        return DEFAULT_RTOL
    r = check_finite("rtol", rtol)
    if not rtol_allowed(r):
        raise ValueError(
            f"rtol must lie in [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}], got {float(r)!r}"
        )
    return r


#: Largest rtol of the rigid partial-slip engine. Beyond it the cells' events outrun the steps
#: and the results leave the tolerance: over five rods and spheres, the largest relative error
#: of e, e_energy and vt_out against rtol 1e-10 was 5e-6 at 1e-6, 1.1e-4 at 1e-5, 1e-3 at 3e-5
#: and 4e-2 at 1e-4 (11 % at 3e-4).
PARTIAL_SLIP_RTOL_MAX = 1e-5
#: Largest rtol with ``mindlin`` friction, whose tangential spring is stiff: over 300 random
#: impacts of the paper's rod (5-88 deg, 0.1-3.2 m/s, mu 0.05-0.6, hertz and ghaednia) against
#: rtol 1e-10, the largest error of e was 2e-4 at 1e-5, 0.2 % at 1e-4 and 26 % at 1e-3 (10 deg,
#: 0.11 m/s: e = 0.61 for 0.49), that of vt_out 0.5 % and 3 % of the normal speed at 1e-4 and
#: 1e-3.
#: coulomb and impulse_ratio keep the whole range (e within 1.1 % at 1e-3).
MINDLIN_RTOL_MAX = 1e-4
#: friction model -> (largest rtol, why a looser one is refused)
_FRICTION_RTOL_MAX = {
    "partial_slip": (
        PARTIAL_SLIP_RTOL_MAX,
        "its default is 3e-8): beyond it the Mindlin-Deresiewicz cells' events outrun the steps "
        "and e moves by percents",
    ),
    "mindlin": (
        MINDLIN_RTOL_MAX,
        "its default is 2e-7): beyond it the stiff tangential spring outruns the steps and e "
        "moves by tens of percents at shallow angles",
    ),
}


def friction_rtol_max(friction: str) -> float:
    """The largest rtol of the friction model named ``friction`` (inf: the whole range)."""
    cap = _FRICTION_RTOL_MAX.get(friction)
    return math.inf if cap is None else cap[0]


def check_friction_rtol(rtol: float, friction: str) -> float:
    """``rtol`` (checked by ``check_rtol``), refused above the friction model's own cap:
    ``PARTIAL_SLIP_RTOL_MAX`` for ``partial_slip``, ``MINDLIN_RTOL_MAX`` for ``mindlin`` (the
    other models: the whole range). ValueError, one line, naming the model and its cap."""
    if rtol > friction_rtol_max(friction):
        cap, why = _FRICTION_RTOL_MAX[friction]
        raise ValueError(
            f"rtol {rtol:g} is too loose for friction {friction!r} (allowed: up to {cap:g}; {why}"
        )
    return rtol


def check_partial_slip_rtol(rtol: float) -> float:
    """``rtol`` (checked by ``check_rtol``), refused above ``PARTIAL_SLIP_RTOL_MAX`` for the
    rigid partial-slip engine."""
    return check_friction_rtol(rtol, "partial_slip")
