"""What ``calibrate`` checks before it samples: the free parameters, the sampler's settings,
the drops' inputs against the parameters and models (mu given or free, one material property
for drops on one material, an input not both fixed and free, a rod's mass where the paper's
is not the rod's), which model uses which
parameter and which fixed input changes none of a model's predictions."""

from __future__ import annotations

import dataclasses
import math
import operator
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD
from impactlab.calibrate.fixed import quantity_object
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.models import CandidateModel, predict
from impactlab.calibrate.priors import Parameter, parse_parameter
from impactlab.calibrate.values import to_unit
from impactlab.dynamics.input_checks import check_partial_slip_cells, gravity_value
from impactlab.friction import PARTIAL_SLIP_CELLS, get_friction
from impactlab.materials import get_material
from impactlab.sweep.dimensions import check_allowed
from impactlab.sweep.engine import Evaluator
from impactlab.sweep.inputs import INPUTS, MATERIAL_OVERRIDES
from impactlab.sweep.material_inputs import CUSTOM
from impactlab.sweep.options import EngineOptions, check_cells_study

__all__ = [
    "check_calibration_inputs",
    "check_engine_cells",
    "engine_options",
    "parameter_usage",
    "parameters",
    "sampler_settings",
    "unused_fixed",
]

#: The largest seed (numpy's legacy RandomState, which emcee's moves use, takes 32 bits).
MAX_SEED = 2**32 - 1


def parameters(given: Sequence[Parameter] | Mapping[str, Any]) -> tuple[Parameter, ...]:
    """The free parameters (Parameters, or name -> prior text); ValueError for none or one
    given twice."""
    if isinstance(given, Mapping):
        out = tuple(
            v if isinstance(v, Parameter) else parse_parameter(k, v) for k, v in given.items()
        )
    elif isinstance(given, Sequence) and not isinstance(given, str):
        out = tuple(given)
        for i, p in enumerate(out):
            if not isinstance(p, Parameter):
                raise ValueError(
                    f"parameters[{i}] is {p!r}, not a Parameter: give Parameters, or a mapping "
                    "of names to priors, e.g. {'mu': 'uniform(0, 1)'}"
                )
    else:
        raise ValueError(
            "parameters must be a mapping of names to priors, e.g. {'mu': 'uniform(0, 1)'}, or "
            f"a sequence of Parameters, got {given!r}"
        )
    if not out:
        raise ValueError("calibrate needs at least one free parameter")
    names = [p.name for p in out]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise ValueError(f"a free parameter is given twice: {', '.join(twice)}")
    return out


#: The options of a calibration's ``[engine]`` table (``engine=`` of ``calibrate``).
ENGINE_OPTIONS = ("gravity", "rtol", "partial_slip_cells")


def engine_options(engine: Mapping[str, Any] | None) -> tuple[dict[str, Any], float]:
    """(the engine options, the gravity in m/s^2): ``gravity``, ``rtol`` and
    ``partial_slip_cells`` (friction ``partial_slip``'s cells) as given, a quantity object of
    results.json (``{"value": 9.80665, "unit": "m/s^2"}``) read as its number in the option's
    unit. ValueError for an unknown option, and a gravity, an rtol or a cell count that the
    engine refuses."""
    eng = dict(engine or {})
    unknown = sorted(set(eng) - set(ENGINE_OPTIONS))
    if unknown:
        raise ValueError(f"unknown engine option(s) {unknown}; known: {', '.join(ENGINE_OPTIONS)}")
    if eng.get("partial_slip_cells") is not None:
        eng["partial_slip_cells"] = check_partial_slip_cells(eng["partial_slip_cells"])
    if isinstance(eng.get("gravity"), Mapping):
        eng["gravity"] = gravity_value(quantity_object(eng["gravity"]))
    if isinstance(eng.get("rtol"), Mapping):
        rtol = quantity_object(eng["rtol"])
        eng["rtol"] = rtol if isinstance(rtol, Mapping) else to_unit(rtol, "1", name="rtol")
    g = gravity_value(eng.get("gravity", True))
    EngineOptions(rtol=eng.get("rtol"))  # ValueError for an rtol the engine refuses
    return eng, g


def check_engine_cells(eng: Mapping[str, Any], models: Sequence[CandidateModel]) -> None:
    """ValueError, in the words of a sweep (``sweep.options.check_cells_study``), when ``[engine]
    partial_slip_cells`` (``eng``, checked by :func:`engine_options`) sets another count than
    the default and no candidate model is a rigid body with friction ``partial_slip``: the
    others never use it (a flexible rod's drop has its compiled cells). With such a model among
    others it applies to that model's impacts."""
    n = eng.get("partial_slip_cells")
    if n is None or n == PARTIAL_SLIP_CELLS:
        return
    kinds = [(get_friction(c.friction).name, c.body) for c in models]
    if ("partial_slip", None) in kinds:  # a rigid body's partial slip uses them
        return
    frictions = {f for f, _ in kinds}
    if "partial_slip" in frictions:  # only flexible rods' partial slip
        check_cells_study(EngineOptions(partial_slip_cells=n), {"flexible_rod"}, frictions)
    raise ValueError(
        f"[engine] partial_slip_cells = {n} sets the cells of friction 'partial_slip' only, "
        f"and the candidate models' friction is {', '.join(sorted(frictions))}: leave it out"
    )


