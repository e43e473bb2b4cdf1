"""The material library (cited values, conditions), ``get_material`` (names, aliases, materials
by values, TOML files), the one rule for partial definitions, and the commands that read them."""

from __future__ import annotations

import json
import math
import sys
from dataclasses import fields

import pytest
from hypothesis import given
from hypothesis import strategies as st

from impactlab.cli import main
from impactlab.materials import (
    AISI_1010,
    AL_6061_T6,
    ALIASES,
    BRITTLE,
    PMMA,
    PRESETS,
    Material,
    dynamic_poisson_ratio,
    get_material,
    library_key,
)
from impactlab.materials.library import PMMA_WAVE_SPEEDS
from impactlab.references import REFERENCES

#: The source's own numbers, in its units (the data sheets read for the library).
CITED = {
    "al-6061-t6": (68.9e9, 0.33, 276e6, 95.0, 2700.0),
    "aisi-304": (193e9, 0.29, 215e6, 123.0, 8000.0),
    "ti-6al-4v": (113.8e9, 0.342, 880e6, 334.0, 4430.0),
    "copper-ofhc": (117e9, 0.34, 48e6, 42.0, 8940.0),
    "alumina-99.5": (416e9, 0.23, 3.0e9, math.nan, 3984.0),
    "pmma": (2.8e9, 0.399, 117e6, math.nan, 1190.0),
}
PSI = 6894.757  # Pa
LB_PER_IN3 = 27679.9047  # kg/m^3


def _cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out = capsys.readouterr()
    return code, out.out, out.err


def test_every_entry_has_a_source_a_condition_and_valid_values() -> None:
    kinds = {"steel": 0, "aluminium": 0, "ti-6al-4v": 0, "brass": 0, "copper": 0, "glass": 0,
             "pmma": 0}  # fmt: skip
    for key, m in PRESETS.items():
        assert m.source in REFERENCES, key  # cited: a key of impactlab.references
        ref = REFERENCES[m.source]
        assert ref.doi or ref.url.startswith(("https://", "http://")), key
        assert m.condition or m.source == "ghaednia-2016-impact", key
        assert 0 < m.yield_strength < m.E and -1 < m.nu < 0.5 and m.density > 0
        assert get_material(key) is m and library_key(m) == key
        for word in kinds:
            kinds[word] += word in m.name.lower()
    assert all(kinds.values()), kinds
    assert {"tungsten-carbide", "alumina-99.5", "soda-lime-glass"} == BRITTLE
    assert {"aisi-52100", "aisi-304", "aisi-1010"} <= set(PRESETS)


@pytest.mark.parametrize("key", sorted(CITED))
def test_values_are_the_sources(key: str) -> None:
    E, nu, sy, hb, rho = CITED[key]
    m = PRESETS[key]
    assert (m.E, m.nu, m.yield_strength, m.density) == (E, nu, sy, rho)
    assert (math.isnan(hb) and not m.has_hardness) or m.brinell_hardness == hb


def test_us_units_converted() -> None:
    brass, bearing = PRESETS["brass-c360"], PRESETS["aisi-52100"]
    assert brass.E == pytest.approx(14_000e3 * PSI) and brass.yield_strength == pytest.approx(
        45e3 * PSI
    )
    assert brass.density == pytest.approx(0.307 * LB_PER_IN3)
    assert bearing.yield_strength == pytest.approx(295e3 * PSI)
    assert bearing.density == pytest.approx(7833, abs=1)
    assert not bearing.has_hardness  # HRC 60-67: beyond the Brinell scale, never guessed


@given(st.floats(-0.99, 0.49), st.floats(100.0, 1e4))
def test_dynamic_poisson_ratio_inverts_the_wave_speed_ratio(nu: float, v_shear: float) -> None:
    """v_l / v_s = sqrt(2 (1 - nu) / (1 - 2 nu)) for an isotropic solid: back to nu."""
    v_long = v_shear * math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))
    assert dynamic_poisson_ratio(v_long, v_shear) == pytest.approx(nu, abs=1e-9)


def test_dynamic_poisson_ratio_refuses_impossible_speeds() -> None:
    for v_long, v_shear in ((1000.0, 1000.0), (1000.0, 0.0), (1000.0, -5.0), (1000.0, 2000.0)):
        with pytest.raises(ValueError, match="0 < v_shear < v_longitudinal"):
            dynamic_poisson_ratio(v_long, v_shear)


