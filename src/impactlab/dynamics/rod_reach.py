"""Where a rigid rod's impact leaves the model of a hemispherical tip on a flat: the flat reaches
the rim of the tip (``ResultFlag.BEYOND_TIP``), or the rod's other end reaches the flat
(``ResultFlag.OTHER_END``). Pure functions of an impact's inputs and outputs, for ``simulate``,
batches and sweeps alike (floats or arrays).

Geometry (the rod's axis at angle theta to the flat; tip and other end: spheres of radius R
whose centres lie L = 2 ``half_length`` apart on the axis; delta: the interference):

- the tip's hemisphere ends at the plane through its centre normal to the axis; that rim's
  lowest point lies R |cos theta| below the centre, R (1 - |cos theta|) above the tip's
  lowest point, so the flat, delta above the lowest point, reaches the rim when
  delta > R (1 - |cos theta|);
- the other end's lowest point lies L sin theta - delta above the flat.

theta changes during the contact: the criteria take, of the angles at first touch and at
separation, the one that puts the rim or the other end nearer to the flat (theta moves one
way during most contacts; the check is then exact at its ends and conservative by at most the
rotation within the contact), with the largest interference delta_max.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.dynamics.kernels.quality import beyond_rim
from impactlab.flags import FLAG_BEYOND_TIP, FLAG_OTHER_END

#: The compiled engines' rim criterion as plain Python (the same comparison).
_beyond_rim = getattr(beyond_rim, "py_func", beyond_rim)  # a function under NUMBA_DISABLE_JIT

__all__ = ["rod_reach_bits", "rod_reach_flags"]


def rod_reach_bits(
    half_length: float, radius: float, angle: float, angle_out: float, delta_max: float
) -> int:
    """The BEYOND_TIP and OTHER_END bits of one rigid rod's impact: ``half_length`` L/2 and
    ``radius`` R [m], the angles to the flat at first touch and at separation [rad] and the
    largest interference [m] (``rod_reach_flags`` for arrays, the same comparisons); 0 where
    an input is NaN."""
    sin_low = min(math.sin(angle), math.sin(angle_out))
    bits = FLAG_BEYOND_TIP if _beyond_rim(radius, angle, angle_out, delta_max) else 0
    if 2.0 * half_length * sin_low <= delta_max:
        bits |= FLAG_OTHER_END
    return bits


def rod_reach_flags(
    half_length: Any, radius: Any, angle: Any, angle_out: Any, delta_max: Any
) -> np.ndarray:
    """``rod_reach_bits`` over arrays (broadcast; int64): batches and sweeps."""
    with np.errstate(invalid="ignore"):
        cos_far = np.maximum(np.abs(np.cos(angle)), np.abs(np.cos(angle_out)))
        sin_low = np.minimum(np.sin(angle), np.sin(angle_out))
        beyond = np.asarray(delta_max > radius * (1.0 - cos_far))
        other = np.asarray(2.0 * np.asarray(half_length) * sin_low <= delta_max)
    return (np.where(beyond, FLAG_BEYOND_TIP, 0) | np.where(other, FLAG_OTHER_END, 0)).astype(
        np.int64
    )
