"""Study files and sweeps with a flexible rod (``body = "flexible_rod"``): one flexible drop per
case (the whole contact sequence, as ``impactlab.dynamics.drop.simulate_drop`` runs it),
evaluated chunk by chunk behind the engine's Evaluator interface (``impactlab.sweep.engine``):
the cases of a chunk are grouped by body (the inputs other than the kinematics), and each
group runs as one compiled batch (``impactlab.dynamics.drop_batch.simulate_drops``).

The body is ``impactlab.FlexibleRod`` with the inputs ``length``, ``tip_radius`` and ``mass``
(unset: the paper's rod), its diameter derived from the mass, the length and the body
material's density as FlexibleRod derives it, and the modal inputs ``n_axial``, ``n_bending``
(integers) and ``damping`` (the modal damping ratio; unset: FlexibleRod's defaults, the mode
counts by frequency, so that each length of a sweep has its own; the axial residual
pseudo-modes come with any axial mode). Each group runs with its own body and mode counts. The
inertia follows from the beam theory: a study of flexible rods only that sets ``inertia`` is
refused when it is built, and in a study of several bodies the flexible rod leaves ``inertia``
(and a sphere's ``radius``) unset; a case that still gives them gets the status BAD_BODY.

Outputs: the store keeps the engine's output fields and, for a study with a flexible rod, the
drop's sequence totals (``impactlab.schema.SEQUENCE_FIELDS``) and scar_length
(``engine.SEQUENCE_OUTPUTS``); a flexible case fills those that the drop defines
(``DROP_OUTPUTS``, each read for the whole sequence as ``DropResult`` documents: e, dent_depth
= final dent depth, sequence_sliding_length = the tip's total slip, sequence_duration = first
touch to last separation, sequence_mean_force = P_n / sequence_duration, scar_length = the
x-extent of the tip's contact-point path over all its contacts, ...) and leaves the others NaN
(-1 for integer outputs): a flexible case has no ``duration``, ``delta_p``, ``sliding_length``
or ``mean_force`` of one contact.
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
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.dynamics.drop import DROP_FRICTION
from impactlab.dynamics.drop_batch import DropBatchResult, input_status, simulate_drops
from impactlab.dynamics.drop_checks import drop_rtol
from impactlab.dynamics.input_checks import DROP_RTOL_MAX, gravity_value
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.models import build_contact_model
from impactlab.materials import Material
from impactlab.sweep.inputs import get_input
from impactlab.sweep.models import Statics, material_for
from impactlab.sweep.options import check_cells_study
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

#: Store columns a drop fills, read from its DropResult (a number) or from the DropBatchResult
#: of many drops (an array): engine outputs of the same meaning and the sequence totals
#: (``impactlab.schema.SEQUENCE_FIELDS``).
DROP_OUTPUTS: dict[str, Callable[[Any], Any]] = {
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
    "scar_length": lambda r: r.scar_length,
    "angle_out": lambda r: r.angle_out,
    "n_steps": lambda r: r.n_steps,
    "flags": lambda r: r.flags,
}

#: What an experiment that drops a rod measures as the impact output (key) is the drop's
#: sequence total (value): the dent left, the total slip, and the mark's extent over all
#: contacts, read for a measured ``scar_length`` (an impact's |contact_travel|; a signed
#: contact_travel has no drop counterpart: ``calibrate.models.DROP_UNPREDICTED``). A measured
#: duration or mean force is one contact's, not the sequence's (flights included): a drop
#: predicts neither. ``impactlab.calibrate`` and ``impactlab.explain`` compare them.
MEASURED_AS: dict[str, str] = {
    "delta_p": "dent_depth",
    "sliding_length": "sequence_sliding_length",
    "contact_travel": "scar_length",
}


def _given(row: Mapping[str, float], name: str) -> float | None:
    v = row[name]
    return None if math.isnan(v) else float(v)


def _count(row: Mapping[str, float], name: str) -> int | None:
    v = _given(row, name)
    if v is None:
        return None  # FlexibleRod's default, by frequency
    if v != math.floor(v) or v < 0:
        raise ValueError(f"{name} must be an integer >= 0, got {v!r}")
    return int(v)


def flexible_body(row: Mapping[str, float], material: Material) -> FlexibleRod:
    """The FlexibleRod of one case (ValueError for what FlexibleRod or the sweep rejects)."""
    for name in ("inertia", "radius"):
        if _given(row, name) is not None:
            raise ValueError(f"a flexible rod takes no {name!r} (its inertia follows the beam)")
    length, tip, mass = (_given(row, n) for n in ("length", "tip_radius", "mass"))
    return FlexibleRod(
        length=PAPER_ROD.length if length is None else length,
        tip_radius=PAPER_ROD.tip_radius if tip is None else tip,
        mass=PAPER_ROD.mass if mass is None else mass,
        material=material,
        n_axial=_count(row, "n_axial"),
        n_bending=_count(row, "n_bending"),
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


#: The inputs that vary per drop; the others (model inputs) define the body and the law.
KINEMATICS = ("angle", "vx", "vy", "spin", "mu")


def _groups(cases: Mapping[str, np.ndarray], names: Sequence[str]) -> list[np.ndarray]:
    """The case indices of each distinct combination of the inputs ``names`` (bitwise: NaN,
    unset, is one value), in order of first appearance."""
    n = len(cases["angle"])
    if not names:
        return [np.arange(n)]
    rows = np.ascontiguousarray(np.stack([cases[k] for k in names], axis=1), dtype=np.float64)
    keys = rows.view(np.dtype((np.void, rows.itemsize * rows.shape[1]))).ravel()
    _, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
    order = np.argsort(first, kind="stable")
    return [np.flatnonzero(inverse == g) for g in order]


def _drops(
    parts: tuple[FlexibleRod, Material, ContactModel],
    kin: Mapping[str, np.ndarray],
    statics: Statics,
) -> tuple[DropBatchResult | None, np.ndarray]:
    """The drops of one body (``simulate_drops``, one compiled call) and the status of each:
    the refusals of the inputs first (``drop_batch.input_status``: the rules of every impact,
    a tip that does not approach the flat), then the drop's."""
    body, flat, model = parts
    engine = dict(statics.engine)
    try:
        g, r = gravity_value(engine.get("gravity", True)), drop_rtol(engine.get("rtol"))
    except ValueError:  # refused for every case (simulate_drops names it)
        g, r = 0.0, math.nan
    status = input_status(body.rigid(), kin, g, r)
    run = status == 0
    status[status == S.ST_BAD_INPUT] = STATUS_BAD_INPUT
    if not np.any(run):
        return None, status
    try:
        drops = simulate_drops(
            body,
            flat,
            law=model,
            friction=statics.categories["friction"],
            **{k: v[run] for k, v in kin.items()},
            gravity=engine.get("gravity", True),
            rtol=engine.get("rtol"),
        )
    except ValueError:  # an input the drop refuses for every case (its message names it)
        status[run] = STATUS_BAD_INPUT
        return None, status
    st = drops.status.astype(np.int32)
    st[st == S.ST_BAD_INPUT] = STATUS_BAD_INPUT
    status[run] = st
    return drops, status


