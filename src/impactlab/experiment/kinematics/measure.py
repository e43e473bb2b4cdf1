"""Measure the impact from marker tracks: :func:`measure_impact` (steps in the package docstring).

``measure_impact`` runs the steps in order; each step is one function here or in ``.estimates``:
the marker cluster and its poses, the impact detection, the free-flight segments, the gravity
check, the centre of mass and axis, the impact frame, then the ballistic fits and the propagated
uncertainties (``.estimates``).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.experiment.checks import check_instance
from impactlab.experiment.errors import ExperimentError, MarkerError
from impactlab.experiment.kinematics.body import RodBody, estimated_body, impact_frame
from impactlab.experiment.kinematics.cluster import marker_poses
from impactlab.experiment.kinematics.derive import DERIVED
from impactlab.experiment.kinematics.detect import (
    Impact,
    detect_impact,
    free_flight,
    later_impact_note,
    several_impacts_hint,
)
from impactlab.experiment.kinematics.estimates import (
    DERIVED_UNITS,
    FitFrame,
    check_derived,
    impact_fits,
    plausibility,
    propagated,
)
from impactlab.experiment.kinematics.frame import G0, parse_up, rod_dimensions
from impactlab.experiment.kinematics.gravity import fitted_gravity
from impactlab.experiment.kinematics.impulse import gyration_squared
from impactlab.experiment.kinematics.mirror import (
    E_SIGMAS,
    checked_against_mirror,
)
from impactlab.experiment.kinematics.options import check_kinematics_options
from impactlab.experiment.kinematics.result import ImpactKinematics
from impactlab.experiment.kinematics.tilt import GROSS_TILT
from impactlab.experiment.markers import MarkerTracks
from impactlab.experiment.rigid import MarkerGeometry
from impactlab.experiment.uncertainty import Estimate

__all__ = ["measure_impact"]

#: Fields of :class:`ImpactKinematics` that are one derived quantity of the same name.
_SCALARS = ("t_impact", "angle_in", "angle_out", "spin_in", "spin_out", "e", "mu", "dv_cx", "dv_cy")
#: Fields that are an (x, y) pair of derived quantities.
_PAIRS = {
    "v_c_in": ("v_cx_in", "v_cy_in"),
    "v_c_out": ("v_cx_out", "v_cy_out"),
    "v_tip_in": ("v_tip_x_in", "v_tip_y_in"),
    "v_tip_out": ("v_tip_x_out", "v_tip_y_out"),
}


def _check_markers(tracks: MarkerTracks, src: str) -> None:
    if tracks.n_markers < 3:
        raise MarkerError(
            f"{src}: {tracks.n_markers} markers; at least 3 are needed for the rod's pose"
        )


def _e_error(src: str, e: Estimate, imp: Impact) -> MarkerError:
    """The error for a restitution coefficient outside [0, 1] that no mirrored geometry explains."""
    cannot = "leave the flat faster than it came" if e.value > 1 else "keep moving into the flat"
    return MarkerError(
        f"{src}: e = {e:.4g} is outside [0, 1] by more than {E_SIGMAS:g} sigma: the tip "
        f"cannot {cannot}, so the fits do not describe one impact of the rod (check the marker "
        f"geometry, up= and the impact found at t = {imp.t_ref:.4f} s)"
        f"{several_impacts_hint(imp)}"
    )


def measure_impact(
    tracks: MarkerTracks,
    rod: Any,
    *,
    geometry: MarkerGeometry | None = None,
    up: Any = "+z",
    g: float = G0,
    guard: int = 2,
    window: int = 5,
    max_fit_frames: int = 40,
    min_fit_frames: int = 6,
    rigidity_tolerance: float = 1.0e-3,
    rigidity_window: int = 15,
    max_com_sigma: float = 5.0e-3,
) -> ImpactKinematics:
    """Measure the impact from marker tracks (steps and frame in the package docstring).

    Parameters
    ----------
    tracks : the markers (SI), e.g. from :func:`impactlab.experiment.read_markers`.
    rod : rod-like (``impactlab.bodies.Rod``): its length (L/2 from C to the tip-sphere centre)
        and ``tip_radius`` place the contact point.
    geometry : the markers' positions in the rod's body frame (:class:`MarkerGeometry`); None
        estimates the axis (principal direction of the cluster: markers mounted along the rod,
        checked by the impulse relation) and C (the ballistic body point; needs the rod to turn
        after the impact).
    up : the lab's upward direction ("+z" default, or a 3-vector), normal to the flat.
    g : gravity [m/s^2]. guard : frames on each side of the impact frame left out of the fits.
    window : frames per side for the impact detector. max_fit_frames, min_fit_frames : length
        limits of each free-flight fit. rigidity_tolerance [m], rigidity_window : see
        :func:`check_rigidity`. max_com_sigma [m] : largest acceptable uncertainty of an estimated
        centre of mass along the rod axis.

    Raises :class:`MarkerError` subclasses naming the problem (loose markers, no impact, too few
    free-flight frames, a free fall far from g, geometry that does not fit, a mirrored geometry,
    an estimated one that breaks the impulse relation: markers not laid out along the rod, e
    outside [0, 1]); TypeError or ValueError naming an option of the wrong kind or range.
    """
    check_instance(tracks, MarkerTracks, "tracks", "read them with read_markers()")
    opts = check_kinematics_options(
        {
            "g": g,
            "guard": guard,
            "window": window,
            "max_fit_frames": max_fit_frames,
            "min_fit_frames": min_fit_frames,
            "rigidity_tolerance": rigidity_tolerance,
            "rigidity_window": rigidity_window,
            "max_com_sigma": max_com_sigma,
        }
    )
    if geometry is not None:
        check_instance(geometry, MarkerGeometry, "geometry", "e.g. MarkerGeometry.from_mapping()")
    src = tracks.source or "marker tracks"
    half, R_tip = rod_dimensions(rod)
    upv = parse_up(up)
    _check_markers(tracks, src)
    k, imp = _measure(tracks, (half, R_tip), geometry, upv, opts, src)
    try:
        return checked_against_mirror(
            k,
            geometry,
            gyration_squared(rod),
            lambda geo: _measure(tracks, (half, R_tip), geo, upv, opts, src)[0],
            src,
            lambda: _e_error(src, k.e, imp),
        )
    except ExperimentError as exc:  # the warnings of the measurement it refuses are kept
        exc.warnings = k.warnings
        raise


def _measure(
    tracks: MarkerTracks,
    rod: tuple[float, float],
    geometry: MarkerGeometry | None,
    upv: np.ndarray,
    opts: dict[str, Any],
    src: str,
) -> tuple[ImpactKinematics, Impact]:
    """The steps of :func:`measure_impact` (``rod``: its half length and tip radius [m]; the
    options checked) and the impact found; an :class:`ExperimentError` carries the warnings
    found before it (``warnings``)."""
    warnings: list[str] = []
    try:
        return _steps(tracks, rod, geometry, upv, opts, src, warnings)
    except ExperimentError as exc:
        exc.warnings = (*warnings, *exc.warnings)
        raise


def _steps(
    tracks: MarkerTracks,
    rod: tuple[float, float],
    geometry: MarkerGeometry | None,
    upv: np.ndarray,
    opts: dict[str, Any],
    src: str,
    warnings: list[str],
) -> tuple[ImpactKinematics, Impact]:
    """:func:`_measure`'s steps, their warnings into ``warnings``."""
    half, R_tip = rod
    g, guard, min_fit = opts["g"], opts["guard"], opts["min_fit_frames"]
    reference, rigidity, poses, ok = marker_poses(
        tracks,
        geometry,
        opts["rigidity_tolerance"],
        opts["rigidity_window"],
        min_fit,
        src,
        rod_length=2.0 * half,
        upv=upv,
        g=g,
        warnings=warnings,
    )
    imp = detect_impact(poses, ok, reference, upv, g, opts["window"], src)
    t_ref = imp.t_ref
    note = later_impact_note(imp)
    warnings += [note] if note else []
    # the time base, the length unit and up= first, from a free fall fitted without g
    falling = ok[ok <= imp.k_star - guard]  # all the record holds: grown back from the impact
    lever = 0.0 if geometry is not None else half + float(np.ptp(reference, axis=0).max())
    doubts: list[str] = []
    fitted_g = fitted_gravity(poses, falling, t_ref, upv, g, src, warnings, lever, doubts)
    used = tracks if geometry is None or geometry.labels is None else tracks.select(geometry.labels)
    pre_fr, post_fr = free_flight(poses, ok, imp, opts, src, used)
    if geometry is not None:
        body = RodBody(np.zeros(3), np.array([1.0, 0.0, 0.0]), None, "given")
    else:  # (a free fall far from g, which spoils the fits, was refused by fitted_gravity)
        body = estimated_body(
            poses, reference, pre_fr, post_fr, t_ref, upv, g, opts["max_com_sigma"], src
        )
        warnings.append(
            "geometry estimated: the rod's axis is taken as the markers' principal direction, "
            "which holds only for markers laid out along the rod (checked, for a rod with an "
            f"inertia, by the tilt the impulse relation implies: beyond "
            f"{math.degrees(GROSS_TILT):.0f} deg refused, a smaller one or one it cannot tell "
            "marks the result not ok); the +- of "
            "e, mu and the angle does not include that assumption (give the "
            "marker geometry to remove it)"
        )
    axes, origin = impact_frame(poses, int(pre_fr[-1]), body, upv, src)
    fm = FitFrame(poses, axes, origin, t_ref, g, half, R_tip)
    pre, post, body = impact_fits(fm, pre_fr, post_fr, body, upv, min_fit, src, warnings)
    y, cov_y, notes = propagated(fm, pre, post, body)
    warnings += notes
    check_derived(y, src)
    sig = np.sqrt(np.clip(np.diag(cov_y), 0.0, None))
    E_ = {n: Estimate(v, s, u_) for n, v, s, u_ in zip(DERIVED, y, sig, DERIVED_UNITS, strict=True)}
    tilt = plausibility(E_, poses, pre, body.axis, axes[2], warnings)
    estimates: dict[str, Any] = {name: E_[name] for name in _SCALARS}
    estimates.update({name: (E_[a], E_[b]) for name, (a, b) in _PAIRS.items()})
    kin = ImpactKinematics(
        **estimates,
        v_c_z_in=E_["v_cz_in"],
        v_c_z_out=E_["v_cz_out"],
        **_geometry(fm, body),
        impact_frame=imp.k_star,
        pre=pre,
        post=post,
        derived_names=DERIVED,
        derived_values=y,
        derived_cov=cov_y,
        rigidity=rigidity,
        fitted_gravity=fitted_g,
        tilt_out_of_plane=tilt,
        poses=poses,
        warnings=tuple(warnings),
        doubts=tuple(doubts),
    )
    return kin, imp


def _geometry(fm: FitFrame, body: RodBody) -> dict[str, Any]:
    """The fields of :class:`ImpactKinematics` that place the rod and the impact frame."""
    return {
        "t_ref": fm.t_ref,
        "gravity": fm.g,
        "half_length": fm.half,
        "tip_radius": fm.R_tip,
        "frame_axes": fm.axes,
        "origin": fm.origin,
        "com_body": body.com,
        "axis_body": body.axis,
        "geometry_source": body.source,
    }
