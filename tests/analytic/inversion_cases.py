"""Inversions shared by the tests of the inversion."""

from __future__ import annotations

import math
from typing import Any

#: mu's sigma reaches mu_c, so Monte Carlo samples are discarded (a warning), and T's
#: distribution has a heavy tail (another).
WIDE: dict[str, Any] = dict(
    angle=math.radians(20),
    v_i=-1.41,
    e=0.5,
    mu=(0.70, 0.05),
    delta_p=22e-6,
    sliding_length=1400e-6,
)

#: The paper's 20 deg drop (SI), the dent as magnitudes.
PAPER_20: dict[str, Any] = dict(
    angle=math.radians(20),
    v_i=-1.41,
    e=0.5,
    mu=0.2,
    delta_p=22e-6,
    sliding_length=1400e-6,
)
