"""``impactlab sweep run --json`` writes one JSON document on stdout, a Monte Carlo study's
uncertainty report inside it (``uncertainty``, as ``sweep uncertainty --json`` writes it)."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

from impactlab._version import __version__

SWEEP_TESTS = Path(__file__).resolve().parents[1] / "sweep"

MC_STUDY = """
[study]
name = "mc-tiny"
[fixed]
flat_nu = 0.3
flat_yield_strength = "305 MPa"
[sample]
size = 40
seed = 2015
angle = { dist = "normal", mean = "20 deg", std = "0.5 deg" }
vy = { dist = "normal", mean = "-1.41 m/s", std = "0.03 m/s" }
mu = { dist = "uniform", low = 0.1, high = 0.3 }
flat_E = { dist = "normal", mean = "200 GPa", std = "5 GPa" }
[uncertainty]
outputs = ["e", "delta_p"]
percentiles = [2.5, 97.5]
"""


def _close(a: Any, b: Any) -> bool:
    """``a`` and ``b`` the same, their floats to a relative 1e-6."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-6, abs_tol=0.0)
    return bool(a == b)


@pytest.fixture
def fake_engine(monkeypatch: pytest.MonkeyPatch) -> None:
    """``run_sweep`` with the closed-form stand-in of the engine (tests/sweep/sweep_fakes.py)."""
    import impactlab.sweep as sweep_pkg

    monkeypatch.syspath_prepend(str(SWEEP_TESTS))
    from sweep_fakes import FakeEvaluator

    real = sweep_pkg.run_sweep

    def run_sweep(*args: Any, **kwargs: Any) -> Any:
        return real(*args, **{**kwargs, "evaluator": FakeEvaluator()})

    monkeypatch.setattr(sweep_pkg, "run_sweep", run_sweep)


@pytest.mark.parametrize("quiet", [(), ("--quiet",)])
def test_monte_carlo_json_is_one_document_with_the_report(
    cli_main: Any, tmp_path: Path, fake_engine: None, quiet: tuple[str, ...]
) -> None:
    study = tmp_path / "mc.toml"
    study.write_text(MC_STUDY)
    args = ("sweep", "run", str(study), "--out", str(tmp_path / "mc.zarr"), "--json", *quiet)
    code, out, err = cli_main(*args)
    assert code == 0, err
    doc = json.loads(out)  # the whole of stdout: no table before it
    assert doc["cases"] == 40 and doc["store"].endswith("mc.zarr")
    (report,) = doc["uncertainty"].values()
    code, alone, err = cli_main("sweep", "uncertainty", str(tmp_path / "mc.zarr"), "--json")
    assert code == 0, err
    # as sweep uncertainty --json writes it (numpy's sums may differ in the last bits with the
    # arrays' alignment in memory: the statistics agree to round-off, the rest exactly)
    alone_doc = json.loads(alone)
    assert doc["impactlab_version"] == alone_doc.pop("impactlab_version") == __version__
    assert "impactlab_version" not in doc["uncertainty"]  # once, at the top of the document
    assert _close(doc["uncertainty"], alone_doc)
    code, info, err = cli_main("sweep", "info", str(tmp_path / "mc.zarr"), "--json")
    assert code == 0, err
    assert json.loads(info)["impactlab_version"] == __version__
    assert [row["output"] for row in report["summary"]] == ["e", "delta_p"]
    assert report["summary"][1]["mean"]["unit"] == "m"


def test_the_table_still_prints_the_report(
    cli_main: Any, tmp_path: Path, fake_engine: None
) -> None:
    study = tmp_path / "mc.toml"
    study.write_text(MC_STUDY)
    code, out, err = cli_main("sweep", "run", str(study), "--out", str(tmp_path / "mc.zarr"))
    assert code == 0, err
    assert "uncertainty: mc-tiny" in out and "sweep mc-tiny" in out


def test_a_grid_has_no_uncertainty_key(cli_main: Any, tmp_path: Path, fake_engine: None) -> None:
    study = tmp_path / "grid.toml"
    study.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['20 deg', '45 deg']\n")
    code, out, err = cli_main("sweep", str(study), "--out", str(tmp_path / "g.zarr"), "--json")
    assert code == 0, err
    assert "uncertainty" not in json.loads(out)
