"""How a sweep shows itself: maps of a 3-D study are faceted and name the slice they
show, and the throughput leaves out each worker's first task (the one-time compile or load)."""

from __future__ import annotations

from types import SimpleNamespace

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest

from impactlab.sweep import Study, SweepStats, plot_output_map, plot_regime_map, run_sweep
from impactlab.sweep.display import _rows, steady_throughput, warm_up_s


@pytest.fixture
def cube(tmp_path, fake):
    st = Study(
        name="cube",
        grid={
            "angle": np.radians(np.linspace(5, 85, 9)),
            "mu": np.linspace(0, 0.6, 7),
            "vy": [-1.0, -2.0, -3.0],
        },
    )
    return run_sweep(st, tmp_path / "c.zarr", evaluator=fake, quiet=True)


def test_regime_map_facets_a_third_dimension(cube) -> None:
    axes = plot_regime_map(cube.dataset)
    titles = [a.get_title() for a in np.ravel(axes) if a.get_visible()]
    assert titles == [f"friction regime\nvy = {v} m/s" for v in (-1, -2, -3)]
    plt.close(np.ravel(axes)[0].figure)


def test_a_given_axes_names_its_slice(cube) -> None:
    fig, ax = plt.subplots()
    assert plot_regime_map(cube.dataset, ax=ax, sel={"vy": -2.0}) is ax
    assert ax.get_title() == "friction regime\nvy = -2 m/s"
    ax.clear()
    plot_output_map(cube.dataset, "e", x="angle", y="mu", ax=ax)  # no sel: first vy, named
    assert ax.get_title() == "e\nvy = -1 m/s"
    plt.close(fig)


def test_output_line_facets(cube) -> None:
    axes = plot_output_map(cube.dataset, "e", x="angle", sel={"vy": -3.0})
    shown = [a for a in np.ravel(axes) if a.get_visible()]
    assert len(shown) == 7  # one panel per mu
    assert shown[-1].get_title() == "e\nmu = 0.6, vy = -3 m/s"
    plt.close(np.ravel(axes)[0].figure)


def test_steady_throughput_leaves_out_first_tasks(cube) -> None:
    s = SweepStats(cases_computed=1000, wall_s=3.0)
    s.first_task_s, s.first_task_cases = {"a": 1.0, "b": 0.5}, {"a": 100, "b": 100}
    assert warm_up_s(s) == 1.0 and steady_throughput(s) == pytest.approx(800 / 2.0)
    s.first_task_cases = {"a": 600, "b": 400}
    assert steady_throughput(s) is None  # every chunk was a first task
    text = dict(_rows(SimpleNamespace(stats=s, path="s.zarr")))["throughput"]
    assert text == "333.33 impacts/s (cases computed / wall time)"
    stats = cube.stats
    assert sum(stats.first_task_cases.values()) == cube.dataset["e"].size  # one chunk
    html = cube._repr_html_()
    assert "first task (compile/load)" in html and "Study &#x27;cube&#x27;" in html
