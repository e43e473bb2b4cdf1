"""Study files and sweeps with a flexible rod (``body = "flexible_rod"``): one flexible drop per
case (``impactlab.dynamics.drop.simulate_drop``, the whole contact sequence), evaluated chunk by
chunk behind the engine's Evaluator interface (``impactlab.sweep.engine``).

The body is ``impactlab.FlexibleRod`` with the inputs ``length``, ``tip_radius`` and ``mass``
(unset: the paper's rod), its diameter derived from the mass, the length and the body
material's density as FlexibleRod derives it, and the modal inputs ``n_axial``, ``n_bending``
(integers) and ``damping`` (the modal damping ratio; unset: FlexibleRod's defaults). The
inertia follows from the beam theory: a study that sets ``inertia`` (or a sphere's ``radius``)
for a flexible rod gets the status BAD_BODY for those cases.

Outputs: the store keeps the engine's output fields and, for a study with a flexible rod, the
drop's sequence totals (``impactlab.schema.SEQUENCE_FIELDS``); a flexible case fills those that
the drop defines (``DROP_OUTPUTS``, each read for the whole sequence as ``DropResult``
documents: e, dent_depth = final dent depth, sequence_sliding_length = the tip's total slip,
sequence_duration = first touch to last separation, sequence_mean_force = P_n /
sequence_duration, ...) and leaves the others NaN (-1 for integer outputs): a flexible case
has no ``duration``, ``delta_p``, ``sliding_length`` or ``mean_force`` of one contact.
Status: the sweep's rejection codes (``impactlab.sweep.status``) before the drop (a body whose
modes cannot be built: BAD_BODY; an input the drop refuses, e.g. an approach speed below
``MIN_APPROACH_SPEED``: BAD_INPUT), and a failed drop with its own code from the one
status table of every engine (``kernels.status``: e.g. ST_MISSED_CONTACT, ST_INACCURATE, ST_TMAX).
Every case gets a status: one bad case
never stops a chunk, so the valid cases are stored.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD
from impactlab.bodies.flexible_rod import DEFAULT_N_AXIAL, DEFAULT_N_BENDING, FlexibleRod
from impactlab.contact import ContactModel
from impactlab.dynamics.drop import DROP_FRICTION, MIN_APPROACH_SPEED, DropError, simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.models import build_contact_model
from impactlab.materials import Material
from impactlab.schema import RENAMED_DROP_FIELDS
from impactlab.sweep.models import Statics, material_for
from impactlab.sweep.status import (
    STATUS_BAD_BODY,
    STATUS_BAD_INPUT,
    STATUS_BAD_LAW,
    STATUS_BAD_MATERIAL,
)

__all__ = [
    "DROP_OUTPUTS",
    "FLEXIBLE_BODY",
    "FLEXIBLE_INPUTS",
    "MEASURED_AS",
    "check_flexible_study",
    "evaluate_flexible",
    "validate_flexible",
]

#: The ``body`` value of a flexible rod.
FLEXIBLE_BODY = "flexible_rod"
#: Inputs that only a flexible rod takes.
FLEXIBLE_INPUTS = ("n_axial", "n_bending", "damping")

#: Store columns a drop fills, read from its DropResult: engine outputs of the same meaning and
#: the sequence totals (``impactlab.schema.SEQUENCE_FIELDS``).
DROP_OUTPUTS: dict[str, Callable[[DropResult], float]] = {
    "e": lambda r: r.e,
    "vx_out": lambda r: r.velocity_out[0],
    "vy_out": lambda r: r.velocity_out[1],
    "spin_out": lambda r: r.spin_out,
    "delta_max": lambda r: r.delta_max,
    "dent_depth": lambda r: r.dent_depth,
    "sequence_sliding_length": lambda r: r.sequence_sliding_length,
    "sequence_duration": lambda r: r.sequence_duration,
    "sequence_mean_force": lambda r: r.sequence_mean_force,
    "max_force": lambda r: r.max_force,
    "normal_impulse": lambda r: r.normal_impulse,
    "tangential_impulse": lambda r: r.tangential_impulse,
    "stick_time": lambda r: r.stick_time,
    "angle_out": lambda r: r.angle_out,
    "n_steps": lambda r: r.n_steps,
    "flags": lambda r: int(r.flags),
}

#: What an experiment that drops a rod measures as the impact output (key) is the drop's
#: sequence total (value): the dent left, the total slip, first touch to last separation
#: (``impactlab.calibrate`` compares them).
MEASURED_AS: dict[str, str] = dict(RENAMED_DROP_FIELDS)


def _given(row: Mapping[str, float], name: str) -> float | None:
    v = row[name]
    return None if math.isnan(v) else float(v)


def _count(row: Mapping[str, float], name: str, default: int) -> int:
    v = _given(row, name)
    if v is None:
        return default
    if v != math.floor(v) or v < 0:
        raise ValueError(f"{name} must be an integer >= 0, got {v!r}")
    return int(v)


def flexible_body(row: Mapping[str, float], material: Material) -> FlexibleRod:
    """The FlexibleRod of one case (ValueError for what FlexibleRod or the sweep rejects)."""
    for name in ("inertia", "radius"):
        if _given(row, name) is not None:
            raise ValueError(f"a flexible rod takes no {name!r} (its inertia follows the beam)")
    length, tip, mass = (_given(row, n) for n in ("length", "tip_radius", "mass"))
    n_axial = _count(row, "n_axial", DEFAULT_N_AXIAL)
    return FlexibleRod(
        length=PAPER_ROD.length if length is None else length,
        tip_radius=PAPER_ROD.tip_radius if tip is None else tip,
        mass=PAPER_ROD.mass if mass is None else mass,
        material=material,
        n_axial=n_axial,
        n_bending=_count(row, "n_bending", DEFAULT_N_BENDING),
        axial_residual=n_axial >= 1,
        damping=_given(row, "damping") or 0.0,
    )


@functools.lru_cache(maxsize=256)
def _models(
    cat: tuple[tuple[str, str], ...], row: tuple[tuple[str, float], ...], lp: tuple[Any, ...]
) -> tuple[int, Any]:
    """(0, (body, flat, contact model)) of one combination of the inputs, or (status, None)."""
    c, r = dict(cat), dict(row)
    try:
        body_mat = material_for("body", c["body_material"], r)
        flat_mat = material_for("flat", c["flat_material"], r)
    except ValueError:
        return STATUS_BAD_MATERIAL, None
    try:
        body = flexible_body(r, body_mat)
        body.basis()  # the modes: a body whose basis fails is a bad body, not a crash
    except (ValueError, ArithmeticError, np.linalg.LinAlgError):
        return STATUS_BAD_BODY, None
    try:
        model = build_contact_model(c["law"], body_mat, flat_mat, body.tip_radius, dict(lp))
    except ValueError:
        return STATUS_BAD_LAW, None
    return 0, (body, flat_mat, model)


def _kinematics_status(body: FlexibleRod, k: Mapping[str, float]) -> int:
    """The engine's status for kinematics the drop would refuse (0: none)."""
    if not all(math.isfinite(k[n]) for n in ("angle", "vx", "vy", "spin", "mu")) or k["mu"] < 0:
        return STATUS_BAD_INPUT
    if not 0.0 < k["angle"] <= 0.5 * math.pi:
        return S.ST_BAD_ANGLE
    vn = k["vy"] - k["spin"] * body.half_length * math.cos(k["angle"])
    if not vn < 0.0:
        return S.ST_NOT_APPROACHING
    if -vn < MIN_APPROACH_SPEED:
        return STATUS_BAD_INPUT
    return 0


