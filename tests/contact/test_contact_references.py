"""Model registries keyed by enums, each member with its citation; references and DOIs."""

from __future__ import annotations

import pytest

from impactlab.contact import Law, get_law, law_names
from impactlab.friction import (
    DEFAULT_MU,
    FRICTION_IDS,
    PARTIAL_SLIP,
    FrictionKind,
    friction_names,
    get_friction,
)
from impactlab.materials import AISI_201, AISI_1010, ContactPair
from impactlab.references import PAPER, REFERENCES, Reference, cite, dois


def test_law_enum_matches_the_registry() -> None:
    assert law_names() == tuple(m.value for m in Law)
    assert Law.GHAEDNIA == "ghaednia"
    assert Law("jackson-green") is Law.JACKSON_GREEN
    for member in Law:
        law = get_law(member)
        assert law is get_law(str(member))
        assert law.law is member
        assert law.name == member.value and type(law.name) is str
        assert law.law_id == member.law_id


@pytest.mark.parametrize("name", law_names())
def test_every_law_and_model_carries_its_references(name: str) -> None:
    law = get_law(name)
    assert law.references and all(isinstance(r, Reference) for r in law.references)
    assert law.references == Law(name).references
    assert law.doi == law.references[0].doi
    model = law.build(ContactPair(AISI_201, AISI_1010), 8.8e-3)
    assert model.references == law.references
    assert law.describe()["references"][0]["doi"] == law.doi


def test_law_dois_are_the_cited_ones() -> None:
    assert get_law("brake").doi == "10.1016/j.ijsolstr.2015.02.019"
    assert get_law("hertz").doi == "10.1515/crll.1882.92.156"
    assert REFERENCES[PAPER] in get_law("ghaednia").references


def test_friction_kinds() -> None:
    assert DEFAULT_MU == 0.0
    assert friction_names() == tuple(m.value for m in FrictionKind)
    assert FrictionKind.COULOMB == "coulomb"
    for kind in FrictionKind:
        model = get_friction(kind)
        assert model is get_friction(str(kind))
        assert model.friction_id == FRICTION_IDS.get(kind, PARTIAL_SLIP) == kind.friction_id
        assert model.references == kind.references and model.references
    assert get_friction("coulomb").references[0].doi == "10.1017/CBO9780511626432"
    with pytest.raises(ValueError, match="known models: impulse_ratio"):
        get_friction("viscous")


def test_reference_registry() -> None:
    dp = REFERENCES["dormand-prince-1980"]
    assert dp.url == "https://doi.org/10.1016/0771-050X(80)90013-3"
    assert REFERENCES["shampine-1986"].doi == "10.1090/S0025-5718-1986-0815836-3"
    assert REFERENCES["jackson-green-2005"].confirmed
    assert not REFERENCES["ghaednia-2016-contact"].confirmed
    for key, ref in REFERENCES.items():
        assert ref.key == key
        if ref.doi:
            assert ref.url == f"https://doi.org/{ref.doi}"
        else:  # a handbook or a data sheet: where it was read, or nothing
            assert ref.url == "" or ref.url.startswith(("https://", "http://"))
    assert cite("hertz-1882", "johnson-1985")[1].key == "johnson-1985"
    with pytest.raises(ValueError, match="unknown reference"):
        cite("nobody-2099")
    refs = get_law("ghaednia").references + get_law("brake").references
    assert dois(refs).count("10.1007/s00419-015-1108-2") == 1
