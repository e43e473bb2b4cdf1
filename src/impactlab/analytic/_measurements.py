"""The measured inputs of the inversion (``impactlab.analytic.invert``): each one as
:class:`~impactlab.analytic.result.Measured` in SI, its range checked, and the plausibility of
the whole against the rod (ValueError for the impossible, ImplausibleInputWarning for the
implausible)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from impactlab._validation import warn_implausible
from impactlab.analytic._inputs import HALF_PI, MIN_SPEED, drop_speed
from impactlab.analytic.result import Measured, measured
from impactlab.bodies._checks import inertia_ratio_problem

__all__ = [
    "E_NOISE_SIGMAS",
    "MIN_DENT_DEPTH",
    "MIN_SPEED",
    "PLAUSIBLE_DENT_DEPTH",
    "PLAUSIBLE_DENT_RATIO",
    "PLAUSIBLE_DURATION",
    "PLAUSIBLE_MIN_SPEED",
    "PLAUSIBLE_SPEED",
    "SIGMA_RANGE_FRACTION",
    "check_momentum",
    "check_plausible",
    "check_restitution",
    "check_rod",
    "check_sigma_fits",
    "measurements",
]

_CONVENTION = "the paper's tables print it negative: give its magnitude"

#: Units of the measured inputs ("": a plain number).
_UNITS = {
    "angle": "rad",
    "v_i": "m/s",
    "mu": "",
    "delta_p": "m",
    "sliding_length": "m",
    "e": "",
    "dv_cy": "m/s",
    "vt_in": "m/s",
}
#: The inputs T needs, each with what it is (named when it is missing, None).
_REQUIRED = {
    "angle": "the rod-to-flat angle",
    "v_i": "the tip's vertical velocity before the impact",
    "mu": "the friction coefficient",
    "delta_p": "the permanent dent depth",
    "sliding_length": "the length of the sliding scar",
}
#: The inputs that are magnitudes although the paper prints them negative.
#: Lengths given as magnitudes (the sliding length is signed in the engine, along +x: its
#: magnitude enters, as v_i's).
_MAGNITUDES = {"delta_p": "the permanent dent depth"}


#: A nominal v_i, dv_cy or |vt_in| above this [m/s] draws an ImplausibleInputWarning.
PLAUSIBLE_SPEED = 100.0
#: A |v_i| below this [m/s] (a fall of 0.05 um) draws an ImplausibleInputWarning: too slow for a
#: steel drop to dent a metal flat; most likely a unit mistake (km/s taken as m/s).
PLAUSIBLE_MIN_SPEED = 1e-3
#: A dent deeper than this fraction of the tip radius draws an ImplausibleInputWarning.
PLAUSIBLE_DENT_RATIO = 0.1
#: A nominal impact duration above this [s] draws an ImplausibleInputWarning.
PLAUSIBLE_DURATION = 0.1
#: A dent shallower than this [m] is refused: no profilometer resolves it (most likely a unit
#: mistake, or no dent at all). The same bound as ``analyze``'s scan check
#: (``impactlab.experiment.profilometry.plausibility.MIN_DEPTH``), which this layer may not import.
MIN_DENT_DEPTH = 1e-9
#: A dent shallower than this [m] draws an ImplausibleInputWarning (``analyze``'s
#: ``PLAUSIBLE_DEPTH`` in ``impactlab.experiment.profilometry.plausibility``).
PLAUSIBLE_DENT_DEPTH = 0.1e-6
#: A measured e given with its sigma may lie this many sigmas outside [0, 1] (noise, with a
#: warning); the experiment pipeline's markers stage accepts the same (``E_SIGMAS``).
E_NOISE_SIGMAS = 3.0
#: The largest standard deviation of an input of bounded range (e in [0, 1], the angle in
#: (0, pi/2) rad), as a fraction of the range's width: at a quarter, the measurement's
#: +-2 sigma band already spans the whole range. (mu has no upper bound of its own: a mu
#: beyond mu_c sticks, and the Monte Carlo's rejected share, warned above 5 %, shows it.)
SIGMA_RANGE_FRACTION = 0.25


def measurements(values: Mapping[str, Any]) -> dict[str, Measured]:
    """The given inputs (None: not measured) as :class:`Measured` in SI, keyed by name, with
    ``v_i``, ``delta_p`` and ``sliding_length`` as magnitudes (``vt_in`` keeps its sign, and is
    left out where it is exactly 0, the paper's assumption); ValueError naming a bad one, and a
    required one (``angle``, ``v_i``, ``mu``, ``delta_p``, ``sliding_length``) given as None."""
    for k, what in _REQUIRED.items():
        if values.get(k) is None:
            raise ValueError(f"{k} is required ({what}), got None")
    meas = {k: measured(k, v, _UNITS[k]) for k, v in values.items() if v is not None}
    if meas.get("vt_in") == Measured(0.0, 0.0):
        del meas["vt_in"]
    if "e" not in meas and "dv_cy" not in meas:
        raise ValueError(
            "e or dv_cy is required: F needs the restitution coefficient (rigid-body "
            "identity) or the centre-of-mass velocity change (Eq. 29)"
        )
    for k, what in _MAGNITUDES.items():
        if meas[k].value < 0.0:
            raise ValueError(
                f"{k} must be >= 0 ({what}, a magnitude in m), got {meas[k].value!r}: {_CONVENTION}"
            )
    for k in ("v_i", "delta_p", "sliding_length"):  # the drop speed; -0.0 -> 0.0
        meas[k] = Measured(abs(meas[k].value), meas[k].sigma)
    _check_ranges(meas)
    if "e" in meas:
        meas["e"] = check_restitution(meas["e"])
    return meas


def _check_ranges(meas: Mapping[str, Measured]) -> None:
    """ValueError for a nominal value outside its range (module docstring of ``invert``)."""
    th = meas["angle"].value
    if not 0.0 < th < HALF_PI:
        hint = "; pass radians or a string such as '20 deg'" if 2.0 <= th <= 90.0 else ""
        if HALF_PI < th <= HALF_PI + math.radians(10.0):  # a bare angle just past the normal
            hint = past_normal_inversion(th)
        why = (
            "at 90 deg it stands vertical and its tip cannot slide"
            if th >= HALF_PI
            else "at 0 deg it lies on the flat, and below 0 its tip points up"
        )
        raise ValueError(
            f"angle must lie in (0, 90) deg, open at both ends (the rod tilted: {why}), got "
            f"{math.degrees(th):.4g} deg ({th!r} rad){hint}"
        )
    drop_speed(meas["v_i"].value)  # |v_i| >= MIN_SPEED, as the closed forms take it
    if meas["mu"].value < 0.0:
        raise ValueError(f"mu must be >= 0, got {meas['mu'].value!r}")
    if meas["sliding_length"].value == 0.0:
        raise ValueError(
            "sliding_length must be non-zero: in gross sliding any normal "
            "impulse makes the tip slide, so a zero sliding length cannot be inverted"
        )
    check_sigma_fits("angle", meas["angle"].sigma, 0.0, HALF_PI, "rad")
    if "e" in meas:
        check_sigma_fits("e", meas["e"].sigma, 0.0, 1.0)
    if "dv_cy" in meas and meas["dv_cy"].value <= 0.0:
        raise ValueError(
            f"dv_cy must be > 0 (upward change of the centre-of-mass velocity), got "
            f"{meas['dv_cy'].value!r}"
        )


def check_restitution(e: Measured) -> Measured:
    """The measured e as the inversion takes it: in [0, 1] as given; given with its sigma, up
    to ``E_NOISE_SIGMAS`` sigmas outside [0, 1] (as ``impactlab.experiment`` accepts it) read as
    measurement noise: taken at the nearer bound, 0 or 1, with its sigma, and an
    ImplausibleInputWarning saying so. ValueError giving e, its sigma and the rule beyond (and
    for any e outside [0, 1] given without a sigma)."""
    v, s = e.value, e.sigma
    if 0.0 <= v <= 1.0:
        return e
    side, bound = ("above 1", 1.0) if v > 1.0 else ("below 0", 0.0)
    if s == 0.0:
        raise ValueError(
            f"e must lie in [0, 1], got {v!r} (a measured e {side} within "
            f"{E_NOISE_SIGMAS:g} sigma is read as noise when given with its sigma: --sigma-e on "
            "the command line, [sigma] e in a measurement file, e=(value, sigma) in Python)"
        )
    n = abs(v - bound) / s
    if n > E_NOISE_SIGMAS:
        raise ValueError(
            f"e must lie in [0, 1], or within {E_NOISE_SIGMAS:g} sigma of it as measurement "
            f"noise ([{-E_NOISE_SIGMAS * s:.4g}, {1.0 + E_NOISE_SIGMAS * s:.4g}] for this "
            f"sigma), got e = {v!r} +- {s!r}, {n:.3g} sigma {side}: no impact gives it; check "
            "the measurement"
        )
    cannot = "leave the flat faster than it came" if v > 1.0 else "keep moving into the flat"
    warn_implausible(
        f"e = {v:.6g} +- {s:.2g} lies {side} ({n:.2g} sigma; the tip cannot {cannot}): read as "
        f"measurement noise (accepted within {E_NOISE_SIGMAS:g} sigma) and taken as e = "
        f"{bound:g} +- {s:.2g}"
    )
    return Measured(bound, s)


def check_sigma_fits(
    name: str, sigma: float, low: float, high: float, unit: str = "", why: str = ""
) -> None:
    """ValueError when the standard deviation ``sigma`` of input ``name`` (same unit as the
    input, ``unit``: "rad" for the angle) exceeds ``SIGMA_RANGE_FRACTION`` of the width of its
    range [low, high] (``why``: what sets the range, named in the error): such a sigma spans the
    whole range and carries no measurement."""
    limit = SIGMA_RANGE_FRACTION * (high - low)
    if sigma <= limit:
        return
    if unit == "rad":
        given = f"{sigma!r} rad ({math.degrees(sigma):.4g} deg)"
        bound = f"(0, 90) deg, at most {math.degrees(limit):.4g} deg"
    else:
        u = f" {unit}" if unit else ""
        given = f"{sigma!r}{u}"
        bound = f"[{low:g}, {high:.4g}]{u}, at most {limit:.4g}{u}"
    if why:
        bound += f"; {why}"
    raise ValueError(
        f"the sigma of {name} = {given} does not fit its range: a standard deviation may be "
        f"at most {SIGMA_RANGE_FRACTION:g} of the range's width ({name} in {bound}); a wider "
        "one spans the whole range and carries no measurement"
    )


def check_plausible(meas: Mapping[str, Measured], length: float, tip_radius: float) -> None:
    """ValueError for what is impossible for this rod (a dent or a sliding length shorter than
    ``MIN_DENT_DEPTH``, a dent deeper than the tip radius, a sliding length longer than the
    rod, a sigma of the dent or of the sliding length wider than ``SIGMA_RANGE_FRACTION`` of
    the tip radius or of the rod's length); ImplausibleInputWarning for a dent or a sliding
    length shorter than ``PLAUSIBLE_DENT_DEPTH``, a dent deeper than ``PLAUSIBLE_DENT_RATIO``
    R, a |v_i| below ``PLAUSIBLE_MIN_SPEED``, or a speed (v_i, dv_cy, |vt_in|) above
    ``PLAUSIBLE_SPEED``."""
    dp, ls = meas["delta_p"].value, meas["sliding_length"].value
    if dp < MIN_DENT_DEPTH:
        raise ValueError(
            f"delta_p = {dp!r} m is below {MIN_DENT_DEPTH * 1e9:g} nm, finer than any "
            "profilometer resolves: invert takes a measured dent (for an elastic impact, "
            "with no dent, analytic.impact_duration gives T from L_s alone); check the value "
            "and its unit (SI: m)"
        )
    if dp < PLAUSIBLE_DENT_DEPTH:
        warn_implausible(
            f"delta_p = {dp * 1e9:.4g} nm is shallower than {PLAUSIBLE_DENT_DEPTH * 1e6:g} um, "
            "implausible for the dent of a drop; check the value and its unit (SI: m)"
        )
    if dp > tip_radius:
        raise ValueError(
            f"delta_p = {dp!r} m is deeper than the rod's tip radius ({tip_radius!r} m): a dent "
            "cannot be deeper than the sphere that made it; check the units (SI: m)"
        )
    if ls < MIN_DENT_DEPTH:
        raise ValueError(
            f"sliding_length = {ls!r} m is below {MIN_DENT_DEPTH * 1e9:g} nm, finer than any "
            "profilometer resolves: a slide that leaves no measurable mark cannot be inverted "
            "(below about 1 um, T no longer depends on it); check the value and its unit (SI: m)"
        )
    if ls < PLAUSIBLE_DENT_DEPTH:
        warn_implausible(
            f"sliding_length = {ls * 1e9:.4g} nm is shorter than {PLAUSIBLE_DENT_DEPTH * 1e6:g} "
            "um, implausible for the mark of a drop (below about 1 um T no longer depends on "
            "it); check the value and its unit (SI: m)"
        )
    if ls > length:
        raise ValueError(
            f"sliding_length = {ls!r} m is longer than the rod ({length!r} m); check the units "
            "(SI: m)"
        )
    check_sigma_fits(
        "delta_p",
        meas["delta_p"].sigma,
        0.0,
        tip_radius,
        "m",
        "no dent is deeper than the rod's tip radius",
    )
    check_sigma_fits(
        "sliding_length",
        meas["sliding_length"].sigma,
        0.0,
        length,
        "m",
        "no scar is longer than the rod",
    )
    if dp > PLAUSIBLE_DENT_RATIO * tip_radius:
        warn_implausible(
            f"delta_p = {dp!r} m is deeper than {PLAUSIBLE_DENT_RATIO:g} of the tip radius "
            f"({tip_radius!r} m), far beyond the contact laws' range; check the units (SI: m)"
        )
    if meas["v_i"].value < PLAUSIBLE_MIN_SPEED:
        warn_implausible(
            f"|v_i| = {meas['v_i'].value!r} m/s is below {PLAUSIBLE_MIN_SPEED:g} m/s, a fall of "
            "0.05 um, too slow to dent a metal flat; check the units (SI: m/s)"
        )
    for k in ("v_i", "dv_cy", "vt_in"):
        if k in meas and abs(meas[k].value) > PLAUSIBLE_SPEED:
            warn_implausible(
                f"{k} = {meas[k].value!r} m/s exceeds {PLAUSIBLE_SPEED:g} m/s; check the units "
                "(SI: m/s)"
            )


def check_rod(mass: float, length: float, inertia: float) -> None:
    """ImplausibleInputWarning (``rod: ...``) where the rod's mass [kg] and inertia [kg m^2] do
    not fit its length [m]: I_C / (m L^2) below ``bodies._checks.INERTIA_RATIO_FLOOR``, the
    check ``impactlab analyze`` makes (a mass in grams given as kilograms)."""
    note = inertia_ratio_problem(mass, inertia, length)
    if note is not None:
        warn_implausible(f"rod: {note}")


def past_normal_inversion(th: float) -> str:
    """What an inversion's rod angle ``th`` [rad] in (pi/2, pi) means: the mirror drop, whose
    measured magnitudes are the same (the dent runs the other way)."""
    mirror = math.degrees(math.pi - th)
    return (
        f"; the rod leans past the flat's normal: that drop is the mirror of one at {mirror:.6g} "
        "deg, with the same magnitudes (the dent runs the other way): invert that angle"
    )


def check_momentum(meas: Mapping[str, Measured], m: float, K_y: float, T0: float, g: float) -> None:
    """ImplausibleInputWarning when the measured dv_cy [m/s] implies a coefficient of
    restitution outside [0, 1], or one that disagrees with the measured ``e`` beyond three
    combined standard uncertainties (and 0.05): F T = m (dv_cy + g T) (Eq. 29) and
    F T = ((1 + e)|v_i| + g T) / K_y (the rigid-body identity) give
    e = (K_y m (dv_cy + g T) - g T) / |v_i| - 1."""
    v = abs(meas["v_i"].value)
    dv = meas["dv_cy"]
    implied = (K_y * m * (dv.value + g * T0) - g * T0) / v - 1.0
    sigma = K_y * m * dv.sigma / v
    text = (
        f"dv_cy = {dv.value:.4g} +- {dv.sigma:.2g} m/s implies e = {implied:.4g} (Eq. 29, "
        "rigid-body identity)"
    )
    if not -3.0 * sigma <= implied <= 1.0 + 3.0 * sigma:
        warn_implausible(f"{text}, outside [0, 1]: no impact gives it; check dv_cy and its sign")
    elif "e" in meas:
        e = meas["e"]
        if abs(implied - e.value) > max(0.05, 3.0 * math.hypot(sigma, e.sigma)):
            warn_implausible(
                f"{text}, but e = {e.value:.4g} +- {e.sigma:.2g} was measured: the force from "
                "dv_cy (F_momentum) and from e (F_rigid) disagree; check both"
            )
