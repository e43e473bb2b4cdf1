"""``help(impactlab.get_material)`` documents what it accepts: the keys of a definition by
values (short and long names, with units), how to list the library's names, and an example
that runs."""

from __future__ import annotations

import doctest

import impactlab
from impactlab.materials import inputs

KEYS = ("E", "nu", "Sy", "S_y", "yield_strength", "rho", "density", "HB", "brinell_hardness",
        "n", "meyer_index", "name", "condition", "brittle")  # fmt: skip


def test_the_docstring_names_every_key_its_unit_and_the_library() -> None:
    doc = impactlab.get_material.__doc__ or ""
    for key in KEYS[:11]:
        assert f"``{key}``" in doc, key
    for unit in ("Pa", "kg/m^3", "kgf/mm^2"):
        assert unit in doc
    assert "impactlab.materials.PRESETS" in doc and "impactlab materials" in doc
    assert "Example::" in doc
    # every key the docstring names is one the reader accepts
    for key in KEYS:
        assert key.lower() in inputs.KEYS


def test_the_example_runs() -> None:
    finder = doctest.DocTestFinder()
    (test,) = [t for t in finder.find(inputs.get_material, "get_material") if t.examples]
    result = doctest.DocTestRunner().run(test)
    assert result.failed == 0 and result.attempted >= 2
