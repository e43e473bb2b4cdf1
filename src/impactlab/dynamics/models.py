"""Contact models and body vectors for the compiled engine, built once per distinct input.

``build_contact_model`` is the one place where the engine's users (``simulate``,
``simulate_batch``, the sweep) build a ContactModel; it is cached by value (laws, materials and
parameters are immutable and hashable). ``kernel_params`` and ``body_params`` give the
float64 vectors the compiled core reads (the first cached per model object).
``references_used`` lists the sources a result records; ``engine_setup`` gathers all of these
for ``simulate``'s fast path, once per (body, flat, law name, friction name).
"""

from __future__ import annotations

import functools
import weakref
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab.bodies import Rod, Sphere
from impactlab.contact import ContactModel, get_law
from impactlab.contact.tabulate import with_table
from impactlab.friction import FrictionKind, FrictionModel, get_friction
from impactlab.materials import ContactPair, Material
from impactlab.references import Reference, cite

#: The integrator's sources: Dormand & Prince (1980), Shampine's dense output (1986).
INTEGRATOR_REFERENCES: tuple[Reference, ...] = cite("dormand-prince-1980", "shampine-1986")

_PARAMS: weakref.WeakKeyDictionary[ContactModel, np.ndarray] = weakref.WeakKeyDictionary()


@functools.lru_cache(maxsize=1024)
def _build(
    law: str,
    body_material: Material,
    flat: Material,
    radius: float,
    law_params: tuple[tuple[str, float], ...],
) -> ContactModel:
    return get_law(law).build(ContactPair(body_material, flat), radius, **dict(law_params))


def build_contact_model(
    law: str,
    body_material: Material,
    flat: Material,
    radius: float,
    law_params: Mapping[str, float] | None = None,
) -> ContactModel:
    """The ContactModel of the registered law ``law`` for a sphere (rod tip) of ``radius`` [m]
    made of ``body_material`` on ``flat``, with the law's ``law_params`` (cached by value).

    ``law_params`` maps parameter names to numbers in their units (or, for a parameter with a
    unit, strings with units or pint Quantities: ``ContactLaw.parameter_values``). ValueError
    for an unknown law, a ``law_params`` that is not a mapping, unknown names or bad values.
    """
    params = get_law(law).parameter_values({} if law_params is None else law_params)
    return _build(str(law), body_material, flat, radius, tuple(sorted(params.items())))


def contact_model(
    body: Rod | Sphere,
    flat: Material,
    law: str | ContactModel,
    law_params: Mapping[str, float] | None = None,
) -> ContactModel:
    """The (cached) ContactModel of ``law`` for ``body`` on ``flat``.

    ``law`` is a registered law name or a ready ContactModel (then ``law_params`` must be
    empty, its radius must equal the body's tip radius and, if a law built it, for ``flat``:
    ``check_model_flat``).
    """
    R = body.tip_radius
    if isinstance(law, ContactModel):
        if law_params:
            raise ValueError("law_params cannot be combined with a ready ContactModel")
        if abs(law.radius - R) > 1e-12 * R:
            raise ValueError(
                f"law: the ContactModel's radius ({law.radius!r} m) differs from the body's tip "
                f"radius ({R!r} m); build the model with radius={R!r}"
            )
        check_model_flat(law, flat)
        return law
    if not isinstance(law, str):
        raise ValueError(f"law must be a law name or a ContactModel, got {type(law).__name__}")
    if law_params is None:  # the common case: one dict lookup (bodies and flats are immutable)
        key = (law, id(body), id(flat))
        hit = _LAST_MODELS.get(key)
        if hit is not None and hit[0] is body and hit[1] is flat:
            return hit[2]
        model = build_contact_model(law, body.material, flat, R)
        if len(_LAST_MODELS) >= 64:
            _LAST_MODELS.clear()
        _LAST_MODELS[key] = (body, flat, model)
        return model
    return build_contact_model(law, body.material, flat, R, law_params)


def check_recorded_model_flat(law: Any, recorded: Any, changes: Mapping[str, Any]) -> None:
    """ValueError when a rerun gives another flat (``changes["flat"]``) to a record whose law
    is a ``ContactModel`` (``law``: its compiled parameters, for the ``recorded`` flat; read
    back, it holds no pair for :func:`check_model_flat` to check) and no law of its own: the
    result would be the recorded flat's dent, named after the new one."""
    flat = changes.get("flat")
    if not isinstance(law, ContactModel) or flat is None or "law" in changes or flat == recorded:
        return
    name = getattr(recorded, "name", "the recorded flat")
    raise ValueError(
        f"flat: the record's law is a ContactModel, its parameters computed for the flat "
        f"{name!r}, not for {getattr(flat, 'name', flat)!r}; give the law by name with the new "
        f"flat (law={law.name!r}, --law {law.name}) to build it for that flat"
    )


