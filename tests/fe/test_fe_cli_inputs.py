"""``impactlab fe indent`` records every input in its JSON ``case`` (a run can be identified
and repeated), names ``--max`` in its radius error with the unit hint only for a bare
number, and refuses an ``IMPACTLAB_CCX`` that cannot be executed in one line; ``python -m
impactlab.verification --help`` runs nothing. No CalculiX run: ``indent`` is replaced."""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import fe
from impactlab._json import shape_problems
from impactlab.fe.ccx import find_ccx
from impactlab.fe.problem import make_problem
from impactlab.materials import AISI_201, AISI_1010

CliMain = Callable[..., tuple[int, str, str]]
CUSTOM = ("--flat-E", "69 GPa", "--flat-nu", "0.33", "--flat-sy", "276 MPa")


def _run() -> fe.IndentationResult:
    d = np.array([0.0, 0.5e-6, 1e-6])
    return fe.IndentationResult(
        1e-6, d, 10.0 * d / 1e-6, np.array([0.0, 60e-6, 97.8e-6]), d[::-1], 10.0 * d[::-1],
        7.4e-8, np.array([0.0, 1e-4]), np.array([-7.4e-8, 3.1e-9]), 0.43624e-6,
        True, 0.0, "", 20, 0, 60, 53.0, 2128, 1e-7, {},
    )  # fmt: skip


@pytest.fixture
def fake_indent(monkeypatch: pytest.MonkeyPatch) -> dict[str, Any]:
    seen: dict[str, Any] = {}

    def indent(flat: Any, body: Any, **kwargs: Any) -> list[fe.IndentationResult]:
        seen.update(kwargs, flat=flat, body=body)
        return [_run()]

    monkeypatch.setattr(fe, "indent", indent)
    monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")
    return seen


def test_the_json_case_records_a_custom_flat_and_its_hardening(
    cli_main: CliMain, fake_indent: dict[str, Any], tmp_path: Path
) -> None:
    table = tmp_path / "h.csv"
    table.write_text("stress,strain\n276e6,0\n300e6,0.01\n350e6,0.1\n")
    args = ("fe", "indent", "--max", "1 um", *CUSTOM, "--hardening", str(table), "--json")
    code, out, err = cli_main(*args)
    assert code == 0, err
    data = json.loads(out)
    assert shape_problems(data) == []
    case = data["case"]
    flat = case["flat"]
    assert flat["name"] == "flat (custom)"
    assert flat["E"] == {"value": 69e9, "unit": "Pa"} and flat["nu"] == {"value": 0.33, "unit": "1"}
    assert flat["yield_strength"] == {"value": 276e6, "unit": "Pa"}
    # not given, not used by a quasi-static indentation: null, not the Material's defaults
    # (a steel's 7850 kg/m^3 and Meyer index 2.2 for an aluminium-like flat)
    assert flat["density"] is None and flat["meyer_index"] is None
    assert flat["brinell_hardness"] is None
    # a library material is recorded whole
    assert case["sphere_material"]["density"] == {"value": AISI_201.density, "unit": "kg/m^3"}
    assert case["flat_hardening"]["true_stress"] == {"value": [276e6, 300e6, 350e6], "unit": "Pa"}
    assert case["flat_hardening"]["true_plastic_strain"]["value"] == [0.0, 0.01, 0.1]
    assert case["sphere_material"]["E"] == {"value": AISI_201.E, "unit": "Pa"}
    assert case["loading_only"] is False and case["mesh_level"] == 1
    # what was run is what was recorded
    assert fake_indent["flat"].E == 69e9 and fake_indent["flat_hardening"][-1] == (350e6, 0.1)


def test_the_json_case_without_hardening_and_the_line_above_the_table(
    cli_main: CliMain, fake_indent: dict[str, Any]
) -> None:
    code, out, err = cli_main("fe", "indent", "--max", "1 um", "--json")
    assert code == 0, err
    case = json.loads(out)["case"]
    assert case["flat_hardening"] is None and case["flat"]["name"].startswith("AISI 1010")
    code, out, err = cli_main("fe", "indent", "--max", "1 um", *CUSTOM)
    assert code == 0, err
    assert "flat (custom): E = 69 GPa, nu = 0.33, S_y = 276 MPa" in out


@pytest.mark.parametrize(
    ("given", "hint"), [("20 mm", False), ("0.02", True), ("9 mm", False), ("1", True)]
)
def test_the_radius_error_names_max_and_hints_only_for_a_bare_number(
    cli_main: CliMain, given: str, hint: bool
) -> None:
    code, _, err = cli_main("fe", "indent", "--max", given)
    assert code == 2 and err.count("\n") == 1
    assert err.startswith(f"error: --max {given!r} (")
    assert "must be smaller than the sphere radius (--radius '8.8 mm', 0.0088 m)" in err
    assert ("a bare number is in m" in err) is hint


