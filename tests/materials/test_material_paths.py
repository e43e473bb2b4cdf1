"""A path given where a material is expected, which is not a TOML file, is named as a path
(a folder, a file of another kind), not taken for an unknown library name."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab import get_material


def test_a_folder_is_named_a_folder(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"flat: '.*' is a folder; give a material's name"):
        get_material(str(tmp_path), "flat")


def test_a_file_of_another_kind_is_named(tmp_path: Path) -> None:
    f = tmp_path / "steel.txt"
    f.write_text("E=200GPa", encoding="utf-8")
    with pytest.raises(ValueError, match=r"is a file whose name does not end in \.toml"):
        get_material(str(f))


def test_a_name_that_is_not_a_path_is_an_unknown_material() -> None:
    with pytest.raises(ValueError, match="unknown material 'steell'"):
        get_material("steell")


def test_keys_beside_a_material_table_are_refused(tmp_path) -> None:
    """The top-level values beside [material] were dropped without a word."""
    from impactlab.materials import get_material

    f = tmp_path / "both.toml"
    f.write_text('HB = 105\n[material]\nE = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = 2700\n')
    with pytest.raises(ValueError, match=r"has key\(s\) HB beside its \[material\] table"):
        get_material(f)
