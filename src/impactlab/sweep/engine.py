"""The one adapter between the sweep and the compiled impact engine.

``evaluate(cases, statics, outputs)`` maps one chunk of cases (input name -> 1-D array, SI) plus
the choices that are constant over the chunk (``Statics``: law, friction, body kind, material
presets, law parameters, engine options) to the kept output arrays and a status array. It builds
the contact models and body vectors once per distinct combination of the numeric inputs that
enter them (cached per process) with the same builder as ``simulate``
(``impactlab.dynamics.models``), rejects what the Python constructors reject with a status code
instead of an exception, and calls ``impactlab.dynamics.batch.run_arrays`` once for the chunk.

Any object with the ``Evaluator`` interface can stand in for the engine (tests use a cheap fake).
"""

from __future__ import annotations

import dataclasses
import math
import os
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

import numpy as np
from numba.core.dispatcher import Dispatcher

from impactlab.bodies import NB, PAPER_ROD, Rod, Sphere
from impactlab.contact import get_law, law_names
from impactlab.contact.kernels import NPARAM
from impactlab.dynamics.batch import (
    FRICTION_IDS,
    OUTPUT_FIELDS,
    REGIME_NAMES,
    STATUS_MESSAGES,
    run_arrays,
)
from impactlab.dynamics.models import body_params, build_contact_model
from impactlab.materials import PRESETS, Material, get_material
from impactlab.sweep.inputs import (
    BODY_INPUTS,
    CATEGORY_INPUTS,
    INTEGER_OUTPUTS,
    KINEMATIC_INPUTS,
    LAW_INPUTS,
    MATERIAL_OVERRIDES,
)

#: Status codes the sweep itself assigns (cases the engine never sees). Engine codes are small
#: non-negative integers; these are kept apart.
STATUS_NOT_RUN = -1
STATUS_BAD_MATERIAL = 101
STATUS_BAD_BODY = 102
STATUS_BAD_LAW = 103
STATUS_BAD_INPUT = 104
SWEEP_STATUS_MESSAGES: dict[int, str] = {
    STATUS_NOT_RUN: "not computed (chunk missing: the sweep was interrupted)",
    STATUS_BAD_MATERIAL: "material rejected (impactlab.materials.Material: e.g. nu outside "
    "(-1, 0.5), S_y >= E, non-positive value)",
    STATUS_BAD_BODY: "body rejected (impactlab.bodies: non-positive length, radius, mass or "
    "inertia, or both mass and density given)",
    STATUS_BAD_LAW: "contact law rejected its parameters (outside the law's validity)",
    STATUS_BAD_INPUT: "non-finite kinematic input (angle, vx, vy, spin or mu)",
}


@dataclass(frozen=True)
class Statics:
    """What is constant over one engine call: the category inputs, the law parameters and the
    engine options."""

    categories: Mapping[str, str]
    law_params: Mapping[str, float] = field(default_factory=dict)
    engine: Mapping[str, Any] = field(default_factory=dict)

    def __getitem__(self, name: str) -> str:
        return self.categories[name]


@runtime_checkable
class Evaluator(Protocol):
    """What the sweep needs from an engine.

    ``identity`` is part of the study hash; ``output_fields`` names every output in order;
    ``status_messages`` maps status codes to reasons; ``regimes`` maps regime codes to names;
    ``validate(categories)`` raises ValueError for an unusable category value;
    ``__call__(cases, statics, outputs)`` returns ({output: 1-D array}, status int32 array).
    """

    identity: str

    def output_fields(self) -> tuple[str, ...]: ...

    def status_messages(self) -> dict[int, str]: ...

    def regimes(self) -> dict[int, str]: ...

    def integer_outputs(self) -> tuple[str, ...]: ...

    def validate(self, categories: Mapping[str, Sequence[str]]) -> None: ...

    def __call__(
        self, cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
    ) -> tuple[dict[str, np.ndarray], np.ndarray]: ...


def engine_available() -> bool:
    """True: the compiled engine is a required part of the package (an install without it
    fails at import)."""
    return True


# -- model construction (cached per process) ----------------------------------------------------

_CACHE_MAX = 200_000
_law_cache: dict[tuple[Any, ...], np.ndarray | int] = {}
_body_cache: dict[tuple[Any, ...], np.ndarray | int] = {}


