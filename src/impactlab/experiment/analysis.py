"""One call from the raw files to e, mu, delta_p, L_s, T and F: :func:`analyze`.

Stages (a stage that fails on its data is recorded and the others go on, so partial results are
never lost; an invalid argument raises a TypeError or ValueError naming it at once):

1. ``markers``: read the marker file, measure the impact (:func:`measure_impact`);
2. ``scan``: read the scan, measure the dent (:func:`measure_dent`) and check that the rod can
   make it (:func:`~impactlab.experiment.profilometry.plausibility.check_dent`);
3. ``inversion``: T and F from both (``impactlab.analytic.invert``: paper Eq. 12 with the
   measured e, mu, v_i, the tip's incoming tangential velocity ``vt_in``, angle, delta_p (the
   dent's maximum depth), L_s; F from Eq. 29 with the measured centre-of-mass velocity
   change; the inputs from the marker tracks correlated as their covariance says:
   :func:`kinematic_correlation`); an impact that sticks within the measurement's
   uncertainty (mu within a few sigma of mu_c, or no tangential exit velocity of the tip:
   ``experiment.sticking``) is this stage's error instead;
4. ``model`` (optional, with ``flat``): the impact engine run with the measured initial state, for
   comparison (the paper's Tables 2-3); then a warning that marks the result not ok
   (``result.doubts``) for an inferred T or F far from the simulated impact's, or a T longer
   than the marker fits allow (``experiment.consistency``);
5. ``figures`` and ``results`` (``results.json``) in ``out_dir``, figures an earlier run
   left there removed (``experiment.saving``: only files an analysis wrote are removed or
   written over; all are written, or, on a full disk, none and nothing removed); a file that
   cannot be written is the stage's error, naming it.
"""

from __future__ import annotations

import threading
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from impactlab import analytic
from impactlab._validation import ImplausibleInputWarning
from impactlab.analytic.result import UNRESOLVED_DENT_PHRASES
from impactlab.bodies import Rod
from impactlab.dynamics import simulate
from impactlab.experiment.arguments import (
    KINEMATICS_DEFAULTS,
    check_measure,
    check_scalars,
    checked_run,
    default_rod,
    implausible_rod,
    options_record,
    rod_properties,
)
from impactlab.experiment.arguments import dent_options as _dent_options
from impactlab.experiment.arguments import kinematics_options as _kinematics_options
from impactlab.experiment.consistency import check_against_model, check_single_impact
from impactlab.experiment.kinematics import ImpactKinematics, measure_impact, parse_up
from impactlab.experiment.markers import read_markers
from impactlab.experiment.profilometry import DentMetrics, measure_dent, read_scan
from impactlab.experiment.profilometry.plausibility import (
    PLAUSIBLE_DEPTH,
    check_dent,
    dent_findings,
)
from impactlab.experiment.result import ExperimentResult
from impactlab.experiment.rigid import MarkerGeometry
from impactlab.experiment.saving import check_folder, save_outputs
from impactlab.experiment.sticking import sticking_message
from impactlab.materials import Material

__all__ = ["ExperimentResult", "analyze", "default_rod", "rod_properties"]

#: What a stage may fail with on bad data: the package's errors (ExperimentError is a ValueError),
#: invalid values, unreadable or unwritable files, and data too large for the memory (a size or
#: unit read wrong): the other stages' results are kept. Anything else is a bug and propagates.
_DATA_ERRORS = (ValueError, OSError, MemoryError)
#: ``warnings.catch_warnings`` swaps process-wide state: one inversion's record at a time.
_RECORDING = threading.Lock()
#: The inversion's warnings (``impactlab.analytic``) that say the result is impossible: a
#: velocity change no impact gives (e outside [0, 1]), a duration no rigid-body impact has;
#: they mark the result not ok (``ExperimentResult.doubts``); so does a Monte Carlo that
#: discarded more than 5 % of its samples for a dent measure at or below zero: a sliding length
#: (or delta_p) within about 1.6 sigma of zero, on which T rests, is not resolved.
IMPOSSIBLE_PHRASES = (
    "no impact gives it",
    "far longer than a rigid-body impact",
    *UNRESOLVED_DENT_PHRASES,
)


def _message(exc: BaseException) -> str:
    if isinstance(exc, MemoryError):
        return (
            f"out of memory ({str(exc) or 'MemoryError'}): the data are larger than this machine "
            "can analyse, or a size or unit was read wrong (the pixel size, the height unit)"
        )
    return str(exc)


