"""The warning for an appended drop that names no material takes that drop by its label, not
by its place: in the drops an append returns, another process's drop may come after it."""

from __future__ import annotations

from types import SimpleNamespace

from impactlab.calibrate.experiment_rows import _default_materials


def test_the_new_drop_is_found_by_its_label() -> None:
    meas = SimpleNamespace(
        labels=("new", "other"),
        categories=[{"flat_material": "aisi-1010"}, {"flat_material": "al-6061"}],
        n_drops=2,
    )
    (text,) = _default_materials(meas, {"label": "new"}, "new")  # type: ignore[arg-type]
    assert text.startswith(
        "drop 'new' names no material of the flat and takes the default aisi-1010, while "
        "earlier drops name al-6061:"
    )


def test_one_drop_or_a_named_material_gives_no_warning() -> None:
    one = SimpleNamespace(labels=("new",), categories=[{"flat_material": "aisi-1010"}], n_drops=1)
    assert _default_materials(one, {"label": "new"}, "new") == []  # type: ignore[arg-type]
    two = SimpleNamespace(
        labels=("new", "other"),
        categories=[{"flat_material": "al-6061"}, {"flat_material": "aisi-1010"}],
        n_drops=2,
    )
    rec = {"label": "new", "flat_material": "al-6061"}
    assert _default_materials(two, rec, "new") == []  # type: ignore[arg-type]
