"""A mirrored marker geometry (or a left-handed lab frame) named as such.

A reflection keeps every inter-marker distance, so the distance check of a given geometry passes
a mirrored one. Two signs show it:

* markers not all in one plane (four or more): no rotation maps the geometry onto the measured
  cluster, but its mirror image fits (:func:`check_not_mirrored_shape`);
* three markers (always in one plane, where a rotation does map the mirror image onto them):
  the body frame, and so the centre of mass and the rod's axis, come out mirrored: the measured
  spin change then disagrees with the one the change of the centre of mass's velocity implies
  (the rigid-body impulse relation, :mod:`.impulse`), or e falls outside [0, 1]. The same
  analysis with the geometry mirrored (:func:`mirrored`) then satisfies the relation, with an
  e within [0, 1] (:func:`checked_against_mirror`). Where both geometries satisfy it (shallow
  angles, where the mirror moves C little) nothing is said.

The cause is one of two: a body frame written left-handed (one coordinate's sign flipped in the
geometry) or a lab frame of the marker file that is left-handed (one camera axis flipped).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.kinematics.gravity import FALL_DOUBT
from impactlab.experiment.kinematics.impulse import (
    IMPULSE_SIGMAS,
    IMPULSE_TOLERANCE,
    ImpulseCheck,
    impulse_check,
)
from impactlab.experiment.kinematics.result import ImpactKinematics
from impactlab.experiment.kinematics.tilt import (
    GROSS_TILT,
    INERTIA_OFF,
    K2_RELATIVE,
    TiltCheck,
    tilt_check,
)
from impactlab.experiment.rigid import MarkerGeometry, kabsch
from impactlab.experiment.uncertainty import Estimate, fixed

__all__ = [
    "CAUSE",
    "E_SIGMAS",
    "E_WARN_SIGMAS",
    "NO_INERTIA",
    "check_not_mirrored_shape",
    "checked_against_mirror",
    "e_outside",
    "given_geometry_note",
    "mirrored",
    "mirrored_geometry_error",
]

#: e outside [0, 1] by more than this many of its sigmas is refused ...
E_SIGMAS = 3.0
#: ... and by more than this many (but not E_SIGMAS) draws a warning.
E_WARN_SIGMAS = 2.0

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


def _angle(k: ImpactKinematics) -> str:
    return f"{math.degrees(k.angle_in.value):.1f} deg"


def mirrored_impulse_error(
    src: str, k: ImpactKinematics, own: ImpulseCheck, flipped: ImpactKinematics, fl: ImpulseCheck
) -> MarkerError:
    """The error for a given geometry that breaks the impulse relation while its mirror image
    satisfies it."""
    return MarkerError(
        f"{src}: with the given marker geometry the velocity changes break the rigid-body "
        f"impulse relations (k^2 dw = b dv_Cx - a dv_Cy, a turn perpendicular to the rod): "
        f"{own.text()}; e = {k.e:.4g}, angle {_angle(k)}; but with the geometry mirrored (its "
        f"third coordinate negated) they hold: {fl.text()}; e = {flipped.e:.4g}, angle "
        f"{_angle(flipped)}; three markers keep every distance in the mirror image, so only the "
        f"motion shows it: {CAUSE}"
    )


def _read(k: ImpactKinematics) -> str:
    return f"angle {_angle(k)}, e = {k.e:.4g}, mu = {k.mu:.4g}"


def _tilt(k: ImpactKinematics, check: TiltCheck) -> str:
    """The implied tilt, with the angle it implies."""
    if math.isnan(check.tilt):
        return check.text()
    angle = math.degrees(k.angle_in.value + check.tilt)
    return f"{check.text()} (a rod's angle of {angle:.1f} deg)"


#: What to do about an estimated geometry in doubt.
_GIVE_GEOMETRY = (
    "give the marker geometry (impactlab analyze --geometry markers.toml; geometry= in Python)"
)


def estimated_geometry_error(src: str, k: ImpactKinematics, check: TiltCheck) -> MarkerError:
    """The error for an estimated geometry whose motion implies a gross tilt of the rod's axis
    (:mod:`.tilt`): the markers are not laid out along the rod."""
    return MarkerError(
        f"{src}: with the marker geometry estimated (the rod's axis taken as the markers' "
        f"principal direction) the rigid-body impulse relation (k^2 dw = b dv_Cx - a dv_Cy) "
        f"holds only with the rod's axis tilted {_tilt(k, check)} from it (more than "
        f"{math.degrees(GROSS_TILT):.0f} deg): either the markers are not laid out along the "
        f"rod, and what was read ({_read(k)}) is then wrong, or the rod's inertia k^2 = I/m "
        f"is off by far more than {100 * K2_RELATIVE:.0f} %; {_GIVE_GEOMETRY}, or check the "
        f"rod's inertia (Rod.inertia, the marker mounts included)"
    )


#: The doubt of an estimated geometry that the tilt check could not judge.
NO_INERTIA = (
    "the marker geometry is in doubt: the tilt check did not run: the rod has no inertia "
    "(k^2 = I/m), so markers not laid out along the rod would go unseen; give the rod's inertia "
    "(Rod.inertia) or the marker geometry (impactlab analyze --geometry markers.toml; geometry= "
    "in Python)"
)


def estimated_geometry_note(k: ImpactKinematics, check: TiltCheck) -> str | None:
    """The warning that marks a result with an estimated geometry not ok: a small tilt of the
    rod's axis that the impulse relation implies, or a check that cannot tell a gross one from
    none; None when it passes."""
    verdict = check.verdict
    if verdict == "tilted":
        return (
            f"the marker geometry is in doubt: with it estimated (the rod's axis taken as the "
            f"markers' principal direction) the impulse relation implies the rod's axis tilted "
            f"{_tilt(k, check)} from it: markers off the rod's axis, which bias what was read "
            f"({_read(k)}) beyond its +-, or the rod's inertia k^2 = I/m off by more than "
            f"{100 * K2_RELATIVE:.0f} %; {_GIVE_GEOMETRY}"
        )
    if verdict == "inertia":
        return (
            f"the marker geometry is in doubt: with it estimated (the rod's axis taken as the "
            f"markers' principal direction) the impulse relation implies the rod's axis tilted "
            f"{_tilt(k, check)} from it, or holds with the rod's inertia k^2 = I/m "
            f"{100 * INERTIA_OFF:.0f} % off: markers not laid out along the rod, which make what "
            f"was read ({_read(k)}) wrong, or an inertia that is off; check the rod's inertia "
            f"(Rod.inertia, the marker mounts included) or {_GIVE_GEOMETRY}"
        )
    if verdict == "undecided":
        return (
            f"the marker geometry is in doubt: with it estimated (the rod's axis taken as the "
            f"markers' principal direction) the impulse relation implies the rod's axis tilted "
            f"{_tilt(k, check)} from it, too uncertain to tell a tilt of "
            f"{math.degrees(GROSS_TILT):.0f} deg from none (a shallow angle, where the rod's "
            f"inertia k^2 = I/m, known to {100 * K2_RELATIVE:.0f} %, weighs most, a slow camera "
            f"or noisy markers), so what was read ({_read(k)}) is unchecked; {_GIVE_GEOMETRY}"
        )
    return None


def given_geometry_note(k: ImpactKinematics, own: ImpulseCheck) -> str:
    """The doubt of a given geometry that breaks the impulse relation while its mirror image
    does not help: C or the rod's axis misplaced in it, or an inertia that is off."""
    rolled = "" if own.axis_agrees else ", or the rod rolled about its axis at the impact"
    check = "check the geometry's origin and axes"
    if any(d.startswith(FALL_DOUBT) for d in k.doubts) and k.fitted_gravity is not None:
        # the free fall is off g too: the fits that take g break the relation as well
        rolled += (
            f", or the time base (the frame rate) or the length unit is off (the free fall "
            f"before the impact accelerates at {k.fitted_gravity:.4g} m/s^2, not "
            f"g = {k.gravity:.4g} m/s^2, and the fits that take g then break the relation)"
        )
        check = (
            "check the frame rate and the marker units first, then the geometry's origin and axes"
        )
    return (
        f"the marker geometry is in doubt: with it the velocity changes break the rigid-body "
        f"impulse relation (k^2 dw = b dv_Cx - a dv_Cy, a turn perpendicular to the rod): "
        f"{own.text()}, beyond {IMPULSE_SIGMAS:g} sigma and {100 * IMPULSE_TOLERANCE:g} %; "
        f"what was read ({_read(k)}) is then biased: the centre of mass C or the rod's axis is "
        f"misplaced in the geometry (marker positions measured from another origin or in a "
        f"rotated frame: a shift along the rod or a turn keeps every distance), the rod's "
        f"inertia k^2 = I/m is off by more than {100 * IMPULSE_TOLERANCE:g} % (Rod.inertia, the "
        f"marker mounts included){rolled}; {check}"
    )


