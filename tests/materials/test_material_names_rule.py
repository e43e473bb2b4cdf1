"""A material by values carries a library entry's name (its key, an alias or its display name)
only with every value of that entry, the unset ones included; the short aliases of the paper's
steels; an unknown name suggests a library name that holds it (or that it holds) first."""

from __future__ import annotations

import pytest

from impactlab.materials import get_material
from impactlab.materials.inputs import library_key
from impactlab.materials.library import AISI_201, AISI_1010, AL_6061_T6, ALIASES, PRESETS

AL = "E=68.9GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"


@pytest.mark.parametrize(
    ("text", "differs"),
    [
        # the display name of a library entry, with an aluminium's values
        (
            "E=69GPa, nu=0.33, Sy=276MPa, rho=2700, name=AISI 1010 low-carbon steel (paper's flat)",
            "E (6.9e+10 Pa; the library's 2e+11 Pa)",
        ),
        # the library's key, every given value the entry's, its hardness left out
        (f"{AL}, name=al-6061-t6", "brinell_hardness (unset; the library's 95.0 kgf/mm^2)"),
        (f"{AL}, name=6061-t6", "brinell_hardness (unset"),  # an alias
        (f"{AL}, HB=95, n=2.3, name=Aluminium 6061-T6", "meyer_index (2.3; the library's 2.2)"),
        (f"{AL}, HB=95, brittle=yes, name=al-6061-t6", "brittle (yes; the library's no)"),
    ],
)
def test_a_library_name_needs_every_value_of_the_entry(text: str, differs: str) -> None:
    with pytest.raises(ValueError, match="is a library material with other values") as err:
        get_material(text)
    message = str(err.value)
    assert differs in message and "\n" not in message
    assert "the unset ones too: give another name" in message


def test_a_library_name_with_every_value_is_that_entry() -> None:
    same = get_material(f"{AL}, HB=95, name=Aluminium 6061-T6")
    assert same is AL_6061_T6 and library_key(same) == "al-6061-t6"
    steel = get_material("E=200GPa, nu=0.3, Sy=305MPa, rho=7870, HB=105, n=2.2, name=AISI 1010")
    assert steel is AISI_1010


def test_other_names_are_free() -> None:
    m = get_material(f"{AL}, name=my aluminium")
    assert m.name == "my aluminium" and not m.has_hardness and library_key(m) is None


def test_short_aliases_of_the_papers_steels() -> None:
    new = {"1010": "aisi-1010", "aisi1010": "aisi-1010", "201": "aisi-201", "aisi201": "aisi-201"}
    for alias, key in new.items():
        assert ALIASES[alias] == key and alias not in PRESETS
    assert get_material("1010") is AISI_1010 and get_material("AISI1010") is AISI_1010
    assert get_material("201") is AISI_201 and get_material(" aisi201 ") is AISI_201
    assert len(set(ALIASES) | set(PRESETS)) == len(ALIASES) + len(PRESETS)  # no collision


@pytest.mark.parametrize(
    ("typed", "suggested"),
    [
        ("soda", "soda-lime-glass"),  # no suggestion before: too short for a close spelling
        ("1010-steel", "aisi-1010"),
        ("201-steel", "aisi-201"),
        ("6061", "al-6061-t6"),  # the entry's name, not the alias '6061-t6'
        ("aisi-101", "aisi-1010"),
        ("asi-1010", "aisi-1010"),  # no substring: the nearest spelling
    ],
)
def test_an_unknown_name_suggests_a_name_that_holds_it(typed: str, suggested: str) -> None:
    with pytest.raises(
        ValueError, match=rf"unknown material '{typed}' \(did you mean '{suggested}'"
    ):
        get_material(typed)


@pytest.mark.parametrize(
    ("typed", "nearest"),
    [
        ("al-6061-t4", "al-6061-t6"),
        ("aisi-1011", "aisi-1010"),
        ("aisi-1018", "aisi-1010"),
        ("al-2024-t3", "al-6061-t6"),
        ("al-6061-o", "al-6061-t6"),
    ],
)
def test_another_grade_or_temper_is_named_as_such(typed: str, nearest: str) -> None:
    """'did you mean al-6061-t6' for T4 offered another material (its yield strength half) as
    a spelling of the name."""
    with pytest.raises(
        ValueError,
        match=rf"unknown material '{typed}' \(the library's nearest is '{nearest}' \(.*\), "
        r"another grade or temper: not the same material, its properties differ\)",
    ):
        get_material(typed)


def test_no_suggestion_when_nothing_is_near() -> None:
    with pytest.raises(ValueError, match=r"unknown material 'al-7075'; known: aisi-201"):
        get_material("al-7075")


def test_the_materials_command_takes_the_short_aliases(cli_main) -> None:
    for name in ("1010", "201"):
        code, out, err = cli_main("materials", name)
        assert code == 0, err
        assert ("AISI 1010" if name == "1010" else "AISI 201") in out


@pytest.mark.parametrize(
    ("typed", "suggested"),
    [("al-661-t6", "al-6061-t6"), ("aisi-512100", "aisi-52100"), ("alumina-9.95", "alumina-99.5")],
)
def test_a_typo_of_a_number_keeps_its_did_you_mean(typed: str, suggested: str) -> None:
    with pytest.raises(
        ValueError, match=rf"unknown material '{typed}' \(did you mean '{suggested}'"
    ):
        get_material(typed)
