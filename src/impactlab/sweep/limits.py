"""How big a study may be: a limit on the number of cases (refused before anything is created,
with an estimate of the compute time and the disk it would take), what a study's cases cost
(the estimates, and the default chunk size of ``options.default_chunk_size``), and warnings for
chunks so small that the per-chunk overhead dominates."""

from __future__ import annotations

import math
import os
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab.sweep.inputs import ALWAYS_STORED, INTEGER_OUTPUTS, OUTPUTS
from impactlab.sweep.models import MAX_TABLES, law_rows

#: Default largest study, in cases, that a sweep accepts (``[study] max_cases`` or
#: ``--max-cases`` raise it).
DEFAULT_MAX_CASES = 100_000_000
#: What one case costs on one core [s], by kind, from the benchmarks (estimates: the machine,
#: its load and the case change them by a factor of 2 or more).
#: A rigid body's impact (rod or sphere; coulomb, mindlin, impulse_ratio): the sweep benchmark
#: of docs/sweep.md ("Benchmark"; benchmarks/results/sweep.json, "full"): 10 000 000 impacts
#: end to end in 44.7 s on 2 cores, 224 000 impacts/s, 112 000 per core.
RIGID_CASE_S = 2.0 / 224_000
#: A ``partial_slip`` impact: 233 us per impact in its batch (benchmarks/results/
#: partial_slip.json, ``all_cases``), 124-266 us over laws and mu, 183 us on average
#: (partial_slip_spread.json; docs/engine/benchmarks.md); a sweep over wider speeds and angles
#: measured about 280 us.
PARTIAL_SLIP_CASE_S = 250e-6
#: A flexible rod's drop: 201 drops per CPU-second in one batch (benchmarks/results/
#: flexible.json, ``batch``; 178-181 in two more runs; docs/flexible.md), about 5.0 ms each.
FLEXIBLE_DROP_S = 1.0 / 201
#: One contact model built in Python, on one core, per distinct law row (a Monte Carlo over
#: material properties builds one per case): about 1.5 ms for the Jackson-Green family
#: (docs/sweep.md, "Cost of per-case materials").
CONTACT_MODEL_S = 1.5e-3
#: A chunk of fewer cases than this is "tiny" (its fixed overhead dominates) ...
TINY_CHUNK = 256
#: ... which matters once a study has more chunks than this.
MANY_CHUNKS = 1_000


class SweepSizeWarning(UserWarning):
    """A study whose chunking makes it needlessly slow or its store needlessly many files."""


