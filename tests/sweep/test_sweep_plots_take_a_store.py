"""The plots and the uncertainty summaries take what the exports take: the Dataset, a store's
path or ``run_sweep``'s result, and refuse anything else in one line (they raised an
AttributeError from inside: ``'SweepResult' object has no attribute 'data_vars'``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import (
    Sample,
    Study,
    Uniform,
    plot_output_map,
    plot_regime_map,
    plot_sweep,
    run_sweep,
    uncertainty_report,
    uncertainty_reports,
)


@pytest.fixture
def result(tmp_path: Path) -> Any:
    study = Study(
        name="maps",
        grid={"angle": ["20 deg", "40 deg"], "mu": [0.1, 0.3]},
        fixed={"vy": -1.41, "law": "hertz"},
        outputs=["e", "regime"],
    )
    return run_sweep(study, tmp_path / "maps.zarr", evaluator=FakeEvaluator(), quiet=True)


@pytest.fixture
def sampled(tmp_path: Path) -> Any:
    study = Study(
        name="mc",
        sample=Sample(size=16, seed=1, inputs={"mu": Uniform(0.1, 0.3)}),
        fixed={"vy": -1.41, "law": "hertz", "angle": "20 deg"},
        outputs=["e"],
    )
    return run_sweep(study, tmp_path / "mc.zarr", evaluator=FakeEvaluator(), quiet=True)


def test_the_maps_take_a_path_or_the_result(result: Any, tmp_path: Path) -> None:
    import matplotlib.pyplot as plt

    for given in (result, result.path, str(result.path)):
        assert plot_regime_map(given) is not None
        assert plot_output_map(given, "e", y="mu") is not None
        plt.close("all")
    files = plot_sweep(result, tmp_path / "plots", outputs=["e"])
    assert files == plot_sweep(str(result.path), tmp_path / "plots", outputs=["e"])
    assert files


def test_the_summaries_take_a_path_or_the_result(sampled: Any) -> None:
    ref = uncertainty_report(sampled.dataset)
    for given in (sampled, sampled.path):
        assert uncertainty_report(given).summary.equals(ref.summary)
        assert list(uncertainty_reports(given)) == list(uncertainty_reports(sampled.dataset))


@pytest.mark.parametrize(
    "call",
    [plot_regime_map, lambda d: plot_output_map(d, "e"), uncertainty_report, uncertainty_reports],
)
def test_anything_else_is_refused_in_one_line(call: Any) -> None:
    with pytest.raises(ValueError, match=r"^ds must be an xarray.Dataset .* got the int 5$"):
        call(5)


def test_plot_sweep_refuses_before_it_makes_the_folder(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"^ds must be an xarray.Dataset"):
        plot_sweep(5, tmp_path / "plots")
    assert not (tmp_path / "plots").exists()
