"""A mirrored marker geometry (or a left-handed lab frame) named as such.

A reflection keeps every inter-marker distance, so the distance check of a given geometry passes
a mirrored one. Two signs show it:

* markers not all in one plane (four or more): no rotation maps the geometry onto the measured
  cluster, but its mirror image fits (:func:`check_not_mirrored_shape`);
* three markers (always in one plane, where a rotation does map the mirror image onto them):
  the body frame, and so the centre of mass and the rod's axis, come out mirrored, and e falls
  outside [0, 1]; the same analysis with the geometry mirrored (:func:`mirrored`) then gives
  an e within it (:func:`mirrored_geometry_error`).

The cause is one of two: a body frame written left-handed (one coordinate's sign flipped in the
geometry) or a lab frame of the marker file that is left-handed (one camera axis flipped).
"""

from __future__ import annotations

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.rigid import MarkerGeometry, kabsch
from impactlab.experiment.uncertainty import Estimate

__all__ = ["CAUSE", "check_not_mirrored_shape", "mirrored", "mirrored_geometry_error"]

#: The two causes of a mirrored fit, and what to do.
CAUSE = (
    "the geometry is mirrored (a left-handed body frame: one coordinate's sign flipped) or the "
    "lab frame of the marker file is left-handed (one camera axis flipped); fix the geometry's "
    "signs or the file's axes"
)
#: The reflection that keeps the rod's axis (e1) and the centre of mass.
_REFLECT = np.diag([1.0, 1.0, -1.0])


def mirrored(geometry: MarkerGeometry) -> MarkerGeometry:
    """``geometry`` reflected through the plane of e1 and e2 (its third coordinate negated)."""
    return MarkerGeometry(geometry.markers @ _REFLECT, geometry.labels, geometry.units_note)


def check_not_mirrored_shape(
    measured: np.ndarray, reference: np.ndarray, tolerance: float, src: str
) -> None:
    """MarkerError when the geometry ``reference`` (m, 3) [m] fits the measured cluster shape
    ``measured`` only as its mirror image (Kabsch residual above ``tolerance`` [m] and more than
    three times that of the mirror image); markers in one plane pass (no shape test)."""
    if reference.shape[0] < 4:
        return
    proper = kabsch(reference, measured)[2]
    flipped = kabsch(reference @ _REFLECT, measured)[2]
    if proper > tolerance and flipped < proper / 3.0:
        raise MarkerError(
            f"{src}: the given marker geometry is the mirror image of the markers' layout: the "
            f"distances agree but no rotation maps one onto the other (residual "
            f"{proper * 1e3:.3g} mm; mirrored, {flipped * 1e3:.3g} mm): {CAUSE}"
        )


def e_outside(e: Estimate, sigmas: float) -> bool:
    """True when e lies outside [0, 1] by more than ``sigmas`` of its uncertainty."""
    return e.value < -sigmas * e.sigma or e.value > 1.0 + sigmas * e.sigma


def mirrored_geometry_error(src: str, e: Estimate, e_mirrored: Estimate) -> MarkerError:
    """The error for an e outside [0, 1] that the mirrored geometry brings within it."""
    return MarkerError(
        f"{src}: e = {e:.4g} is outside [0, 1] with the given marker geometry, but "
        f"e = {e_mirrored:.4g} with the geometry mirrored (its third coordinate negated; "
        f"three markers keep every distance in the mirror image, so only the result shows it): "
        f"{CAUSE}"
    )
