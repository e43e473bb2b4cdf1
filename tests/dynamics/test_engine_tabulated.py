"""The tabulated law end to end: simulate (rod, sphere, flexible rod), simulate_batch, a sweep,
the command line, and ``impactlab.fe.tabulated_law`` (FE runs replaced by the shipped ones)."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from impactlab.bodies import PAPER_ROD, Sphere
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.cli import app
from impactlab.contact import get_law, shipped_curves, tabulated_model
from impactlab.contact._common import jg_critical
from impactlab.dynamics import simulate, simulate_batch
from impactlab.dynamics.drop_result import DropResult
from impactlab.fe.curves import load_cases
from impactlab.fe.tabulated import tabulated_law
from impactlab.materials import AISI_201, AISI_1010, ContactPair

runner = CliRunner()
CASE = {"friction": "coulomb", "mu": 0.2, "angle": math.radians(20.0), "velocity": (0.0, -1.41)}
PAIR = ContactPair(AISI_201, AISI_1010)


def test_simulate_rod_and_sphere() -> None:
    r = simulate(PAPER_ROD, AISI_1010, law="tabulated", **CASE)
    assert r.ok and 0.0 < r.e < 1.0 and r.delta_p > 0.0
    assert "10.1137/0717021" in r.dois()
    # a model built from the same curves by hand gives the same impact
    paper = next(c for c in shipped_curves() if c.name == "paper-aisi201-on-aisi1010")
    model = tabulated_model(paper, PAIR, PAPER_ROD.tip_radius)
    assert simulate(PAPER_ROD, AISI_1010, law=model, **CASE).e == r.e
    s = simulate(Sphere(0.008), AISI_1010, law="tabulated", velocity=(0.0, -2.0))
    assert s.ok and 0.0 < s.e < 1.0
    # past the end of the FE data (1000 delta_c = 0.44 mm): the engine's validity error
    with pytest.raises(ValueError, match="where the tabulated law's curves end"):
        simulate(PAPER_ROD, AISI_1010, law="tabulated", angle=0.3, velocity=(0.0, -30.0))


def test_batch_matches_simulate_and_flags_the_hard_limit() -> None:
    b = simulate_batch(
        PAPER_ROD, AISI_1010, law="tabulated", angle=math.radians(20.0), vy=[-1.41, -2.0, -30.0]
    )
    assert list(b.status[:2]) == [0, 0] and b.status[2] != 0
    one = simulate(PAPER_ROD, AISI_1010, law="tabulated", angle=math.radians(20.0),
                   velocity=(0.0, -2.0))  # fmt: skip
    assert b["e"][1] == pytest.approx(one.e, rel=1e-12)


def test_flexible_rod() -> None:
    body = FlexibleRod.paper(n_axial=2, n_bending=4, axial_residual=False)
    r = simulate(body, AISI_1010, law="tabulated", **CASE)
    assert isinstance(r, DropResult) and r.ok and 0.0 < r.e < 1.0


def test_sweep_with_per_case_pairs(tmp_path) -> None:
    """Per-case flat yield strengths: those within 5 % of the curves' E*/S_y run (each row
    its own tables), the others are refused as a bad law, case by case."""
    from impactlab.sweep import Study, run_sweep
    from impactlab.sweep.engine import STATUS_BAD_LAW

    st = Study(
        name="tab",
        grid={"angle": np.radians([20.0, 60.0]), "flat_yield_strength": [300e6, 310e6, 500e6]},
        fixed={
            "vy": -1.41,
            "mu": 0.2,
            "law": "tabulated",
            "flat_E": AISI_1010.E,  # a flat by values is given whole
            "flat_nu": AISI_1010.nu,
        },
        outputs=["e", "delta_p"],
    )
    ds = run_sweep(st, tmp_path / "tab.zarr", quiet=True).dataset
    status = ds["status"].values
    assert (status[:, :2] == 0).all() and (status[:, 2] == STATUS_BAD_LAW).all()
    flat = dataclasses.replace(AISI_1010, yield_strength=310e6)
    one = simulate(PAPER_ROD, flat, law="tabulated", mu=0.2, angle=math.radians(60.0),
                   velocity=(0.0, -1.41))  # fmt: skip
    assert float(ds["e"].values[1, 1]) == pytest.approx(one.e, rel=1e-9)


def test_command_line() -> None:
    args = ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2"]
    res = runner.invoke(app, [*args, "--law", "tabulated", "--json"])
    assert res.exit_code == 0, res.output
    assert json.loads(res.stdout)["e"]["value"] == simulate(PAPER_ROD, AISI_1010, law="tabulated",
                                                            **CASE).e  # fmt: skip
    listing = runner.invoke(app, ["laws", "--json"])
    assert "tabulated" in json.loads(listing.stdout)
    res = runner.invoke(app, ["laws", "tabulated", "--accuracy"])
    assert res.exit_code != 0 and "built from the shipped FE curves" in res.output


def test_fe_builder_uses_matching_curves_or_runs_fe(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    model = tabulated_law(PAIR, 8.8e-3, run_fe=False)
    assert model.source.startswith("paper-aisi201-on-aisi1010")
    # a pair no curve fits: refused without FE, else "run" (the paper case's runs, rescaled:
    # the same dimensionless curves) and cached, after which law="tabulated" finds them
    flat = dataclasses.replace(AISI_1010, yield_strength=200e6)
    pair = ContactPair(AISI_201, flat)
    with pytest.raises(ValueError, match="no indentation curves for E"):
        tabulated_law(pair, 8.8e-3, run_fe=False)
    case = next(c for c in load_cases() if c.name == "paper-aisi201-on-aisi1010")
    p0, p1 = case.pair, pair
    dc0, fc0 = jg_critical(p0.E_star, case.radius, p0.yield_strength, p0.nu)
    dc1, fc1 = jg_critical(p1.E_star, 8.8e-3, p1.yield_strength, p1.nu)
    ratio, force = dc1 / dc0, fc1 / fc0
    calls = []

    def runner_(flat_, body_, *, radius, delta_max, **kw):
        calls.append(delta_max)
        return [
            dataclasses.replace(
                r,
                delta_max=r.delta_max * ratio,
                loading_delta=r.loading_delta * ratio,
                loading_force=r.loading_force * force,
                residual_depth=r.residual_depth * ratio,
            )
            for r in case.runs
        ]

    # the same nu and a pair whose E*/S_y differs: the paper's curves do not apply
    with pytest.raises(ValueError, match="no indentation curves"):
        get_law("tabulated").build(pair, 8.8e-3)
    model = tabulated_law(pair, 8.8e-3, runner=runner_)
    assert len(calls) == 1 and "FE runs of impactlab.fe.indent" in model.source
    assert list((tmp_path / "tabulated").glob("*.json"))
    again = get_law("tabulated").build(pair, 8.8e-3)
    assert again.source == model.source
    np.testing.assert_array_equal(again.params, model.params)


def test_fe_builder_says_when_ccx_is_missing(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", str(tmp_path))
    monkeypatch.setenv("IMPACTLAB_CCX", str(tmp_path / "no-ccx"))
    flat = dataclasses.replace(AISI_1010, yield_strength=200e6)
    with pytest.raises(RuntimeError, match=r"IMPACTLAB_CCX is set to '.*no-ccx', which is not"):
        tabulated_law(ContactPair(AISI_201, flat), 8.8e-3)


def test_study_file(tmp_path) -> None:
    from impactlab.sweep import load_study, run_sweep

    path = tmp_path / "tab.toml"
    path.write_text(
        '[study]\nname = "tab"\n\n[fixed]\nvy = "-1.41 m/s"\nmu = 0.2\nlaw = "tabulated"\n\n'
        '[grid]\nangle = ["20 deg", "45 deg"]\n\n[outputs]\nkeep = ["e", "delta_p"]\n'
    )
    ds = run_sweep(load_study(path), tmp_path / "tab.zarr", quiet=True).dataset
    assert (ds["status"].values == 0).all()
    assert float(ds["e"].values[0]) == pytest.approx(
        simulate(PAPER_ROD, AISI_1010, law="tabulated", **CASE).e, rel=1e-9
    )
