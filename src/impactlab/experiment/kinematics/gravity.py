"""Gravity in the marker data: the free fall before the impact checks the time base, the length
unit and the up direction before any fit that assumes g (a step of
:func:`~impactlab.experiment.kinematics.measure_impact`).

The fall is fitted with a free acceleration (a quadratic in time per coordinate) over all the
free flight the record holds before the impact: grown backwards from the impact while the frames
agree with it (a wrong sample is skipped; a hold before the release, or an earlier bounce, ends
it), so that the check depends neither on g nor on the segments of the ballistic fits: a wrong
time base is named as such, not as too few free-flight frames. A fall too short or too noisy to
check the time base, or to check it to ``GRAVITY_TOLERANCE``, is reported as a warning that says
why and what the results then rest on.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.kinematics.fits import grow_segment
from impactlab.experiment.rigid import Poses
from impactlab.experiment.uncertainty import fixed

__all__ = [
    "FALL_DOUBT",
    "GRAVITY_SIGMAS",
    "GRAVITY_TOLERANCE",
    "LOCAL_G",
    "TILT_WARN_DEG",
    "fitted_gravity",
    "suggested_up",
]

#: A tilt of the camera's vertical from the fitted gravity [deg] beyond which a warning says so.
TILT_WARN_DEG = 2.0
#: A free fall whose acceleration differs from g by more than this fraction of g ...
GRAVITY_TOLERANCE = 0.10
#: ... and by more than this many of its standard uncertainties is refused.
GRAVITY_SIGMAS = 4.0
#: A free fall within the refusal's bounds whose acceleration still differs from g by more than
#: ``GRAVITY_SIGMAS`` of its uncertainty plus this fraction of g (and the centripetal allowance)
#: marks the result not ok: g varies by 0.5 % over the Earth (9.78-9.83 m/s^2 with latitude and
#: height), where a frame rate 2 % off moves the fitted fall by 4 % (and mu by about 4 %).
LOCAL_G = 0.005
#: How the doubt of a free fall off g begins (:func:`fitted_gravity`).
FALL_DOUBT = "the time base or the length unit is in doubt"
#: The free-fall fit starts from the ``FALL_START`` frames nearest the impact and grows backwards
#: over the free flight; fewer than ``MIN_FALL_FRAMES`` in all give no check (a warning).
FALL_START = 12
MIN_FALL_FRAMES = 8
#: A fit whose acceleration is uncertain by more than this fraction of g checks nothing (a
#: warning).
MAX_FALL_SIGMA = 0.2


def suggested_up(measured_up: np.ndarray, exact: bool = False, sigma_deg: float = 0.0) -> str:
    """The ``up=`` argument for the measured upward unit vector: the camera axis it lies along
    (within ``TILT_WARN_DEG``, the tilt that draws a warning, or 3 of the direction's
    uncertainty ``sigma_deg``), e.g. ``up='+z'``, else (and with ``exact``) the vector itself,
    with the command line's form."""
    k = int(np.argmax(np.abs(measured_up)))
    within = math.radians(max(TILT_WARN_DEG, 3.0 * sigma_deg))
    if not exact and abs(measured_up[k]) >= math.cos(within):
        axis = f"{'+' if measured_up[k] > 0 else '-'}{'xyz'[k]}"
        return f"up='{axis}' (impactlab analyze --up {axis})"
    text = ", ".join(f"{v:.3f}" for v in measured_up)
    return f"up=({text}) (impactlab analyze --up '{text}')"


def _free_fall(
    poses: Poses, fr: np.ndarray, t_ref: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(acceleration (3,) [m/s^2], the variance of each of its coordinates, the frames used): a
    free quadratic fit of the cluster origin, grown backwards from the impact. A rod held
    still before its release departs from the fall's parabola only slowly near its apex (the
    release), so the frames before the fitted apex, where the fall would rise, are left out."""
    order = fr[::-1]
    tau = poses.time[order] - t_ref
    A_all = np.column_stack([np.ones_like(tau), tau, 0.5 * tau * tau])
    D = poses.translation[order]
    n0 = min(FALL_START, order.size)
    keep = np.array(grow_segment(A_all, D, n0, 5.0, np.full(3, 1e-12)))
    for _ in range(3):  # a hold before the release: only the falling side of the apex
        coef, *_ = np.linalg.lstsq(A_all[keep], D[keep], rcond=None)
        falling = (coef[1] + np.outer(tau[keep], coef[2])) @ coef[2] > 0.0
        if falling.all() or falling.sum() < MIN_FALL_FRAMES:
            break
        keep = keep[falling]
    A, X = A_all[keep], D[keep]
    coef, *_ = np.linalg.lstsq(A, X, rcond=None)
    E = X - A @ coef
    s2 = np.sum(E * E, axis=0) / max(len(keep) - 3, 1)
    var_a = np.linalg.inv(A.T @ A)[2, 2] * s2
    return coef[2], var_a, np.sort(order[keep])


def _turn_rate(poses: Poses, fr: np.ndarray) -> float:
    """The rod's mean rate of turn over the frames ``fr`` [rad/s]."""
    R = poses.rotation[fr[0]].T @ poses.rotation[fr[-1]]
    angle = math.acos(max(-1.0, min(1.0, 0.5 * (float(np.trace(R)) - 1.0))))
    return angle / max(float(poses.time[fr[-1]] - poses.time[fr[0]]), 1e-12)


