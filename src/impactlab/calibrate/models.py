"""Candidate models and their predictions for every drop at many parameter values at once.

A candidate model is a contact law x a friction model x a body model (each drop's own rigid
body, or the flexible rod). ``predict`` evaluates W parameter vectors on D drops as one batch of
W x D cases through the sweep's engine adapter (``impactlab.sweep.engine.ENGINE``: the compiled
batch engine on every core for rigid bodies, one compiled batch of drops per body for the
flexible rod, ``sweep.flexible``); the flexible rod on a rate-dependent flat, which the batch
engines do not run, goes through ``simulate`` one case at a time with the same engine options
(``calibrate.one_by_one``; measured in benchmarks/bench_calibrate.py).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import numba
import numpy as np

from impactlab.calibrate.case_status import (  # noqa: F401  (re-exported: the old home)
    STATUS_ENERGY_GAIN,
    STATUS_FLAGGED,
    STATUS_REFUSED,
    status_message,
)
from impactlab.calibrate.fixed import fixed_values, law_param_values
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.one_by_one import (  # noqa: F401  (re-exported: the old home)
    SIMULATE_OPTIONS,
    case_body,
    output_value,
    simulate_options,
    simulate_row,
)
from impactlab.calibrate.one_by_one import one_by_one as _one_by_one
from impactlab.calibrate.priors import Parameter
from impactlab.calibrate.quantities import MEASURABLE, canonical_output
from impactlab.contact import get_law
from impactlab.contact.rate import RATE_LAWS
from impactlab.dynamics.derived import e_gravity_removed
from impactlab.dynamics.input_checks import gravity_value
from impactlab.flags import FLAG_LAW_EXTRAPOLATED
from impactlab.friction import PARTIAL_SLIP_CELLS, get_friction
from impactlab.materials import get_material
from impactlab.sweep.engine import ENGINE, Evaluator
from impactlab.sweep.flexible import DROP_OUTPUTS, FLEXIBLE_BODY, MEASURED_AS
from impactlab.sweep.inputs import MATERIAL_OVERRIDES
from impactlab.sweep.material_inputs import CUSTOM
from impactlab.sweep.models import Statics

__all__ = [
    "CandidateModel",
    "Prediction",
    "case_body",
    "output_value",
    "predict",
    "simulate_row",
    "whole_materials",
]


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
    flag, ``impactlab.flags``; None: not known); ``refused``: why ``simulate`` refused the cases
    of status STATUS_REFUSED (``one_by_one.refusal_key`` -> (cases, the first error's text)).
    """

    values: Mapping[str, np.ndarray]
    status: np.ndarray
    extrapolated: np.ndarray | None = None
    refused: Mapping[str, tuple[int, str]] = field(default_factory=dict)


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


def _checked_theta(theta: Any, params: Sequence[Parameter]) -> np.ndarray:
    """``theta`` as a (W, P) float array, P the number of ``params``; ValueError for another
    shape and for a value that is not finite, naming the parameter (a NaN would be read as
    "unset" downstream, the preset's value)."""
    arr = np.atleast_2d(np.asarray(theta, dtype=np.float64))
    names = ", ".join(p.name for p in params)
    if arr.ndim != 2 or arr.shape[1] != len(params):
        raise ValueError(
            f"theta must have shape (W, {len(params)}), a row of ({names}) per draw, got "
            f"{arr.shape}"
        )
    bad = ~np.isfinite(arr)
    if bad.any():
        row, col = (int(i) for i in np.argwhere(bad)[0])
        raise ValueError(
            f"theta[{row}, {col}] ({params[col].name}) is {float(arr[row, col])!r}; every value of "
            f"({names}) must be finite"
        )
    return arr


def predict(
    model: CandidateModel,
    meas: Measurements,
    params: Sequence[Parameter],
    theta: np.ndarray,
    *,
    evaluator: Evaluator = ENGINE,
    engine: Mapping[str, Any] | None = None,
    quantities: Sequence[str] | None = None,
) -> Prediction:
    """Predict every measured quantity of every drop (or the measurable ``quantities``, aliases
    too: drops without measurements, ``Measurements.conditions``) at each row of ``theta``
    (W, P), the values of ``params`` (SI). One evaluator call per group of drops sharing their
    categories. ValueError naming a quantity that is not measurable or that ``model`` does not
    predict."""
    _check_cells(model, engine)
    theta = _checked_theta(theta, params)
    w, d_all = theta.shape[0], meas.n_drops
    quantities = meas.quantities if quantities is None else _quantities(model, quantities)
    flexible = model.body == FLEXIBLE_BODY
    # a rigid impact's e without the gravity impulse of its contact, as a drop's e
    e_parts = ("vn_in", "vn_out", "duration") if "e" in quantities and not flexible else ()
    base = _engine_outputs(quantities)
    outputs = [*base, *(o for o in e_parts if o not in base)]
    g = gravity_value(dict(engine or {}).get("gravity", True))
    values = {q: np.full((w, d_all), np.nan) for q in quantities}
    status = np.zeros((w, d_all), dtype=np.int32)
    extrapolated = np.zeros((w, d_all), dtype=bool)
    refusals: dict[str, list[Any]] = {}
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
            res, st = _one_by_one(cases, statics, asked, model.rate, refusals)
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
    refused = {k: (int(n), str(text)) for k, (n, text) in refusals.items()}
    return Prediction(values, status, extrapolated, refused)


def _quantities(model: CandidateModel, names: Sequence[str]) -> tuple[str, ...]:
    """``names`` as measurable quantities (aliases resolved); ValueError for one that is not
    measurable or that ``model`` does not predict."""
    out = []
    for name in [names] if isinstance(names, str) else names:
        q = canonical_output(str(name))
        if q is None:
            raise ValueError(
                f"quantity {name!r} is not a measurable quantity; known: {', '.join(MEASURABLE)}"
            )
        out.append(q)
    missing = model.unsupported(out)
    if missing:
        raise ValueError(f"model {model.name!r} does not predict {', '.join(missing)}")
    return tuple(dict.fromkeys(out))


def _check_cells(model: CandidateModel, engine: Mapping[str, Any] | None) -> None:
    """ValueError when ``engine`` sets ``partial_slip_cells`` to another count than the default
    for a model that never uses it (only a rigid body with friction ``partial_slip`` does; a
    flexible rod's drop has its compiled cells), as ``calibrate`` refuses it."""
    n = dict(engine or {}).get("partial_slip_cells")
    if n is None or n == PARTIAL_SLIP_CELLS:
        return
    friction = get_friction(model.friction).name
    if friction != "partial_slip" or model.body is not None:
        kind = (
            "a flexible rod's drop (its cells are compiled)"
            if model.body
            else (f"friction {friction!r}")
        )
        raise ValueError(
            f"engine partial_slip_cells = {n} sets the cells of friction 'partial_slip' on a "
            f"rigid body only, and model {model.name!r} is {kind}: leave it out"
        )


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
