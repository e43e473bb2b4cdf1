"""What ``run_sweep`` returns: :class:`SweepResult`, the store and the study, with
:class:`SweepStats`, the numbers of the run (cases, chunks, wall and compute times [s], the
backend, the store's status and flag counts once it ended)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from impactlab._display import format_number
from impactlab.sweep.display import no_result, results_text, sweep_result_html
from impactlab.sweep.store import SweepStore, open_sweep
from impactlab.sweep.study import Study


@dataclass
class SweepStats:
    """Numbers of one ``run_sweep`` call."""

    #: chunks and cases of the study
    n_chunks: int = 0
    n_cases: int = 0
    #: chunks already stored (intact) when this run started
    chunks_before: int = 0
    #: chunks and cases this run computed
    chunks_computed: int = 0
    cases_computed: int = 0
    #: wall time of the run; time inside the evaluator; per-chunk compute time; writes [s]
    wall_s: float = 0.0
    eval_s: float = 0.0
    compute_s: float = 0.0
    write_s: float = 0.0
    #: the backend and its number of workers
    backend: str = ""
    workers: int = 0
    #: chunks found damaged (files no longer matching their checksums) and computed again
    chunks_repaired: int = 0
    #: per worker: numba cache hits/misses seen by its tasks
    cache: dict[str, dict[str, int]] = field(default_factory=dict)
    #: per worker: wall time of its first task [s]
    first_task_s: dict[str, float] = field(default_factory=dict)
    #: per worker: cases of its first task (``sweep.display.steady_throughput`` leaves them out)
    first_task_cases: dict[str, int] = field(default_factory=dict)
    #: the store's cases per status once the run ended, keyed "<code>: <message>"
    #: (``summary.status_counts``: ``"0: finished"``, the engine ran the case to its end)
    status: dict[str, int] = field(default_factory=dict)
    #: the store's cases per result flag once the run ended, with "flagged" (any flag) and
    #: "not ok" (a flag that is not advisory) (``summary.flag_counts``); {} without ``flags``
    flagged: dict[str, int] = field(default_factory=dict)

    @property
    def not_ok(self) -> int:
        """Cases of the store whose result is not ok: a flag that is not advisory (energy gain,
        beyond the tip, ...; ``flagged`` names them)."""
        return int(self.flagged.get("not ok", 0))

    @property
    def failed(self) -> int:
        """Cases of the store without a result: refused or failed (a status > 0; ``status``
        names why). A run none of whose cases succeeded (``succeeded == 0``) warns
        (``FailedCasesWarning``), as the command line exits with status 2."""
        return no_result(self)

    @property
    def succeeded(self) -> int:
        """Cases of the store the engine ran to their end (status 0, ``"0: finished"``; whether
        their result is ok, ``not_ok`` says)."""
        return sum(n for k, n in self.status.items() if k.partition(":")[0].strip() == "0")

    @property
    def throughput(self) -> float:
        """Cases computed per second of wall time."""
        return self.cases_computed / self.wall_s if self.wall_s > 0 else 0.0

    def __repr__(self) -> str:
        """One line: the study's cases and chunks, what this run computed, its wall time and
        throughput, the backend (the per-worker numbers: the attributes)."""
        repaired = f", {self.chunks_repaired} repaired" if self.chunks_repaired else ""
        rate = f", {format_number(self.throughput)} impacts/s" if self.cases_computed else ""
        return (
            f"SweepStats({_count(self.n_cases, 'case')} in {_count(self.n_chunks, 'chunk')}; "
            f"this run: {_count(self.cases_computed, 'case')} in "
            f"{_count(self.chunks_computed, 'chunk')} computed, {self.chunks_before} already "
            f"stored{repaired}; wall {format_number(self.wall_s)} s{rate}; "
            f"backend={self.backend!r}, workers={self.workers}{results_text(self)})"
        )


def _count(n: int, what: str) -> str:
    """``"1 chunk"``, ``"33 chunks"``."""
    return f"{n} {what}" + ("" if n == 1 else "s")


@dataclass
class SweepResult:
    """A finished (or resumed) sweep: the store and the numbers of this run."""

    path: Path
    study: Study
    stats: SweepStats

    @property
    def dataset(self) -> Any:
        """The results as a lazy xarray Dataset."""
        return open_sweep(self.path)

    def _repr_html_(self) -> str:
        return sweep_result_html(self)

    def __repr__(self) -> str:
        """One line: the store, the study, its size and what this run computed."""
        st = self.stats
        return (
            f"SweepResult(path={str(self.path)!r}, study={self.study.name!r}, "
            f"{_count(st.n_cases, 'case')} in {_count(st.n_chunks, 'chunk')}; this run: "
            f"{_count(st.cases_computed, 'case')} computed in {format_number(st.wall_s)} s, "
            f"backend={st.backend!r}{results_text(st)})"
        )

    @property
    def complete(self) -> bool:
        return len(SweepStore(self.path).done_chunks()) == self.study.layout.n_chunks