def _material(preset: str, overrides: Mapping[str, float]) -> Material:
    base = get_material(preset)
    changes: dict[str, Any] = {k: v for k, v in overrides.items() if not math.isnan(v)}
    if not changes:
        return base
    return dataclasses.replace(base, **changes)


def _side(side: str, row: Mapping[str, float]) -> dict[str, float]:
    return {field: row[name] for name, field in MATERIAL_OVERRIDES[side].items()}


def _body(cat: Mapping[str, str], row: Mapping[str, float], body_mat: Material) -> Rod | Sphere:
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
    raise ValueError(f"unknown body {kind!r}; known: rod, sphere")


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
_BODY_NUMERIC = tuple(n for n in BODY_INPUTS if n not in CATEGORY_INPUTS)


def build_models(
    cases: Mapping[str, np.ndarray], statics: Statics
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per-case law parameters, body parameters and status (0 or a sweep rejection code).

    Returns (law_params (N, NPARAM) or (NPARAM,), body_params (N, NB) or (NB,), status (N,)).
    ContactModels and bodies are built once per distinct combination of the inputs that enter
    them and cached for the life of the process.
    """
    cat = statics.categories
    n = len(cases["angle"])
    status = np.zeros(n, dtype=np.int32)
    names = sorted(set(_LAW_NUMERIC) | set(_BODY_NUMERIC))
    cols = [np.asarray(cases[k], dtype=np.float64) for k in names]
    rows, inverse = _unique_rows(cols)
    lp = tuple(sorted(statics.law_params.items()))
    law_out = np.empty((rows.shape[0], NPARAM))
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
    status[:] = row_status[inverse]
    if rows.shape[0] == 1:
        return law_out[0], body_out[0], status
    return law_out[inverse], body_out[inverse], status


def _build_one(
    cat: Mapping[str, str], row: Mapping[str, float], law_params: Mapping[str, float]
) -> tuple[Any, Any]:
    """(law params, body params) for one combination, or (code, code) when rejected. The
    contact model comes from ``impactlab.dynamics.models``, as in ``simulate``."""
    try:
        body_mat = _material(cat["body_material"], _side("body", row))
        flat_mat = _material(cat["flat_material"], _side("flat", row))
    except ValueError:
        return STATUS_BAD_MATERIAL, STATUS_BAD_MATERIAL
    try:
        body = _body(cat, row, body_mat)
        bp = body_params(body, flat_mat)
    except ValueError:
        return STATUS_BAD_BODY, STATUS_BAD_BODY
    try:
        model = build_contact_model(cat["law"], body_mat, flat_mat, body.tip_radius, law_params)
    except ValueError:
        return STATUS_BAD_LAW, STATUS_BAD_LAW
    return np.asarray(model.params, dtype=np.float64), np.array(bp, dtype=np.float64)


# -- numba cache statistics ----------------------------------------------------------------------


def numba_cache_stats() -> dict[str, int]:
    """Cache hits and misses (compilations) of the compiled functions loaded from impactlab's
    modules in this process: {"hits": ..., "misses": ..., "dispatchers": ...}. A worker that
    loads the kernels from the on-disk cache shows hits > 0 and misses == 0."""
    hits = misses = count = 0
    seen: set[int] = set()
    for name, mod in list(sys.modules.items()):
        if not name.startswith("impactlab.") or mod is None:
            continue
        for obj in list(vars(mod).values()):
            if isinstance(obj, Dispatcher) and id(obj) not in seen:
                seen.add(id(obj))
                st = obj.stats
                count += 1
                hits += sum(st.cache_hits.values())
                misses += sum(st.cache_misses.values())
    return {"hits": hits, "misses": misses, "dispatchers": count}


# -- the engine --------------------------------------------------------------------------------


class EngineEvaluator:
    """The compiled engine (``impactlab.dynamics.batch.run_arrays``) behind the Evaluator
    interface."""

    identity = "impactlab.dynamics.batch"

    def output_fields(self) -> tuple[str, ...]:
        return tuple(OUTPUT_FIELDS)

    def status_messages(self) -> dict[int, str]:
        return {int(k): str(v) for k, v in STATUS_MESSAGES.items()}

    def regimes(self) -> dict[int, str]:
        return {int(k): str(v) for k, v in REGIME_NAMES.items()}

    def integer_outputs(self) -> tuple[str, ...]:
        return tuple(f for f in self.output_fields() if f in INTEGER_OUTPUTS)

    def validate(self, categories: Mapping[str, Sequence[str]]) -> None:
        _validate_categories(categories, tuple(FRICTION_IDS))

    def __call__(
        self, cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
    ) -> tuple[dict[str, np.ndarray], np.ndarray]:
        return evaluate(cases, statics, outputs)


def _validate_categories(categories: Mapping[str, Sequence[str]], frictions: Sequence[str]) -> None:
    for law in categories.get("law", ()):
        try:
            get_law(law)
        except ValueError:
            raise ValueError(
                f"unknown contact law {law!r}; known laws: {', '.join(law_names())}"
            ) from None
    for fr in categories.get("friction", ()):
        if fr not in frictions:
            raise ValueError(f"unknown friction model {fr!r}; known: {', '.join(frictions)}")
    for key in ("body_material", "flat_material"):
        for m in categories.get(key, ()):
            if m not in PRESETS:
                raise ValueError(
                    f"unknown {key} preset {m!r}; known presets: {', '.join(sorted(PRESETS))}"
                )
    for b in categories.get("body", ()):
        if b not in ("rod", "sphere"):
            raise ValueError(f"unknown body {b!r}; known: rod, sphere")


def evaluate(
    cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Run one chunk through the compiled engine.

    cases : input name -> 1-D float64 array (all of ``inputs.INPUTS``' numeric names; NaN =
        preset value), SI units.
    statics : category values, law parameters and engine options for the whole chunk.
    outputs : the engine output fields to return.

    Returns ({output: (N,) array}, status (N,) int32). Cases rejected before the engine get the
    ``SWEEP_STATUS_MESSAGES`` codes and NaN outputs.
    """
    fields = tuple(OUTPUT_FIELDS)
    cols = [fields.index(o) for o in outputs]
    n = len(cases["angle"])
    law_params, body_params, status = build_models(cases, statics)
    initial = np.empty((n, 4))
    for j, name in enumerate(("angle", "vx", "vy", "spin")):
        initial[:, j] = cases[name]
    mu = np.ascontiguousarray(cases["mu"], dtype=np.float64)
    kin_bad = ~np.isfinite(initial).all(axis=1) | ~np.isfinite(mu)
    status[kin_bad & (status == 0)] = STATUS_BAD_INPUT
    ok = status == 0
    res = {o: np.full(n, np.nan) for o in outputs}
    if not ok.any():
        return res, status
    all_ok = bool(ok.all())

    def sel(a: np.ndarray) -> np.ndarray:
        if all_ok or a.ndim == 1:
            return a
        return np.ascontiguousarray(a[ok])

    law_id = _law_id(statics.categories["law"])
    out, st = run_arrays(
        law_id,
        FRICTION_IDS[statics.categories["friction"]],
        sel(law_params),
        sel(body_params),
        initial if all_ok else np.ascontiguousarray(initial[ok]),
        mu if all_ok else np.ascontiguousarray(mu[ok]),
        **dict(statics.engine),
    )
    st = np.asarray(st, dtype=np.int32)
    if all_ok:
        status[:] = st
        for o, c in zip(outputs, cols, strict=True):
            res[o] = np.ascontiguousarray(out[:, c])
    else:
        status[ok] = st
        for o, c in zip(outputs, cols, strict=True):
            res[o][ok] = out[:, c]
    return res, status


def _law_id(name: str) -> int:
    return int(get_law(name).law_id)


#: Silence unused-import linters for names re-exported for the docs.
__all__ = [
    "KINEMATIC_INPUTS",
    "STATUS_BAD_BODY",
    "STATUS_BAD_INPUT",
    "STATUS_BAD_LAW",
    "STATUS_BAD_MATERIAL",
    "STATUS_NOT_RUN",
    "SWEEP_STATUS_MESSAGES",
    "EngineEvaluator",
    "Evaluator",
    "Statics",
    "build_models",
    "engine_available",
    "evaluate",
    "numba_cache_stats",
]

ENGINE = EngineEvaluator()


def default_threads() -> int:
    """Cores usable by this process."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover
        return os.cpu_count() or 1