def _drop(
    parts: tuple[FlexibleRod, Material, ContactModel], k: Mapping[str, float], statics: Statics
) -> tuple[int, DropResult | None]:
    body, flat, model = parts
    st = _kinematics_status(body, k)
    if st:
        return st, None
    engine = dict(statics.engine)
    try:
        r = simulate_drop(
            body,
            flat,
            law=model,
            friction=statics.categories["friction"],
            mu=k["mu"],
            angle=k["angle"],
            velocity=(k["vx"], k["vy"]),
            spin=k["spin"],
            gravity=engine.get("gravity", True),
            rtol=engine.get("rtol"),
            history=False,
        )
    except DropError as exc:
        return int(exc.status), None  # the one status table of every engine (kernels.status)
    except ValueError:  # an input the drop refuses (its one-line message names it)
        return STATUS_BAD_INPUT, None
    except (ArithmeticError, np.linalg.LinAlgError):  # never expected: a status, not a crash
        return S.ST_NAN, None
    return 0, r


def evaluate_flexible(
    cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """One chunk of flexible-rod cases (the Evaluator call of ``impactlab.sweep.engine``):
    ({output: (N,) array}, status (N,) int32); outputs the drop does not define are NaN."""
    n = len(cases["angle"])
    status = np.zeros(n, dtype=np.int32)
    res = {o: np.full(n, np.nan) for o in outputs}
    cat = tuple(sorted(statics.categories.items()))
    lp = tuple(sorted(statics.law_params.items()))
    model_inputs = sorted(set(cases) - {"angle", "vx", "vy", "spin", "mu"})
    for i in range(n):
        row = tuple((name, float(cases[name][i])) for name in model_inputs)
        st, parts = _models(cat, row, lp)
        r = None
        if not st:
            kin = {name: float(cases[name][i]) for name in ("angle", "vx", "vy", "spin", "mu")}
            st, r = _drop(parts, kin, statics)
        status[i] = st
        if r is not None:
            for o in outputs:
                if o in DROP_OUTPUTS:
                    res[o][i] = DROP_OUTPUTS[o](r)
    return res, status


def validate_flexible(categories: Mapping[str, Sequence[str]]) -> None:
    """ValueError when a study with a flexible rod names a friction model the drop lacks."""
    if FLEXIBLE_BODY not in categories.get("body", ()):
        return
    names = tuple(str(k) for k in DROP_FRICTION)
    bad = [f for f in categories.get("friction", ()) if f not in names]
    if bad:
        raise ValueError(
            f"friction {bad[0]!r}: the flexible rod's drop implements {', '.join(names)}"
        )


def check_flexible_study(args: Mapping[str, Any]) -> None:
    """The study-level checks of a flexible rod (``Study`` keyword arguments from a study file):
    the flexible inputs need ``body = "flexible_rod"`` among the bodies, and a flexible rod
    follows its rotation (no ``[engine] constant_angle = true``)."""
    bodies = {args["fixed"].get("body", "rod")}
    set_names = set(args["fixed"])
    for axis in args["grid"]:
        set_names.add(axis.name)
        if axis.name == "body":
            bodies = {str(v) for v in axis.values}
    if args.get("sample") is not None:
        set_names |= set(args["sample"].inputs)
    given = sorted(set_names & set(FLEXIBLE_INPUTS))
    if given and FLEXIBLE_BODY not in bodies:
        raise ValueError(
            f"{', '.join(given)}: inputs of a flexible rod; set body = {FLEXIBLE_BODY!r} "
            f"(the study's bodies: {', '.join(sorted(bodies))})"
        )
    if FLEXIBLE_BODY in bodies and args["engine"].constant_angle:
        raise ValueError(
            "[engine] constant_angle = true freezes the rigid engine's lever arms; a flexible "
            "rod's drop follows its rotation: remove it for body = 'flexible_rod'"
        )
