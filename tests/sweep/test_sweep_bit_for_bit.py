"""A stored case equals ``simulate`` of the same case bit for bit, whatever chunk it is in and
whatever else that chunk holds (a study of few law rows: every case uses its row's table, as
``simulate`` does); a study of many law rows uses the closed forms, also independent of its
chunks (docs/sweep.md, "Bit for bit")."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab
from impactlab.sweep import Normal, Sample, Study, run_sweep
from impactlab.sweep import models as sweep_models
from impactlab.sweep.engine import evaluate
from impactlab.sweep.models import MAX_TABLES, Statics, law_rows, tabulates

FIXED = {
    "angle": "20 deg",
    "vy": -1.41,
    "mu": 0.2,
    "flat_nu": 0.3,
    "flat_yield_strength": "305 MPa",
    "flat_brinell_hardness": 105,
}
MODULI = (200e9, 210e9)
#: chunk_size = 1 on purpose (each case its own chunk)
pytestmark = pytest.mark.filterwarnings("ignore::impactlab.sweep.SweepSizeWarning")


def _stored(tmp_path, chunk_size: int, **extra) -> dict[str, np.ndarray]:
    study = Study(
        name=f"bits{chunk_size}",
        grid={"flat_E": ["200 GPa", "210 GPa"], **extra},
        fixed=FIXED,
        chunk_size=chunk_size,
        outputs=["e", "delta_p"],
    )
    path = tmp_path / f"bits{chunk_size}.zarr"
    ds = run_sweep(study, path, quiet=True).dataset
    return {o: np.asarray(ds[o].values) for o in ("e", "delta_p")}


def _simulated(flat_e: float) -> impactlab.ImpactResult:
    flat = impactlab.Material("flat", E=flat_e, nu=0.3, yield_strength=305e6, brinell_hardness=105)
    return impactlab.simulate(
        impactlab.PAPER_ROD, flat, mu=0.2, angle="20 deg", velocity=(0, -1.41), history=False
    )


@pytest.mark.usefixtures("engine")
def test_a_grid_over_flat_e_equals_simulate_for_every_chunk_size(tmp_path) -> None:
    one_chunk, per_case = _stored(tmp_path, 65536), _stored(tmp_path, 1)
    for j, flat_e in enumerate(MODULI):
        ref = _simulated(flat_e)
        for got in (one_chunk, per_case):
            assert got["e"][j] == ref.e  # bit for bit, not approximately
            assert got["delta_p"][j] == ref.delta_p


@pytest.mark.usefixtures("engine")
def test_a_case_does_not_depend_on_its_neighbours(tmp_path) -> None:
    """Cases of one flat alone in their chunk, and beside the cases of another flat."""
    angles = [f"{a} deg" for a in range(20, 60, 4)]
    fixed = {k: v for k, v in FIXED.items() if k != "angle"}

    def stored(name: str, moduli: list[str]) -> np.ndarray:
        study = Study(
            name=name, grid={"flat_E": moduli, "angle": angles}, fixed=fixed, outputs=["e"]
        )
        return np.asarray(run_sweep(study, tmp_path / f"{name}.zarr", quiet=True).dataset.e)

    alone, crowded = stored("alone", ["200 GPa"]), stored("crowded", ["200 GPa", "210 GPa"])
    np.testing.assert_array_equal(crowded[:1], alone)


@pytest.mark.usefixtures("engine")
def test_many_law_rows_use_the_closed_forms_in_every_chunk(tmp_path, monkeypatch) -> None:
    """Beyond MAX_TABLES law rows every case uses the closed forms: a chunk of one case (which
    the engine alone would tabulate) gives the numbers of a chunk of all of them."""
    monkeypatch.setattr(sweep_models, "MAX_TABLES", 1)
    one_chunk, per_case = _stored(tmp_path, 65536), _stored(tmp_path, 1)
    np.testing.assert_array_equal(one_chunk["e"], per_case["e"])
    np.testing.assert_array_equal(one_chunk["delta_p"], per_case["delta_p"])
    for j, flat_e in enumerate(MODULI):  # the closed forms: within 1e-12 of the table
        assert one_chunk["e"][j] == pytest.approx(_simulated(flat_e).e, rel=1e-12, abs=0)


def test_law_rows_count_the_law_inputs_of_the_study() -> None:
    grid = Study(
        name="rows",
        grid={"flat_E": ["200 GPa", "210 GPa"], "law": ["ghaednia", "hertz"], "mu": [0.1, 0.2]},
        fixed={k: v for k, v in FIXED.items() if k != "mu"},
    )
    assert law_rows(grid.axes, grid.sample) == 4  # mu does not enter the law
    sampled = Study(
        name="mc",
        sample=Sample(MAX_TABLES + 1, 0, {"flat_E": Normal(200e9, 5e9)}),
        fixed=FIXED,
    )
    assert law_rows(sampled.axes, sampled.sample) == MAX_TABLES + 1
    assert tabulates(grid.axes, grid.sample) and not tabulates(sampled.axes, sampled.sample)
    kinematic = Study(
        name="kin",
        sample=Sample(10_000, 0, {"mu": Normal(0.2, 0.01, low=0.0)}),
        fixed={**{k: v for k, v in FIXED.items() if k != "mu"}, "flat_E": "200 GPa"},
    )
    assert law_rows(kinematic.axes, kinematic.sample) == 1


@pytest.mark.usefixtures("engine")
def test_rejected_cases_keep_their_place_among_the_groups() -> None:
    """Cases of three law rows, interleaved, one rejected (S_y >= E): each output lands on its
    own case."""
    study = Study(
        name="mix",
        grid={"flat_yield_strength": ["305 MPa", "250 GPa", "280 MPa", "300 MPa"]},
        fixed={**{k: v for k, v in FIXED.items() if k != "flat_yield_strength"},
               "flat_E": "200 GPa"},
    )  # fmt: skip
    num, cat, _ = study.chunk_cases(0)
    order = np.array([2, 0, 1, 3, 0, 2])
    cases = {k: v[order] for k, v in num.items()}
    res, status = evaluate(cases, Statics(cat, tabulate=True), ("e",))
    for j, i in enumerate(order):  # each case alone in its chunk: the engine tabulates it
        one, st = evaluate({k: v[[i]] for k, v in num.items()}, Statics(cat), ("e",))
        assert status[j] == st[0]
        np.testing.assert_array_equal(res["e"][j], one["e"][0])
    assert status[2] != 0 and np.isnan(res["e"][2])
    assert (status[[0, 1, 3, 4, 5]] == 0).all()