def _time_base_error(src: str, fitted: float, sig: float, g: float) -> MarkerError:
    ratio = fitted / g
    stretch = math.sqrt(g / fitted) if fitted > 0 else math.inf
    if stretch > 1:
        ms = ", milliseconds read as seconds?" if 500.0 < stretch < 2000.0 else ""
        as_if = f" (as if the times were {stretch:.3g} times too long{ms})"
    else:
        as_if = f" (as if the times were {1 / stretch:.3g} times too short)"
    return MarkerError(
        f"{src}: the free fall before the impact accelerates at {fitted:.3g} ± {sig:.2g} "
        f"m/s^2, {ratio:.3g} times g = {g:.4g} m/s^2{as_if}: the time base or the length unit "
        "is wrong (check the frame rate: a C3D's POINT:RATE or a CSV's '# rate:' line; the "
        "time column's unit, seconds; and the marker units); e and mu cannot be measured "
        "from it"
    )


def _off_g(fitted: float, sig: float, g: float, bound: float, centripetal: float) -> str:
    """The doubt of a free fall that differs from ``g`` by more than ``bound`` [m/s^2] (within
    the refusal's)."""
    rate = math.sqrt(g / fitted) if fitted > 0 else math.inf  # times read s too long: g / s^2
    turn = f" and {centripetal:.2g} m/s^2 for the rod's turn" if centripetal > 0 else ""
    return (
        f"{FALL_DOUBT}: the free fall before the impact accelerates at {fitted:.4g} ± "
        f"{sig:.2g} m/s^2, {(fitted - g) / g:+.1%} from g = {g:.4g} m/s^2, beyond "
        f"{GRAVITY_SIGMAS:g} sigma plus {LOCAL_G:.1%} of g (g's variation over the Earth){turn} "
        f"= {bound:.2g} m/s^2: as if the camera's frame rate were {rate:.4g} times the one read "
        "(a C3D's POINT:RATE, a CSV's '# rate:' line or its time column), or the marker "
        f"lengths were read {fitted / g:.4g} times their size (the length unit); the "
        "velocities, e, mu and the fits that take g are biased by it "
        "(a frame rate 2 % off moves mu by about 4 %); check the camera's frame rate and the "
        "marker units"
    )


def _unchecked(why: str) -> str:
    """The warning for a time base that the free fall cannot check."""
    return (
        f"the time base and the length unit are not checked: {why}; e, v_i and every velocity "
        "then rest on the record's frame rate (a C3D's POINT:RATE, a CSV's '# rate:' line or "
        "its time column, in seconds) and marker units being right (a time base 10 % off "
        "moves the velocities by 10 %)"
    )


def _weak(
    used: np.ndarray, poses: Poses, fitted: float, sig: float, allowed: float, g: float
) -> str:
    """The warning for a fall that checks the time base less closely than GRAVITY_TOLERANCE."""
    span = float(poses.time[used[-1]] - poses.time[used[0]])
    off = 50.0 * allowed / g  # a time base off by s moves the acceleration by about 2 s
    return (
        f"the time base is checked only roughly: the free fall before the impact ({used.size} "
        f"frames over {span * 1e3:.3g} ms) accelerates at {fitted:.3g} ± {sig:.2g} m/s^2, so a "
        f"frame rate or time column off by up to about {fixed(off)} % would pass unseen (a longer "
        "record before the impact checks it closely); e, v_i and every velocity rest on it "
        "being right"
    )


