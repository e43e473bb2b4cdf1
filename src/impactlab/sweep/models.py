"""The contact models and body vectors of a chunk's cases, built once per distinct combination
of the numeric inputs that enter them (cached per process) with the same builder as
``simulate`` (``impactlab.dynamics.models``). What the Python constructors reject becomes a
status code (``impactlab.sweep.status``), never an exception.

Whether a study's cases use the tabulated loading curve of their law (``contact.tabulate``, as
``simulate`` does) or its closed form is decided once per study (:func:`tabulates`), never by a
chunk's neighbours: with at most :data:`MAX_TABLES` distinct law rows every case gets its row's
table, and equals ``simulate`` bit for bit; beyond that (a table costs 10-20 impacts) the
closed forms, within about 1e-13 of the table (docs/sweep.md, "Bit for bit")."""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.bodies import NB, PAPER_ROD, Rod, Sphere
from impactlab.contact import get_law, law_names
from impactlab.contact.brittle import first_yield_pressure
from impactlab.contact.kernels import param_length
from impactlab.contact.tabulate import with_table
from impactlab.dynamics.models import body_params, build_contact_model
from impactlab.materials import Material, get_material
from impactlab.sweep.inputs import (
    BODY_INPUTS,
    CATEGORY_INPUTS,
    INPUTS,
    LAW_INPUTS,
    MATERIAL_OVERRIDES,
)
from impactlab.sweep.material_inputs import CUSTOM, material_of
from impactlab.sweep.status import STATUS_BAD_BODY, STATUS_BAD_LAW, STATUS_BAD_MATERIAL


@dataclass(frozen=True)
class Statics:
    """What is constant over one engine call: the category inputs, the law parameters, the
    engine options, and whether each case uses its law row's table (True, a sweep's choice:
    :func:`tabulates`), the closed forms (False) or, None, the engine's own rule (a table only
    where every case shares one law row)."""

    categories: Mapping[str, str]
    law_params: Mapping[str, float] = field(default_factory=dict)
    engine: Mapping[str, Any] = field(default_factory=dict)
    tabulate: bool | None = None

    def __getitem__(self, name: str) -> str:
        return self.categories[name]


_CACHE_MAX = 200_000
_law_cache: dict[tuple[Any, ...], np.ndarray | int] = {}
_body_cache: dict[tuple[Any, ...], np.ndarray | int] = {}


def _side(side: str, row: Mapping[str, float]) -> dict[str, float]:
    return {field: row[name] for name, field in MATERIAL_OVERRIDES[side].items()}


def material_for(side: str, preset: str, row: Mapping[str, float]) -> Material:
    """The material of ``side`` ("body" or "flat"): the library material ``preset``, or
    (``"custom"``) the one the row's property values define
    (``impactlab.sweep.material_inputs``)."""
    return material_of(side, preset, _side(side, row))


def brittle_limit(statics: Statics) -> float:
    """The mean contact pressure [Pa] a brittle member of the chunk's pair stands
    (``contact.brittle.brittle_pressure``): a library material (or one given as text) by its
    ``brittle``, a material by values never; inf when neither is brittle."""
    mats = [
        get_material(name, f"{side}_material")
        for side in ("body", "flat")
        if (name := statics.categories[f"{side}_material"]) != CUSTOM
    ]
    return min((first_yield_pressure(m) for m in mats if m.brittle), default=math.inf)


def make_body(cat: Mapping[str, str], row: Mapping[str, float], body_mat: Material) -> Rod | Sphere:
    def given(name: str) -> float | None:
        v = row[name]
        return None if math.isnan(v) else float(v)

    kind = cat["body"]
    if kind == "rod":
        length, tip, mass = given("length"), given("tip_radius"), given("mass")
        return Rod(
            length=PAPER_ROD.length if length is None else length,
            tip_radius=PAPER_ROD.tip_radius if tip is None else tip,
            mass=PAPER_ROD.mass if mass is None else mass,
            material=body_mat,
            inertia=given("inertia"),
        )
    if kind == "sphere":
        radius = given("radius")
        if radius is None:
            raise ValueError("a sphere needs the input 'radius'")
        if given("inertia") is not None or given("length") is not None:
            raise ValueError("a sphere takes radius and mass (or density), not length/inertia")
        return Sphere(radius=radius, mass=given("mass"), material=body_mat)
    raise ValueError(f"unknown body {kind!r}; known: rod, sphere, flexible_rod")


