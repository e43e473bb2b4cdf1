"""A cheap stand-in for the compiled engine, with the sweep's Evaluator interface.

The outputs are closed forms of the inputs, so tests can check values exactly. It can fail on a
chosen chunk (an exception inside the evaluator, to simulate a crash mid-sweep), sleep per case
(to make a sweep slow enough to kill), and flags cases as invalid like a law's validity limit.
"""

from __future__ import annotations

import os
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np


def store_files(path: Path) -> dict[str, bytes]:
    """Every file of a store (relative path -> bytes): two stores are identical iff equal."""
    return {
        str(p.relative_to(path)): p.read_bytes() for p in sorted(path.rglob("*")) if p.is_file()
    }


FIELDS = ("e", "delta_p", "sliding_length", "duration", "mean_force", "regime")
VY_LIMIT = -5.0  # cases faster than this are "outside the fake law's validity"


class FakeEvaluator:
    identity = "fake-evaluator/1"

    def __init__(self, fail_when: str | None = None, delay: float = 0.0) -> None:
        # fail_when: a file path; when the file exists the evaluator raises (crash simulation)
        self.fail_when = fail_when
        self.delay = delay

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
        n = len(cases["angle"])
        if self.delay:
            time.sleep(self.delay * n)
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


class SlowEvaluator:
    """Wraps an evaluator (same identity, same numbers) and sleeps per chunk: a sweep slow
    enough to kill a worker in the middle of it."""

    def __init__(self, inner, delay: float) -> None:
        self.inner = inner
        self.delay = delay
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

    def __call__(self, cases, statics, outputs):
        time.sleep(self.delay)
        return self.inner(cases, statics, outputs)
