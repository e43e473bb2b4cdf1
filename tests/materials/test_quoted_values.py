"""The text form of a material by values: a quoted value may hold the separators."""

from __future__ import annotations

import pytest

from impactlab import get_material
from impactlab.materials.inputs import parse_values

BASE = "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"


@pytest.mark.parametrize("quote", ['"', "'"])
def test_a_quoted_name_keeps_its_comma_and_semicolon(quote: str) -> None:
    m = get_material(f"{BASE}, name={quote}Al 6061, aged; lot 7{quote}")
    assert m.name == "Al 6061, aged; lot 7"
    assert m.E == 69e9


def test_quotes_around_a_quantity_are_read_past() -> None:
    assert parse_values("E='69 GPa'; nu=\"0.33\"") == {"E": "69 GPa", "nu": "0.33"}


def test_an_unquoted_comma_in_a_name_names_the_way_out() -> None:
    with pytest.raises(ValueError, match=r"quote a value that holds a comma.*got 'aged'"):
        get_material(f"{BASE}, name=Al 6061, aged")


def test_an_unclosed_quote_is_refused() -> None:
    with pytest.raises(ValueError, match=r"flat: a \" opened in .* is not closed"):
        parse_values('E=69GPa, name="Al 6061', "flat")


def test_an_empty_quoted_value_is_refused() -> None:
    with pytest.raises(ValueError, match="expected key=value pairs"):
        parse_values('E=69GPa, name=""')


def test_an_apostrophe_inside_a_value_is_text() -> None:
    values = parse_values("E=69GPa, name=AISI 1010 (paper's flat), rho=2700")
    assert values == {"E": "69GPa", "name": "AISI 1010 (paper's flat)", "rho": "2700"}


def test_a_quoted_value_may_hold_the_other_quote() -> None:
    assert parse_values("""name="the paper's flat, aged" """) == {"name": "the paper's flat, aged"}
