"""A library name on a material: the entry's values in other units are the entry's (to 1 part in
10^7, the round-off of a unit conversion; psi, ksi and lb/in^3 converted exactly), and a
refusal shows the values compared so that they read apart; ``Material(...)`` in Python follows
the same rule as the text form; the soda-lime glass citation names the column its values come
from."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from impactlab import Material
from impactlab.materials import get_material
from impactlab.materials import library as lib
from impactlab.materials.naming import SAME_VALUE_RTOL
from impactlab.references import REFERENCES
from impactlab.units import to_si

DOCS = Path(__file__).resolve().parents[2] / "docs" / "materials.md"


@pytest.mark.parametrize(
    ("text", "key"),
    [
        ("E=200GPa, nu=0.3, Sy=305MPa, rho=7.87 g/cm^3, HB=105, name=aisi-1010", "aisi-1010"),
        (
            "E=72GPa, nu=0.23, Sy=330MPa, rho=2.52 g/cm^3, brittle=yes, name=glass",
            "soda-lime-glass",
        ),
        # the sources' own units (psi, ksi, lb/in^3)
        ("E=29.5e6 psi, nu=0.30, Sy=295 ksi, rho=0.283 lb/in^3, name=aisi-52100", "aisi-52100"),
        ("E=14000 ksi, nu=0.31, Sy=45 ksi, rho=0.307 lb/in^3, name=brass-c360", "brass-c360"),
    ],
)
def test_the_entry_in_other_units_is_the_entry(text: str, key: str) -> None:
    assert get_material(text) is lib.PRESETS[key]


def test_the_us_units_are_exact() -> None:
    assert lib._KSI == 6.894757293168361e6  # 1000 lbf / in^2, lbf = 4.4482216152605 N
    assert lib._KSI == pytest.approx(to_si("1 ksi", "Pa"), rel=1e-15)  # pint: to an ulp
    assert lib._LB_PER_IN3 == pytest.approx(0.45359237 / 0.0254**3, rel=1e-15)
    assert lib.AISI_52100.E == pytest.approx(to_si("29.5e6 psi", "Pa"), rel=1e-15)
    assert lib.BRASS_C360.density == pytest.approx(to_si("0.307 lb/in^3", "kg/m^3"), rel=1e-15)


def test_a_value_beyond_round_off_is_refused_and_reads_apart() -> None:
    off = 200e9 * (1 + 5 * SAME_VALUE_RTOL)
    with pytest.raises(ValueError, match="is a library material with other values") as err:
        get_material(f"E={off} Pa, nu=0.3, Sy=305MPa, rho=7870, HB=105, name=aisi-1010")
    assert "E (2.000001e+11 Pa; the library's 2e+11 Pa)" in str(err.value)
    assert "get_material('aisi-1010') for the library's entry" in str(err.value)


def test_long_values_read_apart_in_one_notation() -> None:
    steel = lib.AISI_52100  # E = 203395340148.46664 Pa: 12 significant digits shown
    with pytest.raises(ValueError, match=r"E \(203395535829 Pa; the library's 203395340148 Pa\)"):
        Material(steel.name, 203395535829.0, 0.3, steel.yield_strength, density=steel.density)


@pytest.mark.parametrize(
    "name", ["aluminium 6061-T6", "Aluminium 6061-T6", "al-6061-t6", "6061-t6", "aluminium_6061_t6"]
)
def test_material_refuses_a_library_name_with_other_values(name: str) -> None:
    with pytest.raises(ValueError, match="is a library material") as err:
        Material(name, 200e9, 0.3, 305e6, 105.0, density=7870)
    message = str(err.value)
    assert message.startswith(f"name {name!r} is a library material with other values")
    assert "it names 'al-6061-t6', which differs in E (2e+11 Pa; the library's 6.89e+10 Pa)" in (
        message
    )
    assert "give another name, or get_material('al-6061-t6')" in message


def test_material_with_the_entry_values_or_another_name_is_made() -> None:
    al = lib.AL_6061_T6
    same = Material(al.name, al.E, al.nu, al.yield_strength, 95.0, density=2700.0)
    assert same.name == al.name and same.source == ""
    mine = Material("my aluminium", 200e9, 0.3, 305e6, 105.0, density=7870)
    assert mine.name == "my aluminium"


def test_a_library_entry_changed_in_part_is_renamed() -> None:
    changed = dataclasses.replace(lib.AISI_1010, E=69e9)
    assert changed.name == "AISI 1010 low-carbon steel (paper's flat), modified (E)"
    assert changed.source == ""
    assert dataclasses.replace(lib.AISI_1010) == lib.AISI_1010
    with pytest.raises(ValueError, match="is a library material with other values"):
        dataclasses.replace(lib.AISI_1010, E=69e9, source="")


def test_a_changed_entry_changed_again_says_what_differs_now() -> None:
    """A copy changed back to the entry's values kept its "modified (E)" label."""
    entry = lib.AISI_1010
    changed = dataclasses.replace(entry, E=69e9)
    assert dataclasses.replace(changed, E=entry.E) == entry
    both = dataclasses.replace(changed, nu=0.2)
    assert both.name == f"{entry.name}, modified (E, nu)"
    assert dataclasses.replace(both, E=entry.E).name == f"{entry.name}, modified (nu)"
    mine = Material("my steel, modified (E)", 69e9, 0.3, 305e6)  # not a library name
    assert mine.name == "my steel, modified (E)"


