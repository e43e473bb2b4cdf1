"""A store of flexible rods' drops is plotted with the outputs its cases have: the drop's dent,
slip, mark extent and sequence duration beside e; the one-contact outputs and the regime,
which a drop has no value of, are named as not plotted (one line each), not drawn empty."""

from __future__ import annotations

import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import pytest
from sweep_fakes import run_cli

from impactlab.sweep import PlotSkipped, Study, plot_plan, plot_sweep, run_sweep

_TABLE = {
    "study": {"name": "drops"},
    "fixed": {"body": "flexible_rod", "mu": 0.2, "n_axial": 2, "n_bending": 4},
    "grid": {"angle": ["20 deg", "45 deg"], "vy": [-1.0, -1.41]},
}


@pytest.fixture
def store(tmp_path: Path) -> Path:
    return run_sweep(Study.from_dict(_TABLE), tmp_path / "drops.zarr", quiet=True).path


def test_a_drop_store_plots_the_drop_outputs(store: Path, tmp_path: Path) -> None:
    from impactlab.sweep import open_sweep

    ds = open_sweep(store)
    plan = plot_plan(ds)
    names = [n for n, _ in plan.plots]
    assert names == [
        "e_angle_vy.png",
        "dent_depth_angle_vy.png",
        "sequence_sliding_length_angle_vy.png",
        "scar_length_angle_vy.png",
        "sequence_duration_angle_vy.png",
    ]
    assert plan.skipped == [
        "delta_p: no case of the store has a value of it; a flexible rod's drop gives dent_depth",
        "sliding_length: no case of the store has a value of it; a flexible rod's drop gives "
        "sequence_sliding_length",
        "duration: no case of the store has a value of it; a flexible rod's drop gives "
        "sequence_duration",
        "regime map: no case of the store has a regime (a flexible rod's drop has none)",
    ]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        files = plot_sweep(ds, tmp_path / "p")
    said = [str(w.message) for w in caught if w.category is PlotSkipped]
    assert [f.name for f in files] == names
    assert said == [f"not plotted: {s}" for s in plan.skipped]  # no empty panel drawn


def test_sweep_plot_of_drops_draws_them(store, tmp_path, monkeypatch, capsys) -> None:
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "plot", str(store), "--out", str(tmp_path / "q")
    )
    assert code == 0 and "dent_depth_angle_vy.png" in out and "delta_p_" not in out
    assert "not plotted: delta_p: no case of the store has a value of it" in err
    assert "empty panel" not in err
