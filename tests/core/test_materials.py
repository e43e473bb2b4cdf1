"""Materials, pairs and presets: validation and hand-calculated values."""

from __future__ import annotations

import math
import re
import warnings

import pytest
from hypothesis import given
from hypothesis import strategies as st

from impactlab._validation import ImplausibleInputWarning
from impactlab.materials import (
    AISI_201,
    AISI_1010,
    ContactPair,
    Material,
    brinell_to_pa,
    get_material,
    reduced_modulus,
)


def test_paper_pair_reduced_modulus_by_hand() -> None:
    # Two steels, E = 200 GPa, nu = 0.3: E* = E / (2 (1 - nu^2)) = 200e9 / 1.82
    pair = ContactPair(AISI_201, AISI_1010)
    assert pair.E_star == pytest.approx(200e9 / 1.82, rel=1e-12)
    assert pair.yield_strength == 305e6  # the flat yields first
    assert pair.weaker is AISI_1010


def test_presets_carry_the_unit_corrections() -> None:
    assert AISI_201.yield_strength == 760e6  # printed "760 GPa" in Table 1
    assert AISI_201.brinell_hardness == 327.0  # kgf/mm^2, printed kgf/m^2
    assert AISI_1010.brinell_hardness == 105.0
    assert brinell_to_pa(105.0) == pytest.approx(105 * 9.80665e6)


def test_rigid_partner() -> None:
    assert reduced_modulus(AISI_1010) == pytest.approx(200e9 / 0.91)


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("E", -1.0),
        ("E", math.nan),
        ("nu", 0.5),
        ("nu", -1.0),
        ("yield_strength", 0.0),
        ("yield_strength", math.inf),
        ("brinell_hardness", -3.0),
        ("meyer_index", 2.0),
        ("density", -7800.0),
        ("name", ""),
    ],
)
def test_invalid_material_names_the_parameter(field: str, value: object) -> None:
    kwargs: dict[str, object] = dict(name="x", E=200e9, nu=0.3, yield_strength=300e6)
    kwargs[field] = value
    with pytest.raises(ValueError, match=field):
        Material(**kwargs)  # type: ignore[arg-type]


def test_yield_above_modulus_is_a_unit_error() -> None:
    with pytest.raises(ValueError, match="yield_strength"):
        Material(name="x", E=200e9, nu=0.3, yield_strength=760e9)


def test_unknown_preset_lists_known() -> None:
    with pytest.raises(ValueError, match="aisi-1010"):
        get_material("steel")


@given(
    E1=st.floats(1e9, 1e12),
    E2=st.floats(1e9, 1e12),
    n1=st.floats(-0.9, 0.49),
    n2=st.floats(-0.9, 0.49),
)
def test_reduced_modulus_symmetric_and_below_each(
    E1: float, E2: float, n1: float, n2: float
) -> None:
    a = Material(name="a", E=E1, nu=n1, yield_strength=1e6)
    b = Material(name="b", E=E2, nu=n2, yield_strength=1e6)
    es = reduced_modulus(a, b)
    assert es == pytest.approx(reduced_modulus(b, a), rel=1e-12)
    assert es < min(reduced_modulus(a), reduced_modulus(b))


def test_moduli_take_units_and_numbers_refuse_text() -> None:
    m = Material(
        "x", E="200 GPa", nu=0.3, yield_strength="305 MPa", brinell_hardness="105 kgf/mm^2"
    )
    assert (m.E, m.yield_strength, m.brinell_hardness) == pytest.approx((200e9, 305e6, 105.0))
    with pytest.raises(ValueError, match=r"nu must be a real number, got the string '0.3'"):
        Material("x", E=200e9, nu="0.3", yield_strength=305e6)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="E: the string '200e9' has no unit"):
        Material("x", E="200e9", nu=0.3, yield_strength=305e6)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="meyer_index must be a real number, got the bool True"):
        Material("x", E=200e9, nu=0.3, yield_strength=305e6, meyer_index=True)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "E=69GPa, nu=0.33, Sy=276, rho=2700kg/m^3, HB=95",
            "material Sy = 276 has no unit and is read in Pa: 276 Pa is below 10000 Pa, an "
            "implausible magnitude; give its unit, e.g. '276 MPa'",
        ),
        (
            "E=69, nu=0.33, Sy=276MPa, rho=2700",
            "material E = 69 has no unit and is read in Pa: 69 Pa is below 10000 Pa, an "
            "implausible magnitude; give its unit, e.g. '69 GPa'",
        ),
        (
            "E=69GPa, nu=0.33, Sy=276MPa, rho=2.7",
            "material rho = 2.7 has no unit and is read in kg/m^3: 2.7 kg/m^3 is below 5 "
            "kg/m^3, an implausible magnitude; give its unit, e.g. '2.7 g/cm^3'",
        ),
    ],
)
def test_a_bare_value_of_an_implausible_magnitude_is_refused(text: str, message: str) -> None:
    """``Sy=276`` in a definition by values is 276 Pa, a unit left out: refused, naming the
    unit to give (the rule of the calibration's measurements); SI numbers read as before."""
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        get_material(text)
    m = get_material("E=69e9, nu=0.33, Sy=276e6, rho=2700, HB=95")
    assert (m.E, m.yield_strength, m.density, m.brinell_hardness) == (69e9, 276e6, 2700.0, 95.0)


def test_a_material_of_implausible_values_warns() -> None:
    """Material(E=200, ...) in Pa (GPa meant) warns naming each value; plausible ones do not."""
    with pytest.warns(ImplausibleInputWarning) as record:
        Material("x", E=200, nu=0.3, yield_strength=30.0)
    texts = [str(w.message) for w in record]
    assert any("E = 200.0 Pa lies outside the plausible range" in t for t in texts)
    assert any("yield_strength = 30.0 Pa" in t for t in texts)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        Material("y", E=69e9, nu=0.33, yield_strength=276e6, density=2700.0)


def test_the_fe_rigid_stand_in_warns_nothing() -> None:
    """The FE's rigid sphere is a material 10^9 times stiffer than the flat on purpose."""
    from impactlab.fe.problem import Problem

    problem = Problem(AISI_1010, AISI_201, "rigid", 8.8e-3, 5e-6, (), (), 0.0, 1)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        assert problem.pair.E_star == pytest.approx(AISI_1010.E / (1 - AISI_1010.nu**2), rel=1e-8)
