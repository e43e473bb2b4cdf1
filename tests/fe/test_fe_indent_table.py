"""``impactlab fe indent``'s table: every length in um (as every command shows dents), ccx's
run time in s, and ``last_converged_delta`` only for a run that stopped early, labelled as
where it stopped; the JSON keeps its SI fields."""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from impactlab import fe
from impactlab.cli.fe import STOPPED_AT

CliMain = Callable[..., tuple[int, str, str]]


def _run(converged: bool, balance: float = 1e-7, reached: float = 1e-6) -> fe.IndentationResult:
    """A run to 1 um: residual depth 0.0745 um, contact radius 97.8 um, pile-up 3.1 nm, 53 s
    (``balance``: its force balance; ``reached``: where its loading ended)."""
    d = np.array([0.0, 0.5e-6, reached])
    end = 0.0 if converged else 0.8e-6  # a converged run's last increment ends the unloading
    return fe.IndentationResult(
        1e-6, d, 10.0 * d / 1e-6, np.array([0.0, 60e-6, 97.832e-6]), d[::-1], 10.0 * d[::-1],
        7.4526e-8, np.array([0.0, 1e-4]), np.array([-7.4526e-8, 3.0951e-9]), 0.43624e-6,
        converged, end, "", 20, 0, 60, 53.041, 2128, balance, {},
    )  # fmt: skip


@pytest.fixture
def fake_runs(monkeypatch: pytest.MonkeyPatch) -> Callable[[bool], None]:
    def use(converged: bool, **run: Any) -> None:
        def fake_indent(flat: Any, body: Any, **kwargs: Any) -> list[fe.IndentationResult]:
            return [_run(converged, **run)]

        monkeypatch.setattr(fe, "indent", fake_indent)
        monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")

    return use


def _rows(out: str) -> dict[str, tuple[str, str]]:
    """quantity -> (value, unit) of the table's rows."""
    rows = {}
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip("│ ").split("│")]
        if len(cells) == 3:
            rows[cells[0]] = (cells[1], cells[2])
    return rows


def test_lengths_in_um_and_run_time_in_s(cli_main: CliMain, fake_runs: Any) -> None:
    fake_runs(True)
    code, out, err = cli_main("fe", "indent", "--max", "1 um")
    assert code == 0, err
    rows = _rows(out)
    assert "FE indentation to 1 um" in out
    assert rows["delta_max"] == ("1", "um") and rows["delta_c"] == ("0.43624", "um")
    assert rows["residual_depth"] == ("0.074526", "um")
    assert rows["contact_radius_at_max"] == ("97.832", "um")
    assert rows["pile_up"] == ("0.0030951", "um")
    assert rows["run_time"] == ("53.041", "s")
    assert "last_converged_delta" not in out  # converged: nothing stopped


def test_a_run_that_stopped_says_where(cli_main: CliMain, fake_runs: Any) -> None:
    fake_runs(False)
    code, out, err = cli_main("fe", "indent", "--max", "1 um")
    assert code == 2 and "1 of 1 FE run(s) did not converge (delta_max = 1 um)" in err
    assert _rows(out)[STOPPED_AT] == ("0.8", "um")  # what was computed is printed


def test_json_keeps_its_si_fields(cli_main: CliMain, fake_runs: Any) -> None:
    fake_runs(True)
    code, out, err = cli_main("fe", "indent", "--max", "1 um", "--json")
    assert code == 0, err
    run = json.loads(out)["runs"][0]
    assert run["last_converged_delta"] == {"value": 0.0, "unit": "m"}
    assert run["residual_depth"]["unit"] == "m" and run["run_time"]["unit"] == "s"


def test_json_follows_the_schema_rules(cli_main: CliMain, fake_runs) -> None:
    """Every number with a unit, or a dimensionless ratio, is a quantity object (the rules of
    docs/json-schema.md): the ratios too."""
    from impactlab._json import shape_problems

    fake_runs(True)
    code, out, _ = cli_main("fe", "indent", "--max", "1 um", "--json")
    data = json.loads(out)
    assert code == 0 and shape_problems(data) == []
    run = data["runs"][0]
    for name in ("delta_max_over_delta_c", "residual_ratio", "force_balance"):
        assert run[name]["unit"] == "1", name
    case = data["case"]  # what was indented: two outputs can be told apart
    assert case["radius"] == {"value": 0.0088, "unit": "m"} and case["mesh_level"] == 1
    assert case["flat"]["name"].startswith("AISI 1010") and case["sphere"] == "elastic-plastic"


def _loading_only() -> fe.IndentationResult:
    """A loading-only run to 1 um: no unloading, no dent, no residual depth."""
    d = np.array([0.0, 0.5e-6, 1e-6])
    empty = np.array([])
    return fe.IndentationResult(
        1e-6, d, 10.0 * d / 1e-6, np.array([0.0, 60e-6, 97.832e-6]), empty, empty,
        np.nan, empty, empty, 0.43624e-6, True, 1e-6, "", 10, 0, 30, 20.0, 2128, 1e-7, {},
    )  # fmt: skip


@pytest.mark.parametrize(("runs", "panels"), [((_loading_only,), 1), ((_loading_only, _run), 2)])
def test_plot_draws_a_dent_panel_only_for_a_dent(
    cli_main: CliMain, monkeypatch: pytest.MonkeyPatch, tmp_path: Any, runs: Any, panels: int
) -> None:
    """A loading-only run has no dent: its figure is the loading curve alone (no empty panel);
    beside a run that unloaded, the dent panel shows that run's dent."""
    import matplotlib.figure

    made = [make(True) if make is _run else make() for make in runs]
    monkeypatch.setattr(fe, "indent", lambda flat, body, **kwargs: made)
    monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")
    saved: list[int] = []
    monkeypatch.setattr(
        matplotlib.figure.Figure, "savefig", lambda fig, *a, **k: saved.append(len(fig.axes))
    )
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--plot", "--out", str(tmp_path))
    assert code == 0, err
    assert saved == [panels]


def test_an_unbalanced_run_is_not_a_plain_success(cli_main: CliMain, fake_runs: Any) -> None:
    """A run whose forces on the sphere and on the flat differ by 147 % of the peak (a
    delta_max far below what the mesh resolves) finished, but it is no reference: its status
    says so and the command exits 2 (it printed "converged", exit 0)."""
    fake_runs(True, balance=1.4748)
    code, out, err = cli_main("fe", "indent", "--max", "1 um")
    assert code == 2
    assert "1 of 1 FE run(s) did not converge or do not balance their forces" in err
    assert "UNBALANCED" in out
    code, out, err = cli_main("fe", "indent", "--max", "1 um", "--json")
    status = json.loads(out)["runs"][0]["status"]
    assert status.startswith("UNBALANCED: the forces on the sphere and on the flat differ by 1.47 ")
    assert not _run(True, balance=1.4748).usable and _run(True).usable


def test_a_run_that_stopped_has_no_radius_at_the_maximum(cli_main: CliMain, fake_runs: Any) -> None:
    """Loading stopped at 0.8 um of 1 um: the contact radius there is not that at delta_max."""
    fake_runs(False, reached=0.8e-6)
    code, out, _err = cli_main("fe", "indent", "--max", "1 um", "--json")
    assert code == 2
    run = json.loads(out)["runs"][0]
    assert run["max_force"]["value"] is None
    assert run["contact_radius_at_max"]["value"] is None