def test_a_changed_entry_with_a_source_of_its_own_says_what_differs_now() -> None:
    """A changed copy given its own source is labelled by what differs from the entry, as one
    without: nu changed is named, all values back leave no "modified" label; the source kept."""
    entry = lib.AISI_1010
    mine = dataclasses.replace(dataclasses.replace(entry, E=69e9), source="lab")
    assert (mine.name, mine.source) == (f"{entry.name}, modified (E)", "lab")
    more = dataclasses.replace(mine, nu=0.31)
    assert (more.name, more.source) == (f"{entry.name}, modified (E, nu)", "lab")
    back = dataclasses.replace(mine, E=entry.E)
    assert (back.name, back.source) == (entry.name, "lab")
    assert dataclasses.replace(back, source=entry.source) == entry
    given = dataclasses.replace(entry, E=69e9, source="lab")  # the source given with the change
    assert (given.name, given.source) == (f"{entry.name}, modified (E)", "lab")
    assert dataclasses.replace(entry, E=69e9).source == ""  # the entry's own is cleared


def test_every_library_entry_rebuilds_from_its_fields() -> None:
    for entry in lib.PRESETS.values():
        fields = {f.name: getattr(entry, f.name) for f in dataclasses.fields(entry)}
        assert Material(**fields) == entry
        assert Material(**{**fields, "source": ""}).name == entry.name


def test_the_finite_element_reference_reads_its_materials() -> None:
    """The FE reference's stored AISI 52100 (converted with a 7-digit ksi) is within round-off
    of the library's: its cases still read."""
    from impactlab.fe.curves import load_cases

    names = {c.sphere_material.name for c in load_cases()}
    assert lib.AISI_52100.name in names


def test_the_glass_citation_names_the_container_column() -> None:
    ref = REFERENCES["makeitfrom-soda-lime"]
    assert "container glass" in ref.citation and "of window glass from" not in ref.citation
    assert "container glass" in ref.note
    assert (lib.SODA_LIME_GLASS.E, lib.SODA_LIME_GLASS.density) == (72e9, 2520.0)
    row = next(line for line in DOCS.read_text().splitlines() if "`soda-lime-glass` |" in line)
    assert "container-glass column" in row


def test_every_display_name_names_its_library_entry() -> None:
    """The name every result prints was refused: "unknown material 'OFHC copper, annealed'"."""
    from impactlab import get_material
    from impactlab.materials import PRESETS

    for entry in PRESETS.values():
        assert get_material(entry.name) is entry
        assert get_material(entry.name.upper()) is entry  # case free, as keys are
