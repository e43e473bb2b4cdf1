"""A cheap stand-in for the compiled engine, with the sweep's Evaluator interface, and wrappers
that make distributed runs deterministic.

The outputs are closed forms of the inputs, so tests can check values exactly. It can fail on a
chosen chunk (an exception inside the evaluator, to simulate a crash mid-sweep), record which
process ran it, and flags cases as invalid like a law's validity limit. ``GatedEvaluator`` and
``BarrierEvaluator`` hold chunks back until a condition a test controls holds (a file exists),
so no test depends on how fast a process happens to run.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from impactlab.cli import main
from impactlab.sweep import Normal, Sample, Study, Uniform


def store_files(path: Path) -> dict[str, bytes]:
    """Every file of a store (relative path -> bytes): two stores are identical iff equal."""
    return {
        str(p.relative_to(path)): p.read_bytes() for p in sorted(path.rglob("*")) if p.is_file()
    }


def run_cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    """``impactlab ARGS`` in this process: (exit status, stdout, stderr)."""
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    return code, out, err


FIELDS = ("e", "delta_p", "sliding_length", "duration", "mean_force", "regime")
VY_LIMIT = -5.0  # cases faster than this are "outside the fake law's validity"


class FakeEvaluator:
    identity = "fake-evaluator/1"

    def __init__(self, fail_when: str | None = None, pid_dir: str | None = None) -> None:
        # fail_when: a file path; when the file exists the evaluator raises (crash simulation)
        # pid_dir: a folder; every call leaves a file named after the process id there
        self.fail_when = fail_when
        self.pid_dir = pid_dir

    def output_fields(self) -> tuple[str, ...]:
        return FIELDS

    def status_messages(self) -> dict[int, str]:
        return {0: "ok", 1: "fake: vy outside the validity range"}

    def regimes(self) -> dict[int, str]:
        return {0: "slip", 1: "stick", 2: "reversal"}

    def integer_outputs(self) -> tuple[str, ...]:
        return ("regime",)

    def validate(self, categories: Mapping[str, Sequence[str]]) -> None:
        for law in categories.get("law", ()):
            if law not in ("ghaednia", "hertz", "brake"):
                raise ValueError(f"unknown contact law {law!r}")

    def __call__(self, cases, statics, outputs):
        if self.fail_when is not None and os.path.exists(self.fail_when):
            raise RuntimeError("simulated crash")
        if self.pid_dir is not None:
            Path(self.pid_dir, str(os.getpid())).touch()
        th, vy, mu = cases["angle"], cases["vy"], cases["mu"]
        law = {"ghaednia": 0.0, "hertz": 1.0, "brake": 2.0}[statics.categories["law"]]
        E = np.where(np.isnan(cases["flat_E"]), 200e9, cases["flat_E"])
        out = {
            "e": 0.5 + 0.1 * np.sin(th) - 0.2 * mu + 0.01 * law,
            "delta_p": 1e-5 * np.abs(vy) * (200e9 / E),
            "sliding_length": 1e-3 * mu * np.cos(th),
            "duration": 1e-4 + 0.0 * th,
            "mean_force": 1000.0 * np.abs(vy),
            "regime": (mu > 0.5 * np.cos(th)).astype(float),
        }
        status = np.where(vy < VY_LIMIT, 1, 0).astype(np.int32)
        res = {}
        for o in outputs:
            v = out[o].astype(float).copy()
            v[status != 0] = np.nan
            res[o] = v
        return res, status


class CrashingEvaluator(FakeEvaluator):
    """Same identity and numbers as FakeEvaluator, but raises on its (after+1)-th call."""

    def __init__(self, after: int) -> None:
        super().__init__()
        self.after = after
        self.calls = 0

    def __call__(self, cases, statics, outputs):
        self.calls += 1
        if self.calls > self.after:
            raise RuntimeError("simulated crash mid-sweep")
        return super().__call__(cases, statics, outputs)


def wait_for(condition, what: str, timeout: float = 300.0) -> None:
    """Poll ``condition()`` until it holds; AssertionError naming ``what`` after ``timeout`` s
    (a bound against a hang, far above any expected wait)."""
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out after {timeout} s waiting for {what}")
        time.sleep(0.01)


class _Wrapper:
    """Wraps an evaluator: same identity, same numbers."""

    def __init__(self, inner) -> None:
        self.inner = inner
        self.identity = inner.identity

    def output_fields(self):
        return self.inner.output_fields()

    def status_messages(self):
        return self.inner.status_messages()

    def regimes(self):
        return self.inner.regimes()

    def integer_outputs(self):
        return self.inner.integer_outputs()

    def validate(self, categories):
        return self.inner.validate(categories)


class GatedEvaluator(_Wrapper):
    """The victim process (``victim_pid``) computes one chunk, then blocks until it is killed;
    every other process waits until the file ``gate/release`` exists. So the first chunk stored
    is the victim's, and the sweep is still running when the victim dies."""

    def __init__(self, inner, gate: str, victim_pid: int) -> None:
        super().__init__(inner)
        self.gate = gate
        self.victim_pid = victim_pid

    def __call__(self, cases, statics, outputs):
        gate = Path(self.gate)
        if os.getpid() == self.victim_pid:
            done = gate / "victim-computed"
            if done.exists():
                wait_for(lambda: False, "the test to kill this worker", timeout=600)
            done.touch()
        else:
            wait_for((gate / "release").exists, "the test to release the other workers")
        return self.inner(cases, statics, outputs)


