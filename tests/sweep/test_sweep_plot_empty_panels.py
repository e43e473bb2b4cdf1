"""A panel that shows no value says so: on the panel, and in one ``not plotted`` line per plot
and reason naming the panels (``plot_sweep``'s PlotSkipped warnings, ``sweep plot``'s stderr):
no case there has a result (its status), or the output has no value where cases have one."""

from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")
import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import PlotSkipped, Study, plot_output_map, plot_sweep, run_sweep
from impactlab.sweep.plotgrid import EmptyPanel


class _LawEvaluator(FakeEvaluator):
    """Every case of the law 'brake' fails (status 1); 'hertz' has no duration."""

    def __call__(self, cases, statics, outputs):
        res, status = super().__call__(cases, statics, outputs)
        law = statics.categories["law"]
        if law == "brake":
            status = np.ones_like(status)
            res = {o: np.full_like(v, np.nan) for o, v in res.items()}
        if law == "hertz" and "duration" in res:
            res["duration"] = np.full_like(res["duration"], np.nan)
        return res, status


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """The store of the file's tests (they only read it), with the default outputs."""
    study = Study(
        name="laws",
        grid={
            "law": ["ghaednia", "hertz", "brake"],
            "angle": np.radians([20.0, 45.0, 70.0]),
            "mu": [0.1, 0.3],
        },
        fixed={"vy": -1.41},
    )
    path = tmp_path_factory.mktemp("laws") / "laws.zarr"
    return run_sweep(study, path, evaluator=_LawEvaluator(), quiet=True).path


def test_plot_sweep_names_the_empty_panels_and_why(store, tmp_path) -> None:
    from impactlab.sweep import open_sweep

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        files = plot_sweep(open_sweep(store), tmp_path / "p")
    said = [str(w.message) for w in caught if w.category is PlotSkipped]
    assert {f.name for f in files} >= {"e_angle_mu.png", "duration_angle_mu.png"}
    failed = "empty panel(s) law = brake: no case there has a result (status 1: fake: vy outside"
    assert any(s.startswith(f"not plotted: e_angle_mu.png: {failed}") for s in said), said
    assert any(s.startswith(f"not plotted: regime_map.png: {failed}") for s in said), said
    assert (
        "not plotted: duration_angle_mu.png: empty panel(s) law = hertz: duration has no value "
        "where the cases have a result (not an output of theirs)"
    ) in said
    assert not any("law = ghaednia" in s for s in said)
    assert not [w for w in caught if w.category is EmptyPanel]  # gathered into the lines


def test_a_panel_drawn_alone_warns_and_says_it_on_the_panel(store) -> None:
    from impactlab.sweep import open_sweep

    with pytest.warns(EmptyPanel, match=r"e: empty panel \(law = brake\): no case there"):
        axes = plot_output_map(open_sweep(store), "e", x="angle", y="mu")
    texts = [" ".join(t.get_text().split()) for t in np.ravel(axes)[2].texts]  # wrapped
    assert texts and texts[0].startswith("no value: no case there has a result (status 1")
    assert not np.ravel(axes)[0].texts


def test_sweep_plot_prints_the_empty_panels(store, tmp_path, monkeypatch, capsys) -> None:
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "plot", str(store), "--out", str(tmp_path / "q")
    )
    assert code == 0 and "e_angle_mu.png" in out
    assert "not plotted: e_angle_mu.png: empty panel(s) law = brake: no case there" in err
