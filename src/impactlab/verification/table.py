"""The result container of every verification family and the published tolerances."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["TOLERANCES", "Column", "VerificationTable", "columns", "worst_of"]

#: Tolerances of the checks (relative unless stated; see each function).
TOLERANCES: Mapping[str, float] = {
    "hertz": 1e-6,  # relative error of T, F_max, delta_max; |e - 1|
    "thornton": 2e-6,  # absolute error of e
    "rigid": 1e-6,  # relative error of the impulses, |dv_t|/|v_n0|, |e - 1|
    "critical_friction": 1e-6,  # relative error of the slip/stick boundary
    # engine (default rtol) vs solve_ivp at rtol 1e-11, relative to each quantity's scale: the
    # accuracy contract of tests/dynamics/test_accuracy.py
    "reference": 1e-5,
    "paper_duration": 0.05,  # analytic T vs the paper's published T
    "invariants": 1e-6,  # -dissipated / E0, e and e* above 1
    # energy rise / E0 along a recorded history (dense output): 100 times the default rtol
    # (2e-7); the interpolant's error where a power-law unloading curve ends at separation
    "energy_history": 2e-5,
}


@dataclass(frozen=True)
class Column:
    """A table column: ``key`` in each record, the ``label`` printed, and a format spec."""

    key: str
    label: str
    fmt: str = ""


def columns(spec: str) -> tuple[Column, ...]:
    """The columns of a table from a text table, one column a line: ``key | label | format``
    (the format may be left out)."""
    out = []
    for line in spec.strip().splitlines():
        key, label, *fmt = (part.strip() for part in line.split(" | "))
        out.append(Column(key, label, *fmt))
    return tuple(out)


def _cell(value: Any, fmt: str) -> str:
    if value is None:
        return "-"
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "**no**"
    if isinstance(value, float | np.floating):
        if math.isnan(float(value)):
            return "-"
        return format(float(value), fmt or ".6g")
    if isinstance(value, str):
        return value
    return format(value, fmt) if fmt else str(value)


@dataclass(frozen=True)
class VerificationTable:
    """One verification family: what was compared, the rows, and the verdict.

    ``records`` hold the raw numbers (SI, one dict per row); ``worst`` is the largest value of
    the checked error metric over the rows, ``passed`` whether every row met ``tolerance``
    (and any exact requirement such as a matching regime). ``figure`` names a PNG written by
    :func:`main` (None when none).
    """

    key: str
    title: str
    text: str
    columns: tuple[Column, ...]
    records: tuple[Mapping[str, Any], ...]
    metric: str
    worst: float
    tolerance: float
    passed: bool
    figure: str | None = None
    extra: Mapping[str, Any] = field(default_factory=dict, repr=False)

    def to_markdown(self) -> str:
        """The table as a Markdown section (title, description, table, verdict)."""
        head = "| " + " | ".join(c.label for c in self.columns) + " |"
        sep = "|" + "|".join("---" for _ in self.columns) + "|"
        body = [
            "| " + " | ".join(_cell(r.get(c.key), c.fmt) for c in self.columns) + " |"
            for r in self.records
        ]
        verdict = "**pass**" if self.passed else "**FAIL**"
        lines = [
            f"## {self.title}",
            "",
            self.text.strip(),
            "",
            head,
            sep,
            *body,
            "",
            f"Checked: {self.metric}; worst {self.worst:.3g}, tolerance "
            f"{self.tolerance:.3g}: {verdict}.",
            "",
        ]
        if self.figure:
            lines += [f"![{self.title}]({self.figure})", ""]
        return "\n".join(lines)


def worst_of(values: Sequence[float] | np.ndarray) -> float:
    """The largest value (0 for none, inf if any is NaN): the worst error of a family."""
    a = np.asarray(values, dtype=float)
    if a.size == 0:
        return 0.0
    if np.any(np.isnan(a)):
        return math.inf
    return float(np.max(a))
