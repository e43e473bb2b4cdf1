"""Candidate models and their predictions for every drop at many parameter values at once.

A candidate model is a contact law x a friction model x a body model (each drop's own rigid
body, or the flexible rod). ``predict`` evaluates W parameter vectors on D drops as one batch of
W x D cases through the sweep's engine adapter (``impactlab.sweep.engine.ENGINE``: the compiled
batch engine on every core for rigid bodies, one compiled batch of drops per body for the
flexible rod, ``sweep.flexible``); the flexible rod on a rate-dependent flat, which the batch
engines do not run, goes through ``simulate`` one case at a time with the same engine options
(measured in benchmarks/bench_calibrate.py).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import numba
import numpy as np

from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod, Sphere
from impactlab.calibrate.fixed import fixed_values, law_param_values
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.priors import Parameter
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.contact import get_law
from impactlab.contact.rate import RATE_LAWS
from impactlab.dynamics import simulate
from impactlab.dynamics.derived import e_gravity_removed
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.input_checks import gravity_value
from impactlab.dynamics.kernels.status import STATUS_MESSAGES
from impactlab.flags import (
    FLAG_BEYOND_TIP,
    FLAG_BRITTLE,
    FLAG_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED,
    FLAG_LAW_EXTRAPOLATED,
    FLAG_OTHER_END,
)
from impactlab.friction import get_friction
from impactlab.materials import get_material
from impactlab.sweep.engine import ENGINE, Evaluator
from impactlab.sweep.flexible import DROP_OUTPUTS, FLEXIBLE_BODY, MEASURED_AS, flexible_body
from impactlab.sweep.inputs import MATERIAL_OVERRIDES
from impactlab.sweep.material_inputs import CUSTOM
from impactlab.sweep.models import Statics, material_for
from impactlab.sweep.status import SWEEP_STATUS_MESSAGES

__all__ = [
    "CandidateModel",
    "Prediction",
    "case_body",
    "output_value",
    "predict",
    "simulate_row",
    "whole_materials",
]

#: Status of a case that ran but broke physics (energy gain): a likelihood of zero.
STATUS_ENERGY_GAIN = 301
#: Status of a partial-slip case that ``simulate`` refused.
STATUS_REFUSED = 302
#: Status of a case flagged by another invalidating flag (``impactlab.flags``: not ``ok``), by
#: flag, in bit order: its outputs are not a prediction of the drop, a likelihood of zero.
STATUS_FLAGGED = {
    FLAG_ENERGY_GAIN: STATUS_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED: 303,
    FLAG_OTHER_END: 304,
    FLAG_BEYOND_TIP: 305,
    FLAG_BRITTLE: 306,
}
_OWN_MESSAGES = {
    STATUS_ENERGY_GAIN: "result flagged ENERGY_GAIN (breaks energy conservation)",
    STATUS_REFUSED: "simulate refused the case (or the drop failed)",
    303: "result flagged GRAVITY_DOMINATED (e and the impact measures not meaningful)",
    304: "result flagged OTHER_END (the other end landed: not one bounce of the tip)",
    305: "result flagged BEYOND_TIP (the flat reached the rim of the tip)",
    306: "result flagged BRITTLE (a brittle member past first yield)",
}


def status_message(code: int) -> str:
    """What a case status means (engine, sweep and calibration codes)."""
    code = int(code)
    return (
        _OWN_MESSAGES.get(code)
        or SWEEP_STATUS_MESSAGES.get(code)
        or STATUS_MESSAGES.get(code)
        or f"status {code}"
    )


#: Measured quantities a drop does not predict though their engine output has a drop column:
#: a signed ``contact_travel`` (the drop's scar_length, read for it, is the mark's unsigned
#: extent; it predicts the measured ``scar_length``, a magnitude).
DROP_UNPREDICTED = ("contact_travel",)


@dataclass(frozen=True)
class CandidateModel:
    """One physical model: ``law`` (a registered contact law), ``friction`` (a friction
    model), ``body`` (None: each drop's own rigid body; ``"flexible_rod"``: every rod is the
    flexible rod), ``fixed`` inputs this model sets for every drop (e.g. ``damping``; numbers in
    the input's unit or quantity strings, ``"300 MPa"``; ValueError naming the key for an
    unknown input or a value outside its range: ``calibrate.fixed``), the
    law's ``law_params`` (numbers in each parameter's unit or quantity strings, ``"105 HB"``;
    ValueError naming an unknown one) and, for the flexible rod, the flat's ``rate`` law
    (``"cowper-symonds"`` or ``"johnson-cook"``, ``impactlab.contact.rate``). ``name`` defaults to
    ``law/friction[/flexible_rod][/rate]``."""

    law: str = "ghaednia"
    friction: str = "coulomb"
    body: str | None = None
    fixed: Mapping[str, float | str] = field(default_factory=dict)
    law_params: Mapping[str, float] = field(default_factory=dict)
    name: str = ""
    rate: str | None = None

    def __post_init__(self) -> None:
        get_law(self.law)  # ValueError naming the known laws
        get_friction(self.friction)
        if self.body not in (None, FLEXIBLE_BODY):
            raise ValueError(f"model body must be None or {FLEXIBLE_BODY!r}, got {self.body!r}")
        if self.rate is not None and self.body != FLEXIBLE_BODY:
            raise ValueError(
                f"a rate law ({self.rate!r}) needs body={FLEXIBLE_BODY!r}: the rigid models of a "
                "calibration are impacts, and a rate-dependent flat is a drop's "
                "(`impactlab drop --rigid --rate` runs one rigid rod)"
            )
        if self.rate not in (None, *RATE_LAWS):
            raise ValueError(f"unknown rate law {self.rate!r}; known: {', '.join(RATE_LAWS)}")
        if not self.name:
            parts = [self.law, self.friction] + ([self.body] if self.body else [])
            parts += [self.rate] if self.rate else []
            object.__setattr__(self, "name", "/".join(parts))
        object.__setattr__(self, "fixed", fixed_values(self.name, self.fixed))
        object.__setattr__(
            self, "law_params", law_param_values(self.name, self.law, self.law_params)
        )

    def unsupported(self, quantities: Sequence[str]) -> list[str]:
        """The measured ``quantities`` this model does not predict: the flexible drop defines
        fewer outputs than the rigid engine (``sweep.flexible.DROP_OUTPUTS``), a measured
        duration or mean force is one contact's (``MEASURED_AS``), and a signed contact_travel
        has no counterpart in a drop (:data:`DROP_UNPREDICTED`)."""
        if self.body != FLEXIBLE_BODY:
            return []
        drop = set(DROP_OUTPUTS)
        return [
            q
            for q in quantities
            if q in DROP_UNPREDICTED or not set(_drop_outputs(MEASURABLE[q].outputs)) <= drop
        ]

    @property
    def batched(self) -> bool:
        """True when the sweep's engine adapter runs this model (every model but the flexible
        rod on a rate-dependent flat)."""
        return self.rate is None


@dataclass(frozen=True)
class Prediction:
    """W x D predictions: ``values`` quantity -> (W, D) (NaN where a case failed),
    ``status`` (W, D) (0: finished; ``status_message``) and ``extrapolated`` (W, D): True where an
    ok case's contact law was used beyond its verified range (the advisory LAW_EXTRAPOLATED
    flag, ``impactlab.flags``; None: not known)."""

    values: Mapping[str, np.ndarray]
    status: np.ndarray
    extrapolated: np.ndarray | None = None


def _drop_outputs(outputs: Sequence[str]) -> list[str]:
    """The store columns of a drop that give the engine ``outputs`` an experiment measures (a
    dent depth is the drop's final dent: ``sweep.flexible.MEASURED_AS``)."""
    return [MEASURED_AS.get(o, o) for o in outputs]


def _engine_outputs(quantities: Sequence[str]) -> list[str]:
    outs = [o for q in quantities for o in MEASURABLE[q].outputs]
    return [*dict.fromkeys(outs), "flags"]


def _groups(
    meas: Measurements, model: CandidateModel
) -> dict[tuple[tuple[str, str], ...], list[int]]:
    """Drops grouped by their categories (one engine call per group)."""
    groups: dict[tuple[tuple[str, str], ...], list[int]] = {}
    for d, cat in enumerate(meas.categories):
        c = dict(cat)
        if model.body == FLEXIBLE_BODY:
            if c["body"] == "sphere":
                raise ValueError(
                    f"model {model.name!r}: drop {meas.labels[d]!r} is a sphere; the flexible "
                    "body model applies to rods"
                )
            c["body"] = FLEXIBLE_BODY
        c.update(law=model.law, friction=model.friction)
        groups.setdefault(tuple(sorted(c.items())), []).append(d)
    return groups


#: Below this many cases a batch runs on one thread: the engine's threads meet at the end of
#: each call, and on a busy machine that wait costs more than a small batch (measured: 18
#: cases, 2 ms on one thread, 6 ms on two; a whole 12-walker chain 1.4 s against 10 s).
THREADED_MIN_CASES = 2048


@contextmanager
def _threads_for(n_cases: int) -> Iterator[None]:
    before = numba.get_num_threads()
    if n_cases < THREADED_MIN_CASES and before > 1:
        numba.set_num_threads(1)
    try:
        yield
    finally:
        numba.set_num_threads(before)


def predict(
    model: CandidateModel,
    meas: Measurements,
    params: Sequence[Parameter],
    theta: np.ndarray,
    *,
    evaluator: Evaluator = ENGINE,
    engine: Mapping[str, Any] | None = None,
) -> Prediction:
    """Predict every measured quantity of every drop at each row of ``theta`` (W, P), the
    values of ``params`` (SI). One evaluator call per group of drops sharing their categories."""
    theta = np.atleast_2d(np.asarray(theta, dtype=np.float64))
    w, d_all = theta.shape[0], meas.n_drops
    quantities = meas.quantities
    flexible = model.body == FLEXIBLE_BODY
    # a rigid impact's e without the gravity impulse of its contact, as a drop's e
    e_parts = ("vn_in", "vn_out", "duration") if "e" in quantities and not flexible else ()
    base = _engine_outputs(quantities)
    outputs = [*base, *(o for o in e_parts if o not in base)]
    g = gravity_value(dict(engine or {}).get("gravity", True))
    values = {q: np.full((w, d_all), np.nan) for q in quantities}
    status = np.zeros((w, d_all), dtype=np.int32)
    extrapolated = np.zeros((w, d_all), dtype=bool)
    for key, idx in _groups(meas, model).items():
        nd = len(idx)
        cases = {k: np.tile(v[idx], w) for k, v in meas.inputs.items()}
        for k, v in model.fixed.items():
            cases[k] = np.full(w * nd, float(v))
        for j, p in enumerate(params):
            cases[p.name] = np.repeat(theta[:, j], nd)
        categories = whole_materials(dict(key), cases)
        statics = Statics(categories, dict(model.law_params), dict(engine or {}))
        asked = _drop_outputs(outputs) if flexible else outputs
        if model.batched:
            with _threads_for(w * nd):
                res, st = evaluator(cases, statics, asked)
        else:
            res, st = _one_by_one(cases, statics, asked, model.rate)
        res = {o: res[a] for o, a in zip(outputs, asked, strict=True)}
        if e_parts:
            res["e"] = e_gravity_removed(res["vn_in"], res["vn_out"], res["duration"], g)
        st = np.asarray(st, dtype=np.int32).copy()
        flags = np.nan_to_num(res["flags"], nan=0.0).astype(np.int64)
        for flag, code in STATUS_FLAGGED.items():  # a case flagged twice: its lowest bit
            st[(st == 0) & ((flags & flag) != 0)] = code
        status[:, idx] = st.reshape(w, nd)
        advisory = (st == 0) & ((flags & FLAG_LAW_EXTRAPOLATED) != 0)
        extrapolated[:, idx] = advisory.reshape(w, nd)
        for q in quantities:
            got = _derived(q, res, cases)
            values[q][:, idx] = np.where(st == 0, got, np.nan).reshape(w, nd)
    return Prediction(values, status, extrapolated)


def whole_materials(cat: dict[str, str], cases: dict[str, np.ndarray]) -> dict[str, str]:
    """A calibrated material property (``flat_yield_strength``, ...) of a library material: the
    cases get every property of that material as columns, the free one replaced, and the side's
    material is ``"custom"`` (a library material is never partly changed,
    ``sweep.material_inputs``). ``cases`` is completed in place; returns the categories."""
    for side, fields in MATERIAL_OVERRIDES.items():
        key = f"{side}_material"
        given = [n for n in fields if n in cases and not np.isnan(cases[n]).all()]
        if cat.get(key) == CUSTOM or not given:
            continue
        base = get_material(cat[key], key)
        n = len(next(iter(cases.values())))
        for name, attr in fields.items():
            value = getattr(base, attr, None)
            library = np.full(n, np.nan if value is None else float(value))
            column = cases.get(name)
            cases[name] = library if column is None else np.where(np.isnan(column), library, column)
        cat[key] = CUSTOM
    return cat


def _derived(q: str, res: Mapping[str, np.ndarray], cases: Mapping[str, np.ndarray]) -> Any:
    """Measurable ``q`` from the engine outputs ``res`` of ``cases``."""
    if q == "e_t":
        return res["vx_out"] / cases["vx"]
    if q == "sliding_distance":
        return np.abs(res["sliding_length"])
    if q == "scar_length":  # an impact's travel; a drop's scar_length (MEASURED_AS), >= 0
        return np.abs(res["contact_travel"])
    return res[MEASURABLE[q].outputs[0]]


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


def _one_by_one(
    cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str], rate: str | None
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """One ``simulate`` call per case (:func:`simulate_row`, the engine options of the batch),
    for the flexible rod on a rate-dependent flat. A refused case or a failed drop gets
    STATUS_REFUSED, never an exception."""
    n = len(cases["angle"])
    res = {o: np.full(n, np.nan) for o in outputs}
    status = np.zeros(n, dtype=np.int32)
    for i in range(n):
        row = {k: float(v[i]) for k, v in cases.items()}
        try:
            r = simulate_row(case_body(statics.categories, row), statics, row, rate or None)
        except (ValueError, ArithmeticError, np.linalg.LinAlgError):
            status[i] = STATUS_REFUSED
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
