"""The study's bodies checked when the study is built: a rod other than the paper's needs its
mass, and a body that every combination of the study's values refuses (a tip wider than half
the rod) is refused in the body's own words, not run as cases that all fail."""

from __future__ import annotations

import itertools
import math
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

from impactlab.bodies import PAPER_ROD
from impactlab.materials import get_material
from impactlab.sweep.flexible import FLEXIBLE_BODY, flexible_body
from impactlab.sweep.inputs import INPUTS, MATERIAL_OVERRIDES
from impactlab.sweep.material_inputs import CUSTOM
from impactlab.sweep.models import BODY_NUMERIC, MAX_PROBES, make_body, material_for
from impactlab.sweep.study_rules import IGNORED_BY

__all__ = ["body_problem", "check_study_bodies"]

_ROD_BODIES = ("rod", "flexible_rod")
#: The inputs that make a body (its geometry, a flexible rod's modes, its material's values).
_BODY_PROBED = tuple(
    sorted({*BODY_NUMERIC, "n_axial", "n_bending", "damping", *MATERIAL_OVERRIDES["body"]})
)


def _check_rod_mass(
    fixed: Mapping[str, Any], grid: Mapping[str, Any], sampled: Sequence[str], bodies: list[str]
) -> None:
    """ValueError for a rod of another material or length than the paper's without ``mass``:
    the default mass is the paper's rod's (``impactlab drop`` and ``Rod`` refuse it too)."""
    if not set(bodies) & set(_ROD_BODIES) or any("mass" in s for s in (fixed, grid, sampled)):
        return
    default = INPUTS["body_material"].default
    materials = [str(m) for m in grid.get("body_material", (fixed.get("body_material", default),))]
    other = [m for m in materials if m == CUSTOM or get_material(m) != PAPER_ROD.material]
    lengths = [float(v) for v in grid.get("length", (fixed.get("length", PAPER_ROD.length),))]
    longer = [v for v in lengths if not math.isclose(v, PAPER_ROD.length, rel_tol=1e-9)]
    if not other and not longer and "length" not in sampled:
        return
    why = f"length = {longer[0]:g} m" if longer else "a sampled length"
    why = f"body_material = {other[0]!r}" if other else why
    raise ValueError(
        f"mass: give it for a rod other than the paper's ({why}): the default is the paper's "
        f"rod's, {PAPER_ROD.mass:g} kg, that of its AISI 201 rod of length {PAPER_ROD.length:g} "
        "m; set mass in [fixed], [grid] or [sample]"
    )


def body_problem(kind: str, material: str, row: Mapping[str, float]) -> str:
    """The body's own words (its ValueError) for a combination of the inputs ``row`` that makes
    no body ``kind`` of the ``material`` preset (status ``STATUS_BAD_BODY``); "" when it
    builds, or when the material is refused first (its own status)."""
    try:
        mat = material_for("body", material, row)
    except ValueError:
        return ""
    try:
        with warnings.catch_warnings():  # an implausible value warns when the study runs
            warnings.simplefilter("ignore")
            if kind == FLEXIBLE_BODY:
                flexible_body(row, mat)
            else:
                make_body({"body": kind}, row, mat)
    except ValueError as exc:
        return str(exc)
    return ""


def check_study_bodies(
    fixed: Mapping[str, Any], axes: Sequence[Any], sampled: Sequence[str]
) -> None:
    """ValueError for a rod other than the paper's without its mass, and, in the body's own
    words (``Rod``, ``Sphere``, ``FlexibleRod``), for a body of the study that every
    combination of the study's values refuses (a tip wider than half the rod: every case of
    it would fail). Checked where the body's inputs take at most :data:`MAX_PROBES`
    combinations over the grid and none is sampled; otherwise each refused case gets
    ``STATUS_BAD_BODY``."""
    grid = {a.name: a.values for a in axes}
    bodies = [str(b) for b in grid.get("body", (fixed.get("body", "rod"),))]
    _check_rod_mass(fixed, grid, sampled, bodies)
    if any(n in sampled for n in (*_BODY_PROBED, "body_material")):
        return
    varied = {n: v for n, v in grid.items() if n in (*_BODY_PROBED, "body_material")}
    if math.prod(len(v) for v in varied.values()) > MAX_PROBES:
        return
    for kind in bodies:
        problems = []
        for combo in itertools.product(*varied.values()):
            values = {n: fixed.get(n) for n in (*_BODY_PROBED, "body_material")}
            values.update(zip(varied, combo, strict=True))
            material = str(values.pop("body_material") or INPUTS["body_material"].default)
            row = {n: math.nan if v is None else float(v) for n, v in values.items()}
            row.update({n: math.nan for n in IGNORED_BY.get(kind, ())})
            problems.append(body_problem(kind, material, row))
            if not problems[-1]:
                break
        if problems[-1]:
            raise ValueError(
                f"{problems[0]} (every case of body {kind!r} would fail; change the study's values)"
            )
