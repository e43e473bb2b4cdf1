"""How big a study may be: a limit on the number of cases (refused before anything is created,
with an estimate of the compute time and the disk it would take) and warnings for chunks so
small that the per-chunk overhead dominates."""

from __future__ import annotations

import math
import os
import warnings
from collections.abc import Sequence
from typing import Any

import numpy as np

from impactlab.sweep.inputs import ALWAYS_STORED, INTEGER_OUTPUTS, OUTPUTS

#: Default largest study, in cases, that a sweep accepts (``[study] max_cases`` or
#: ``--max-cases`` raise it).
DEFAULT_MAX_CASES = 100_000_000
#: Throughput of the compiled engine per core used for the estimates: the benchmark of
#: docs/sweep.md measured 78 000 impacts/s on 2 cores (paper's rod, Ghaednia, Coulomb).
IMPACTS_PER_CORE_S = 39_000.0
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


def estimate(n_cases: int, outputs: Sequence[str] | None) -> str:
    """``"about 3.2 h on this machine's 2 cores (...) and about 21 GB of disk ..."``."""
    cores = usable_cores()
    seconds = n_cases / (IMPACTS_PER_CORE_S * cores)
    disk = float(n_cases) * bytes_per_case(outputs)
    return (
        f"about {_duration(seconds)} on this machine's {cores} core(s) (at about "
        f"{IMPACTS_PER_CORE_S:,.0f} impacts/s per core) and about {_bytes(disk)} of disk before "
        f"compression"
    )


def too_many(what: str, n_cases: int, max_cases: int, outputs: Sequence[str] | None) -> ValueError:
    """The error for a study (or one grid axis) of ``n_cases`` cases over ``max_cases``."""
    return ValueError(
        f"{what} has {n_cases:,} cases, more than max_cases = {max_cases:,}: "
        f"{estimate(n_cases, outputs)}; shrink the grid or the sample, or raise max_cases "
        f"([study] max_cases, --max-cases) if you mean it"
    )


def warn_chunking(name: str, chunk_size: int, n_cases: int, n_chunks: int) -> None:
    """Warn (SweepSizeWarning) when the chunks are so small that their overhead dominates."""
    if n_chunks <= 1 or (chunk_size > 1 and (chunk_size >= TINY_CHUNK or n_chunks <= MANY_CHUNKS)):
        return
    per = n_cases / n_chunks
    warnings.warn(
        f"study {name!r}: chunk_size = {chunk_size} cuts {n_cases:,} cases into {n_chunks:,} "
        f"chunks of about {math.ceil(per):,} case(s); each chunk is one engine call and one file "
        f"per output, so the overhead dominates: use chunk_size = 10000 or more",
        SweepSizeWarning,
        stacklevel=4,
    )
