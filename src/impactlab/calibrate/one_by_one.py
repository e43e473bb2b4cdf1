"""Cases run one at a time through ``simulate`` (the flexible rod on a rate-dependent flat, which
the batch engines do not run) with the batch's engine options: a case's body, its ``simulate``
call and an engine output read from its result (SI)."""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod, Sphere
from impactlab.calibrate.case_status import STATUS_REFUSED
from impactlab.dynamics import simulate
from impactlab.dynamics.drop_result import DropResult
from impactlab.sweep.flexible import DROP_OUTPUTS, FLEXIBLE_BODY, flexible_body
from impactlab.sweep.models import Statics, material_for

__all__ = [
    "SIMULATE_OPTIONS",
    "case_body",
    "one_by_one",
    "output_value",
    "refusal_key",
    "simulate_options",
    "simulate_row",
]


def case_body(cat: Mapping[str, str], row: Mapping[str, float]) -> Rod | Sphere | FlexibleRod:
    """The body of the case ``row`` (SI inputs; NaN: not given) with the categories ``cat``:
    a FlexibleRod, a Sphere, or a Rod (the paper's geometry and mass where not given)."""
    mat = material_for("body", cat["body_material"], row)

    def given(name: str, default: Any = None) -> Any:
        v = row.get(name, np.nan)
        return default if np.isnan(v) else float(v)

    if cat["body"] == FLEXIBLE_BODY:
        return flexible_body(row, mat)
    if cat["body"] == "sphere":
        return Sphere(radius=given("radius"), mass=given("mass"), material=mat)
    return Rod(
        length=given("length", PAPER_ROD.length),
        tip_radius=given("tip_radius", PAPER_ROD.tip_radius),
        mass=given("mass", PAPER_ROD.mass),
        material=mat,
        inertia=given("inertia"),
    )


#: The engine options (``Statics.engine``) ``simulate`` takes, by body, as the batch engines
#: take them: a rigid body's (``sweep.engine.evaluate``), a drop's (``sweep.flexible``).
_RIGID_OPTIONS = ("gravity", "rtol", "constant_angle", "partial_slip_cells")
SIMULATE_OPTIONS = {"rigid": _RIGID_OPTIONS, FLEXIBLE_BODY: ("gravity", "rtol")}


def simulate_options(statics: Statics) -> dict[str, Any]:
    """The keyword arguments of ``simulate`` from the engine options of ``statics`` (gravity on
    when not given; the cells for friction ``partial_slip`` only), so that a case run one by
    one has the numerics of the batch."""
    cat, engine = statics.categories, dict(statics.engine)
    keys = SIMULATE_OPTIONS[FLEXIBLE_BODY if cat["body"] == FLEXIBLE_BODY else "rigid"]
    out = {k: engine[k] for k in keys if engine.get(k) is not None}
    if cat["friction"] != "partial_slip":
        out.pop("partial_slip_cells", None)
    return {"gravity": True} | out


def simulate_row(body: Any, statics: Statics, row: Mapping[str, float], rate: Any = None) -> Any:
    """``simulate`` of the case ``row`` (its flat, kinematics and mu; the categories' law and
    friction, the study's engine options: gravity, rtol, ... (:func:`simulate_options`), and
    law parameters) on ``body``, without its history; the flat's ``rate`` law (a name or a
    RateLaw) for a flexible rod. Its errors propagate."""
    cat = statics.categories
    return simulate(
        body,
        material_for("flat", cat["flat_material"], row),
        law=cat["law"],
        friction=cat["friction"],
        mu=row["mu"],
        angle=row["angle"] if cat["body"] != "sphere" else None,
        velocity=(row["vx"], row["vy"]),
        spin=row["spin"],
        law_params=dict(statics.law_params) or None,
        history=False,
        **simulate_options(statics),
        **({"rate": rate} if rate is not None else {}),
    )


_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def refusal_key(text: str) -> str:
    """The reason of a refusal without its numbers: the refusals of one rule at different
    values (``yield strength = 110 MPa outside 150 to 450 MPa``, ``= 520 MPa ...``) are one."""
    return _NUMBER.sub("#", text)


def one_by_one(
    cases: Mapping[str, np.ndarray],
    statics: Statics,
    outputs: Sequence[str],
    rate: str | None,
    refusals: dict[str, list[Any]] | None = None,
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """One ``simulate`` call per case (:func:`simulate_row`, the engine options of the batch),
    for the flexible rod on a rate-dependent flat. A refused case or a failed drop gets
    STATUS_REFUSED, never an exception; ``refusals`` (when given) collects why: the reason's
    :func:`refusal_key` -> [cases, the first error's text] (a rate law's material range, ...)."""
    n = len(cases["angle"])
    res = {o: np.full(n, np.nan) for o in outputs}
    status = np.zeros(n, dtype=np.int32)
    for i in range(n):
        row = {k: float(v[i]) for k, v in cases.items()}
        try:
            r = simulate_row(case_body(statics.categories, row), statics, row, rate or None)
        except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
            status[i] = STATUS_REFUSED
            if refusals is not None:
                text = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
                refusals.setdefault(refusal_key(text), [0, text])[0] += 1
            continue
        for o in outputs:
            res[o][i] = output_value(r, o)
    return res, status


def output_value(result: Any, output: str) -> float:
    """An engine output field of an ImpactResult or a DropResult (``DROP_OUTPUTS``)."""
    if isinstance(result, DropResult):
        read = DROP_OUTPUTS.get(output)
        return math.nan if read is None else float(read(result))
    if output in ("vx_out", "vy_out"):
        return float(result.velocity_out[0 if output == "vx_out" else 1])
    return float(getattr(result, output))
