"""How ``analyze`` reads the scan's L_s for T and F: as the slip (the paper's reading, the
default) or as the contact's travel (``measure="travel"``, ``--measure travel``), as
``invert`` does, and recorded in the result's options."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import pytest

from impactlab.experiment import analyze


def _run(drops: dict, scans: dict, rod: Any, **kw: Any) -> Any:
    d, sc = drops[20], scans[20]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return analyze(d.c3d, sc.files["x3p"], rod, geometry=d.geometry, figures=False,
                       n_samples=2000, **kw)  # fmt: skip


def test_the_travel_reading_gives_the_longer_duration(drops: dict, scans: dict, rod: Any) -> None:
    slip, travel = _run(drops, scans, rod), _run(drops, scans, rod, measure="travel")
    assert slip.options["measure"] == "slip" and travel.options["measure"] == "travel"
    t_slip, t_travel = slip.inversion.duration, travel.inversion.duration
    assert 1.1 < t_travel / t_slip < 1.35  # the tip rolls as it slides (22 % at 20 deg)
    assert travel.inversion.mean_force < slip.inversion.mean_force


def test_an_unknown_reading_is_refused_before_anything_runs(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"^measure must be 'slip' .* or 'travel' .* got 'dent'"):
        analyze(tmp_path / "none.c3d", None, measure="dent", out_dir=tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_the_command_refuses_another_reading_before_its_folder(  # type: ignore[no-untyped-def]
    cli_main, drops: dict, scans: dict, tmp_path: Path
) -> None:
    d, sc = drops[20], scans[20]
    out = tmp_path / "out"
    code, _, err = cli_main(
        "analyze", str(d.c3d), str(sc.files["x3p"]), "--measure", "dent", "--out", str(out)
    )
    assert code == 2 and "--measure must be 'slip' or 'travel', got 'dent'" in err, err
    assert not out.exists()