def fitted_gravity(
    poses: Poses,
    fr: np.ndarray,
    t_ref: float,
    upv: np.ndarray,
    g: float,
    src: str,
    warnings: list[str],
    lever: float = 0.0,
    doubts: list[str] | None = None,
) -> float | None:
    """The free fall before the impact (the frames ``fr`` before it, in time order) fitted
    with a free acceleration: its magnitude [m/s^2] (None, with a warning, for a fall too short
    or too noisy to check; a warning too for one that checks the time base only roughly).

    MarkerError when the acceleration differs from ``g`` by more than ``GRAVITY_TOLERANCE`` of
    it and ``GRAVITY_SIGMAS`` of its uncertainty (a wrong time base or length unit), or when it
    points more than 25 deg away from -``up``; a warning for a smaller tilt beyond its noise.
    ``lever`` [m]: the largest distance of the fitted point (the cluster origin) from the centre
    of mass, 0 when it is the centre of mass (a given geometry): a turning rod's centripetal
    acceleration there is allowed for. A fall that passes but differs from ``g`` by more than
    ``GRAVITY_SIGMAS`` of its uncertainty plus ``LOCAL_G`` of g (and that allowance) is a doubt
    (into ``doubts`` and ``warnings``): a frame rate or length unit a few percent off."""
    if fr.size < MIN_FALL_FRAMES:
        span = float(poses.time[fr[-1]] - poses.time[fr[0]]) if fr.size > 1 else 0.0
        warnings.append(
            _unchecked(
                f"the record holds only {fr.size} frames ({span * 1e3:.3g} ms) of free fall "
                f"before the impact, fewer than {MIN_FALL_FRAMES}",
            )
        )
        return None
    a, var_a, used = _free_fall(poses, fr, t_ref)
    if used.size < MIN_FALL_FRAMES:
        warnings.append(
            _unchecked(
                f"only {used.size} frames before the impact fall freely (fewer than "
                f"{MIN_FALL_FRAMES}; the rest is held, or bounces)",
            )
        )
        return None
    fitted_g = float(np.linalg.norm(a))
    down = a / fitted_g if fitted_g > 0 else -upv
    sig_a = float(np.sqrt(np.sum(down * down * var_a)))  # the magnitude's (along a)
    if not sig_a < MAX_FALL_SIGMA * max(g, fitted_g):
        span = float(poses.time[used[-1]] - poses.time[used[0]])
        warnings.append(
            _unchecked(
                f"the free fall before the impact ({used.size} frames over {span * 1e3:.3g} ms)"
                f" gives the acceleration only to ± {sig_a:.2g} m/s^2, more than "
                f"{MAX_FALL_SIGMA:g} g (too short a fall for the markers' noise)",
            )
        )
        return None
    centripetal = _turn_rate(poses, used) ** 2 * lever
    allowed = max(GRAVITY_TOLERANCE * g, GRAVITY_SIGMAS * sig_a, centripetal)
    if abs(fitted_g - g) > allowed:
        raise _time_base_error(src, fitted_g, sig_a, g)
    if allowed > GRAVITY_TOLERANCE * g and GRAVITY_SIGMAS * sig_a >= centripetal:
        warnings.append(_weak(used, poses, fitted_g, sig_a, allowed, g))
    bound = GRAVITY_SIGMAS * sig_a + LOCAL_G * g + centripetal
    if abs(fitted_g - g) > bound and doubts is not None:
        doubt = _off_g(fitted_g, sig_a, g, bound, centripetal)
        doubts.append(doubt)
        warnings.append(doubt)
    tilt = math.degrees(math.acos(max(-1.0, min(1.0, float(-(down @ upv))))))
    dirn = ", ".join(f"{v:+.2f}" for v in down)
    # the fitted direction's own uncertainty (all the components', conservatively)
    sig_deg = math.degrees(float(np.sqrt(np.sum(var_a))) / fitted_g)
    if tilt > 25.0:
        raise MarkerError(
            f"{src}: gravity in the data points along ({dirn}) in camera coordinates, "
            f"{tilt:.0f} deg away from the downward direction -up that up= gives; pass "
            f"{suggested_up(-down, sigma_deg=sig_deg)}"
        )
    # tilts within the direction's uncertainty are noise
    if tilt > max(TILT_WARN_DEG, 3.0 * sig_deg):
        warnings.append(
            f"gravity in the data points along ({dirn}), {tilt:.1f} deg away from -up: e, mu "
            "and the angle are measured in a frame tilted by as much (10 deg biases mu by "
            f"several percent); pass {suggested_up(-down, exact=True)}"
        )
    return fitted_g
