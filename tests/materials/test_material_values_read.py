"""A material by values reads what users and the library write: ``impactlab materials NAME
--json`` fed back (``{"value", "unit"}`` objects, descriptive keys read past), an exponent's
digits next to a power written without ``^`` (``rho=2.7e3 kg/m3``), a Brinell hardness with
its symbol (``HB=95 HB``); an unknown name suggests the entry it begins (``al``: al-6061-t6)
and a single character nothing; a missing file is named once."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from impactlab.materials import get_material
from impactlab.materials.library import AL_6061_T6, PRESETS

AL = "E=69GPa, nu=0.33, Sy=276MPa"


@pytest.mark.parametrize("key", list(PRESETS))
def test_the_json_of_every_library_entry_feeds_back(cli_main, key: str) -> None:
    code, out, err = cli_main("materials", key, "--json")
    assert code == 0, err
    data = json.loads(out)
    assert get_material(data) is PRESETS[key]
    quantities = {k: v for k, v in data.items() if isinstance(v, dict)}
    assert get_material(quantities | {"name": "my copy"}).E == PRESETS[key].E  # no library name


def test_value_and_unit_objects_are_quantities() -> None:
    m = get_material({"E": {"value": 69, "unit": "GPa"}, "nu": {"value": 0.33, "unit": "1"},
                      "Sy": {"value": 276, "unit": "MPa"}, "rho": {"value": 2.7, "unit": "g/cm^3"},
                      "HB": {"value": None, "unit": "kgf/mm^2"}})  # fmt: skip
    assert (m.E, m.nu, m.yield_strength) == (69e9, 0.33, 276e6)
    assert m.density == pytest.approx(2700.0, rel=1e-12)
    with pytest.raises(ValueError, match=r"^material E: expected a number or a quantity"):
        get_material({"E": {"value": 69, "unit": "GPa", "sigma": 1}, "nu": 0.3})


@pytest.mark.parametrize(
    "rho", ["2.7e3", "2.7e3 kg/m^3", "2.7e3 kg/m3", "2700kg/m3", "2.7E+3 kg/m3", "2.7 g/cm3"]
)
def test_an_exponent_is_no_power_of_a_unit(rho: str) -> None:
    assert get_material(f"{AL}, rho={rho}").density == pytest.approx(2700.0, rel=1e-12)
    assert get_material(f"E=69GPa, nu=0.33, Sy=2.76e2 MPa, rho={rho}").yield_strength == 276e6


@pytest.mark.parametrize("hb", ["95 HB", "95 HBW", "HBW 95", "95"])
def test_a_brinell_hardness_takes_its_symbol(hb: str) -> None:
    m = get_material(f"{AL}, rho=2700kg/m^3, HB={hb}")
    assert m.brinell_hardness == pytest.approx(95.0, rel=1e-12)
    same = get_material(
        f"{AL}, rho=2700kg/m^3, HB={hb}, name=al-6061-t6".replace("69GPa", "68.9GPa")
    )
    assert same is AL_6061_T6


@pytest.mark.parametrize(("typed", "suggested"), [("al", "al-6061-t6"), ("copper", "copper-ofhc")])
def test_a_name_suggests_the_entry_it_begins(typed: str, suggested: str) -> None:
    with pytest.raises(
        ValueError, match=rf"unknown material '{typed}' \(did you mean '{suggested}'"
    ):
        get_material(typed)


@pytest.mark.parametrize("typed", ["a", "e", "1"])
def test_one_character_suggests_nothing(typed: str) -> None:
    with pytest.raises(ValueError, match=rf"^unknown material '{typed}'; known: aisi-201"):
        get_material(typed)


def test_a_missing_file_is_named_once(tmp_path: Path) -> None:
    missing = str(tmp_path / "myal.toml")
    with pytest.raises(ValueError, match=r"^material file '.*myal\.toml' does not exist$"):
        get_material(missing)
    with pytest.raises(ValueError, match=r"^--flat: material file '.*myal\.toml' does not exist$"):
        get_material(missing, "--flat")


def test_a_mapping_reads_none_as_not_given_and_a_records_material_back() -> None:
    """HB=None was a pint error about a unit 'None', name=None named the material "None", and
    the material a result records was refused for its 'type' and its unset hardness."""
    import impactlab as il

    base = {"E": "69 GPa", "nu": 0.33, "Sy": "276 MPa", "rho": 2700}
    assert math.isnan(get_material({**base, "HB": None}).brinell_hardness)
    assert get_material({**base, "name": None}).name.startswith("custom (")
    with pytest.raises(ValueError, match="missing E"):
        get_material({**base, "E": None})
    record = il.simulate(il.Rod.paper(), angle=0.3, velocity=(0.0, -1.0)).to_dict()
    flat = json.loads(json.dumps(record["input"]["flat"]))
    assert get_material(flat) is il.AISI_1010
