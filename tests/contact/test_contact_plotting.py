"""plot_laws: one figure with every law (smoke test with a small number of points)."""

from __future__ import annotations

import pytest
from matplotlib.figure import Figure

from impactlab.contact import law_names
from impactlab.contact.plotting import plot_laws
from impactlab.materials import ContactPair


def test_plot_has_every_law(paper_pair: ContactPair) -> None:
    fig = plot_laws(paper_pair, 8.8e-3, 200e-6, n_points=40)
    assert isinstance(fig, Figure)
    left, _right = fig.axes
    labels = [t.get_text() for t in left.get_legend().get_texts()]
    assert labels == list(law_names())
    # loading + 3 unloading branches per law on the left
    assert len(left.lines) == 4 * len(law_names())


def test_plot_rejects_bad_input(paper_pair: ContactPair) -> None:
    with pytest.raises(ValueError, match="delta_max"):
        plot_laws(paper_pair, 8.8e-3, -1.0)
    with pytest.raises(ValueError, match="unknown contact law"):
        plot_laws(paper_pair, 8.8e-3, 1e-4, laws=["nope"])
    with pytest.raises(ValueError, match="unload_fractions"):
        plot_laws(paper_pair, 8.8e-3, 1e-4, unload_fractions=(0.0,))