def _markers_stage(res: ExperimentResult, path: Path, rod: Rod, opts: dict[str, Any]) -> None:
    try:
        tracks = read_markers(path, units=opts.pop("marker_units"))
        res.kinematics = measure_impact(tracks, rod, **opts)
    except _DATA_ERRORS as exc:
        res.errors["markers"] = _message(exc)
        # what the measurement had found before it failed (frames left out, ...)
        res.warnings += [f"markers: {w}" for w in getattr(exc, "warnings", ())]
        return
    res.warnings += [f"markers: {w}" for w in res.kinematics.warnings]


def _scan_stage(res: ExperimentResult, path: Path, rod: Rod, opts: dict[str, Any]) -> None:
    """Read the scan (the other way up with ``flip_heights``), measure the dent and check that the
    rod can make it (:func:`check_dent`: an impossible dent is this stage's error)."""
    try:
        hm = read_scan(path, pixel_size=opts.pop("pixel_size"), height_unit=opts.pop("height_unit"))
        if opts.pop("flip_heights"):
            hm = hm.flipped()
        dent = measure_dent(hm, **opts)
        plausible = check_dent(dent, tip_radius=rod.tip_radius, rod_length=rod.length, scan=hm)
    except _DATA_ERRORS as exc:
        res.errors["scan"] = _message(exc)
        return
    res.dent = dent
    said, doubts = dent_findings(dent, plausible, tip_radius=rod.tip_radius, scan=hm)
    res.warnings += [f"scan: {w}" for w in said]
    for doubt in doubts:  # not a result to take as measured
        res.add_doubt(f"scan: {doubt}")
    if dent.direction_ambiguous:
        res.warnings.append(
            "scan: the sliding direction is ambiguous (both ends of the dent equally sharp)"
        )


def _inversion_stage(
    res: ExperimentResult,
    k: ImpactKinematics,
    d: DentMetrics,
    rod: Rod,
    reading: tuple[bool, str],
    n_samples: int,
) -> None:
    """T and F from the kinematics and the dent; ``reading``: (gravity, measure) of ``invert``."""
    stuck = sticking_message(k, rod)
    if stuck is not None:
        res.errors["inversion"] = stuck
        return
    with _RECORDING, warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            # through the module attribute, so that the inversion can be replaced (tests)
            res.inversion = analytic.invert(
                angle=k.angle_in.pair(),
                v_i=k.v_i.pair(),
                mu=k.mu.pair(),
                e=k.e.pair(),
                dv_cy=k.dv_cy.pair(),
                vt_in=k.v_tip_in[0].pair(),  # the tip's incoming tangential velocity
                correlation=kinematic_correlation(k),
                delta_p=d.delta_p.pair(),
                sliding_length=d.sliding_length.pair(),
                rod=rod,
                gravity=reading[0],
                measure=reading[1],
                n_samples=n_samples,
            )
        except ValueError as exc:
            res.errors["inversion"] = _message(exc)
    for text in _inversion_warnings(caught, d, res.doubts):
        if any(phrase in text for phrase in IMPOSSIBLE_PHRASES):
            res.add_doubt(text)
        else:
            res.warnings.append(text)


#: The inversion's inputs from the marker tracks: keyword of ``invert`` -> derived quantity of
#: the kinematics (``ImpactKinematics.derived_names``), each passed as that quantity's value.
KINEMATIC_INPUTS = {
    "angle": "angle_in",
    "v_i": "v_tip_y_in",
    "mu": "mu",
    "e": "e",
    "dv_cy": "dv_cy",
    "vt_in": "v_tip_x_in",
}


def kinematic_correlation(k: ImpactKinematics) -> dict[tuple[str, str], float]:
    """The correlation coefficients of the inversion's inputs measured from the same marker
    tracks (``KINEMATIC_INPUTS``), from the kinematics' covariance (``k.derived_cov``), for
    ``invert``'s ``correlation``: every pair of them with a sigma > 0 (the dent's delta_p and
    L_s are measured apart, independent of them)."""
    names = list(k.derived_names)
    idx = {key: names.index(name) for key, name in KINEMATIC_INPUTS.items()}
    sigma = np.sqrt(np.clip(np.diag(np.asarray(k.derived_cov, dtype=np.float64)), 0.0, None))
    corr = np.clip(k.correlation, -1.0, 1.0)
    keys = [key for key in KINEMATIC_INPUTS if sigma[idx[key]] > 0]
    return {(a, b): float(corr[idx[a], idx[b]]) for i, a in enumerate(keys) for b in keys[i + 1 :]}


