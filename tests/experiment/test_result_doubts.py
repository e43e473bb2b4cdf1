"""A result that its own checks find impossible or implausible is not ok (``result.doubts``,
``"ok": false``, exit status 0 as for a doubted marker geometry), and the result's table shows
the warnings and the engine comparison."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab.bodies import PAPER_ROD, Rod
from impactlab.experiment.arguments import implausible_rod

from .conftest import EXAMPLE_DATA, analyse_example


def _grams_as_kg() -> Rod:
    """The paper's rod with its mass in grams given as kilograms."""
    return Rod(length=0.3048, tip_radius=0.0088, mass=460.7, inertia=0.0035667)


def _example(**kwargs: Any) -> Any:
    return analyse_example(n_samples=1000, **kwargs)


def test_a_rod_whose_mass_and_inertia_do_not_fit_is_named() -> None:
    assert implausible_rod(PAPER_ROD) is None
    note = implausible_rod(_grams_as_kg())
    assert note is not None and "I_C / (m L^2) = 8.3e-05" in note
    assert "a mass in grams given as kilograms? (mass = 0.4607 kg gives 0.0833)" in note


@pytest.fixture(scope="module")
def heavy() -> Any:
    with pytest.warns(Warning, match="not ok: "):
        return _example(rod=_grams_as_kg())


def test_an_impossible_result_is_not_ok(heavy: Any) -> None:
    """It was ok although its warnings said e = 1065, 'no impact gives it'."""
    assert not heavy.errors and not heavy.ok
    geometry, rod, e = heavy.doubts
    assert rod.startswith("rod: the mass and the inertia do not fit")
    assert geometry.startswith("the marker geometry is in doubt") and "k^2 = I/m is off" in geometry
    assert e.startswith("inversion: dv_cy") and "no impact gives it" in e
    assert {rod, e} <= set(heavy.warnings) and f"markers: {geometry}" in heavy.warnings
    data = heavy.to_dict()
    assert data["ok"] is False and data["doubts"] == list(heavy.doubts)
    assert "ok=False" in repr(heavy)
    text = str(heavy)
    assert "  ok " in text and "  doubt " in text and "no impact gives it" in text


def test_the_rods_note_is_listed_once(heavy: Any) -> None:
    """The inversion checks the rod too: its ``inversion: rod: ...`` repeated the doubt."""
    (rod,) = [w for w in heavy.warnings if "the mass and the inertia do not fit" in w]
    assert rod == heavy.doubts[1] and rod.startswith("rod: ")


def test_an_implausible_duration_is_not_ok_and_the_table_shows_the_model() -> None:
    """With --flat the inferred T is 34 times the simulated one: warned, yet ok before; the
    table showed neither the warnings nor the engine's numbers."""
    with pytest.warns(Warning, match="not ok: plausibility: implausible T"):
        res = _example(flat="aisi-1010")
    assert not res.errors and not res.ok
    assert [d.split(":")[0] for d in res.doubts] == ["plausibility", "plausibility"]
    assert "implausible T" in res.doubts[0] and "implausible F" in res.doubts[1]
    text, html = str(res), res._repr_html_()
    for row in ("model e (ghaednia)", "model duration (ghaednia)", "model mean_force (ghaednia)"):
        assert row in text and row in html
    assert ">no<" in html and "implausible T" in html


def test_the_table_shows_the_warnings(analysed_example: Any) -> None:
    res = analysed_example
    assert res.ok and not res.doubts
    assert str(res).count("\n  warning ") == len(res.warnings)


def test_the_command_line_marks_it_not_ok_with_exit_status_0(
    tmp_path: Path, cli_main: Callable[..., tuple[int, str, str]]
) -> None:
    rod = tmp_path / "rod.toml"
    rod.write_text(
        '[rod]\nmass = 460.7\nlength = "304.8 mm"\ntip_radius = "8.8 mm"\n'
        'inertia = "0.0035667 kg*m^2"\n' + (EXAMPLE_DATA / "markers.toml").read_text()
    )
    args = ("analyze", str(EXAMPLE_DATA / "drop.csv"), str(EXAMPLE_DATA / "dent.npy"),
            "--pixel-size", "12 um", "--height-unit", "um", "--up", "+y",
            "--rod", str(rod))  # fmt: skip
    code, out, err = cli_main(*args, "--json")
    data = json.loads(out)
    assert code == 0 and data["ok"] is False and len(data["doubts"]) == 3
    code, out, err = cli_main(*args)
    assert code == 0 and "no: the marker geometry is in doubt and" in out
    assert "the result is implausible (see the" in out
    assert "warning: rod: the mass and the inertia do not fit" in err