def _integer(name: str, value: Any) -> int:
    """``value`` as an int; ValueError naming ``name`` for a float, text or a bool."""
    try:
        if isinstance(value, bool):
            raise TypeError
        return operator.index(value)
    except TypeError:
        raise ValueError(f"{name} must be an integer, got {value!r}") from None


def check_n_ppc(value: Any) -> int:
    """The posterior draws a calibration re-runs for its predictive checks: an integer >= 0
    (0: the best fit only); ValueError naming ``n_ppc`` before any step is sampled."""
    n = _integer("n_ppc", value)
    if n < 0:
        raise ValueError(
            f"n_ppc must be an integer >= 0 (posterior draws re-run for the predictive checks; 0: "
            f"the best fit only), got {value!r}"
        )
    return n


#: The most values the chain holds (walkers x steps x parameters, float64: 1.6 GB).
MAX_CHAIN_VALUES = 200_000_000


def sampler_settings(
    n_params: int, walkers: int | None, steps: int, burn: int | None, seed: int
) -> tuple[int, int, int, int]:
    """(walkers, steps, burn, seed) checked: walkers >= max(4, 2 P) (default max(16, 4 P),
    made even), steps >= 10, 0 <= burn < steps (default steps // 2), 0 <= seed < 2^32."""
    least = max(4, 2 * n_params)
    if walkers is not None and _integer("walkers", walkers) < least:
        raise ValueError(f"walkers must be >= {least} (4 and 2 x parameters), got {walkers}")
    nw = walkers if walkers is not None else max(16, 4 * n_params)
    nw += nw % 2
    if _integer("steps", steps) < 10:
        raise ValueError(f"steps must be >= 10, got {steps}")
    most = MAX_CHAIN_VALUES // (nw * max(1, n_params))
    if steps > most:  # refused before the chain's arrays are made
        raise ValueError(
            f"steps must be at most {most:,} with {nw} walkers and {n_params} parameter(s) (the "
            f"chain holds at most {MAX_CHAIN_VALUES:.0e} values, 1.6 GB), got {steps:,}"
        )
    nburn = steps // 2 if burn is None else _integer("burn", burn)
    if not 0 <= nburn < steps:
        raise ValueError(f"burn must lie in [0, steps), got {burn}")
    if not 0 <= _integer("seed", seed) <= MAX_SEED:
        raise ValueError(f"seed must be an integer in [0, {MAX_SEED}], got {seed!r}")
    return int(nw), int(steps), int(nburn), int(seed)


def check_calibration_inputs(
    meas: Measurements,
    params: Sequence[Parameter],
    models: Sequence[CandidateModel],
    note: list[str],
) -> None:
    """ValueError for drops without mu when mu is not free, for a material property calibrated
    over drops on different materials, and for an input a model fixes that is also free; a
    note (appended to ``note``) for drop values a free parameter replaces."""
    free = {p.name for p in params}
    if "mu" not in free and not np.isfinite(meas.inputs["mu"]).all():
        missing = [
            lab for lab, m in zip(meas.labels, meas.inputs["mu"], strict=True) if math.isnan(m)
        ]
        raise ValueError(
            f"drops {missing} give no mu: give it in the measurements file or make mu a free "
            "parameter"
        )
    for p in params:
        given = np.isfinite(meas.inputs[p.name])
        if given.any():
            note.append(
                f"{p.name} is a free parameter: the value given for {int(given.sum())} drop(s) "
                "in the measurements is not used"
            )
    _one_material(meas, params)
    _rod_mass(meas, params, models)
    for m in models:
        both = sorted(free & set(m.fixed))
        if both:
            raise ValueError(
                f"model {m.name!r} fixes {', '.join(both)}, which is also a free parameter: "
                "remove it from the model's fixed inputs or from the parameters"
            )


