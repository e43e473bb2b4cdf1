"""``impactlab fe indent --hardening FILE`` names the option in the table's messages (it
printed ``flat_hardening: a true plastic strain of 10 ...``, the Python name), and a file
without data rows says so (it printed ``--hardening must be rows of ..., got shape (0,)``).
Refused before CalculiX is looked for: ``indent`` is replaced."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab import fe
from impactlab.fe.problem import check_hardening

CliMain = Callable[..., tuple[int, str, str]]


@pytest.fixture
def never_runs(monkeypatch: pytest.MonkeyPatch) -> None:
    def indent(*args: Any, **kwargs: Any) -> Any:
        pytest.fail("indent called")

    monkeypatch.setattr(fe, "indent", indent)


def _run(cli_main: CliMain, path: Path) -> str:
    code, _, err = cli_main("fe", "indent", "--max", "0.2 um", "--hardening", str(path))
    assert code == 2 and err.count("\n") == 1
    return err


def test_a_strain_past_the_largest_is_named_by_the_option(
    tmp_path: Path, cli_main: CliMain, never_runs: None
) -> None:
    path = tmp_path / "h.csv"
    path.write_text("plastic_strain,stress_Pa\n0,305e6\n10,400e6\n")
    err = _run(cli_main, path)
    assert "error: --hardening: a true plastic strain of 10 (allowed: up to 5)" in err
    assert "flat_hardening" not in err
    path.write_text("305e6,0\n3e12,0.1\n")  # a stress not below E
    err = _run(cli_main, path)
    assert "error: --hardening: a true stress of 3e+12 Pa is not below E" in err


@pytest.mark.parametrize("text", ["", "\n\n", "stress_Pa,plastic_strain\n", "A title\n"])
def test_a_file_without_data_rows_says_so(
    text: str, tmp_path: Path, cli_main: CliMain, never_runs: None
) -> None:
    path = tmp_path / "h.csv"
    path.write_text(text)
    err = _run(cli_main, path)
    assert f"error: --hardening {path}: the file has no data rows; give rows of" in err
    assert "shape" not in err


def test_an_empty_table_is_named_in_the_api() -> None:
    with pytest.raises(ValueError, match=r"^flat_hardening must hold at least one row .* none$"):
        check_hardening("flat_hardening", [])
