"""One result through the Python API: the figures refuse a drop in one line, the range status as
an attribute, the dent's grid checked, a sphere's angles left out of to_pint, rerun's record."""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics import plotting

ROD = il.Rod.paper()
KW = {"mu": 0.2, "angle": "20 deg", "velocity": (0.0, -1.41)}


@pytest.fixture(scope="module")
def impact() -> il.ImpactResult:
    return il.simulate(ROD, il.AISI_1010, **KW)


@pytest.fixture(scope="module")
def drop() -> il.DropResult:
    return il.simulate_drop(ROD, il.AISI_1010, **KW)


@pytest.mark.parametrize(
    "fn",
    [plotting.plot_force_time, plotting.plot_force_penetration, plotting.plot_contact_path],
)
def test_impact_figures_refuse_a_drop_in_one_line(fn: object, drop: il.DropResult) -> None:
    with pytest.raises(ValueError, match=r"takes an ImpactResult .*got a DropResult") as err:
        fn(drop)  # type: ignore[operator]
    assert "\n" not in str(err.value) and "plot_dent" in str(err.value)


def test_save_figures_refuses_a_drop_before_writing(drop: il.DropResult, tmp_path: Path) -> None:
    out = tmp_path / "figs"
    with pytest.raises(ValueError, match=r"^save_figures takes an ImpactResult"):
        plotting.save_figures(drop, out)
    assert not out.exists()


def test_plot_dent_still_draws_a_drop(drop: il.DropResult) -> None:
    fig = plotting.plot_dent(drop)
    assert fig.axes and "dent: depth" in fig.axes[0].get_title()


def test_impact_has_its_fitted_range_status(impact: il.ImpactResult, drop: il.DropResult) -> None:
    assert impact.fitted_range_status == "verified"
    assert impact.to_dict()["fitted_range_status"] == impact.fitted_range_status
    assert drop.fitted_range_status == impact.fitted_range_status


@pytest.mark.parametrize(
    ("kw", "message"),
    [
        ({"nx": 2.5}, r"^nx must be an integer >= 3 \(grid points\), got 2.5$"),
        ({"nx": "64"}, r"^nx must be an integer >= 3 \(grid points\), got '64'$"),
        ({"ny": True}, r"^ny must be an integer >= 3 \(grid points\), got True$"),
        ({"nx": 2}, r"^nx must be an integer >= 3 \(grid points\), got 2$"),
        ({"margin": "0.1"}, r"^margin must be a real number"),
        ({"margin": -1.0}, r"^margin must be >= 0, got -1.0$"),
    ],
)
def test_dent_grid_is_checked(
    kw: dict, message: str, impact: il.ImpactResult, drop: il.DropResult
) -> None:
    for result in (impact, drop):
        with pytest.raises(ValueError, match=message):
            result.dent(**kw)


def test_dent_takes_numpy_integers(impact: il.ImpactResult, drop: il.DropResult) -> None:
    for result in (impact, drop):
        dm = result.dent(nx=np.int64(31), ny=np.int32(21))
        assert dm.height.shape == (21, 31)
    np.testing.assert_array_equal(
        impact.dent(nx=np.int64(31), ny=np.int32(21)).height, impact.dent(nx=31, ny=21).height
    )


def test_sphere_to_pint_leaves_out_the_angles() -> None:
    r = il.simulate(il.Sphere(radius="5 mm", material="aisi-52100"), velocity=(0.0, -1.0))
    q = r.to_pint()
    assert "angle" not in q and "angle_out" not in q
    assert set(q) <= set(r.to_dict()) | {"max_delta_ratio"}
    assert q["e"].magnitude == r.e
    rod = il.simulate(ROD, il.AISI_1010, **KW).to_pint()
    assert rod["angle"].to("deg").magnitude == pytest.approx(20.0)
    assert math.isfinite(rod["angle_out"].magnitude)


@pytest.mark.parametrize("record", ["impact_result.json", Path("out/impact_result.json")])
def test_rerun_of_a_file_name_says_to_load_it(record: object) -> None:
    with pytest.raises(ValueError, match=r"got the file name .*json\.load") as err:
        il.rerun(record)  # type: ignore[arg-type]
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("record", [None, 3, [1, 2]])
def test_rerun_refuses_what_is_no_record(record: object) -> None:
    name = type(record).__name__
    with pytest.raises(ValueError, match=rf"^record must be .*\(a mapping\), got {name}$"):
        il.rerun(record)  # type: ignore[arg-type]


def test_rerun_of_a_record_still_runs(impact: il.ImpactResult) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        again = il.rerun(impact.to_dict())
    assert again.e == impact.e


def test_rerun_of_json_text_says_to_read_it(impact: il.ImpactResult) -> None:
    text = json.dumps(impact.to_dict(), indent=2)
    with pytest.raises(
        ValueError, match=r"got JSON text '\{ \"e\": .{20,40}\.\.\.': read it"
    ) as err:
        il.rerun(text)
    message = str(err.value)
    assert "\n" not in message and "rerun(json.loads(text))" in message and len(message) < 200
    assert il.rerun(json.loads(text)).e == impact.e


def test_rerun_takes_a_result(impact: il.ImpactResult, drop: il.DropResult) -> None:
    assert il.rerun(impact).e == impact.e
    assert il.rerun(impact, mu=0.3).e == il.simulate(ROD, il.AISI_1010, **(KW | {"mu": 0.3})).e
    again = il.rerun(drop)
    assert isinstance(again, il.DropResult) and again.e == drop.e