def _rod_mass(
    meas: Measurements, params: Sequence[Parameter], models: Sequence[CandidateModel]
) -> None:
    """ValueError for a rod drop of another material or length than the paper's whose mass no
    one gives (the drop's ``mass``, a free ``mass`` or every model's fixed ``mass``): the
    default mass is the paper's rod's (``Rod``, ``impactlab drop`` and sweeps refuse it too)."""
    if "mass" in {p.name for p in params}:
        return
    unfixed = [m.name for m in models if "mass" not in m.fixed]
    if not unfixed:
        return
    free_length = "length" in {p.name for p in params}
    mass, length = meas.inputs.get("mass"), meas.inputs.get("length")
    for i, (label, cat) in enumerate(zip(meas.labels, meas.categories, strict=True)):
        if cat.get("body", "rod") == "sphere" or (mass is not None and np.isfinite(mass[i])):
            continue
        material = cat.get("body_material", INPUTS["body_material"].default)
        why = ""
        if free_length:
            why = "length is a free parameter"
        elif (
            length is not None
            and np.isfinite(length[i])
            and not math.isclose(length[i], PAPER_ROD.length, rel_tol=1e-9)  # "12 in"
        ):
            why = f"length = {length[i]:g} m"
        if material == CUSTOM or get_material(material) != PAPER_ROD.material:
            why = f"body_material = {material!r}"
        if why:
            raise ValueError(
                f"drop {label!r}: give the rod's mass (column 'mass', a free parameter mass or "
                f"a model's fixed mass; missing for model(s) {', '.join(unfixed)}): {why}, and "
                f"the default is the paper's rod's, {PAPER_ROD.mass:g} kg, that of its AISI 201 "
                f"rod of length {PAPER_ROD.length:g} m"
            )


def _one_material(meas: Measurements, params: Sequence[Parameter]) -> None:
    """A free material property (``flat_yield_strength``, ...) is one value for every drop: the
    drops must share that side's material."""
    for side, fields in MATERIAL_OVERRIDES.items():
        key = f"{side}_material"
        calibrated = [p.name for p in params if p.name in fields]
        by_material: dict[str, list[str]] = {}
        for label, cat in zip(meas.labels, meas.categories, strict=True):
            by_material.setdefault(cat[key], []).append(label)
        if calibrated and len(by_material) > 1:
            groups = "; ".join(f"{k}: {', '.join(v)}" for k, v in by_material.items())
            raise ValueError(
                f"{', '.join(calibrated)} is one free parameter for every drop, but the drops' "
                f"{key} differ ({groups}): one value cannot describe different materials; "
                "calibrate the drops of each material on their own"
            )


def parameter_usage(
    model: CandidateModel,
    meas: Measurements,
    params: Sequence[Parameter],
    evaluator: Evaluator,
    engine: Mapping[str, Any],
) -> list[bool]:
    """For each parameter: does changing it (over the prior's deciles 1, 3, 5, 7, 9, the
    others at their medians) change any prediction of ``model``? One batch of 5P + 1 vectors.
    (A parameter whose every value fails counts as used: the prior check names the reason.)"""
    med = np.array([float(p.quantile(0.5)) for p in params])
    levels = (0.1, 0.3, 0.5, 0.7, 0.9)
    rows = [med]
    for j, p in enumerate(params):
        for q in levels:
            t = med.copy()
            t[j] = float(p.quantile(q))
            rows.append(t)
    pred = predict(model, meas, params, np.array(rows), evaluator=evaluator, engine=engine)
    used = []
    k = len(levels)
    for j in range(len(params)):
        idx = list(range(1 + k * j, 1 + k * (j + 1)))
        same = all(
            np.array_equal(v[i], v[idx[0]], equal_nan=True)
            for v in pred.values.values()
            for i in idx[1:]
        ) and all(np.array_equal(pred.status[i], pred.status[idx[0]]) for i in idx[1:])
        all_failed = bool((pred.status[idx] != 0).all())
        used.append(not same or all_failed)
    return used


def _moved(name: str, x: float) -> float | None:
    """Another value of input ``name`` near ``x`` that its range allows (x +- 20 %, +- 0.1 or,
    for a count, +- 1), or None."""
    for y in (x * 1.2, x * 0.8, x + 0.1, x - 0.1, x + 1.0, x - 1.0):
        try:
            check_allowed(name, [y], name)
        except ValueError:
            continue
        if y != x:
            return y
    return None


def unused_fixed(
    model: CandidateModel,
    meas: Measurements,
    params: Sequence[Parameter],
    evaluator: Evaluator,
    engine: Mapping[str, Any],
) -> list[str]:
    """The inputs ``model`` fixes that change none of its predictions of the measured values
    (each moved by about 20 %, the free parameters at their prior medians): a rigid body's
    ``damping``, a Brinell hardness under a law that does not read it. One evaluation of the
    drops per fixed input, and one. (Cases that all fail tell nothing: counted as used.)"""
    if not model.fixed:
        return []
    theta = np.array([[float(p.quantile(0.5)) for p in params]])
    base = predict(model, meas, params, theta, evaluator=evaluator, engine=engine)
    if (base.status != 0).all():
        return []
    unused = []
    for name, x in model.fixed.items():
        y = _moved(name, float(x))
        if y is None:
            continue
        other = dataclasses.replace(model, fixed={**model.fixed, name: y})
        pred = predict(other, meas, params, theta, evaluator=evaluator, engine=engine)
        if np.array_equal(pred.status, base.status) and all(
            np.array_equal(pred.values[q], v, equal_nan=True) for q, v in base.values.items()
        ):
            unused.append(name)
    return unused
