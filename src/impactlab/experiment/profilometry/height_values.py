"""Height values that no profilometer scan of a dent can hold: corrupt numbers in the file.

A damaged file (flipped bytes, a wrong data offset) gives a few absurd heights, e.g. 1e176 m,
that would otherwise be taken for a bump (a "sign-flipped" scan) or a dent. They are refused
before the scan is levelled, naming the file. A wrong height unit scales every height alike, so
it is left to the dent plausibility checks, which name the unit.
"""

from __future__ import annotations

import numpy as np

from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.profilometry.heightmap import HeightMap

__all__ = ["check_height_values"]

#: A height farther from the median than this [m] is absurd for any scan of a dent, even with
#: a wrong height unit (1 mm read in nm as metres is 1e6 m).
ABSURD_HEIGHT = 1e7

#: An isolated height at least this many times farther from the median than 99 % of the scan
#: (and over :data:`MIN_SPIKE` [m] from it) is a damaged value, not a feature of the surface.
SPIKE_RATIO = 1e3

#: Smallest distance from the median [m] that counts as a spike (keeps noise-free scans safe).
MIN_SPIKE = 1e-3


def check_height_values(hm: HeightMap) -> None:
    """FileFormatError naming the scan when some heights are implausible: farther than
    :data:`ABSURD_HEIGHT` from the median height, or isolated spikes over :data:`SPIKE_RATIO`
    times farther from it than 99 % of the valid heights [m]."""
    z = hm.z[np.isfinite(hm.z)]
    deviation = np.abs(z - np.median(z))
    typical = float(np.percentile(deviation, 99.0))
    bad = (deviation > ABSURD_HEIGHT) | (
        (deviation > MIN_SPIKE) & (deviation > SPIKE_RATIO * typical)
    )
    if not bad.any():
        return
    worst = float(deviation[bad].max())
    raise FileFormatError(
        hm.source or "scan",
        f"{int(bad.sum())} implausible height value(s), up to {worst:.3g} m from the scan's "
        f"median height while 99 % of the heights lie within {typical:.3g} m of it: no "
        "profilometer scan of a dent holds such heights; the file's numbers look corrupt "
        "(damaged or misread bytes): export the scan again",
    )
