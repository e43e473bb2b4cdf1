"""A sweep whose cases pair a softer body with the flat (``materials.body_yields_first``): the
run's summary and ``sweep info`` name those pairs once, with their cases and the advisory
sentence of the single results (``dynamics.dent.flattening_warning``); no number changes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sweep_fakes import run_cli

import impactlab as il
from impactlab._json import shape_problems
from impactlab.sweep import store_info

STUDY = (
    "[study]\nname = 'soft'\n"
    "[fixed]\nangle = '30 deg'\nmu = 0.2\nmass = '0.3 kg'\n"
    "[grid]\nvy = ['-1 m/s', '-2 m/s']\nbody_material = ['copper-ofhc', 'aisi-1010']\n"
)


def test_run_and_info_name_the_pair_whose_body_yields_first(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    study = tmp_path / "soft.toml"
    study.write_text(STUDY)
    store = tmp_path / "soft.zarr"
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "run", str(study), "--out",
                             str(store), "--json")  # fmt: skip
    assert code == 0, err
    summary = json.loads(out)
    assert shape_problems(summary) == []
    (pair,) = summary["body_yields_first"]  # the steel rod on steel: not listed
    assert pair["body_material"] == "copper-ofhc" and pair["flat_material"] == "aisi-1010"
    assert pair["cases"] == 2 and pair["warning"].startswith("body yields first: ")
    rod = il.Rod(length=0.3048, tip_radius=8.8e-3, mass=0.3,
                 material=il.get_material("copper-ofhc"))  # fmt: skip
    one = il.simulate(rod, il.AISI_1010, angle="30 deg", velocity=(0.0, -2.0), mu=0.2)
    assert one.body_yields_first
    assert f"the largest delta_p of these cases = {one.delta_p * 1e6:.4g} um" in pair["warning"]
    assert store_info(store)["body_yields_first"] == [pair]
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert code == 0 and json.loads(out)["body_yields_first"] == [pair]
    monkeypatch.setenv("COLUMNS", "2000")  # a wide table: each row on one line
    for args in (("sweep", "info", str(store)), ("sweep", "run", str(study), "--out", str(store))):
        code, out, err = run_cli(monkeypatch, capsys, *args)
        rows = [line for line in out.splitlines() if "body yields first: copper-ofhc" in line]
        assert code == 0 and len(rows) == 1, out
        assert "on aisi-1010" in rows[0] and "2 case(s)" in rows[0]
        assert "not a dent in the flat" in rows[0]


def test_a_study_of_the_paper_s_pair_says_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    study = tmp_path / "steel.toml"
    study.write_text(STUDY.replace("'copper-ofhc', ", ""))
    store = tmp_path / "steel.zarr"
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "run", str(study), "--out",
                             str(store), "--json")  # fmt: skip
    assert code == 0, err
    assert "body_yields_first" not in json.loads(out)
    assert "body_yields_first" not in store_info(store)
