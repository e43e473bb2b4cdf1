"""``impactlab laws``: its errors name the option as the user typed it (``--material`` or
``--body`` for the body's material, ``--radius``)."""

from __future__ import annotations

import pytest

BAD = "E=1GPa"


@pytest.mark.parametrize("option", ["--material", "--body"])
def test_a_bad_body_material_is_named_by_its_option(cli_main, option) -> None:
    code, _out, err = cli_main("laws", "ghaednia", option, BAD)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith(f"error: {option}: a material by values needs E, nu, Sy and rho")
    other = "--body" if option == "--material" else "--material"
    assert other not in err


@pytest.mark.parametrize("option", ["--material", "--body"])
def test_the_example_options_name_the_one_given(cli_main, option) -> None:
    code, _out, err = cli_main("laws", option, "aisi-52100")
    assert code == 2 and f"{option} without a law" in err
    code, _out, err = cli_main("laws", "--accuracy", option, "aisi-52100")
    assert code == 2 and f"{option} with --accuracy" in err
    code, _out, err = cli_main("laws", option, "aisi-201")  # the default: nothing set
    assert code == 0, err


def test_body_and_material_together_are_refused(cli_main) -> None:
    code, _out, err = cli_main("laws", "ghaednia", "--body", "aisi-201", "--material", "aisi-201")
    assert code == 2 and "--body and --material both given" in err


def test_material_and_body_give_the_same_numbers(cli_main) -> None:
    args = ("laws", "ghaednia", "--json")
    code, by_material, err = cli_main(*args, "--material", "aisi-52100")
    assert code == 0, err
    assert by_material == cli_main(*args, "--body", "aisi-52100")[1]
    assert by_material != cli_main(*args)[1]


def test_a_bad_radius_is_named_by_its_option(cli_main) -> None:
    code, _out, err = cli_main("laws", "ghaednia", "--radius", "-1 mm")
    assert code == 2 and err.startswith("error: --radius must be > 0")
