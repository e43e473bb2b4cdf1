"""Names a study cannot take are refused with what to do: a rate-dependent flat (``rate``,
which no sweep runs: its rate factor is iterated drop by drop) and an unknown body (the known
ones named, the flexible rod among them)."""

from __future__ import annotations

import pytest
from sweep_fakes import run_cli

from impactlab.materials import AISI_1010
from impactlab.sweep import Study
from impactlab.sweep.models import make_body

RATE_STUDY = (
    '[study]\nname = "r"\n[fixed]\nvy = -1.41\nmu = 0.1\nrate = "cowper-symonds"\n'
    '[grid]\nangle = { start = "10 deg", stop = "80 deg", num = 3 }\n'
)


def test_a_rate_in_a_study_file_says_why_and_what_to_do(tmp_path, monkeypatch, capsys) -> None:
    (tmp_path / "r.toml").write_text(RATE_STUDY)
    code, _out, err = run_cli(
        monkeypatch,
        capsys,
        "sweep",
        "run",
        str(tmp_path / "r.toml"),
        "--out",
        str(tmp_path / "r.zarr"),
    )
    assert code == 2 and err.count("\n") == 1
    assert "input 'rate' cannot be swept: a study takes no rate-dependent flat" in err
    assert "drop by drop" in err and "simulate_drop(body, flat, rate=" in err
    assert "known inputs" not in err
    assert not (tmp_path / "r.zarr").exists()


@pytest.mark.parametrize("table", ["fixed", "grid"])
def test_a_rate_in_a_python_study_is_refused_alike(table) -> None:
    fixed: dict[str, object] = {"vy": -1.41, "mu": 0.1}
    grid: dict[str, object] = {"angle": [0.2, 0.4]}
    if table == "fixed":
        fixed["rate"] = "cowper-symonds"
    else:
        grid["rate"] = ["cowper-symonds", "none"]
    with pytest.raises(ValueError, match=r"input 'rate' cannot be swept.*simulate_drop"):
        Study(name="r", fixed=fixed, grid=grid)


def test_an_unknown_body_names_every_known_one() -> None:
    with pytest.raises(ValueError, match=r"unknown body 'cube'; known: rod, sphere, flexible_rod"):
        make_body({"body": "cube"}, {}, AISI_1010)
