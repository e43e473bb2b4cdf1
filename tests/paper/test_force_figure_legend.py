"""The force figures' legends lie clear of the curves (inside the axes they hid the largest
peaks: Kogut-Komvopoulos's 19.5 kN at 70 deg, Brake's at 20 deg), within the figure."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab.paper.figures as F
from impactlab.paper.simulations import run_simulations


@pytest.mark.parametrize("angle", [20, 70])
def test_the_legend_hides_no_curve(angle, tmp_path, monkeypatch):
    shown = []
    monkeypatch.setattr(F, "_save", lambda plt, fig, path: shown.append(fig) or path)
    F.figure_forces(tmp_path / "f.png", run_simulations(angles=(angle,)), angle)
    fig = shown[0]
    fig.tight_layout()  # as _save does before writing
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    figure_box = fig.bbox
    for ax in fig.axes:
        legend = ax.get_legend()
        assert legend is not None and len(legend.get_texts()) == 3
        box = legend.get_window_extent(renderer)
        assert not box.overlaps(ax.bbox), "the legend lies on the plot"
        assert figure_box.x0 <= box.x0 and box.x1 <= figure_box.x1
        assert figure_box.y0 <= box.y0 and box.y1 <= figure_box.y1
        for line in ax.get_lines():
            xy = ax.transData.transform(np.asarray(line.get_xydata()))
            inside = (
                (xy[:, 0] >= box.x0)
                & (xy[:, 0] <= box.x1)
                & (xy[:, 1] >= box.y0)
                & (xy[:, 1] <= box.y1)
            )
            assert not inside.any(), line.get_label()
