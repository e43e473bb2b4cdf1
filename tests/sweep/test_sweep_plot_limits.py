"""Maps end at the grid's first and last values, also on an unevenly spaced grid (no angle
axis past 90 deg), and the titles of facets, each as wide as its panel, never overlap."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import Study, open_sweep, run_sweep
from impactlab.sweep.plots import plot_output_map, plot_regime_map


@pytest.fixture(scope="module")
def store(tmp_path_factory) -> Path:
    study = Study(
        name="uneven",
        grid={
            "angle": np.radians([10.0, 20.0, 60.0, 89.0]),
            "mu": [0.1, 0.2, 0.5],
            "vy": [-1.0, -1.5, -2.0, -2.5],
            "friction": ["impulse_ratio", "coulomb"],
        },
    )
    path = tmp_path_factory.mktemp("plot") / "u.zarr"
    return run_sweep(study, path, evaluator=FakeEvaluator(), quiet=True).path


@pytest.mark.parametrize("draw", [plot_output_map, plot_regime_map])
def test_map_axes_end_at_the_grid(store, draw) -> None:
    ds = open_sweep(store)
    args = ("e",) if draw is plot_output_map else ()
    axes = np.ravel(draw(ds, *args, x="angle", y="mu"))
    for ax in axes:
        assert ax.get_xlim() == pytest.approx((10.0, 89.0))
        assert ax.get_ylim() == pytest.approx((0.1, 0.5))


def test_facet_titles_do_not_overlap(store) -> None:
    axes = plot_output_map(open_sweep(store), "e", x="angle", y="mu")
    fig = axes.flat[0].figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for row in axes:
        boxes = [a.title.get_window_extent(renderer) for a in row if a.get_visible()]
        assert len(boxes) > 1
        for left, right in itertools.pairwise(boxes):
            assert left.x1 < right.x0
        assert boxes[0].x0 >= 0
