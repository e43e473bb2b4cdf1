"""Running a study for ``impactlab sweep run`` and ``sweep uncertainty``: ``run_sweep`` with
the command's options, the study's warnings printed, its errors (a Dask scheduler that does
not answer, no workers, a lost worker) as one line; a study refused before it runs."""

from __future__ import annotations

import sys
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import typer

from impactlab.cli._common import UserError
from impactlab.cli.printing import print_wrapped

if TYPE_CHECKING:
    from impactlab.sweep import SweepResult

# impactlab.sweep (about 1 s to import) is imported inside the functions, as in
# impactlab.cli.sweep: ``impactlab --help`` and the other commands start without it.


@dataclass(frozen=True)
class Where:
    """Where and how a study runs (the options shared by ``run`` and ``uncertainty``)."""

    out: Path | None
    scheduler: str | None
    workers: int | None
    max_cases: int | None
    worker_timeout: float | None = None  # None: run_sweep's default
    backend: str | None = None


def run_study(study_path: Path, where: Where, quiet: bool, restart: bool) -> SweepResult:
    """``run_sweep`` of the study file ``study_path`` with ``where``'s options; the study's
    size warnings printed, a Dask scheduler's or its workers' failure as one line."""
    from impactlab.sweep import Study, SweepSizeWarning, backends, run_sweep
    from impactlab.sweep.runner import FlaggedCasesWarning

    timeout = where.worker_timeout

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SweepSizeWarning)
        study = Study.from_toml(study_path, max_cases=where.max_cases)
    for w in caught:
        print_wrapped(f"warning: {w.message}")
    try:
        with warnings.catch_warnings():  # the summary counts them (--quiet: no summary)
            warnings.simplefilter("ignore", FlaggedCasesWarning)
            return run_sweep(
                study,
                where.out,
                scheduler=where.scheduler,
                workers=where.workers,
                backend=where.backend,
                quiet=quiet,
                restart=restart,
                worker_timeout=backends.DEFAULT_WORKER_TIMEOUT if timeout is None else timeout,
            )
    except (OSError, TimeoutError) as exc:
        if where.scheduler is not None and not isinstance(exc, backends.StoreWriteError):
            raise UserError(
                f"cannot use the Dask scheduler {where.scheduler!r}: {exc}; the store "
                f"{where.out} keeps what it holds (run again to resume, with a scheduler that "
                "answers or without --scheduler)"
            ) from None
        raise
    except KeyboardInterrupt as exc:  # SIGTERM (kill PID): Ctrl-C's line, then status 143
        from impactlab.sweep.termination import TERMINATED_EXIT, terminated

        if not terminated(exc):
            raise
        if not getattr(exc, "said", False):
            print(exc.args[0] if exc.args else "terminated", file=sys.stderr, flush=True)
        raise typer.Exit(TERMINATED_EXIT) from None
    except backends.NoWorkersError as exc:  # one line, as docs/sweep.md says
        raise UserError(str(exc)) from None
    except backends.WorkerLostError as exc:  # one line, as an interrupt's; not the user's input: 1
        print_wrapped(f"error: {exc}")
        raise typer.Exit(1) from None


def check_uncertainty_study(path: Path, max_cases: int | None) -> None:
    """UserError, before the sweep runs, for a study without a Monte Carlo sample, which the
    uncertainty report cannot summarise (its warnings are given when the sweep builds it)."""
    from impactlab.sweep import Study

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        study = Study.from_toml(path, max_cases=max_cases)
    if study.sample is None:
        raise UserError(
            f"{path}: the uncertainty report needs a Monte Carlo sample ([sample]); this study "
            "is a grid only: run it with `impactlab sweep` instead"
        )
