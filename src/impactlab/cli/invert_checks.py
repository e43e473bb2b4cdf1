"""The checks of ``impactlab invert`` around the inversion: every input given, the rod built
from its options (an error names them as given), and the comparison with a simulated impact."""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from typing import Any

from impactlab._validation import ImplausibleInputWarning
from impactlab.analytic import InversionResult
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli._common import UserError
from impactlab.cli.invert_inputs import FIELDS, IN_FILE

#: the inputs that T needs (F needs e or dv_cy besides)
REQUIRED = ("angle", "v_i", "mu", "delta_p", "L_s")
#: the rod's properties, their options and SI units
_ROD = {"mass": ("--mass", "kg"), "length": ("--length", "m"),
        "tip_radius": ("--tip-radius", "m"), "inertia": ("--inertia", "kg m^2")}  # fmt: skip


def check_complete(have: set[str], sigmas: set[str]) -> None:
    """Every input T and F need is there (checked before any value is parsed): one error that
    lists all that are missing, ``--e (or --dv-cy)`` among them."""
    missing = []
    for name in FIELDS:  # in the options' order: --angle, --vi, --e, --mu, ...
        if name == "e" and not {"e", "dv_cy"} & have:
            missing.append("--e (or --dv-cy)")
        elif name in REQUIRED and name not in have:
            missing.append(FIELDS[name][2])
    if missing:
        raise UserError(
            "missing input(s): "
            + ", ".join(missing)
            + " (or use --case paper-20|paper-45|paper-70 or --file)"
        )
    alone = sorted(sigmas - have)
    if alone:
        raise UserError(f"an uncertainty is given for {', '.join(alone)} but not its value")


def inversion_rod(values: Mapping[str, float], given: Mapping[str, Any]) -> Rod:
    """The paper's rod with the given properties (``values``, SI) replaced (without an explicit
    inertia the slender-rod m L^2 / 12 of the new mass and length); ``given``: the command
    line's texts (``{"length": "1 mm"}``), the others from the measurement file's [rod]. A rod
    that cannot be built is a UserError naming each property as given (its option and text, the
    file's key, or the paper's value where none was given) before the reason."""
    if not values:
        return PAPER_ROD
    try:
        with warnings.catch_warnings():  # a rod's doubt: the inversion's own (check_rod)
            warnings.simplefilter("ignore", ImplausibleInputWarning)
            return Rod(
                mass=values.get("mass", PAPER_ROD.mass),
                length=values.get("length", PAPER_ROD.length),
                tip_radius=values.get("tip_radius", PAPER_ROD.tip_radius),
                inertia=values.get("inertia"),
            )
    except ValueError as exc:
        keys = [k for k in _ROD if k in str(exc)] or list(_ROD)  # those the reason names
        raise UserError(f"{_rod_origins(keys, values, given)}: {exc}") from None


def _rod_origins(keys: list[str], values: Mapping[str, float], given: Mapping[str, Any]) -> str:
    """The rod properties ``keys`` as the user gave them: ``--length 1 mm``, ``rod.mass in the
    measurement file = 0.5 kg``, or ``the paper's tip_radius 0.0088 m (no --tip-radius)``."""
    parts = []
    for key in keys:
        option, unit = _ROD[key]
        if given.get(key) is not None:
            parts.append(f"{option} {str(given[key]).strip()}")
        elif key in values:
            parts.append(f"rod.{key} {IN_FILE} = {values[key]:.6g} {unit}")
        elif key == "inertia":
            parts.append("inertia m L^2 / 12 (no --inertia)")
        else:
            parts.append(f"the paper's {key} {getattr(PAPER_ROD, key):.6g} {unit} (no {option})")
    return " with ".join(parts)


def inversion_warnings(caught: list[warnings.WarningMessage]) -> list[str]:
    """The texts of the inversion's ImplausibleInputWarnings (for the JSON's ``warnings`` and
    stderr); any other warning is shown again as Python shows it."""
    texts = []
    for w in caught:
        if issubclass(w.category, ImplausibleInputWarning):
            texts.append(str(w.message))
        else:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    return texts


def compare_with_engine(res: InversionResult, flat: str) -> tuple[dict[str, Any], list[str]]:
    """The impact simulated with the measured angle, tip velocity (vt_in, v_i) (no spin: the
    centre of mass moves with the tip) and mu on ``flat``, and the warnings of
    ``experiment.consistency`` on the inferred T and F."""
    from impactlab.dynamics import simulate  # lazy: a fast CLI start
    from impactlab.experiment.consistency import check_against_model
    from impactlab.materials import get_material

    try:
        material = get_material(flat.strip())
    except ValueError as exc:
        raise UserError(f"--flat: {exc}") from None
    rod = res.rod
    with warnings.catch_warnings():  # the rod's doubts were reported with the inversion's
        warnings.simplefilter("ignore", ImplausibleInputWarning)
        body = Rod(length=rod["length"], tip_radius=rod["tip_radius"], mass=rod["mass"],
                   inertia=rod.get("inertia"))  # fmt: skip
    law = "ghaednia"
    try:
        r = simulate(body, material, law=law, mu=res.inputs["mu"][0],
                     angle=res.inputs["angle"][0], velocity=(res.inputs.get("vt_in", (0.0,))[0],
                     -abs(res.inputs["v_i"][0])), history=False)  # fmt: skip
    except ValueError as exc:
        raise UserError(f"--flat: the simulated impact failed: {exc}") from None
    model: dict[str, Any] = {"law": law, "flat": material.name}
    model |= {"duration": r.duration, "mean_force": r.mean_force, "e": r.e, "delta_p": r.delta_p}
    found = check_against_model(
        res.duration, res.mean_force, model_duration=r.duration, model_force=r.mean_force,
        law=law, sigma_duration=res.sigma_T_linear,
    )  # fmt: skip
    return model, found
