"""The one adapter between the sweep and the compiled impact engine.

``evaluate(cases, statics, outputs)`` maps one chunk of cases (input name -> 1-D array, SI) plus
the choices that are constant over the chunk (``Statics``: law, friction, body kind, material
presets, law parameters, engine options) to the kept output arrays and a status array. It builds
the contact models and body vectors once per distinct combination of the numeric inputs that
enter them (cached per process) with the same builder as ``simulate``
(``impactlab.dynamics.models``; :mod:`impactlab.sweep.models`), rejects what the Python
constructors reject with a status code instead of an exception, and calls
``impactlab.dynamics.batch.run_arrays`` once for the chunk, or, where the study's cases use
their law's table (``Statics.tabulate``, :func:`impactlab.sweep.models.tabulates`), once per
distinct law row with that row's table, so that every case equals ``simulate`` bit for bit
whatever its chunk holds.

Any object with the ``Evaluator`` interface can stand in for the engine (tests use a cheap fake).
"""

from __future__ import annotations

import sys
from collections.abc import Mapping, Sequence
from typing import Protocol, runtime_checkable

import numpy as np
from numba.core.dispatcher import Dispatcher

from impactlab._validation import did_you_mean
from impactlab.contact import get_law, law_names
from impactlab.dynamics.batch import (
    BATCH_FRICTION_IDS,
    OUTPUT_FIELDS,
    REGIME_NAMES,
    STATUS_MESSAGES,
    run_arrays,
)
from impactlab.friction import friction_names
from impactlab.schema import DERIVED_FIELDS, SEQUENCE_FIELDS
from impactlab.sweep.flexible import FLEXIBLE_BODY, evaluate_flexible, validate_flexible
from impactlab.sweep.inputs import INTEGER_OUTPUTS, KINEMATIC_INPUTS
from impactlab.sweep.material_inputs import validate_material_names
from impactlab.sweep.models import Statics, brittle_limit, build_models, law_table, model_rows
from impactlab.sweep.status import (
    STATUS_BAD_BODY,
    STATUS_BAD_INPUT,
    STATUS_BAD_LAW,
    STATUS_BAD_MATERIAL,
    STATUS_NOT_RUN,
    SWEEP_STATUS_MESSAGES,
)
from impactlab.sweep.study_rules import unset_ignored


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


# -- numba cache statistics ----------------------------------------------------------------------


#: (the impactlab modules loaded, their compiled functions) of the last scan
_SCANNED: tuple[tuple[int, ...], list[Dispatcher]] = ((), [])


def _dispatchers() -> list[Dispatcher]:
    """The compiled functions of impactlab's loaded modules (scanned again only when the set of
    loaded modules changed: a scan costs about 4 ms, and a sweep asks twice per chunk)."""
    global _SCANNED
    mods = [m for n, m in list(sys.modules.items()) if n.startswith("impactlab.") and m]
    key = tuple(id(m) for m in mods)
    if key != _SCANNED[0]:
        found: dict[int, Dispatcher] = {}
        for mod in mods:
            for obj in list(vars(mod).values()):
                if isinstance(obj, Dispatcher):
                    found.setdefault(id(obj), obj)
        _SCANNED = (key, list(found.values()))
    return _SCANNED[1]


#: (compiled signatures of the dispatchers, their stats) of the last count
_COUNTED: tuple[tuple[int, int], dict[str, int]] = ((-1, -1), {})


def numba_cache_stats() -> dict[str, int]:
    """Cache hits and misses (compilations) of the compiled functions loaded from impactlab's
    modules in this process: {"hits": ..., "misses": ..., "dispatchers": ...}. A worker that
    loads the kernels from the on-disk cache shows hits > 0 and misses == 0. (Counted again only
    when a signature was added since: a hit or a miss adds one.)"""
    global _COUNTED
    dispatchers = _dispatchers()
    signatures = (len(dispatchers), sum(len(d.overloads) for d in dispatchers))
    if signatures != _COUNTED[0]:
        hits = misses = 0
        for obj in dispatchers:
            st = obj.stats
            hits += sum(st.cache_hits.values())
            misses += sum(st.cache_misses.values())
        _COUNTED = (signatures, {"hits": hits, "misses": misses, "dispatchers": len(dispatchers)})
    return dict(_COUNTED[1])


# -- the engine --------------------------------------------------------------------------------


#: The engine's diagnostic outputs: computed (``run_arrays(diagnostics=True)``, a few per cent
#: of the engine's time, every other output bit for bit the same) only for a chunk that keeps
#: one of them.
DIAGNOSTIC_OUTPUTS = frozenset({"energy_rise", "friction_excess"})

