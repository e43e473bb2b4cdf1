"""A hardening table with its columns swapped: a header that names them sets their order
(``strain,stress`` was read as stress 0 Pa at plastic strain 3.05e8 before), a header that
names both columns the same is refused, and a table without a header whose columns look
swapped is refused naming which value is read as stress and which as strain."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab import fe
from impactlab.cli.fe_hardening import read_hardening
from impactlab.fe.problem import check_hardening

CliMain = Callable[..., tuple[int, str, str]]
ROWS = [(305e6, 0.0), (400e6, 0.1)]


@pytest.mark.parametrize(
    "text",
    [
        "stress,strain\n305e6,0\n400e6,0.1\n",
        "strain,stress\n0,305e6\n0.1,400e6\n",
        "plastic_strain, true_stress_Pa\n0,305e6\n0.1,400e6\n",
        "eps_p;x\n0,305e6\n0.1,400e6\n".replace(";", ","),  # the strain named alone
        "a,sigma [Pa]\n0,305e6\n0.1,400e6\n",  # the stress named alone, second
        "305e6,0\n400e6,0.1\n",  # no header: stress first
    ],
)
def test_a_header_sets_the_column_order(text: str, tmp_path: Path) -> None:
    path = tmp_path / "h.csv"
    path.write_text(text)
    assert read_hardening(path) == ROWS


def test_a_header_naming_both_columns_alike_is_refused(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "h.csv"
    path.write_text("stress,stress_MPa\n305e6,0\n")
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--hardening", str(path))
    assert code == 2 and err.count("\n") == 1
    assert "line 1 ('stress,stress_MPa') names both columns stress;" in err
    path.write_text("strain,stress\n0,305e6\nx,400e6\n")
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--hardening", str(path))
    assert "line 3 must be 'plastic_strain, stress_Pa' (the header's order), got" in err


def test_swapped_columns_without_a_header_are_named(
    tmp_path: Path, cli_main: CliMain, monkeypatch: pytest.MonkeyPatch
) -> None:
    with pytest.raises(ValueError, match=r"^flat_hardening must start") as info:
        check_hardening("flat_hardening", [(0.0, 305e6), (0.1, 400e6)])
    assert str(info.value) == (
        "flat_hardening must start at plastic strain 0 with positive stresses: each row is "
        "(true stress [Pa], true plastic strain), so row 1 reads as stress 0.0 Pa and plastic "
        "strain 305000000.0; the columns look swapped: give the stress first"
    )
    with pytest.raises(ValueError, match=r"row 2 reads as stress -1.0 Pa and plastic strain 0.1$"):
        check_hardening("flat_hardening", [(305e6, 0.0), (-1.0, 0.1)])
    path = tmp_path / "h.csv"
    path.write_text("0,305e6\n0.1,400e6\n")
    seen: dict[str, Any] = {}
    monkeypatch.setattr(fe, "indent", lambda *a, **k: seen.update(k) or [])
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--hardening", str(path))
    assert code == 2 and err.count("\n") == 1 and not seen
    assert "--hardening must start at plastic strain 0" in err
    assert "the columns look swapped" in err


@pytest.mark.parametrize(
    ("text", "why"),
    [
        ("Stress-strain curve of the flat\n305e6,0\n400e6,0.1\n", "a title, not a header"),
        ("plastic_strain,stress_MPa\n0,305\n0.1,400\n", "the header's order and unit"),
        ("stress_Pa;plastic_strain\n305e6,0\n400e6,0.1\n", "one cell: a title"),
    ],
)
def test_only_a_two_cell_header_orders_the_columns_and_its_unit_applies(
    tmp_path: Path, text: str, why: str
) -> None:
    from impactlab.cli.fe_hardening import read_hardening

    path = tmp_path / "h.csv"
    path.write_text(text)
    assert read_hardening(path) == [(305e6, 0.0), (400e6, 0.1)], why