class BarrierEvaluator(_Wrapper):
    """Each process's first chunk waits until ``n`` processes have started one: every worker of
    an ``n``-worker cluster computes at least one chunk, whatever the scheduling."""

    def __init__(self, inner, gate: str, n: int) -> None:
        super().__init__(inner)
        self.gate = gate
        self.n = n

    def __call__(self, cases, statics, outputs):
        gate = Path(self.gate)
        (gate / f"started-{os.getpid()}").touch()
        wait_for(lambda: len(list(gate.glob("started-*"))) >= self.n, f"{self.n} workers")
        return self.inner(cases, statics, outputs)


class FlaggingEvaluator(FakeEvaluator):
    """FakeEvaluator (same identity and numbers) that also has the engine's ``flags`` output:
    energy gain (1) where mu > 0.4, gravity-dominated (2) where vy > -0.5."""

    def output_fields(self) -> tuple[str, ...]:
        return (*FIELDS, "flags")

    def integer_outputs(self) -> tuple[str, ...]:
        return ("regime", "flags")

    def flags_for(self, cases) -> np.ndarray:
        """The ``flags`` of ``cases`` (a subclass sets other bits)."""
        return np.where(cases["mu"] > 0.4, 1, 0) | np.where(cases["vy"] > -0.5, 2, 0)

    def __call__(self, cases, statics, outputs):
        res, status = super().__call__(cases, statics, [o for o in outputs if o != "flags"])
        if "flags" in outputs:
            res["flags"] = np.where(status == 0, self.flags_for(cases), np.nan)
        return res, status


def kill_study(seed: int = 5) -> Study:
    """A grid + sample study of 18 chunks (category, grid and sample dimensions; the sampled
    inputs are written by the chunks at the start of the grid)."""
    return Study(
        name="kill",
        chunk_size=100,
        grid={"law": ["ghaednia", "hertz"], "angle": [0.2, 0.5, 0.9]},
        sample=Sample(
            size=300, seed=seed, inputs={"vy": Normal(-1.41, 0.05), "mu": Uniform(0.1, 0.3)}
        ),
    )


def run_kill_study(
    log: str, env: dict[str, str], seed: int, store: str, pid_dir: str, backend: str, restart: bool
) -> None:
    """The body of a kill test's child process: ``run_sweep`` of ``kill_study(seed)`` into
    ``store`` (2 workers of ``backend``; the evaluator leaves its process ids in ``pid_dir``),
    with ``env`` added to the environment (the kill hook's variables) and stderr written to the
    file ``log``. Run in a process forked from a server that imported this module and the sweep
    package once (``multiprocessing``'s forkserver): no child pays the package import (2-3 s)."""
    import signal

    from impactlab.sweep import run_sweep

    # as an interactive command: Ctrl-C raises KeyboardInterrupt (a process started from a
    # non-interactive background job inherits SIGINT ignored)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    fd = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
    os.dup2(fd, 2)
    os.close(fd)
    os.environ.update(env)
    evaluator = FakeEvaluator(pid_dir=pid_dir)
    run_sweep(
        kill_study(seed), store, evaluator=evaluator, backend=backend, workers=2, restart=restart
    )
