"""``print(body)`` and ``print(material)``: one readable line in display units, while
``repr`` stays exact and rebuilds the object (equality, hashing, pickling unchanged): a
library material's is the call that gives it, ``get_material('aisi-201')``."""

from __future__ import annotations

import dataclasses
import pickle

import pytest

from impactlab.bodies import FlexibleRod, Rod, Sphere
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material, get_material


def test_rod_str_in_display_units() -> None:
    text = str(Rod.paper())
    assert text == (
        "Rod: length = 304.8 mm, tip_radius = 8.8 mm, mass = 0.4607 kg, "
        "inertia = 0.0035667 kg m^2, overall_length = 322.4 mm, "
        "material = AISI 201 stainless steel (paper's rod)"
    )


def test_sphere_str_shows_derived_inertia() -> None:
    text = str(Sphere(0.005, mass=0.004))
    assert text.startswith("Sphere: radius = 5 mm, mass = 0.004 kg, density = ")
    assert "inertia = 4e-8 kg m^2" in text and text.endswith("material = " + AISI_201.name)


def test_flexible_rod_str_leaves_out_unset_fields() -> None:
    text = str(FlexibleRod.paper())
    assert text.startswith("FlexibleRod: length = 304.8 mm, tip_radius = 8.8 mm")
    assert "n_bending = 12" in text and "diameter" not in text and "\n" not in text


def test_material_and_pair_str() -> None:
    assert str(AISI_1010) == (
        "Material AISI 1010 low-carbon steel (paper's flat): E = 200 GPa, nu = 0.3, "
        "yield_strength = 305 MPa, brinell_hardness = 105 kgf/mm^2, meyer_index = 2.2, "
        "density = 7870 kg/m^3"
    )
    bare = Material("x", 70e9, 0.33, 2.5e8)  # no Brinell hardness: left out, not "nan"
    assert "brinell" not in str(bare) and "nan" not in str(bare)
    text = str(ContactPair(AISI_201, AISI_1010))
    assert text.startswith("ContactPair: body = AISI 201") and "E_star = 109.89 GPa" in text
    assert text.endswith("yield_strength = 305 MPa")


_NAMES = {
    "Rod": Rod,
    "Material": Material,
    "ContactPair": ContactPair,
    "FlexibleRod": FlexibleRod,
    "get_material": get_material,
}
_MODIFIED = dataclasses.replace(AISI_1010, E=69e9)  # no longer the library's: every field


@pytest.mark.parametrize(
    "obj",
    [
        Rod.paper(),
        Sphere(0.01),
        AISI_201,
        _MODIFIED,
        Material("x", 70e9, 0.33, 2.5e8, 120.0),
        ContactPair(AISI_201, AISI_1010),
        FlexibleRod.paper(),
    ],
)
def test_repr_stays_exact(obj: object) -> None:
    text = repr(obj)
    library = obj == AISI_201
    call = "get_material" if library else type(obj).__name__
    assert text.startswith(f"{call}(") and text != str(obj)
    assert pickle.loads(pickle.dumps(obj)) == obj
    assert hash(pickle.loads(pickle.dumps(obj))) == hash(obj)
    if not isinstance(obj, Sphere):  # a Sphere's repr holds mass and density (derived)
        again = eval(text, dict(_NAMES))  # the repr rebuilds it
        assert again == obj and hash(again) == hash(obj)


def test_a_signature_shows_the_library_name() -> None:
    """``help(simulate)`` shows its default flat as the call that gives it, not every field."""
    import inspect

    from impactlab import simulate

    assert "flat: 'Material' = get_material('aisi-1010')" in str(inspect.signature(simulate))
    assert "material=get_material('aisi-201')," in repr(Rod.paper())
