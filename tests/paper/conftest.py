"""The paper's tests share one full reproduction (a few seconds with a warm engine cache), one
without the simulations, and the reading of the numbers the paper's pages quote (``page``)."""

from __future__ import annotations

import re
from pathlib import Path
from types import SimpleNamespace

import pandas as pd
import pytest

from impactlab.paper import reproduction as R

DOCS = Path(__file__).resolve().parents[2] / "docs"


def _agrees(quoted: str, value: float) -> bool:
    """``value`` rounds to ``quoted`` (a number as a page prints it): within half a unit of its
    last digit."""
    q = quoted.strip().replace("\u2212", "-")
    decimals = len(q.split(".")[1]) if "." in q else 0
    return abs(float(q) - value) <= 0.5 * 10.0**-decimals * (1 + 1e-9) + 1e-12


def _check(quoted: str, value: float, what: str) -> None:
    assert _agrees(quoted, value), f"{what}: the page says {quoted}, the code gives {value!r}"


def _numbers(pattern: str, text: str) -> tuple[str, ...]:
    """The groups of the one match of ``pattern`` (whitespace in it matches any whitespace, so
    a sentence may wrap)."""
    found = re.findall(r"\s+".join(pattern.split()), text)
    assert len(found) == 1, f"{pattern!r}: {len(found)} matches on the page"
    return found[0] if isinstance(found[0], tuple) else (found[0],)


def _table(text: str, header_start: str) -> list[list[str]]:
    """The rows (cells stripped) of the Markdown table whose header starts ``header_start``."""
    lines = text.splitlines()
    i = next(k for k, line in enumerate(lines) if line.startswith(header_start))
    rows = []
    for line in lines[i + 2 :]:
        if not line.startswith("|"):
            break
        rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows


@pytest.fixture(scope="package")
def page() -> SimpleNamespace:
    """The pages' text (``reproduction``, ``errata``, ``tutorial``) and how their numbers are
    read: ``check(quoted, value, what)``, ``numbers(pattern, text)``, ``table(text, header)``."""
    return SimpleNamespace(
        reproduction=(DOCS / "paper" / "reproduction.md").read_text(encoding="utf-8"),
        errata=(DOCS / "paper" / "errata.md").read_text(encoding="utf-8"),
        tutorial=(DOCS / "tutorials" / "reproduce.md").read_text(encoding="utf-8"),
        agrees=_agrees,
        check=_check,
        numbers=_numbers,
        table=_table,
    )


@pytest.fixture(scope="package")
def full_reproduction(tmp_path_factory) -> R.ReproductionResult:
    """``reproduce`` with the simulations, once; tests copy its folder before writing there."""
    return R.reproduce(tmp_path_factory.mktemp("repro_full"))


@pytest.fixture(scope="package")
def analytic_reproduction(tmp_path_factory) -> R.ReproductionResult:
    """``reproduce(simulate=False)`` (the analytic part only), once, into a folder it creates
    with its parents; tests copy its folder before writing there."""
    out = tmp_path_factory.mktemp("repro_analytic") / "new" / "folder"
    return R.reproduce(out, simulate=False)


@pytest.fixture(scope="package")
def sims(full_reproduction) -> pd.DataFrame:
    """The simulations (impulse-ratio friction), indexed by angle [deg] and law."""
    s = full_reproduction.simulations
    return s[s["friction"] == "impulse_ratio"].set_index(["angle [deg]", "law"])


@pytest.fixture(scope="package")
def fe(full_reproduction) -> pd.DataFrame:
    """fe_reference.csv of the reproduction."""
    return pd.read_csv(full_reproduction.files["fe_reference"])