def test_pmma_is_cited_and_consistent() -> None:
    """PMMA: the data sheet's E, compressive yield and density; nu the CRC Handbook's dynamic
    value, which its third wave speed (v_ext = 1840 m/s in a thin rod, E = rho v_ext^2) and
    G = rho v_s^2 confirm: E / (2 G) - 1 within 0.001."""
    v_long, v_shear = PMMA_WAVE_SPEEDS
    assert PMMA.nu == round(dynamic_poisson_ratio(v_long, v_shear), 3) == 0.399
    assert 1840.0**2 / (2.0 * v_shear**2) - 1.0 == pytest.approx(PMMA.nu, abs=1e-3)
    assert "1840" in REFERENCES["crc-sound-speed"].citation
    assert PMMA.source == "usplastic-acrylic-sheet" and "crc-sound-speed" in PMMA.note
    assert "viscoelastic" in PMMA.note and "pmma" not in BRITTLE and not PMMA.has_hardness
    for alias in ("acrylic", "Plexiglas", "perspex", "PMMA"):
        assert get_material(alias) is PMMA


def test_names_and_aliases() -> None:
    assert get_material("AL_6061_T6") is AL_6061_T6
    assert get_material(" 6061-T6 ") is AL_6061_T6
    for alias, key in ALIASES.items():
        assert get_material(alias) is PRESETS[key]
    with pytest.raises(ValueError, match=r"unknown material 'al-7075'; known: aisi-201.*E=69GPa"):
        get_material("al-7075")


def test_a_material_by_values_is_complete_or_refused() -> None:
    m = get_material("E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m3")
    assert (m.E, m.nu, m.yield_strength, m.density) == (69e9, 0.33, 276e6, 2700.0)
    assert not m.has_hardness and m.meyer_index == 2.2  # nothing borrowed from a library entry
    assert m.name.startswith("custom (E 69 GPa") and library_key(m) is None
    same = get_material({"E": "69 GPa", "nu": 0.33, "yield_strength": "276 MPa", "rho": 2700})
    assert (same.E, same.yield_strength, same.density) == (m.E, m.yield_strength, m.density)
    full = get_material("E=69e9; nu=0.33; Sy=276e6; rho=2700; HB=95; n=2.3; name=my Al")
    assert (full.brinell_hardness, full.meyer_index, full.name) == (95.0, 2.3, "my Al")
    hard = get_material("E=69e9, nu=0.33, Sy=276e6, rho=2700, HB=95 kgf/mm^2")
    assert hard.brinell_hardness == pytest.approx(95.0)
    with pytest.raises(ValueError, match="missing Sy, rho"):
        get_material("E=69GPa, nu=0.33")
    with pytest.raises(ValueError, match="unknown property 'Ey'"):
        get_material("Ey=69GPa, nu=0.33, Sy=276MPa, rho=2700")
    with pytest.raises(ValueError, match="is a library material with other values"):
        get_material("E=69GPa, nu=0.33, Sy=276MPa, rho=2700, name=aisi-1010")
    with pytest.raises(ValueError, match="wrong dimension"):
        get_material("E=69 kg, nu=0.33, Sy=276MPa, rho=2700")
    with pytest.raises(ValueError, match="yield_strength"):
        get_material("E=1GPa, nu=0.33, Sy=2GPa, rho=2700")


def test_toml_file(tmp_path) -> None:
    f = tmp_path / "al.toml"
    f.write_text('[material]\nname = "al"\nE = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = 2700\n')
    assert get_material(str(f)).E == 69e9
    f.write_text('E = "69 GPa"\nnu = 0.33\n')
    with pytest.raises(ValueError, match=r"al.toml\): a material by values needs"):
        get_material(str(f))
    with pytest.raises(ValueError, match="does not exist"):
        get_material(str(tmp_path / "none.toml"))


def test_new_fields_are_plain_dataclass_fields() -> None:
    names = [f.name for f in fields(Material)]
    assert names[-4:] == ["condition", "source", "note", "brittle"]
    assert "Table 1" not in str(AISI_1010) and "note" not in repr(AISI_1010)


def test_materials_command(monkeypatch, capsys) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    code, out, _ = _cli(monkeypatch, capsys, "materials")
    assert code == 0
    assert all(key in out for key in PRESETS)
    assert max(len(line) for line in out.splitlines()) <= 80
    code, out, _ = _cli(monkeypatch, capsys, "materials", "--json")
    data = json.loads(out)
    assert data["al-6061-t6"]["E"] == {"value": 68.9e9, "unit": "Pa"}
    assert data["alumina-99.5"]["brittle"] is True
    assert data["ti-6al-4v"]["url"].startswith("http")