def test_a_max_past_the_equator_is_named_as_typed_with_the_radius(cli_main: CliMain) -> None:
    """Before: "--max (0.005 m) is too large for radius 0.0088 m: ...; allowed delta_max <
    0.0034236112905077663 m", the value not as typed, --radius not named, 17 digits."""
    code, _, err = cli_main("fe", "indent", "--max", "5 mm")
    assert code == 2 and err == (
        "error: --max '5 mm' (0.005 m) is too large for the sphere radius (--radius '8.8 mm', "
        "0.0088 m): the contact radius would reach the sphere's equator; allowed --max < "
        "0.003423 m\n"
    )
    code, _, err = cli_main("fe", "indent", "--max", "0.003", "--radius", "6 mm")
    assert code == 2 and "(--radius '6 mm', 0.006 m)" in err and "allowed --max < 0.002334 m" in err
    assert err.rstrip().endswith("(a bare number is in m: give a unit, e.g. '5 um')")
    with pytest.raises(ValueError, match=r"^delta_max \(0\.005 m\)") as info:
        make_problem(AISI_1010, AISI_201, radius="8.8 mm", delta_max="5 mm")
    assert str(info.value) == (
        "delta_max (0.005 m) is too large for radius 0.0088 m: the contact radius would reach "
        "the sphere's equator; allowed delta_max < 0.003423 m"
    )
    # every value below the bound shown is taken
    make_problem(AISI_1010, AISI_201, radius="8.8 mm", delta_max="3.4229 mm")


def test_the_python_radius_error_hints_only_for_a_number() -> None:
    with pytest.raises(ValueError, match=r"\(0\.0088 m\)$"):
        make_problem(AISI_1010, AISI_201, radius="8.8 mm", delta_max="20 mm")
    with pytest.raises(ValueError, match="a bare number is in m"):
        make_problem(AISI_1010, AISI_201, radius=8.8e-3, delta_max=0.02)


def test_an_option_is_named_in_a_problem_error(cli_main: CliMain) -> None:
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--mu", "3")
    assert code == 2 and err == "error: --mu must lie in [0, 2], got 3.0\n"


def test_an_impactlab_ccx_without_execute_permission_is_one_line(
    cli_main: CliMain, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    plain = tmp_path / "loading.csv"
    plain.write_text("delta,F\n")
    plain.chmod(0o644)
    if os.access(plain, os.X_OK):  # pragma: no cover - a file system without permissions
        pytest.skip("execute permission is not enforced here")
    monkeypatch.setenv("IMPACTLAB_CCX", str(plain))
    monkeypatch.setattr(fe, "indent", lambda *a, **k: pytest.fail("ccx would have run"))
    with pytest.raises(
        RuntimeError, match=r"not an executable file \(a file without execute permission\)"
    ):
        find_ccx()
    code, _, err = cli_main("fe", "indent", "--max", "0.05 um", "--sphere", "rigid")
    assert code == 2 and err.count("\n") == 1
    assert f"IMPACTLAB_CCX is set to {str(plain)!r}, which is not an executable file" in err
    assert "Errno" not in err
    runnable = tmp_path / "ccx"
    runnable.write_text("#!/bin/sh\n")
    runnable.chmod(0o755)
    monkeypatch.setenv("IMPACTLAB_CCX", str(runnable))
    assert find_ccx() == str(runnable)


def test_verification_help_runs_nothing_and_out_names_the_folder(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from impactlab.verification import __main__ as verification

    calls: list[tuple[str, bool]] = []

    class _Table:
        passed = True

    def fake_main(out: str, *, fast: bool = False) -> list[_Table]:
        calls.append((out, fast))
        return [_Table()]

    monkeypatch.setattr(verification.page, "main", fake_main)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:
        verification.cli(["--help"])
    assert stop.value.code == 0 and "--out DIR" in capsys.readouterr().out
    assert calls == [] and list(tmp_path.iterdir()) == []
    assert verification.cli([]) == 0 and calls[-1] == ("docs/verification", False)
    assert verification.cli(["--out", "site/v", "--fast"]) == 0 and calls[-1] == ("site/v", True)
    assert verification.cli(["elsewhere"]) == 0 and calls[-1] == ("elsewhere", False)
    with pytest.raises(SystemExit) as stop:
        verification.cli(["a", "--out", "b"])
    assert stop.value.code == 2 and len(calls) == 3


def test_every_modulus_and_strength_option_says_its_unit(cli_main: CliMain) -> None:
    """Formerly --body-E and --body-sy gave no unit or example, while the flat's did."""
    code, out, _ = cli_main("fe", "indent", "--help")
    assert code == 0
    text = " ".join(out.replace("│", " ").split())
    for example in ("'69 GPa'", "'276 MPa'", "'210 GPa'", "'1.5 GPa'"):
        assert f"e.g. {example} (a bare number: Pa)" in text, example
