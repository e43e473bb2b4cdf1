"""``impactlab invert --vt-in``: the tip's incoming tangential velocity reaches the inversion
(value and sigma, a bare sigma in the value's unit, a measurement file's ``vt_in``), its JSON
echoes it, and a sigma below the value's rounding gives a finite uncertainty without numpy's
warnings."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab.analytic import invert

CliMain = Callable[..., tuple[int, str, str]]

ARGS = ("invert", "--angle", "45 deg", "--vi", "-2.18 m/s", "--e", "0.49", "--mu", "0.13",
        "--delta-p", "26 um", "--ls", "1650 um", "--samples", "200")  # fmt: skip
PY: dict[str, Any] = {
    "angle": math.radians(45),
    "v_i": -2.18,
    "e": 0.49,
    "mu": 0.13,
    "delta_p": 26e-6,
    "sliding_length": 1650e-6,
    "n_samples": 200,
}


def _json(cli_main: CliMain, *args: str) -> dict[str, Any]:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    assert "RuntimeWarning" not in err
    return json.loads(out)  # type: ignore[no-any-return]


@pytest.mark.parametrize(
    ("value", "sigma"), [("-0.3 m/s", "0.005"), ("-30 cm/s", "0.5"), ("-0.3", "0.005 m/s")]
)
def test_vt_in_and_its_sigma_reach_the_inversion(cli_main: CliMain, value: str, sigma: str) -> None:
    data = _json(cli_main, *ARGS, "--vt-in", value, "--sigma-vt-in", sigma)
    assert data["inputs"]["vt_in"] == {"value": -0.3, "unit": "m/s", "sigma": pytest.approx(0.005)}
    py = invert(**PY, vt_in=(-0.3, 0.005))
    assert data["duration"]["value"] == pytest.approx(py.duration, rel=1e-12)
    assert data["duration"]["sigma"] == pytest.approx(py.sigma_T_linear, rel=1e-9)
    assert data["sensitivity_T"]["vt_in"]["unit"] == "s/(m/s)"
    # a tip already sliding towards -x covers its slip sooner: a shorter T than the paper's form
    assert py.duration < invert(**PY).duration


def test_without_vt_in_the_paper_form_is_unchanged(cli_main: CliMain) -> None:
    data = _json(cli_main, *ARGS)
    assert "vt_in" not in data["inputs"]
    assert data["duration"]["value"] == pytest.approx(invert(**PY).duration, rel=1e-12)


def test_vt_in_shows_in_the_table(cli_main: CliMain) -> None:
    code, out, err = cli_main(*ARGS, "--vt-in", "-0.3 m/s", "--sigma-vt-in", "0.005")
    assert code == 0, err
    assert any(line.split("│")[1].strip() == "vt_in" for line in out.splitlines() if "│" in line)


@pytest.mark.parametrize("key", ["vt_in", "vt-in"])
def test_a_measurement_file_gives_vt_in(cli_main: CliMain, tmp_path: Path, key: str) -> None:
    path = tmp_path / "m.toml"
    path.write_text(f'{key} = "-30 cm/s"\n[sigma]\n{key} = 0.5\n')
    data = _json(cli_main, *ARGS, "--file", str(path))
    assert data["inputs"]["vt_in"]["value"] == pytest.approx(-0.3)
    assert data["inputs"]["vt_in"]["sigma"] == pytest.approx(0.005)


def test_a_bare_sigma_of_vt_in_from_a_file_needs_its_unit(
    cli_main: CliMain, tmp_path: Path
) -> None:
    path = tmp_path / "m.toml"
    path.write_text('vt_in = "-0.3 m/s"\n')
    code, _, err = cli_main(*ARGS, "--file", str(path), "--sigma-vt-in", "0.005")
    assert code == 2 and "--sigma-vt-in 0.005 has no unit" in err


def test_a_positive_vt_in_beyond_the_reversal_is_refused_by_its_option(cli_main: CliMain) -> None:
    code, _, err = cli_main(*ARGS, "--vt-in", "5 m/s")
    assert code == 2 and err.startswith("error: --vt-in = 5 m/s is at least |alpha| |v_i|")


def test_the_help_describes_vt_in(cli_main: CliMain) -> None:
    code, out, _ = cli_main("invert", "--help")
    text = " ".join(out.split())
    assert code == 0 and "--vt-in" in text and "--sigma-vt-in" in text
    assert "spin included" in text and "the sign matters" in text


def test_a_sigma_below_the_rounding_gives_a_finite_sigma(cli_main: CliMain) -> None:
    data = _json(cli_main, *ARGS, "--sigma-e", "1e-310")
    assert math.isfinite(data["duration"]["value"]) and math.isfinite(data["mean_force"]["value"])
    for out in ("duration", "mean_force", "T_mc", "F_mc"):
        assert data[out].get("sigma", 0.0) is not None
        assert math.isfinite(data[out].get("sigma", 0.0))
