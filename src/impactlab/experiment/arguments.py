"""The arguments of :func:`impactlab.experiment.analyze`, checked before any work: one
TypeError (wrong kind of value) or ValueError (a value outside what is allowed) naming the
parameter, the value given and what is allowed; and the rod as a ``bodies.Rod``."""

from __future__ import annotations

import inspect
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.bodies._checks import (
    INERTIA_RATIO_FLOOR,
    heavy_rod_problem,
    inertia_ratio_problem,
)
from impactlab.contact.registry import get_law
from impactlab.experiment.checks import (
    check_input_file,
    check_instance,
    check_options,
    check_output_folder,
    output_folder,
)
from impactlab.experiment.kinematics import measure_impact
from impactlab.experiment.kinematics.options import check_kinematics_options
from impactlab.experiment.markers import length_factor
from impactlab.experiment.profilometry import measure_dent
from impactlab.experiment.profilometry.heightmap import pixel_pair
from impactlab.experiment.result import ExperimentResult
from impactlab.experiment.rigid import MarkerGeometry
from impactlab.materials import Material, get_material

__all__ = [
    "INERTIA_RATIO_FLOOR",
    "KINEMATICS_DEFAULTS",
    "AnalysisRun",
    "check_scalars",
    "checked_run",
    "default_rod",
    "dent_options",
    "implausible_rod",
    "kinematics_options",
    "rod_properties",
]

#: The defaults of :func:`measure_impact`'s keyword options.
KINEMATICS_DEFAULTS = {
    p.name: p.default
    for p in inspect.signature(measure_impact).parameters.values()
    if p.kind is p.KEYWORD_ONLY
}


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
    if isinstance(rod, Sphere):  # it has a mass and a tip radius, but no rod's length
        raise ValueError(
            "rod: got a Sphere; analyze needs a Rod (the impulse relations are a tilted rod's, "
            "its tip L/2 from the centre of mass): impactlab.Rod(length=..., tip_radius=..., "
            "mass=...), or None for the paper's rod"
        )
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


def implausible_rod(rod: Rod) -> str | None:
    """Why the rod's mass and inertia do not fit each other (None when they do): I_C / (m L^2)
    below ``INERTIA_RATIO_FLOOR`` (``impactlab.bodies._checks.inertia_ratio_problem``, the
    check ``impactlab.analytic.invert`` makes too); or, for a rod of uniform section (no
    diameter, I_C = m L^2 / 12), a mass that makes it far wider than its tip
    (``heavy_rod_problem``, which ``Rod`` only warns of), with the grams hint. The inertia's
    check is blind to that one: m L^2 / 12 scales with the mass."""
    inertia = rod.inertia_ratio * rod.mass * rod.length**2  # given, or m L^2 / 12
    problem = inertia_ratio_problem(rod.mass, inertia, rod.length)
    if problem is not None or rod.diameter is not None:
        return problem
    if abs(12.0 * rod.inertia_ratio - 1.0) > 1e-9:  # an inertia given: not a uniform rod
        return None
    L, R, m = rod.length, rod.tip_radius, rod.mass
    heavy = heavy_rod_problem(L, R, m, rod.material)
    if heavy is None:
        return None
    hint = ""
    if heavy_rod_problem(L, R, 1e-3 * m, rod.material) is None:
        hint = f"; a mass in grams given as kilograms? (mass = {1e-3 * m:.4g} kg fits)"
    return (
        f"the mass does not fit the rod's size: {heavy}{hint}; its inertia, m L^2 / 12, "
        "scales with the mass, so the force F and the inertia's checks would be off by as much"
    )


def _flat_material(flat: Any) -> Material:
    try:
        return flat if isinstance(flat, Material) else get_material(str(flat))
    except ValueError as exc:
        raise ValueError(f"flat: {exc}") from None


def check_scalars(n_samples: Any, law: Any, **switches: Any) -> None:
    """``n_samples`` (an int >= 100), ``law`` (a known contact law's name, checked also without
    ``flat``) and the True/False ``switches``."""
    if isinstance(n_samples, bool) or not isinstance(n_samples, int) or n_samples < 100:
        raise ValueError(f"n_samples must be an integer >= 100, got {n_samples!r}")
    if not isinstance(law, str):
        raise TypeError(f"law must be a contact law's name such as 'ghaednia', got {law!r}")
    try:
        get_law(law)
    except ValueError as exc:
        raise ValueError(f"law: {exc}") from None
    for name, value in switches.items():
        if not isinstance(value, bool):
            raise TypeError(f"{name} must be True or False, got {type(value).__name__} {value!r}")


