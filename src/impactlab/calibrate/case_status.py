"""The status codes a calibration gives its cases beyond the engine's and the sweep's (a result
flagged as no prediction of the drop, a case ``simulate`` refused), and what every status means."""

from __future__ import annotations

from impactlab.dynamics.kernels.status import STATUS_MESSAGES
from impactlab.flags import (
    FLAG_BEYOND_TIP,
    FLAG_BRITTLE,
    FLAG_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED,
    FLAG_OTHER_END,
)
from impactlab.sweep.status import SWEEP_STATUS_MESSAGES

__all__ = ["STATUS_ENERGY_GAIN", "STATUS_FLAGGED", "STATUS_REFUSED", "status_message"]

#: Status of a case that ran but broke physics (energy gain): a likelihood of zero.
STATUS_ENERGY_GAIN = 301
#: Status of a partial-slip case that ``simulate`` refused.
STATUS_REFUSED = 302
#: Status of a case flagged by another invalidating flag (``impactlab.flags``: not ``ok``), by
#: flag, in bit order: its outputs are not a prediction of the drop, a likelihood of zero.
STATUS_FLAGGED = {
    FLAG_ENERGY_GAIN: STATUS_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED: 303,
    FLAG_OTHER_END: 304,
    FLAG_BEYOND_TIP: 305,
    FLAG_BRITTLE: 306,
}
_OWN_MESSAGES = {
    STATUS_ENERGY_GAIN: "result flagged ENERGY_GAIN (breaks energy conservation)",
    STATUS_REFUSED: "simulate refused the case (or the drop failed)",
    303: "result flagged GRAVITY_DOMINATED (e and the impact measures not meaningful)",
    304: "result flagged OTHER_END (the other end landed: not one bounce of the tip)",
    305: "result flagged BEYOND_TIP (the flat reached the rim of the tip)",
    306: "result flagged BRITTLE (a brittle member past first yield)",
}


def status_message(code: int) -> str:
    """What a case status means (engine, sweep and calibration codes)."""
    code = int(code)
    return (
        _OWN_MESSAGES.get(code)
        or SWEEP_STATUS_MESSAGES.get(code)
        or STATUS_MESSAGES.get(code)
        or f"status {code}"
    )
