"""What a newcomer meets first on the command line and in the figures: a velocity that does not
reach the flat is refused naming the options as typed (``--vy``, ``--spin``), a mistyped
``--stop`` gets the "did you mean" of the other choices, ``invert``'s correlation row shows a
pair in the command's order of the inputs, ``impactlab drop``'s table names a contact's slip
``sliding_length``, and the contact-path figure of a body that yields first leaves out the dent
the flat does not have."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path

import pytest

import impactlab as il

CliMain = Callable[..., tuple[int, str, str]]


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main(*args)
    assert code == 2 and out == "", (code, out, err)
    assert err.count("\n") == 1 and err.startswith("error: "), err
    return err.strip().removeprefix("error: ")


@pytest.mark.parametrize(
    ("command", "what"),
    [
        (("simulate", "rod"), "contact point"),
        (("simulate", "rod", "--flexible"), "tip"),
        (("drop",), "tip"),
    ],
)
def test_a_velocity_away_from_the_flat_names_the_option(
    cli_main: CliMain, command: tuple[str, ...], what: str
) -> None:
    text = _error(cli_main, *command, "--angle", "20 deg", "--vy", "1.41 m/s")
    assert text == (
        f'--vy "1.41 m/s": the {what} does not approach the flat (its normal velocity vy = '
        "1.41 m/s must be < 0, towards the flat)"
    )


def test_the_spin_is_named_where_it_was_given(cli_main: CliMain) -> None:
    args = ("--angle", "20 deg", "--vy", "-1.41 m/s", "--spin", "-100 rad/s")
    text = _error(cli_main, "simulate", "rod", *args)
    assert text.startswith('--vy "-1.41 m/s", --spin "-100 rad/s": the contact point does not')
    assert "vy - spin * (L/2) cos(angle) = 12.91 m/s must be < 0" in text
    speed = ("--angle", "20 deg", "--speed", "1 m/s", "--incidence", "10 deg", "--spin", "-100")
    text = _error(cli_main, "drop", *speed)
    assert text.startswith('--speed "1 m/s", --incidence "10 deg", --spin "-100": the tip')
    # a sphere's spin does not move its contact point: not named
    text = _error(cli_main, "simulate", "sphere", "--vy", "1.41 m/s", "--spin", "3 rad/s")
    assert text.startswith('--vy "1.41 m/s": the contact point') and "spin" not in text


def test_python_keeps_its_keyword() -> None:
    with pytest.raises(ValueError, match=r"^velocity: the contact point does not approach"):
        il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0.0, 1.41))


def test_a_mistyped_stop_gets_did_you_mean(cli_main: CliMain) -> None:
    text = _error(cli_main, "drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--stop", "flght")
    assert text == "--stop must be one of sequence, flight, got 'flght' (did you mean 'flight'?)"
    with pytest.raises(ValueError, match=r"got 'seqence' \(did you mean 'sequence'\?\)$"):
        il.simulate_drop(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), stop="seqence")


@pytest.mark.parametrize("typed", ["e,mu=-0.3", "mu,e=-0.3"])
def test_invert_shows_a_pair_in_the_inputs_order(cli_main: CliMain, typed: str) -> None:
    args = ("invert", "--case", "paper-20", "--sigma-e", "0.02", "--sigma-mu", "0.01")
    code, out, err = cli_main(*args, "--correlation", typed, "--samples", "200")
    assert code == 0, err
    row = next(line for line in out.splitlines() if "correlation" in line)
    assert "(e, mu) -0.3" in row and "(mu, e)" not in row, row


def test_the_drop_table_names_the_slip_as_json_does(cli_main: CliMain) -> None:
    args = ("drop", "--rigid", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2")
    code, out, err = cli_main(*args)
    assert code == 0, err
    header = out.splitlines()[1].split()
    assert "sliding_length" in header and "slip" not in header
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    contact = json.loads(out)["contacts"][0]
    assert contact["sliding_length"]["unit"] == "m" and "slip" not in contact


def test_contact_path_leaves_out_the_dent_of_a_body_that_yields_first(tmp_path: Path) -> None:
    from impactlab.dynamics import plotting

    soft = il.Sphere(radius=0.003, material=il.get_material("al-6061-t6"))
    r = il.simulate(soft, il.get_material("aisi-52100"), law="jackson-green",
                    velocity=(0.0, -2.5))  # fmt: skip
    assert r.body_yields_first and r.delta_p > 0
    fig = plotting.plot_contact_path(r)  # dent=True: no dent in the flat to draw
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert "no dent in the flat: the body yields first" in labels
    assert "predicted dent (y = 0)" not in labels
    paths = plotting.save_figures(r, tmp_path, formats=("png",))
    assert sorted(p.name for p in paths) == [
        "impact_contact_path.png", "impact_force_penetration.png", "impact_force_time.png",
    ]  # fmt: skip
    rod = il.simulate(il.Rod.paper(), angle=math.radians(20), velocity=(0.0, -1.41))
    labels = [
        t.get_text() for t in plotting.plot_contact_path(rod).axes[0].get_legend().get_texts()
    ]
    assert "predicted dent (y = 0)" in labels  # the flat's dent: drawn