#: Store columns of a flexible drop's sequence totals (``impactlab.schema.SEQUENCE_FIELDS``)
#: and of the extent of its mark over all its contacts (``scar_length``, a ``DropResult`` field:
#: ``schema.DROP_FIELDS``, whose unit and meaning the store takes): NaN for the rigid bodies'
#: cases (the mark of one impact: its ``contact_travel``'s magnitude, as
#: ``calibrate.models.predict`` reads it for a measured scar_length).
SEQUENCE_OUTPUTS: tuple[str, ...] = (*(f.name for f in SEQUENCE_FIELDS), "scar_length")


class EngineEvaluator:
    """The compiled engine (``impactlab.dynamics.batch.run_arrays``) behind the Evaluator
    interface."""

    identity = "impactlab.dynamics.batch"

    def output_fields(self) -> tuple[str, ...]:
        """The engine's outputs, a flexible drop's sequence totals (``SEQUENCE_OUTPUTS``: a
        study without a flexible rod leaves them out), then the derived outputs
        (``schema.register_output``)."""
        return (*OUTPUT_FIELDS, *SEQUENCE_OUTPUTS, *DERIVED_FIELDS)

    def status_messages(self) -> dict[int, str]:
        return {int(k): str(v) for k, v in STATUS_MESSAGES.items()}

    def regimes(self) -> dict[int, str]:
        return {int(k): str(v) for k, v in REGIME_NAMES.items()}

    def integer_outputs(self) -> tuple[str, ...]:
        return tuple(f for f in self.output_fields() if f in INTEGER_OUTPUTS)

    def validate(self, categories: Mapping[str, Sequence[str]]) -> None:
        validate_flexible(categories)
        _validate_categories(categories, tuple(BATCH_FRICTION_IDS))

    def __call__(
        self, cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
    ) -> tuple[dict[str, np.ndarray], np.ndarray]:
        body = statics.categories.get("body", "rod")
        cases = unset_ignored(cases, body)  # another body's inputs (a study of several)
        if body == FLEXIBLE_BODY:  # one drop per case
            return evaluate_flexible(cases, statics, outputs)
        rigid = [o for o in outputs if o not in SEQUENCE_OUTPUTS]
        res, status = evaluate(cases, statics, rigid)
        n = len(status)
        return {o: res[o] if o in res else np.full(n, np.nan) for o in outputs}, status


def computed_outputs(kept: Sequence[str]) -> tuple[str, ...]:
    """The engine outputs a chunk computes to give ``kept``: its engine outputs and those the
    derived ones among it need (``schema.register_output``)."""
    needs = [n for o in kept if o in DERIVED_FIELDS for n in DERIVED_FIELDS[o].needs]
    return tuple(dict.fromkeys([*(o for o in kept if o not in DERIVED_FIELDS), *needs]))


def with_derived(values: Mapping[str, np.ndarray], kept: Sequence[str]) -> dict[str, np.ndarray]:
    """``kept`` from a chunk's engine outputs ``values``: the derived outputs computed here (the
    writer's process, where they were registered), the others as they are."""
    out = {}
    for o in kept:
        d = DERIVED_FIELDS.get(o)
        if d is None:
            out[o] = values[o]
        else:
            got = d.compute(**{n: values[n] for n in d.needs})
            out[o] = np.asarray(got, dtype=np.float64)
    return out


def _validate_categories(categories: Mapping[str, Sequence[str]], frictions: Sequence[str]) -> None:
    for law in categories.get("law", ()):
        try:
            get_law(law)
        except ValueError:
            raise ValueError(
                f"unknown contact law {law!r}{did_you_mean(law, law_names())}; known laws: "
                f"{', '.join(law_names())}; a law of your own: impactlab --law-file FILE, or "
                f"{law} = 'FILE' in the study's [laws] table"
            ) from None
    for fr in categories.get("friction", ()):
        if fr in frictions:
            continue
        if fr in friction_names():  # a model, but not one of the batch engine
            raise ValueError(
                f"friction model {fr!r} does not run in the batch engine that sweeps use; "
                f"sweep models: {', '.join(frictions)} (impactlab.simulate runs {fr!r})"
            )
        raise ValueError(
            f"unknown friction model {fr!r}{did_you_mean(fr, friction_names())}; known: "
            f"{', '.join(friction_names())}"
        )
    for key in ("body_material", "flat_material"):
        validate_material_names(categories.get(key, ()), key)
    for b in categories.get("body", ()):
        if b not in ("rod", "sphere", FLEXIBLE_BODY):
            raise ValueError(f"unknown body {b!r}; known: rod, sphere, {FLEXIBLE_BODY}")


