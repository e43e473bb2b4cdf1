"""A Material's numbers as its text inputs take them: a Brinell hardness with its symbol
(``"95 HB"``), NaN of any float type as an unset hardness, a number beyond a float's range
refused naming its parameter; an angle in percent is no angle; a misspelt aluminium is
suggested the aluminium, not the alumina."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from impactlab import Material
from impactlab.materials import get_material
from impactlab.materials.library import AL_6061_T6
from impactlab.units import angle_to_rad

STEEL = dict(name="x", E=200e9, nu=0.3, yield_strength=300e6, density=7800.0)


@pytest.mark.parametrize("hb", ["95 HB", "95 HBW", "HBW 95", "95 kgf/mm^2"])
def test_the_constructor_takes_the_brinell_symbol(hb: str) -> None:
    assert Material(**STEEL, brinell_hardness=hb).brinell_hardness == 95.0  # type: ignore[arg-type]


@pytest.mark.parametrize("nan", [math.nan, np.float64("nan"), np.float32("nan"), np.float16("nan")])
def test_a_nan_hardness_of_any_float_type_is_unset(nan: float) -> None:
    m = Material(**STEEL, brinell_hardness=nan)  # type: ignore[arg-type]
    assert not m.has_hardness and type(m.brinell_hardness) is float
    assert m == Material(**STEEL)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("field", "unit"),
    [
        ("E", " in Pa"),
        ("yield_strength", " in Pa"),
        ("density", " in kg/m^3"),
        ("brinell_hardness", " in kgf/mm^2"),
        ("nu", ""),
        ("meyer_index", ""),
    ],
)
def test_a_number_beyond_a_float_names_its_parameter(field: str, unit: str) -> None:
    start = re.escape(f"{field} must be a finite number{unit}, got ")
    with pytest.raises(ValueError, match=start) as err:
        Material(**{**STEEL, field: 10**400})  # type: ignore[arg-type]
    assert str(err.value).endswith(
        "got 100000000000... (401 characters): beyond the largest float, about 1.8e308"
    )


@pytest.mark.parametrize("text", ["20 %", "20 percent", "20 ppm"])
def test_percent_is_no_angle(text: str) -> None:
    with pytest.raises(ValueError, match="is not an angle") as err:
        angle_to_rad(text)
    assert str(err.value).startswith(f"angle: '{text}' is not an angle (its unit is ")
    assert "a ratio's, not an angle's); give deg, rad, turn or arcmin" in str(err.value)
    assert "has no unit" not in str(err.value)


@pytest.mark.parametrize("typed", ["alumnium", "aluminim", "aluminum", "Aluminium"])
def test_a_misspelt_aluminium_is_the_aluminium(typed: str) -> None:
    with pytest.raises(ValueError, match=rf"unknown material '{typed}' \(did you mean "):
        get_material(typed)
    with pytest.raises(ValueError, match=r"\(did you mean 'al-6061-t6'\?\)"):
        get_material(typed)


def test_a_beginning_of_several_names_lists_them() -> None:
    with pytest.raises(ValueError, match="did you mean") as err:
        get_material("alu")
    assert (
        "unknown material 'alu' (did you mean 'al-6061-t6' (aluminium 6061-T6) or "
        "'alumina-99.5' (alumina 99.5 %)?)"
    ) in str(err.value)
    assert get_material("alumina").name == "alumina 99.5 %"  # an alias: found as before
    assert AL_6061_T6.name == "aluminium 6061-T6"


def test_the_command_line_suggests_the_aluminium(cli_main) -> None:
    code, _, err = cli_main(
        "simulate", "sphere", "--radius", "5 mm", "--vy", "-1 m/s", "--flat", "alumnium"
    )
    assert code == 2
    assert "--flat: unknown material 'alumnium' (did you mean 'al-6061-t6'?)" in err


def test_a_yield_strain_beyond_any_solid_warns() -> None:
    """E=690MPa (69 GPa meant) with Sy=276MPa ran silently as plain success."""
    import warnings

    from impactlab import ImplausibleInputWarning, Material

    with pytest.warns(ImplausibleInputWarning, match=r"is 0\.4 of E .* one of them in another"):
        Material("slip", 690e6, 0.33, 276e6)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Material("pmma-like", 3.1e9, 0.35, 0.124e9)  # 0.04: a polymer
