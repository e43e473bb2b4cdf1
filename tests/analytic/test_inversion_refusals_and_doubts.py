"""The inversion's refusals and doubts named for what they are: a rod whose mass and inertia do
not fit (a doubt, as ``analyze`` says), a sigma of a length wider than its range, a Monte Carlo
that spreads T beyond any impact, the sticking regime before a vanishing sliding length, every
missing input listed, and a rod that cannot be built named by its options."""

from __future__ import annotations

import json
import math
from collections.abc import Callable

import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.bodies._checks import inertia_ratio_problem
from impactlab.experiment.arguments import implausible_rod

CliMain = Callable[..., tuple[int, str, str]]
BASE = {"angle": math.radians(20), "v_i": -1.41, "e": 0.5, "mu": 0.2, "delta_p": 22e-6,
        "sliding_length": 1400e-6, "n_samples": 1000}  # fmt: skip
CLI = ["invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
       "--delta-p", "22 um", "--ls", "1400 um"]  # fmt: skip


def test_the_rod_check_is_one_shared_by_analyze_and_invert() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match="^rod: the mass and the inertia"):
        grams = Rod(length=0.3048, tip_radius=0.0088, mass=460.7, inertia=3.5667e-3)
    assert implausible_rod(grams) == inertia_ratio_problem(460.7, 3.5667e-3, 0.3048)
    assert inertia_ratio_problem(PAPER_ROD.mass, PAPER_ROD.mass * 0.3048**2 / 12, 0.3048) is None
    with pytest.warns(il.ImplausibleInputWarning, match="mass and the inertia do not fit"):
        res = il.invert(**BASE, rod=grams)
    assert res.warnings[0].startswith("rod: the mass and the inertia do not fit")


def test_cli_a_mass_in_grams_given_as_kilograms_is_a_doubt(cli_main: CliMain) -> None:
    """It was ok with T = 2.351 ms (4.106 ms for the right mass)."""
    code, out, err = cli_main(*CLI, "--mass", "460.7", "--inertia", "3.5667e-3", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["ok"] is False and len(data["doubts"]) == 1
    doubt = data["doubts"][0]
    assert "I_C / (m L^2) = 8.3e-05" in doubt and "mass = 460.7 kg" in doubt
    assert "inertia = 0.003567 kg m^2" in doubt and "grams given as kilograms" in doubt


@pytest.mark.parametrize(
    ("change", "needle"),
    [
        ({"sliding_length": (1400e-6, 50.0)}, "sigma of sliding_length = 50.0 m does not fit"),
        ({"delta_p": (22e-6, 5e-3)}, "sigma of delta_p = 0.005 m does not fit"),
    ],
)
def test_a_sigma_of_a_length_wider_than_its_range_is_refused(change: dict, needle: str) -> None:
    with pytest.raises(ValueError, match=needle) as err:
        il.invert(**{**BASE, **change})
    assert "tip radius" in str(err.value) or "longer than the rod" in str(err.value)


def test_cli_names_the_sigma_option_of_a_length(cli_main: CliMain) -> None:
    code, _, err = cli_main(*CLI, "--sigma-delta-p", "5 mm")
    assert code != 0 and err.startswith("error: --sigma-delta-p = 0.005 m does not fit")


def test_a_monte_carlo_spread_beyond_any_impact_is_a_doubt(cli_main: CliMain) -> None:
    """A sigma of L_s just inside its range: T's median is no rigid-body impact's."""
    with pytest.warns(il.ImplausibleInputWarning, match="far longer than a rigid-body impact"):
        res = il.invert(**{**BASE, "sliding_length": (1400e-6, 0.07)})
    assert res.duration < 0.1 and max(res.T_median_mc, res.T_interval_mc[1]) > 0.1
    assert "sigma of sliding_length" in res.warnings[-1]
    code, out, err = cli_main(*CLI, "--sigma-ls", "70 mm", "--samples", "1000", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["ok"] is False
    assert any("far longer than a rigid-body impact" in d for d in data["doubts"])
    assert any("drew |sliding_length| <= 0" in d for d in data["doubts"])  # L_s unresolved


def test_a_stuck_impact_is_named_as_such_before_its_tiny_scar() -> None:
    with pytest.raises(ValueError, match="sticking") as err:
        il.invert(angle=math.radians(20), v_i=-2.0, e=0.42, mu=0.8, delta_p=60e-6,
                  sliding_length=2.7e-13)  # fmt: skip
    assert "below 1 nm" not in str(err.value)


def test_cli_lists_every_missing_input_e_among_them(cli_main: CliMain) -> None:
    code, _, err = cli_main("invert", "--angle", "20 deg")
    assert code != 0
    assert "--vi, --e (or --dv-cy), --mu, --delta-p, --ls" in err


def test_cli_names_the_rod_options_of_a_rod_that_cannot_be(cli_main: CliMain) -> None:
    code, _, err = cli_main(*CLI, "--length", "1 mm")
    assert code != 0
    assert err.startswith("error: --length 1 mm with the paper's tip_radius 0.0088 m (no "
                          "--tip-radius): tip_radius = 0.0088 m exceeds half")  # fmt: skip


def test_cli_an_e_within_noise_above_1_is_taken_at_1_and_stays_ok(cli_main: CliMain) -> None:
    """As docs/tutorials/invert.md says: a measured e up to 3 sigma above 1 is noise."""
    code, out, err = cli_main("invert", "--case", "paper-20", "--e", "1.02", "--sigma-e", "0.01",
                              "--samples", "1000", "--json")  # fmt: skip
    assert code == 0, err
    data = json.loads(out)
    assert data["inputs"]["e"]["value"] == 1.0
    assert any("read as measurement noise" in w for w in data["warnings"])
    assert not any("e = 1.02" in d for d in data["doubts"])
    code, _, err = cli_main("invert", "--case", "paper-20", "--e", "1.02")
    assert code != 0 and "e must lie in [0, 1]" in err
