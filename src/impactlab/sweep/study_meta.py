"""What a study's store is made for: the outputs it keeps (checked against the evaluator), the
values of its category inputs, and the store metadata (outputs, messages, the engine's
identity and the study's hash)."""

from __future__ import annotations

from impactlab._code_identity import results_code_hash
from impactlab._version import __version__
from impactlab.contact.ranges import law_range
from impactlab.contact.registered import RegisteredLaw
from impactlab.contact.registry import get_law
from impactlab.sweep.engine import SEQUENCE_OUTPUTS, Evaluator
from impactlab.sweep.flexible import FLEXIBLE_BODY
from impactlab.sweep.inputs import ALWAYS_STORED, CATEGORY_INPUTS, OUTPUT_ALIASES
from impactlab.sweep.store import StoreMeta
from impactlab.sweep.study import Study

__all__ = ["category_values", "engine_identity", "law_ranges", "resolve_outputs", "store_meta"]


def resolve_outputs(study: Study, evaluator: Evaluator) -> tuple[str, ...]:
    """The outputs to keep, checked against what the evaluator provides."""
    fields = tuple(evaluator.output_fields())
    drops_only: tuple[str, ...] = ()
    if FLEXIBLE_BODY not in category_values(study)["body"]:  # no drop: no sequence totals
        drops_only = tuple(f for f in fields if f in SEQUENCE_OUTPUTS)
        fields = tuple(f for f in fields if f not in SEQUENCE_OUTPUTS)
    if study.outputs is None:
        return fields
    outs = tuple(OUTPUT_ALIASES.get(o, o) for o in study.outputs)
    sequence = [o for o in outs if o in drops_only]
    if sequence:
        raise ValueError(
            f"output(s) {sequence} are totals of a drop's sequence: a study gives them only "
            f"with body = {FLEXIBLE_BODY!r} (a drop), and this study has no such body"
        )
    unknown = [o for o in outs if o not in fields]
    if unknown:
        raise ValueError(
            f"unknown output(s) {unknown}; the engine provides: {', '.join(fields)} "
            f"(aliases: {', '.join(f'{k}={v}' for k, v in OUTPUT_ALIASES.items())})"
        )
    return outs + tuple(o for o in ALWAYS_STORED if o in fields and o not in outs)


def category_values(study: Study) -> dict[str, list[str]]:
    """Every value each category input takes in the study."""
    vals: dict[str, list[str]] = {}
    for name in CATEGORY_INPUTS:
        axis = next((a for a in study.axes if a.name == name), None)
        if axis is not None:
            vals[name] = [str(v) for v in axis.values]
        else:
            vals[name] = [str(study.value_of(name))]
    return vals


def engine_identity(evaluator: Evaluator) -> str:
    """What computes a store's results: the evaluator, the impactlab version and
    ``results_code_hash`` (a store's chunks are all computed by the same code)."""
    return f"{evaluator.identity}|impactlab {__version__}|code {results_code_hash()}"


def law_ranges(study: Study) -> dict[str, dict[str, str]]:
    """The range and source of each law of ``study`` (law name -> ``range``, ``source``), as a
    store records them: a user's law (``register_law``) its curves' end in delta_c (of each
    case's pair and radius: a case past it has status 1) and their name and source; a built-in
    law its stand-in range (``contact.ranges``) and where that comes from."""
    out: dict[str, dict[str, str]] = {}
    for name in category_values(study)["law"]:
        law = get_law(name)
        if isinstance(law, RegisteredLaw):
            c = law.own_curves
            out[name] = {
                "range": f"tabulated: interpolated from its curves up to their end, "
                f"{c.max_delta:.4g} delta_c (each case's Jackson-Green delta_c), and refused "
                f"beyond it (status 1); pairs with E*/S_y = "
                f"{c.e_star_over_sy:.4g} (within 5 %) and nu = {c.nu:g} (within 0.03) "
                f"whose {c.yielding} yields",
                "source": f"{c.name}: {c.source}",
            }
        else:
            rec = law_range(name)
            verified = "; the verified range of the case's pair where FE covers its E*/S_y"
            out[name] = {
                "range": rec.stand_in_text + (verified if rec.verified else ""),
                "source": rec.source,
            }
    return out


def store_meta(study: Study, evaluator: Evaluator) -> StoreMeta:
    """The store metadata for ``study`` run by ``evaluator`` (hash includes the engine, the
    impactlab version and the hash of the code that computes results)."""
    outputs = resolve_outputs(study, evaluator)
    ident = engine_identity(evaluator)
    return StoreMeta(
        study_hash=study.hash(ident),
        outputs=outputs,
        integer_outputs=tuple(o for o in evaluator.integer_outputs() if o in outputs),
        status_messages=evaluator.status_messages(),
        regimes=evaluator.regimes(),
        engine=ident,
        law_ranges=law_ranges(study),
    )
