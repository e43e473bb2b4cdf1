"""The figures of one impact: returned, drawn, and not kept open by pyplot (a notebook shows
each once, as the cell's value); with ``ax`` they draw into the caller's axes."""

from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pytest

import impactlab as il
from impactlab.dynamics import plotting


@pytest.fixture(scope="module")
def result() -> il.ImpactResult:
    return il.simulate(il.Rod.paper(), angle=math.radians(20), velocity=(0.0, -1.41), mu=0.2)


@pytest.mark.parametrize(
    "fn", [plotting.plot_force_time, plotting.plot_force_penetration, plotting.plot_contact_path,
           plotting.plot_dent],
)  # fmt: skip
def test_returned_once_not_kept_open(result, fn) -> None:
    before = set(plt.get_fignums())
    fig = fn(result)
    assert set(plt.get_fignums()) == before  # nothing left for the notebook to show again
    assert fig.axes and any(ax.has_data() for ax in fig.axes)


def test_draws_into_given_axes(result) -> None:
    fig, ax = plt.subplots()
    assert plotting.plot_force_time(result, ax=ax) is fig and ax.lines
    plt.close(fig)