def check_measure(measure: Any) -> None:
    """``measure``: how the inversion reads the scan's L_s, ``"slip"`` or ``"travel"``."""
    if measure not in ("slip", "travel"):
        raise ValueError(
            "measure must be 'slip' (the tip's slip, the paper's reading of L_s) or 'travel' "
            f"(the contact's travel, the mark's extent), got {measure!r}"
        )


def kinematics_options(options: Any) -> dict[str, Any]:
    """``kinematics_options`` checked: known keys of :func:`measure_impact` (ValueError naming
    an unknown one) with values of the right kind and range (each error naming the option)."""
    given = check_options(options, measure_impact, "kinematics_options")
    check_kinematics_options({**KINEMATICS_DEFAULTS, **given}, "kinematics_options: ")
    return given


def dent_options(options: Any) -> dict[str, Any]:
    """``dent_options`` checked: known keys of :func:`measure_dent` (ValueError naming an
    unknown one)."""
    return check_options(options, measure_dent, "dent_options")


@dataclass(frozen=True)
class AnalysisRun:
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


#: The length units a marker file or a height map may be in [m]: picometres to metres.
UNIT_RANGE = (1e-12, 1.0)


def _check_length_unit(name: str, unit: str) -> None:
    """ValueError naming ``name`` (and its option) for a unit that is not a length, or one
    outside ``UNIT_RANGE`` ('km', 'ly': no scan or marker file is written in them)."""
    option = "--" + name.replace("_", "-")
    factor = length_factor(unit, name=f"{name} ({option})")
    if not UNIT_RANGE[0] <= factor <= UNIT_RANGE[1]:
        raise ValueError(
            f"{name} ({option}): {unit!r} is {factor:g} m, outside the units a measurement "
            f"file is written in ({UNIT_RANGE[0]:g} m to {UNIT_RANGE[1]:g} m: 'nm', 'um', 'mm', "
            "'m')"
        )


def checked_run(
    markers_path: Any,
    scan_path: Any,
    rod: Any,
    flat: Any,
    out_dir: Any,
    kinematics: dict[str, Any],
    dent: dict[str, Any],
) -> AnalysisRun:
    """Every argument checked before any work: one TypeError/ValueError naming the parameter
    (a marker or scan file that does not exist or cannot be read: FileFormatError, before the
    output folder is touched)."""
    if out_dir is not None:
        check_output_folder(out_dir, "out_dir")  # made last, after the inputs are found
    geometry = kinematics["geometry"]
    if geometry is not None:
        check_instance(geometry, MarkerGeometry, "geometry", "e.g. MarkerGeometry.from_mapping()")
    if dent["pixel_size"] is not None:
        if isinstance(dent["pixel_size"], str) and not dent["pixel_size"].strip():
            raise ValueError(  # the general hint, '1.0 m', is above the largest pixel allowed
                f"pixel_size (--pixel-size) is empty ({dent['pixel_size']!r}); write one length "
                "and its unit, e.g. '12.5 um', or leave it out where the scan states it"
            )
        pixel_pair(dent["pixel_size"], "pixel_size (--pixel-size)")  # ValueError naming it
    names = {"marker_units": kinematics["marker_units"], "height_unit": dent["height_unit"]}
    for name, opt in names.items():
        if opt is not None and not isinstance(opt, str):
            raise TypeError(f"{name} must be a unit name such as 'mm' or None, got {opt!r}")
        if opt is not None:
            _check_length_unit(name, opt)
    return AnalysisRun(
        None if markers_path is None else check_input_file(markers_path, "markers_path"),
        None if scan_path is None else check_input_file(scan_path, "scan_path"),
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


def options_record(**options: Any) -> dict[str, Any]:
    """The analysis's settings as given, JSON-ready (``ExperimentResult.options``): a material
    by its name, a marker geometry by its markers [m] and labels, anything else JSON cannot
    hold by its text."""

    def plain(x: Any) -> Any:
        if x is None or isinstance(x, bool | int | float | str):
            return x
        if isinstance(x, Material):
            return x.name
        if isinstance(x, MarkerGeometry):
            return {"markers": plain(x.markers), "labels": plain(x.labels)}
        if isinstance(x, dict):
            return {str(k): plain(v) for k, v in x.items()}
        if isinstance(x, list | tuple | np.ndarray):
            return [plain(v) for v in np.asarray(x, dtype=object).tolist()]
        if isinstance(x, np.generic):
            return x.item()
        return str(x)

    return {k: plain(v) for k, v in options.items()}