def usable_cores() -> int:
    """Cores usable by this process."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not on Linux
        return os.cpu_count() or 1


def check_max_cases(value: Any) -> int:
    """``max_cases`` as an integer >= 1 (an integral float such as TOML's ``1e9`` is accepted)."""
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 1:
        raise ValueError(f"max_cases must be an integer >= 1, got {value!r}")
    return int(value)


def _duration(seconds: float) -> str:
    for unit, size in (("years", 365.25 * 86400), ("days", 86400), ("h", 3600), ("min", 60)):
        if seconds >= size:
            return f"{seconds / size:,.1f} {unit}"
    return f"{seconds:.0f} s"


def _bytes(n: float) -> str:
    for unit, size in (("PB", 1e15), ("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if n >= size:
            return f"{n / size:,.1f} {unit}"
    return f"{n:.0f} B"


def bytes_per_case(outputs: Sequence[str] | None) -> int:
    """Stored bytes per case before compression: the kept outputs (all when None), the result
    flags and the status."""
    names = set(OUTPUTS if outputs is None else outputs) | (set(ALWAYS_STORED) & set(OUTPUTS))
    sizes = [np.dtype(INTEGER_OUTPUTS.get(n, "float64")).itemsize for n in names]
    return int(sum(sizes)) + 4


@dataclass(frozen=True)
class StudyCost:
    """What a study's cases cost on one core [s], estimated from the benchmarks.

    mean_case_s : one case, the mean over the study's bodies and friction models (each an
        equal share of the cases, as on a grid).
    max_case_s : one case of the dearest of them (a chunk holds cases of one kind).
    models : contact models built (distinct law rows, ``models.law_rows``), each
        ``CONTACT_MODEL_S`` on one core.
    n_cases : the study's cases.
    cases : what a case is: "impacts", "drops" (flexible rods only) or "cases" (both).
    """

    mean_case_s: float = RIGID_CASE_S
    max_case_s: float = RIGID_CASE_S
    models: int = 1
    n_cases: int = 1
    cases: str = "impacts"

    def seconds(self, cores: int) -> float:
        """The study's compute time on ``cores`` cores [s] (the models built on one)."""
        return self.n_cases * self.mean_case_s / cores + self.models * CONTACT_MODEL_S

    def chunk_case_s(self) -> float:
        """One case of a chunk of the dearest kind on one core [s], with its share of the
        models where they are many (more than ``models.MAX_TABLES``: a Monte Carlo over
        material properties, a large grid of materials); a few models are built once."""
        share = min(1.0, self.models / max(self.n_cases, 1)) if self.models > MAX_TABLES else 0.0
        return self.max_case_s + CONTACT_MODEL_S * share


def case_seconds(body: str, friction: str, cells: int | None = None) -> float:
    """One case of ``body`` with ``friction`` on one core [s] (the constants above); a
    ``partial_slip`` impact of ``cells`` cells (None: the default 16) as (cells / 16)^1.2 times
    one of 16 (a rod's batch on one core: 0.28 ms at 16 cells, 0.65 ms at 32, 1.5 ms at 64)."""
    if body == "flexible_rod":
        return FLEXIBLE_DROP_S
    if friction != "partial_slip":
        return RIGID_CASE_S
    return PARTIAL_SLIP_CASE_S * (1.0 if cells is None else max(1.0, cells / 16.0) ** 1.2)


def study_cost(study: Any) -> StudyCost:
    """The :class:`StudyCost` of a ``Study``: its bodies and friction models (grid axes or
    single values), its law rows and its number of cases."""
    kinds = {
        name: next((a.values for a in study.axes if a.name == name), (study.value_of(name),))
        for name in ("body", "friction")
    }
    cells = getattr(getattr(study, "engine", None), "partial_slip_cells", None)
    costs = [case_seconds(str(b), str(f), cells) for b in kinds["body"] for f in kinds["friction"]]
    n = math.prod(len(a.values) for a in study.axes)
    n *= 1 if study.sample is None else study.sample.size
    models = law_rows(study.axes, study.sample)
    drops = [str(b) == "flexible_rod" for b in kinds["body"]]
    cases = "drops" if all(drops) else "cases" if any(drops) else "impacts"
    return StudyCost(sum(costs) / len(costs), max(costs), models, n, cases)


def estimate(n_cases: int, outputs: Sequence[str] | None, cost: StudyCost | None = None) -> str:
    """``"about 3.2 h on this machine's 2 core(s) (...) and about 21 GB of disk ..."``: the
    time from ``cost`` (None: a rigid body's impacts), an estimate."""
    cores = usable_cores()
    whose = "this study's bodies and friction models"
    if cost is None:
        cost, whose = StudyCost(n_cases=n_cases), "a rigid body's impacts"
    seconds = cost.seconds(cores)
    models = cost.models * CONTACT_MODEL_S
    built = (
        f", and its {cost.models:,} contact models built on one core at about "
        f"{CONTACT_MODEL_S * 1e3:g} ms each"
        if models >= 0.1 * seconds
        else ""
    )
    disk = float(n_cases) * bytes_per_case(outputs)
    return (
        f"about {_duration(seconds)} on this machine's {cores} core(s) (an estimate at about "
        f"{1.0 / cost.mean_case_s:,.0f} {cost.cases}/s per core, the benchmarks' figure for "
        f"{whose}{built}) and about {_bytes(disk)} of disk before compression"
    )


def too_many(
    what: str,
    n_cases: int,
    max_cases: int,
    outputs: Sequence[str] | None,
    cost: StudyCost | None = None,
) -> ValueError:
    """The error for a study (or one grid axis) of ``n_cases`` cases over ``max_cases``
    (``cost``: the study's, for the time estimate; None: a rigid body's impacts)."""
    return ValueError(
        f"{what} has {n_cases:,} cases, more than max_cases = {max_cases:,}: "
        f"{estimate(n_cases, outputs, cost)}; shrink the grid or the sample, or raise max_cases "
        f"([study] max_cases, --max-cases) if you mean it"
    )


def check_size(study: Any, default_chunk: int) -> None:
    """Refuse a ``Study`` of more than its ``max_cases`` cases (with an estimate of its time and
    disk) and warn when its chunks are tiny (``default_chunk``: its default chunk size)."""
    lay = study.layout
    if lay.n_cases > study.max_cases:
        name = f"study {study.name!r}"
        raise too_many(name, lay.n_cases, study.max_cases, study.outputs, study_cost(study))
    warn_chunking(study.name, study.cases_per_chunk, lay.n_cases, lay.n_chunks, default_chunk)


def warn_chunking(
    name: str, chunk_size: int, n_cases: int, n_chunks: int, default: int | None = None
) -> None:
    """Warn (SweepSizeWarning) when the chunks are so small that their overhead dominates
    (``default``: the study's default chunk size, suggested instead)."""
    if n_chunks <= 1 or (chunk_size > 1 and (chunk_size >= TINY_CHUNK or n_chunks <= MANY_CHUNKS)):
        return
    per = n_cases / n_chunks
    better = (
        f"leave chunk_size unset (this study's default: {default:,})"
        if default is not None and default > chunk_size
        else f"use chunk_size = {TINY_CHUNK} or more"
    )
    warnings.warn(
        f"study {name!r}: chunk_size = {chunk_size} cuts {n_cases:,} cases into {n_chunks:,} "
        f"chunks of about {math.ceil(per):,} case(s); each chunk is one engine call and one file "
        f"per output, so the overhead dominates: {better}",
        SweepSizeWarning,
        stacklevel=5,  # the caller of Study(...)
    )
