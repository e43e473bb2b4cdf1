"""The runs of one shipped FE case to different maxima do not follow one loading path: their
force at the same interference differs from the farthest run's (the curve the accuracy tables
and the tabulated law use) by up to 1.3 % below 10 delta_c and 2.7 % beyond, twice the 1.4 %
mesh uncertainty. ``ReferenceCase.loading_spread`` measures it from the shipped data; the table
of docs/fe.md ("Run-to-run spread") and the statements built on it are checked here."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from impactlab.contact import get_law
from impactlab.fe.curves import ReferenceCase, load_cases

DOCS = Path(__file__).resolve().parents[2] / "docs"
#: The docs' names of the cases (the table's first column) by case.
NAMES = {
    "paper-aisi201-on-aisi1010": "paper's pair",
    "aisi201-on-al6061t6": "aluminium",
    "elastic-sphere-on-aisi4340": "hard steel",
    "aisi201-on-pmma": "PMMA",
    "elastic-52100-on-aisi304": "AISI 304",
    "elastic-52100-on-copper-ofhc": "OFHC copper",
}
BANDS = ((0.0, 1.0 + 1e-4), (1.0 + 1e-4, 10.0 + 1e-4), (10.0 + 1e-4, np.inf))


@pytest.fixture(scope="module")
def cases() -> list[ReferenceCase]:
    return load_cases()


def _table() -> dict[str, list[str]]:
    text = (DOCS / "fe.md").read_text()
    section = text.split("### Run-to-run spread", 1)[1].split("###", 1)[0]
    rows = {}
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 4 and cells[0].endswith(")"):
            rows[cells[0].rsplit(" (", 1)[0]] = cells[1:]
    return rows


def test_the_documented_spread_is_the_data_s(cases: list[ReferenceCase]) -> None:
    table = _table()
    assert set(table) == set(NAMES.values())
    for case in cases:
        row = table[NAMES[case.name]]
        for (low, high), cell in zip(BANDS, row, strict=True):
            s = case.loading_spread(low, high)
            if np.isnan(s.delta_ratio):
                assert cell.startswith("-")  # no other run there
                continue
            number = float(re.match(r"[+-]?([\d.]+) %", cell).group(1))  # type: ignore[union-attr]
            assert number == pytest.approx(100 * abs(s.relative), abs=0.051), (case.name, cell)
            if cell[0] in "+-":  # a signed cell also says where
                assert cell[0] == ("+" if s.relative > 0 else "-")
                assert f" at {s.delta_ratio:.2g}" in cell or f" at {s.delta_ratio:.3g}" in cell


def test_below_10_delta_c_within_1_3_percent_beyond_within_2_7(
    cases: list[ReferenceCase],
) -> None:
    low = max(abs(c.loading_spread(0.0, 10.0 + 1e-4).relative) for c in cases)
    high = max(abs(c.loading_spread(10.0 + 1e-4).relative) for c in cases)
    assert 0.012 < low < 0.0135 and 0.026 < high < 0.0275  # 1.3 % and 2.7 %
    # where the verified ranges lie (to 3 delta_c): within 1.1 %
    assert max(abs(c.loading_spread(0.0, 3.0 + 1e-4).relative) for c in cases) < 0.011
    doc = (DOCS / "fe.md").read_text()
    assert "within 1.3 % up to 10 $\\delta_c$ and\n  2.7 % beyond" in doc


def test_the_tabulated_law_against_every_run(cases: list[ReferenceCase]) -> None:
    """Fitted to the farthest run (within 2.5 % of its points), within 2.8 % of every run's:
    the paper's pair at 300 delta_c (docs/laws/tabulated.md, docs/fe.md)."""
    worst = []
    for case in cases:
        model = get_law("tabulated").build(case.pair, case.radius)
        for r in case.runs:
            d, f = r.loading_delta, r.loading_force
            keep = (d > case.delta_c * 1.0001) & (d <= model.max_interference) & (f > 0.0)
            if not keep.any():  # a run that stays below delta_c
                continue
            rel = np.abs(model.force(d[keep]) / f[keep] - 1.0)
            j = int(np.argmax(rel))
            worst.append((float(rel[j]), case.name, float(d[keep][j] / case.delta_c)))
    top = max(worst)
    assert 0.0265 < top[0] < 0.028 and top[1] == "paper-aisi201-on-aisi1010"
    assert top[2] == pytest.approx(300.0, rel=1e-3)
    assert "within 2.8 %" in (DOCS / "laws" / "tabulated.md").read_text()


def test_the_docstring_no_longer_claims_one_path() -> None:
    doc = ReferenceCase.loading_curve.__doc__ or ""
    assert "same path" not in doc and "2.7 %" in doc