def evaluate_flexible(
    cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """One chunk of flexible-rod cases (the Evaluator call of ``impactlab.sweep.engine``):
    ({output: (N,) array}, status (N,) int32); outputs the drop does not define are NaN. The
    cases of each distinct body run in one compiled batch (``simulate_drops``)."""
    n = len(cases["angle"])
    status = np.zeros(n, dtype=np.int32)
    res = {o: np.full(n, np.nan) for o in outputs}
    cat = tuple(sorted(statics.categories.items()))
    lp = tuple(sorted(statics.law_params.items()))
    model_inputs = sorted(set(cases) - set(KINEMATICS))
    for idx in _groups(cases, model_inputs):
        row = tuple((name, float(cases[name][idx[0]])) for name in model_inputs)
        st, parts = _models(cat, row, lp)
        if st:
            status[idx] = st
            continue
        kin = {k: np.asarray(cases[k][idx], dtype=np.float64) for k in KINEMATICS}
        drops, status[idx] = _drops(parts, kin, statics)
        if drops is None:
            continue
        ran = idx[status[idx] == 0]
        ok = drops.status == 0
        for o in outputs:
            if o in DROP_OUTPUTS:
                res[o][ran] = np.asarray(DROP_OUTPUTS[o](drops), dtype=np.float64)[ok]
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
    """The study-level checks of a flexible rod (``Study``'s fixed values, grid axes, sample and
    engine options):
    the flexible inputs need ``body = "flexible_rod"`` among the bodies, and a flexible rod
    follows its rotation (no ``[engine] constant_angle = true``) and its ``rtol`` is at most
    ``DROP_RTOL_MAX``; ``[engine] partial_slip_cells`` (``options.check_cells_study``)."""
    bodies = {args["fixed"].get("body", "rod")}
    frictions = {str(args["fixed"].get("friction", get_input("friction").default))}
    set_names = set(args["fixed"])
    for axis in args["grid"]:
        set_names.add(axis.name)
        if axis.name == "body":
            bodies = {str(v) for v in axis.values}
        if axis.name == "friction":
            frictions = {str(v) for v in axis.values}
    check_cells_study(args["engine"], bodies, frictions)
    if args.get("sample") is not None:
        set_names |= set(args["sample"].inputs)
    given = sorted(set_names & set(FLEXIBLE_INPUTS))
    if given and FLEXIBLE_BODY not in bodies:
        raise ValueError(
            f"{', '.join(given)}: inputs of a flexible rod; set body = {FLEXIBLE_BODY!r} "
            f"(the study's bodies: {', '.join(sorted(bodies))})"
        )
    rtol = args["engine"].rtol
    if FLEXIBLE_BODY in bodies and rtol is not None and float(rtol) > DROP_RTOL_MAX:
        raise ValueError(
            f"[engine] rtol {float(rtol):g} is too loose for a flexible rod's drop (allowed: up to "
            f"{DROP_RTOL_MAX:g}; beyond it the integrator creates energy and contacts): lower it "
            f"for body = {FLEXIBLE_BODY!r}"
        )
    if FLEXIBLE_BODY in bodies and args["engine"].constant_angle:
        raise ValueError(
            "[engine] constant_angle = true freezes the rigid engine's lever arms; a flexible "
            "rod's drop follows its rotation: remove it for body = 'flexible_rod'"
        )
