"""One call from the raw files to e, mu, delta_p, L_s, T and F: :func:`analyze`.

Stages (a stage that fails on its data is recorded and the others go on, so partial results are
never lost; an invalid argument raises a TypeError or ValueError naming it at once):

1. ``markers``: read the marker file, measure the impact (:func:`measure_impact`);
2. ``scan``: read the scan, measure the dent (:func:`measure_dent`) and check that the rod can
   make it (:func:`~impactlab.experiment.profilometry.plausibility.check_dent`);
3. ``inversion``: T and F from both (``impactlab.analytic.invert``: paper Eq. 12 with the
   measured e, mu, v_i, angle, delta_p, L_s; F from Eq. 29 with the measured centre-of-mass
   velocity change);
4. ``model`` (optional, with ``flat``): the impact engine run with the measured initial state, for
   comparison (the paper's Tables 2-3); then a warning for an inferred T or F far from the
   simulated impact's, or a T longer than the marker fits allow (``experiment.consistency``);
5. ``figures`` and ``results.json`` in ``out_dir``.
"""

from __future__ import annotations

import inspect
import threading
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from impactlab import analytic
from impactlab._mpl import pyplot
from impactlab._validation import ImplausibleInputWarning
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.dynamics import simulate
from impactlab.experiment.checks import check_instance, check_options, check_path, output_folder
from impactlab.experiment.consistency import check_against_model, check_single_impact
from impactlab.experiment.kinematics import ImpactKinematics, measure_impact, parse_up
from impactlab.experiment.markers import read_markers
from impactlab.experiment.plots import plot_dent, plot_kinematics
from impactlab.experiment.profilometry import DentMetrics, measure_dent, read_scan
from impactlab.experiment.profilometry.heightmap import pixel_pair
from impactlab.experiment.profilometry.plausibility import PLAUSIBLE_DEPTH, check_dent
from impactlab.experiment.result import ExperimentResult
from impactlab.experiment.rigid import MarkerGeometry
from impactlab.materials import Material, get_material

__all__ = ["ExperimentResult", "analyze", "default_rod", "rod_properties"]

#: What a stage may fail with on bad data: the package's errors (ExperimentError is a ValueError),
#: invalid values and unreadable or unwritable files. Anything else is a bug and propagates.
_DATA_ERRORS = (ValueError, OSError)
#: ``warnings.catch_warnings`` swaps process-wide state: one inversion's record at a time.
_RECORDING = threading.Lock()


def _is_paper(rod: Any) -> bool:
    """True for no rod or the name ``"paper"`` (any case): the paper's rod."""
    return rod is None or (isinstance(rod, str) and rod.strip().lower() == "paper")


def default_rod() -> Rod:
    """The paper's rod: ``impactlab.bodies.PAPER_ROD`` (L = 0.3048 m, R = 8.8 mm, m = 0.4607 kg,
    I_C = m L^2 / 12)."""
    return PAPER_ROD


def rod_properties(rod: Any) -> Rod:
    """The rod as an ``impactlab.bodies.Rod`` (mass, length, tip_radius, inertia): a Rod itself,
    or a rod-like object with ``mass``, ``tip_radius``, a length (``L``, ``length`` or
    ``half_length``) and optionally ``inertia``. ValueError naming ``rod`` otherwise."""
    if isinstance(rod, Rod):
        return rod
    if hasattr(rod, "length"):
        length = float(rod.length)
    elif hasattr(rod, "L"):
        length = float(rod.L)
    elif hasattr(rod, "half_length"):
        length = 2.0 * float(rod.half_length)
    else:
        raise ValueError(f"rod must have a length (L or length), got {rod!r}")
    try:
        return Rod(
            length=length,
            tip_radius=float(rod.tip_radius),
            mass=float(rod.mass),
            inertia=getattr(rod, "inertia", None),
        )
    except AttributeError as exc:
        raise ValueError(f"rod must have mass and tip_radius: {exc}") from None


def _message(exc: BaseException) -> str:
    return str(exc)