def _e_note(e: Estimate) -> str | None:
    """A warning for an e outside [0, 1] by more than ``E_WARN_SIGMAS`` (and not ``E_SIGMAS``)."""
    if not e_outside(e, E_WARN_SIGMAS):
        return None
    below = e.value < 0.0
    n = (-e.value if below else e.value - 1.0) / e.sigma if e.sigma > 0 else math.inf
    where = "below 0" if below else "above 1"
    cannot = "keep moving into the flat" if below else "leave the flat faster than it came"
    return (
        f"e = {e:.4g} lies {fixed(n)} sigma {where} (the tip cannot {cannot}; accepted as noise "
        f"within {E_SIGMAS:g} sigma): check the marker geometry (a mirrored one), up= and the "
        "impact found"
    )


def _axis_note(
    k: ImpactKinematics, own: ImpulseCheck, flipped: ImpactKinematics, fl: ImpulseCheck
) -> str:
    """The warning for a turn off the perpendicular to the rod that the mirrored geometry
    removes, while the spin change agrees with the impulse either way."""
    return (
        f"with the given marker geometry the rod turns at the impact about an axis "
        f"{fixed(own.axis_degrees)} deg off the perpendicular to it, with the geometry mirrored "
        f"(its third coordinate negated) {fixed(fl.axis_degrees)} deg: the geometry may be "
        f"mirrored (three markers keep every distance in the mirror image), or the rod rolled "
        f"about its axis at the impact (a tip sliding sideways); e = {k.e:.4g} and the angle "
        f"{_angle(k)} hold for the given geometry only, and the mirrored one gives e = "
        f"{flipped.e:.4g} and {_angle(flipped)} (a mirror comes from a geometry written "
        f"left-handed, one coordinate's sign flipped, or a marker file whose lab frame is "
        f"left-handed, one camera axis flipped)"
    )