def _unique_rows(cols: Sequence[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Distinct rows of the columns (bitwise, NaN == NaN) and the inverse index."""
    n = cols[0].shape[0]
    if all((c[0] == c[-1] and (c == c[0]).all()) or np.isnan(c).all() for c in cols):
        return np.stack([c[:1] for c in cols], axis=1), np.zeros(n, dtype=np.intp)
    stacked = np.ascontiguousarray(np.stack(cols, axis=1))
    view = stacked.view(np.dtype((np.void, stacked.dtype.itemsize * stacked.shape[1]))).ravel()
    _, first, inverse = np.unique(view, return_index=True, return_inverse=True)
    return stacked[first], inverse.ravel()


_LAW_NUMERIC = tuple(n for n in LAW_INPUTS if n not in CATEGORY_INPUTS)
#: The inputs whose values can change a case's law parameters (the body's density cannot).
_TABLE_INPUTS = tuple(n for n in LAW_INPUTS if n != "body_density")
#: The most distinct law rows a study may have for its cases to use the tables: each costs
#: 10-20 impacts to build (once per process) and one engine call per chunk that has it.
MAX_TABLES = 64
_tables: dict[tuple[int, bytes], np.ndarray] = {}


def law_rows(axes: Sequence[Any], sample: Any) -> int:
    """The distinct law rows a study can have (an upper bound): the product of the sizes of
    its grid axes among the law's inputs, times the sample size when it samples one."""
    n = math.prod(len(a.values) for a in axes if a.name in _TABLE_INPUTS)
    sampled = () if sample is None else sample.inputs
    return n * (sample.size if any(i in _TABLE_INPUTS for i in sampled) else 1)


def tabulates(axes: Sequence[Any], sample: Any) -> bool:
    """True when every case of the study (``axes``, ``sample``) uses its law row's table: it
    has at most :data:`MAX_TABLES` law rows (:func:`law_rows`)."""
    return law_rows(axes, sample) <= MAX_TABLES


def law_table(law_id: int, p: np.ndarray) -> np.ndarray:
    """``p`` with its loading-curve table (``contact.tabulate.with_table``, as ``simulate``
    builds it), cached per process."""
    key = (law_id, p.tobytes())
    hit = _tables.get(key)
    if hit is None:
        if len(_tables) >= 4 * MAX_TABLES:
            _tables.clear()
        hit = _tables[key] = with_table(law_id, p)
    return hit


BODY_NUMERIC = tuple(n for n in BODY_INPUTS if n not in CATEGORY_INPUTS)


def build_models(
    cases: Mapping[str, np.ndarray], statics: Statics
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per-case law parameters, body parameters and status (0 or a sweep rejection code).

    Returns (law_params (N, P) or (P,), P = ``kernels.param_length`` of the law; body_params
    (N, NB) or (NB,); status (N,)).
    ContactModels and bodies are built once per distinct combination of the inputs that enter
    them and cached for the life of the process.
    """
    law_out, body_out, row_status, inverse = model_rows(cases, statics)
    status = row_status[inverse]
    if law_out.shape[0] == 1:
        return law_out[0], body_out[0], status
    return law_out[inverse], body_out[inverse], status


def model_rows(
    cases: Mapping[str, np.ndarray], statics: Statics
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``build_models`` per distinct combination: (law params (R, P), body params (R, NB),
    status (R,), the combination of each case (N,))."""
    cat = statics.categories
    names = sorted(set(_LAW_NUMERIC) | set(BODY_NUMERIC))
    cols = [np.asarray(cases[k], dtype=np.float64) for k in names]
    rows, inverse = _unique_rows(cols)
    lp = tuple(sorted(statics.law_params.items()))
    law_out = np.empty((rows.shape[0], param_length(get_law(cat["law"]).law_id)))
    body_out = np.empty((rows.shape[0], NB))
    row_status = np.zeros(rows.shape[0], dtype=np.int32)
    for r in range(rows.shape[0]):
        row = dict(zip(names, rows[r].tolist(), strict=True))
        key = (
            cat["law"],
            cat["body"],
            cat["body_material"],
            cat["flat_material"],
            lp,
            rows[r].tobytes(),
        )
        cached_l, cached_b = _law_cache.get(key), _body_cache.get(key)
        if cached_l is None or cached_b is None:
            cached_l, cached_b = _build_one(cat, row, statics.law_params)
            if len(_law_cache) > _CACHE_MAX:
                _law_cache.clear()
                _body_cache.clear()
            _law_cache[key], _body_cache[key] = cached_l, cached_b
        if isinstance(cached_l, int):
            row_status[r] = cached_l
            law_out[r] = np.nan
            body_out[r] = np.nan
        else:
            assert not isinstance(cached_b, int)
            law_out[r] = cached_l
            body_out[r] = cached_b
    return law_out, body_out, row_status, inverse


def law_problem(
    cat: Mapping[str, str], row: Mapping[str, float], law_params: Mapping[str, float]
) -> str:
    """The contact law's own words (its ValueError) for a combination of the inputs that it
    refuses (status ``STATUS_BAD_LAW``); "" when it builds, when the law is unknown here, or
    when a material or the radius is refused first (its own status)."""
    if cat["law"] not in law_names():
        return ""
    try:
        body_mat = material_for("body", cat["body_material"], row)
        flat_mat = material_for("flat", cat["flat_material"], row)
    except ValueError:
        return ""
    radius = row["radius" if cat["body"] == "sphere" else "tip_radius"]
    radius = PAPER_ROD.tip_radius if math.isnan(radius) and cat["body"] != "sphere" else radius
    if not radius > 0.0:  # unset for a sphere, or not a radius: the body's status
        return ""
    try:
        build_contact_model(cat["law"], body_mat, flat_mat, radius, law_params)
    except ValueError as exc:
        return str(exc)
    return ""


#: The most combinations of the law's grid inputs the study check builds a law for.
MAX_PROBES = MAX_TABLES


def check_study_laws(
    fixed: Mapping[str, Any], axes: Sequence[Any], sampled: Sequence[str], law_params: Any
) -> None:
    """ValueError, in the law's own words, when the contact law with the study's
    ``law_params`` refuses every combination of the study's inputs that enter it
    (``law_problem``) and accepts the first without them: the
    ``[law_params]`` would refuse every case. Checked where the law's inputs take at most
    :data:`MAX_PROBES` combinations over the grid and none is sampled; otherwise (or where only
    some combinations fail, or the law refuses the pair whatever its parameters) each refused
    case gets ``STATUS_BAD_LAW``, and the law's words for the first of them are in the sweep's
    summary (``summary.status_counts``)."""
    names = [*_LAW_NUMERIC, "law", "body", "body_material", "flat_material"]
    if any(n in sampled for n in names):
        return
    grid = {a.name: a.values for a in axes if a.name in names}
    if math.prod(len(v) for v in grid.values()) > MAX_PROBES:
        return
    if not law_params:
        return
    first: tuple[str, dict[str, str], dict[str, float]] | None = None
    for combo in itertools.product(*grid.values()):
        values = {n: fixed.get(n, INPUTS[n].default) for n in names}
        values.update(zip(grid, combo, strict=True))
        cat = {n: str(values[n]) for n in CATEGORY_INPUTS if n in names}
        row = {n: math.nan if values[n] is None else float(values[n]) for n in _LAW_NUMERIC}
        why = law_problem(cat, row, law_params)
        if not why:
            return
        first = first or (why, cat, row)
    if first is None or law_problem(first[1], first[2], {}):
        return  # the law refuses the pair whatever its parameters: each case's status says so
    raise ValueError(
        f"[law_params]: {first[0]} (contact law {first[1]['law']!r}); the law refuses every "
        "case of the study with these parameters (`impactlab laws` lists them and their ranges)"
    )


def _build_one(
    cat: Mapping[str, str], row: Mapping[str, float], law_params: Mapping[str, float]
) -> tuple[Any, Any]:
    """(law params, body params) for one combination, or (code, code) when rejected. The
    contact model comes from ``impactlab.dynamics.models``, as in ``simulate``."""
    try:
        body_mat = material_for("body", cat["body_material"], row)
        flat_mat = material_for("flat", cat["flat_material"], row)
    except ValueError:
        return STATUS_BAD_MATERIAL, STATUS_BAD_MATERIAL
    try:
        body = make_body(cat, row, body_mat)
        bp = body_params(body, flat_mat)
    except ValueError:
        return STATUS_BAD_BODY, STATUS_BAD_BODY
    try:
        model = build_contact_model(cat["law"], body_mat, flat_mat, body.tip_radius, law_params)
    except ValueError:
        return STATUS_BAD_LAW, STATUS_BAD_LAW
    return np.asarray(model.params, dtype=np.float64), np.array(bp, dtype=np.float64)