def _flat_material(flat: Any) -> Material:
    try:
        return flat if isinstance(flat, Material) else get_material(str(flat))
    except ValueError as exc:
        raise ValueError(f"flat: {exc}") from None


def _markers_stage(res: ExperimentResult, path: Path, rod: Rod, opts: dict[str, Any]) -> None:
    try:
        tracks = read_markers(path, units=opts.pop("marker_units"))
        res.kinematics = measure_impact(tracks, rod, **opts)
    except _DATA_ERRORS as exc:
        res.errors["markers"] = _message(exc)
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
    res.warnings += [f"scan: {w}" for w in (*dent.warnings, *plausible)]
    if dent.direction_ambiguous:
        res.warnings.append(
            "scan: the sliding direction is ambiguous (both ends of the dent equally sharp)"
        )


def _inversion_stage(
    res: ExperimentResult,
    k: ImpactKinematics,
    d: DentMetrics,
    rod: Rod,
    gravity: bool,
    n_samples: int,
) -> None:
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
                delta_p=d.delta_p.pair(),
                sliding_length=d.sliding_length.pair(),
                rod=rod,
                gravity=gravity,
                n_samples=n_samples,
            )
        except ValueError as exc:
            res.errors["inversion"] = _message(exc)
    res.warnings += _inversion_warnings(caught, d)