def _inversion_warnings(
    caught: list[warnings.WarningMessage], d: DentMetrics, doubts: Sequence[str] = ()
) -> list[str]:
    """The inversion's ImplausibleInputWarnings as the result's warnings (``inversion: ...``),
    less its warning of a dent shallower than 0.1 um, which the scan stage gave already (the
    same bound, ``PLAUSIBLE_DEPTH``, with the scan's likely cause: the height unit), and less
    one that is already among the result's ``doubts`` word for word (the rod's ``rod: ...``,
    which ``analyze`` checks first); any other warning is issued again as Python issues it."""
    out = []
    for w in caught:
        if not issubclass(w.category, ImplausibleInputWarning):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
            continue
        text = str(w.message)
        if text in doubts or (
            d.delta_p.value < PLAUSIBLE_DEPTH
            and text.startswith("delta_p = ")
            and "shallower" in text
        ):
            continue
        out.append(f"inversion: {text}")
    return out


def _model_stage(res: ExperimentResult, rod: Rod, flat: Material, law: str) -> None:
    if res.kinematics is None:
        return
    try:
        res.model = _engine_comparison(rod, flat, res.kinematics, law)
    except ValueError as exc:
        res.errors["model"] = _message(exc)


#: The marker fits' default guard (frames left out on each side of the impact instant).
_GUARD = int(KINEMATICS_DEFAULTS["guard"])


def _plausibility_stage(res: ExperimentResult, guard: int) -> None:
    """Doubts (warnings that mark the result not ok) when the inferred T or F disagree with
    the simulated impact (``model``) or T with the single-impact assumption of the marker fits
    (``experiment.consistency``)."""
    inv, k = res.inversion, res.kinematics
    if inv is None:
        return
    found: list[str] = []
    if res.model is not None:
        found += check_against_model(
            inv.duration,
            inv.mean_force,
            model_duration=res.model.get("duration"),
            model_force=res.model.get("mean_force"),
            law=str(res.model.get("law", "")),
            sigma_duration=inv.sigma_T_mc,
        )
    if k is not None and len(k.pre.tau) and len(k.post.tau):
        gap = float(min(k.post.tau)) - float(max(k.pre.tau))
        single = check_single_impact(inv.duration, gap, guard)
        found += [single] if single else []
    for w in found:  # a T or F that cannot be the impact's: the result is not ok
        res.add_doubt(f"plausibility: {w}")


