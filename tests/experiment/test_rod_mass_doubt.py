"""A rod whose mass, with no inertia or diameter, makes it far wider than its tip (a mass in
grams given as kilograms) is a ``rod:`` doubt of the result: in ``result.doubts``, the JSON and
results.json, not only a warning when the rod is made (the inertia's check is blind to it:
m L^2 / 12 scales with the mass)."""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable
from pathlib import Path

import pytest

from impactlab.bodies import PAPER_ROD, Rod
from impactlab.experiment.arguments import implausible_rod

from .conftest import EXAMPLE_DATA, analyse_example

CliMain = Callable[..., tuple[int, str, str]]


def _grams() -> Rod:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return Rod(length=0.3048, tip_radius=0.0088, mass=460.7)


def test_the_note_names_the_width_and_the_grams() -> None:
    assert implausible_rod(PAPER_ROD) is None
    assert implausible_rod(Rod(length=0.3048, tip_radius=0.0088, mass=2.0, inertia=0.02)) is None
    note = implausible_rod(_grams())
    assert note is not None and note.startswith("the mass does not fit the rod's size")
    assert "exceeds twice the tip radius" in note
    assert "a mass in grams given as kilograms? (mass = 0.4607 kg fits)" in note


def test_the_result_is_not_ok(tmp_path: Path) -> None:
    """F came out 69625 N with "ok": true and no warning in the result."""
    with pytest.warns(Warning, match="not ok: rod: "):
        res = analyse_example(rod=_grams(), n_samples=1000, out_dir=tmp_path / "out")
    assert not res.ok
    (doubt,) = [d for d in res.doubts if d.startswith("rod: ")]
    assert "grams given as kilograms" in doubt and doubt in res.warnings
    saved = json.loads((tmp_path / "out" / "results.json").read_text())
    assert saved["ok"] is False and doubt in saved["doubts"]


def test_the_command_line_reports_it_once(tmp_path: Path, cli_main: CliMain) -> None:
    rod = tmp_path / "grams.toml"
    rod.write_text("[rod]\nmass = 460.7\nlength = 0.3048\ntip_radius = 0.0088\n")
    code, out, err = cli_main(
        "analyze", str(EXAMPLE_DATA / "drop.csv"), str(EXAMPLE_DATA / "dent.npy"),
        "--pixel-size", "12 um", "--height-unit", "um", "--up", "+y",
        "--geometry", str(EXAMPLE_DATA / "markers.toml"), "--rod", str(rod), "--json",
    )  # fmt: skip
    data = json.loads(out)
    assert code == 0 and data["ok"] is False
    assert any(d.startswith("rod: the mass does not fit") for d in data["doubts"])
    assert err.count("exceeds twice the tip radius") == 1