def evaluate(
    cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Run one chunk through the compiled engine.

    cases : input name -> 1-D float64 array (all of ``inputs.INPUTS``' numeric names; NaN =
        preset value), SI units.
    statics : category values, law parameters, engine options and the choice of the law's
        table (``Statics.tabulate``) for the whole chunk.
    outputs : the engine output fields to return.

    Returns ({output: (N,) array}, status (N,) int32). Cases rejected before the engine get the
    ``SWEEP_STATUS_MESSAGES`` codes and NaN outputs.
    """
    n = len(cases["angle"])
    law_rows, body_rows, row_status, inverse = model_rows(cases, statics)
    status = row_status[inverse]
    initial = np.empty((n, 4))
    for j, name in enumerate(("angle", "vx", "vy", "spin")):
        initial[:, j] = cases[name]
    mu = np.ascontiguousarray(cases["mu"], dtype=np.float64)
    kin_bad = ~np.isfinite(initial).all(axis=1) | ~np.isfinite(mu)
    status[kin_bad & (status == 0)] = STATUS_BAD_INPUT
    ok = np.flatnonzero(status == 0)
    res: dict[str, np.ndarray] = {}
    diagnostics = not DIAGNOSTIC_OUTPUTS.isdisjoint(outputs)  # the others' bits unchanged
    engine = dict(statics.engine)
    if statics.categories["friction"] != "partial_slip":  # the cells of partial_slip only
        engine.pop("partial_slip_cells", None)
    groups: list[tuple[int | None, np.ndarray]] = [(None, ok)] if ok.size else []
    if statics.tabulate:  # each law row with its table, as simulate: one call per row
        groups = list(_law_groups(law_rows, inverse, ok))
    for row, idx in groups:
        whole = idx.size == n  # every case in one call: no copies
        out, st = run_arrays(
            _law_id(statics.categories["law"]),
            BATCH_FRICTION_IDS[statics.categories["friction"]],
            _law_params(statics, row, law_rows, inverse[idx]),
            _per_case(body_rows, inverse[idx]),
            initial if whole else np.ascontiguousarray(initial[idx]),
            mu if whole else np.ascontiguousarray(mu[idx]),
            brittle_limit=brittle_limit(statics),
            diagnostics=diagnostics,
            tabulate=statics.tabulate is not False,
            **engine,
        )
        status[idx] = np.asarray(st, dtype=np.int32)
        for o in outputs:
            col = out[:, OUTPUT_FIELDS.index(o)]
            if whole:
                res[o] = np.ascontiguousarray(col)
            else:
                res.setdefault(o, np.full(n, np.nan))[idx] = col
    return {o: res[o] if o in res else np.full(n, np.nan) for o in outputs}, status


def _per_case(rows: np.ndarray, combos: np.ndarray) -> np.ndarray:
    """The rows of the cases of combinations ``combos``: one (1-D) when they share it."""
    if bool((combos == combos[0]).all()):
        return rows[combos[0]]
    return np.ascontiguousarray(rows[combos])


def _law_params(
    statics: Statics, row: int | None, law_rows: np.ndarray, combos: np.ndarray
) -> np.ndarray:
    """The law parameters of a group of cases (combinations ``combos``): law row ``row`` with
    its table (``statics.tabulate`` True), else each case's row, shared (1-D) where the chunk
    has one combination only (the engine's rule, None, then tabulates it; False never does)."""
    if row is not None:
        return law_table(_law_id(statics.categories["law"]), law_rows[row])
    if law_rows.shape[0] == 1:
        return law_rows[0]
    return np.ascontiguousarray(law_rows[combos])


def _law_groups(
    law_rows: np.ndarray, inverse: np.ndarray, ok: np.ndarray
) -> list[tuple[int, np.ndarray]]:
    """The cases ``ok`` (their combinations: ``inverse``) grouped by their law parameters
    (bitwise): (a combination of the group, its cases in order)."""
    if law_rows.shape[0] == 1:
        return [(0, ok)] if ok.size else []
    rows = np.ascontiguousarray(law_rows)
    view = rows.view(np.dtype((np.void, rows.itemsize * rows.shape[1]))).ravel()
    _, first, same = np.unique(view, return_index=True, return_inverse=True)
    group = first[same.ravel()][inverse[ok]]
    order = np.argsort(group, kind="stable")
    cuts = np.flatnonzero(np.diff(group[order])) + 1
    return [(int(group[part[0]]), ok[part]) for part in np.split(order, cuts) if part.size]


def _law_id(name: str) -> int:
    return int(get_law(name).law_id)


#: Silence unused-import linters for names re-exported for the docs.
__all__ = [
    "DIAGNOSTIC_OUTPUTS",
    "KINEMATIC_INPUTS",
    "SEQUENCE_OUTPUTS",
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
    "computed_outputs",
    "evaluate",
    "numba_cache_stats",
    "with_derived",
]

ENGINE = EngineEvaluator()