def checked_against_mirror(
    k: ImpactKinematics,
    geometry: MarkerGeometry | None,
    k2: float | None,
    remeasure: Callable[[MarkerGeometry], ImpactKinematics],
    src: str,
    e_error: Callable[[], MarkerError],
) -> ImpactKinematics:
    """``k`` checked for a mirrored geometry (module docstring) and for e in [0, 1].

    With a given ``geometry`` that breaks an impulse relation (``k2`` = I_C / m [m^2]; None
    skips them) or gives an e outside [0, 1] by more than ``E_SIGMAS``, the analysis is repeated
    with the geometry mirrored (``remeasure``). When that one satisfies both relations with an e
    within [0, 1]: the mirrored-geometry error for a bad e or a spin change that disagrees with
    the impulse; a warning for a turn off the perpendicular to the rod only (a rod that rolls
    about its axis at the impact breaks that relation too). Otherwise an e outside [0, 1] by
    more than ``E_SIGMAS`` is ``e_error()``, by more than ``E_WARN_SIGMAS`` a warning; a given
    geometry that breaks an impulse relation with no mirror to explain it marks ``k`` not ok
    (:func:`given_geometry_note`); ``k`` is returned with the warnings. Without a ``geometry``
    (estimated), the tilt of the rod's axis that the impulse relation implies (:mod:`.tilt`): a
    gross one is :func:`estimated_geometry_error`, a small one or an undecided check marks
    ``k`` not ok (:func:`estimated_geometry_note`, in ``k.doubts`` and the warnings); without
    ``k2`` the check cannot run, which marks ``k`` not ok too (``NO_INERTIA``)."""
    doubts: list[str] = []
    if geometry is None and k2 is not None:
        estimated = tilt_check(k, k2)
        if estimated.verdict == "gross":
            raise estimated_geometry_error(src, k, estimated)
        doubt = estimated_geometry_note(k, estimated)
        doubts += [doubt] if doubt else []
    elif geometry is None:
        doubts.append(NO_INERTIA)
    bad_e = e_outside(k.e, E_SIGMAS)
    own = impulse_check(k, k2) if geometry is not None and k2 is not None else None
    notes: list[str] = []
    if geometry is not None and (bad_e or (own is not None and not own.consistent)):
        try:
            flipped: ImpactKinematics | None = remeasure(mirrored(geometry))
        except ValueError:  # the mirrored geometry does not fit either
            flipped = None
        if flipped is not None and not e_outside(flipped.e, E_SIGMAS):
            fl = impulse_check(flipped, k2) if k2 is not None else None
            if fl is None or fl.consistent:
                if bad_e:
                    raise mirrored_geometry_error(src, k.e, flipped.e)
                if own is not None and fl is not None:
                    if not own.spin_agrees:
                        raise mirrored_impulse_error(src, k, own, flipped, fl)
                    notes.append(_axis_note(k, own, flipped, fl))
    if bad_e:
        raise e_error()
    if own is not None and not own.consistent and not notes:
        doubts.append(given_geometry_note(k, own))
    note = _e_note(k.e)
    notes += [note] if note else []
    if not notes and not doubts:
        return k
    return dataclasses.replace(
        k, warnings=(*k.warnings, *doubts, *notes), doubts=(*k.doubts, *doubts)
    )