def analyze(
    markers_path: str | Path | None,
    scan_path: str | Path | None,
    rod: Any = None,
    *,
    flat: Any = None,
    geometry: MarkerGeometry | None = None,
    up: Any = "+z",
    marker_units: str | None = None,
    pixel_size: Any = None,
    height_unit: str | None = None,
    flip_heights: bool = False,
    out_dir: str | Path | None = None,
    figures: bool = True,
    gravity: bool = False,
    n_samples: int = 20_000,
    strict: bool = False,
    kinematics_options: dict[str, Any] | None = None,
    dent_options: dict[str, Any] | None = None,
    law: str = "ghaednia",
    measure: str = "slip",
) -> ExperimentResult:
    """Analyse one drop: marker tracks + dent scan -> e, mu, delta_p, L_s, T, F.

    Parameters
    ----------
    markers_path : C3D or CSV marker file (None skips the stage).
    scan_path : profilometer scan (None skips the stage). A path that names no readable file
        raises FileFormatError at once, before anything is written.
    rod : an ``impactlab.bodies.Rod`` (or rod-like: :func:`rod_properties`); default (or
        ``"paper"``, as ``--rod paper``) the paper's.
    flat : a flat material (``Material`` or preset name): also run the impact engine with the
        measured initial state, for comparison.
    geometry : the markers on the rod (:class:`MarkerGeometry`); None estimates it.
    up : the lab's upward axis ("+z" default). marker_units : override/supply the marker units.
    pixel_size, height_unit : for height maps whose file does not state them (plain .npy/.csv);
        where the file states them they must agree with it (the stage's error otherwise).
    flip_heights : the scan stores depths as positive heights: read it the other way up (a
        sign-flipped scan is refused otherwise, see :func:`measure_dent`).
    out_dir : save results.json and the figures (dent.png, kinematics.png) there (a folder,
        created; an existing file there is refused); a figure of an earlier run that this run
        does not draw is removed (a warning says so); a file there that no analysis wrote is
        never removed or written over, and when ``results.json`` cannot be written nothing is
        (docs/experiment.md, The output folder).
    gravity : passed to ``invert`` (gravity during the contact in Eq. 12; the measured velocity
        change already excludes the gravity impulse, see docs/experiment.md).
    n_samples : Monte Carlo samples of the inversion (>= 100). strict : raise
        :class:`ExperimentError` after saving if a stage failed (default: ``result.errors``).
    measure : how the inversion reads the scan's L_s: ``"slip"`` (default), the tip's slip, as
        the paper does; ``"travel"``, the contact's travel, the mark's extent (``invert``).
    kinematics_options, dent_options : extra keywords for :func:`measure_impact` and
        :func:`measure_dent` (names, and the values of the kinematics' options, checked at
        once). law : contact law of the engine comparison (checked even without ``flat``).

    A stage that fails on its data (a bad file, a failed fit, a sticking impact, an inversion
    outside its range, a dent the rod cannot make: :func:`check_dent`, a file that cannot be
    written) is recorded in ``result.errors``; an invalid
    argument raises TypeError or ValueError naming it at once. A result that is not ok for a
    doubt (``result.doubts``: an estimated marker geometry in doubt, a rod whose mass and
    inertia do not fit, a velocity change that implies e outside [0, 1], an implausible T or F)
    warns of each one with an ``ImplausibleInputWarning`` too.
    """
    switches = {"flip_heights": flip_heights, "figures": figures, "gravity": gravity}
    check_scalars(n_samples, law, strict=strict, **switches)
    check_measure(measure)
    run = checked_run(
        markers_path,
        scan_path,
        rod,
        flat,
        out_dir,
        {"marker_units": marker_units, "geometry": geometry, "up": parse_up(up)}
        | _kinematics_options(kinematics_options),
        {"pixel_size": pixel_size, "height_unit": height_unit, "flip_heights": flip_heights}
        | _dent_options(dent_options),
    )
    res = run.result()
    rod_note = implausible_rod(run.rod)
    if rod_note is not None:
        res.add_doubt(f"rod: {rod_note}")
    res.options = options_record(
        flat=flat, geometry=geometry, up=up, marker_units=marker_units, pixel_size=pixel_size,
        height_unit=height_unit, flip_heights=flip_heights, gravity=gravity,
        n_samples=n_samples, law=law, measure=measure, kinematics_options=kinematics_options,
        dent_options=dent_options,
    )  # fmt: skip
    if run.markers is not None:
        _markers_stage(res, run.markers, run.rod, run.kinematics)
    if run.scan is not None:
        _scan_stage(res, run.scan, run.rod, run.dent)
    if res.kinematics is not None and res.dent is not None:
        _inversion_stage(res, res.kinematics, res.dent, run.rod, (gravity, measure), n_samples)
    if run.flat is not None:
        _model_stage(res, run.rod, run.flat, law)
    _plausibility_stage(res, int(run.kinematics.get("guard", _GUARD)))
    if run.out is not None and check_folder(res, run.out, figures):
        save_outputs(res, run.out, figures)
    if strict:
        res.raise_for_errors()
    for doubt in res.doubts:  # seen where a notebook shows it, not only in res.ok
        warnings.warn(f"not ok: {doubt}", ImplausibleInputWarning, stacklevel=2)
    return res


def _engine_comparison(rod: Rod, flat: Material, k: ImpactKinematics, law: str) -> dict[str, Any]:
    """Run the engine with the measured angle, velocity, spin and friction coefficient."""
    r = simulate(
        rod,
        flat,
        law=law,
        mu=k.mu.value,
        angle=k.angle_in.value,
        velocity=(k.v_c_in[0].value, k.v_c_in[1].value),
        spin=k.spin_in.value,
    )
    out: dict[str, Any] = {"law": law, "flat": flat.name}
    for name in ("e", "delta_p", "sliding_length", "contact_travel", "duration", "mean_force"):
        out[name] = float(getattr(r, name))
    out["velocity_out"] = [float(v) for v in r.velocity_out]
    out["spin_out"] = float(r.spin_out)
    return out
