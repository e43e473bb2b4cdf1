"""A calibration's ``[engine] partial_slip_cells``: checked, used by the predictions, recorded."""

from __future__ import annotations

import pytest

from impactlab.calibrate.input_checks import engine_options
from impactlab.calibrate.models import Statics, simulate_options
from impactlab.calibrate.sampler import _engine


def test_cells_are_checked_and_kept() -> None:
    eng, g = engine_options({"partial_slip_cells": 32})
    assert eng["partial_slip_cells"] == 32
    assert g == pytest.approx(9.80665)
    for bad in (3, 65, 16.0, "32", True):
        with pytest.raises(ValueError, match="partial_slip_cells"):
            engine_options({"partial_slip_cells": bad})
    with pytest.raises(ValueError, match="known: gravity, rtol, partial_slip_cells"):
        engine_options({"cells": 32})


def test_cells_reach_simulate_for_partial_slip_only() -> None:
    def statics(friction: str) -> Statics:
        cat = {"law": "hertz", "friction": friction, "body": "sphere"}
        return Statics(cat, {}, {"partial_slip_cells": 32})

    assert simulate_options(statics("partial_slip"))["partial_slip_cells"] == 32
    assert "partial_slip_cells" not in simulate_options(statics("coulomb"))


def test_saved_chain_key() -> None:
    """The default count acts as no option (chains saved without it stay usable)."""
    assert _engine({}) == []
    assert _engine({"partial_slip_cells": 16}) == []
    assert ("partial_slip_cells", 32) in _engine({"partial_slip_cells": 32})
    assert _engine({"partial_slip_cells": 32}) != _engine({"partial_slip_cells": 64})


def test_config_file_reads_cells(tmp_path) -> None:
    from impactlab.calibrate.config import load_config

    (tmp_path / "drops.csv").write_text("e\n0.5\n")
    cfg = tmp_path / "cal.toml"
    cfg.write_text(
        'measurements = "drops.csv"\nmodels = ["hertz/partial_slip"]\n'
        '[parameters]\nmu = "uniform(0, 0.6)"\n[engine]\npartial_slip_cells = 32\n'
    )
    kw = load_config(cfg)
    assert dict(kw["engine"])["partial_slip_cells"] == 32