def test_simulate_refuses_a_material_given_in_parts(monkeypatch, capsys, tmp_path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text('body = "sphere"\nvy = "-1 m/s"\nflat_E = "69 GPa"\n')
    code, _, err = _cli(monkeypatch, capsys, "simulate", "--config", str(cfg))
    assert code == 2 and "flat_E in the config file: give a material whole" in err
    code, _, err = _cli(
        monkeypatch, capsys, "simulate", "sphere", "--vy", "-1 m/s", "--flat", "E=69GPa,nu=0.3"
    )
    assert code == 2 and "--flat: a material by values needs E, nu, Sy and rho" in err
    code, _, err = _cli(monkeypatch, capsys, "simulate", "sphere", "--vy", "-1", "--flat", "al")
    assert code == 2 and "unknown material 'al'" in err


def test_simulate_on_pmma(monkeypatch, capsys) -> None:
    """A steel ball on the library's PMMA, by an alias, from the command line."""
    args = ("simulate", "sphere", "--radius", "3 mm", "--vy", "-1 m/s", "--material", "52100")
    code, out, err = _cli(monkeypatch, capsys, *args, "--flat", "acrylic", "--json")
    assert code == 0, err
    data = json.loads(out)
    flat = data["input"]["flat"]
    assert flat["name"] == PMMA.name and flat["E"]["value"] == PMMA.E
    assert 0.0 < data["e"]["value"] <= 1.0


def test_fe_takes_a_material_whole(monkeypatch, capsys) -> None:
    code, _, err = _cli(monkeypatch, capsys, "fe", "indent", "--max", "5 um", "--flat-E", "69 GPa")
    assert code == 2 and "--flat-E without --flat-nu, --flat-sy: a material by values" in err
    code, _, err = _cli(monkeypatch, capsys, "fe", "indent", "--max", "5 um", "--flat", "al")
    assert code == 2 and "--flat: unknown material 'al'" in err


def test_simulate_takes_a_material_by_values_and_a_config_table(monkeypatch, capsys, tmp_path):
    """The researcher's case: a 6 mm AISI 52100 ball on 6061-T6, by name, by values on the
    command line and as a --config table: the same impact as in Python."""
    import impactlab as il

    ball = il.Sphere(radius=0.003, material=PRESETS["aisi-52100"])
    ref = il.simulate(ball, AL_6061_T6, velocity=(0.0, -2.5))
    base = ("simulate", "sphere", "--radius", "3 mm", "--material", "52100", "--json")
    code, out, err = _cli(monkeypatch, capsys, *base, "--vy", "-2.5 m/s", "--flat", "6061-t6")
    assert code == 0, err
    assert json.loads(out)["e"]["value"] == ref.e
    values = "E=68.9GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3, HB=95"
    code, out, err = _cli(monkeypatch, capsys, *base, "--speed", "2.5 m/s", "--incidence",
                          "0 deg", "--flat", values)  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["e"]["value"] == ref.e  # the same values, another name
    cfg = tmp_path / "case.toml"
    cfg.write_text(
        'vy = "-2.5 m/s"\n[flat]\nE = "68.9 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = 2700\n'
    )
    code, out, err = _cli(monkeypatch, capsys, *base, "--config", str(cfg))
    assert code == 0, err
    assert json.loads(out)["e"]["value"] == ref.e


def test_a_library_material_changed_in_python_loses_its_label() -> None:
    from dataclasses import replace

    m = replace(AISI_1010, E=69e9, yield_strength=276e6)
    assert m.name == "AISI 1010 low-carbon steel (paper's flat), modified (E, yield_strength)"
    assert m.source == "" and library_key(m) is None
    assert replace(AISI_1010) == AISI_1010  # unchanged: still the library's


def test_the_materials_command_shows_one_material(cli_main) -> None:
    """``impactlab materials NAME`` (a name or an alias) shows one entry in full; an unknown
    name suggests the nearest."""
    import json

    code, out, err = cli_main("materials", "6061-t6", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["key"] == "al-6061-t6" and data["condition"] == "T6 (T651)"
    code, _, err = cli_main("materials", "aisi-101")
    assert code == 2 and "did you mean 'aisi-1010'?" in err