def check_model_flat(model: ContactModel, flat: Material) -> None:
    """ValueError when the ready ``model`` was built by a law for another flat than ``flat``:
    the dent would be the other flat's while the result names this one (and Mindlin's G* takes
    this one). A model made by hand (``model.pair`` None) is the user's, and so is one built
    for another body material on this flat (a stiffer rod with the same contact, say)."""
    if model.pair is None or model.pair.flat == flat:
        return
    raise ValueError(
        f"law: the ContactModel was built for the flat {model.pair.flat.name!r}, not for "
        f"{flat.name!r}; pass that flat, or build the model for this one "
        "(get_law(name).build(ContactPair(body.material, flat), radius))"
    )


#: (law, id(body), id(flat)) -> (body, flat, model) of ``contact_model`` without law_params:
#: the objects are kept, so an id is never reused while its entry lives.
_LAST_MODELS: dict[tuple[str, int, int], tuple[Any, Any, ContactModel]] = {}


def kernel_params(model: ContactModel) -> np.ndarray:
    """A writable C-contiguous copy of ``model.params`` for the compiled engine (one numba
    specialisation for every caller: read-only arrays would compile a second one), with the
    table of the law's loading curve appended (``contact.tabulate.with_table``). Cached per
    model object, for as long as the model lives."""
    p = _PARAMS.get(model)
    if p is None:
        p = with_table(model.law_id, np.asarray(model.params, dtype=np.float64))
        _PARAMS[model] = p
    return p


def references_used(
    model: ContactModel, friction: FrictionModel, frictional: bool
) -> tuple[Reference, ...]:
    """The sources a computation with ``model`` used: the contact law, the friction model
    (only when ``frictional``, i.e. some mu > 0) and the integrator, without repeats (cached
    per model object, friction model and ``frictional``)."""
    key = (id(model), friction.name, bool(frictional))
    hit = _REFERENCES.get(key)
    if hit is not None and hit[0] is model:
        return hit[1]
    refs = [*model.references]
    if frictional:
        refs += friction.references
    refs += INTEGRATOR_REFERENCES
    out = tuple(dict.fromkeys(refs))
    if len(_REFERENCES) >= 256:
        _REFERENCES.clear()
    _REFERENCES[key] = (model, out)
    return out


#: (id(model), friction name, frictional) -> (model, references) of ``references_used``.
_REFERENCES: dict[tuple[int, str, bool], tuple[ContactModel, tuple[Reference, ...]]] = {}


def body_params(body: Rod | Sphere, flat: Material) -> np.ndarray:
    """The body vector (``impactlab.bodies.layout``) of ``body`` on ``flat`` for the compiled
    engine (writable, C-contiguous). Not cached: it costs 1.6 us, and the callers that repeat
    it keep what they build (``engine_setup``, the sweep's models; docs/architecture.md,
    "Caches")."""
    return np.require(body.to_params(flat), np.float64, ["C", "W"])


#: What ``simulate``'s fast path needs of one (body, flat, law name, friction name), built once:
#: (body, flat, model, friction model, kernel_params, body_params, references with mu = 0,
#: references with mu > 0); None for a combination the fast path leaves to the full checks.
EngineSetup = tuple[
    Any, Any, ContactModel, FrictionModel, np.ndarray, np.ndarray, tuple[Reference, ...],
    tuple[Reference, ...],
]  # fmt: skip

#: (id(body), id(flat), law, friction) -> (body, flat, setup) of ``engine_setup`` (the entry
#: holds the body and the flat, so an id is never reused while its entry lives).
_SETUPS: dict[tuple[int, int, str, str], tuple[Any, Any, EngineSetup | None]] = {}


def engine_setup(body: Rod | Sphere, flat: Material, law: str, friction: str) -> EngineSetup | None:
    """The cached setup of an impact of ``body`` (a Rod or a Sphere) on ``flat`` with the
    registered law and friction model named ``law`` and ``friction`` (see ``EngineSetup``).

    None for partial-slip friction (another engine), a ``flat`` that is not a Material and
    when building the setup fails (an unknown name, ...): the caller then takes the full path,
    whose checks raise the error.
    Bodies, flats, models and friction models are immutable, so a setup never goes stale.
    """
    hit = _SETUPS.get((id(body), id(flat), law, friction))
    if hit is not None and hit[0] is body and hit[1] is flat:
        return hit[2]
    if not isinstance(flat, Material):
        return None
    try:
        model = contact_model(body, flat, law)
        fric = get_friction(friction)
    except Exception:  # not cached: the full path raises it again
        return None
    setup: EngineSetup | None = None
    if fric.kind is not FrictionKind.PARTIAL_SLIP:
        setup = (
            body, flat, model, fric, kernel_params(model), body_params(body, flat),
            references_used(model, fric, False), references_used(model, fric, True),
        )  # fmt: skip
    if len(_SETUPS) >= 64:
        _SETUPS.clear()
    _SETUPS[(id(body), id(flat), law, friction)] = (body, flat, setup)
    return setup


__all__ = [
    "INTEGRATOR_REFERENCES",
    "EngineSetup",
    "body_params",
    "build_contact_model",
    "contact_model",
    "engine_setup",
    "kernel_params",
    "references_used",
]
