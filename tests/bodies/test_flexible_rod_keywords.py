"""``FlexibleRod`` called with a keyword it does not take names the nearest field, or what to
use instead (the command line's ``modes_axial``/``modes_bending``, a result's ``n_modes``), and
every field it takes, as ``simulate`` does; its signature and ``dataclasses.replace`` stay the
dataclass's."""

from __future__ import annotations

import dataclasses
import inspect
from typing import Any

import pytest

from impactlab.bodies import FlexibleRod

TAKES = (
    r"; it takes axial_residual, damping, diameter, geometric, length, mass, material, n_axial, "
    r"n_bending, theory, tip_radius$"
)


@pytest.mark.parametrize(
    ("given", "hint"),
    [
        ({"n_modes": 5}, r"n_modes \(give n_axial and n_bending; a DropResult's n_modes is "),
        ({"modes_axial": 16}, r"modes_axial \(use n_axial, the command line's --modes-axial\)"),
        ({"modes_bending": 16}, r"modes_bending \(use n_bending, the command line's "),
        ({"n_bendig": 16}, r"n_bendig \(did you mean 'n_bending'\?\)"),
        ({"dampng": 0.1}, r"dampng \(did you mean 'damping'\?\)"),
    ],
)
def test_a_wrong_keyword_names_what_to_use(given: dict[str, Any], hint: str) -> None:
    with pytest.raises(TypeError, match=rf"^FlexibleRod\(\) got unexpected keyword argument\(s\) "
                       rf"{hint}.*{TAKES}"):  # fmt: skip
        FlexibleRod.paper(**given)
    with pytest.raises(TypeError, match=hint):
        FlexibleRod(0.3, 0.008, mass=0.4, **given)


def test_the_class_keeps_its_signature_and_replace() -> None:
    params = list(inspect.signature(FlexibleRod).parameters)
    assert params == [f.name for f in dataclasses.fields(FlexibleRod)]
    rod = FlexibleRod.paper(n_bending=6)
    assert dataclasses.replace(rod, damping=0.1).damping == 0.1
    assert FlexibleRod(**{f.name: getattr(rod, f.name) for f in dataclasses.fields(rod)}) == rod
    with pytest.raises(TypeError, match=r"n_modes \(give n_axial"):
        dataclasses.replace(rod, n_modes=3)  # type: ignore[call-arg]