def _inversion_warnings(caught: list[warnings.WarningMessage], d: DentMetrics) -> list[str]:
    """The inversion's ImplausibleInputWarnings as the result's warnings (``inversion: ...``),
    less its warning of a dent shallower than 0.1 um, which the scan stage gave already (the
    same bound, ``PLAUSIBLE_DEPTH``, with the scan's likely cause: the height unit); any other
    warning is issued again as Python issues it."""
    out = []
    for w in caught:
        if not issubclass(w.category, ImplausibleInputWarning):
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
            continue
        text = str(w.message)
        if (
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
_GUARD = int(inspect.signature(measure_impact).parameters["guard"].default)


def _plausibility_stage(res: ExperimentResult, guard: int) -> None:
    """Warnings when the inferred T or F disagree with the simulated impact (``model``) or T
    with the single-impact assumption of the marker fits (``experiment.consistency``)."""
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
    res.warnings += [f"plausibility: {w}" for w in found]


def _figures_stage(res: ExperimentResult, out: Path) -> None:
    plt = pyplot()
    try:
        if res.kinematics is not None:
            p = out / "kinematics.png"
            plt.close(plot_kinematics(res.kinematics, p))
            res.figures["kinematics"] = str(p)
        if res.dent is not None:
            p = out / "dent.png"
            plt.close(plot_dent(res.dent, p))
            res.figures["dent"] = str(p)
    except OSError as exc:
        res.errors["figures"] = _message(exc)


def _check_scalars(n_samples: Any, law: Any, **switches: Any) -> None:
    if isinstance(n_samples, bool) or not isinstance(n_samples, int) or n_samples < 100:
        raise ValueError(f"n_samples must be an integer >= 100, got {n_samples!r}")
    if not isinstance(law, str):
        raise TypeError(f"law must be a contact law's name such as 'ghaednia', got {law!r}")
    for name, value in switches.items():
        if not isinstance(value, bool):
            raise TypeError(f"{name} must be True or False, got {type(value).__name__} {value!r}")


@dataclass(frozen=True)
class _Run:
    """The checked arguments of :func:`analyze`."""

    markers: Path | None
    scan: Path | None
    rod: Rod
    flat: Material | None
    out: Path | None
    kinematics: dict[str, Any]
    dent: dict[str, Any]
    names: tuple[str | None, str | None]

    def result(self) -> ExperimentResult:
        """An empty result for these files and this rod."""
        rod = {k: float(getattr(self.rod, k)) for k in ("mass", "length", "tip_radius", "inertia")}
        return ExperimentResult(*self.names, rod=rod)


def _checked(
    markers_path: Any,
    scan_path: Any,
    rod: Any,
    flat: Any,
    out_dir: Any,
    kinematics: dict[str, Any],
    dent: dict[str, Any],
) -> _Run:
    """Every argument checked before any work: one TypeError/ValueError naming the parameter."""
    geometry = kinematics["geometry"]
    if geometry is not None:
        check_instance(geometry, MarkerGeometry, "geometry", "e.g. MarkerGeometry.from_mapping()")
    if dent["pixel_size"] is not None:
        pixel_pair(dent["pixel_size"])  # ValueError naming pixel_size
    names = {"marker_units": kinematics["marker_units"], "height_unit": dent["height_unit"]}
    for name, opt in names.items():
        if opt is not None and not isinstance(opt, str):
            raise TypeError(f"{name} must be a unit name such as 'mm' or None, got {opt!r}")
    return _Run(
        None if markers_path is None else check_path(markers_path, "markers_path"),
        None if scan_path is None else check_path(scan_path, "scan_path"),
        rod_properties(default_rod() if _is_paper(rod) else rod),
        None if flat is None else _flat_material(flat),
        None if out_dir is None else output_folder(out_dir, "out_dir"),
        kinematics,
        dent,
        (
            None if markers_path is None else str(markers_path),
            None if scan_path is None else str(scan_path),
        ),
    )


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
) -> ExperimentResult:
    """Analyse one drop: marker tracks + dent scan -> e, mu, delta_p, L_s, T, F.

    Parameters
    ----------
    markers_path : C3D or CSV marker file (None skips the stage).
    scan_path : profilometer scan (None skips the stage).
    rod : an ``impactlab.bodies.Rod`` (or rod-like: :func:`rod_properties`); default (or
        ``"paper"``, as ``--rod paper``) the paper's.
    flat : a flat material (``Material`` or preset name): also run the impact engine with the
        measured initial state, for comparison.
    geometry : the markers on the rod (:class:`MarkerGeometry`); None estimates it.
    up : the lab's upward axis ("+z" default). marker_units : override/supply the marker units.
    pixel_size, height_unit : for plain .npy/.csv height maps.
    flip_heights : the scan stores depths as positive heights: read it the other way up (a
        sign-flipped scan is refused otherwise, see :func:`measure_dent`).
    out_dir : save results.json and the figures (dent.png, kinematics.png) there (a folder,
        created; an existing file there is refused).
    gravity : passed to ``invert`` (gravity during the contact in Eq. 12; the measured velocity
        change already excludes the gravity impulse, see docs/experiment.md).
    n_samples : Monte Carlo samples of the inversion (>= 100). strict : raise
        :class:`ExperimentError` after saving if a stage failed (default: ``result.errors``).
    kinematics_options, dent_options : extra keywords for :func:`measure_impact` and
        :func:`measure_dent`. law : contact law of the engine comparison.

    A stage that fails on its data (a bad file, a failed fit, an inversion outside its range, a
    dent the rod cannot make: :func:`check_dent`) is recorded in ``result.errors``; an invalid
    argument raises TypeError or ValueError naming it at once.
    """
    switches = {"flip_heights": flip_heights, "figures": figures, "gravity": gravity}
    _check_scalars(n_samples, law, strict=strict, **switches)
    run = _checked(
        markers_path,
        scan_path,
        rod,
        flat,
        out_dir,
        {"marker_units": marker_units, "geometry": geometry, "up": parse_up(up)}
        | check_options(kinematics_options, measure_impact, "kinematics_options"),
        {"pixel_size": pixel_size, "height_unit": height_unit, "flip_heights": flip_heights}
        | check_options(dent_options, measure_dent, "dent_options"),
    )
    res = run.result()
    if run.markers is not None:
        _markers_stage(res, run.markers, run.rod, run.kinematics)
    if run.scan is not None:
        _scan_stage(res, run.scan, run.rod, run.dent)
    if res.kinematics is not None and res.dent is not None:
        _inversion_stage(res, res.kinematics, res.dent, run.rod, gravity, n_samples)
    if run.flat is not None:
        _model_stage(res, run.rod, run.flat, law)
    _plausibility_stage(res, int(run.kinematics.get("guard", _GUARD)))
    if run.out is not None:
        if figures:
            _figures_stage(res, run.out)
        res.save(run.out)
    if strict:
        res.raise_for_errors()
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
