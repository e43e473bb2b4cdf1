"""A sweep store records the resolved material values of every case (E, nu, S_y, hardness,
Meyer index, the body's density; body and flat), not only a library name: for a library
material, a grid of materials and a material given by values (``sweep.material_record``)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.materials import AISI_201, AISI_1010, AL_6061_T6, BRASS_C360
from impactlab.sweep import Study, open_sweep, run_sweep

KINEMATICS = {"angle": 0.5, "mu": 0.2}
BODY_FIELDS = ("E", "nu", "yield_strength", "brinell_hardness", "meyer_index", "density")
FLAT_FIELDS = BODY_FIELDS[:-1]  # the flat is massive: no density


def test_library_materials_are_stored_by_value(tmp_path, fake) -> None:
    st = Study(name="lib", fixed=KINEMATICS, grid={"vy": [-1.0, -2.0]})
    ds = open_sweep(run_sweep(st, tmp_path / "lib.zarr", evaluator=fake, quiet=True).path)
    for field in BODY_FIELDS:
        assert float(ds[f"body_{field}"]) == getattr(AISI_201, field), field
        assert "aisi-201" in ds[f"body_{field}"].attrs["resolved_from"]
    for field in FLAT_FIELDS:
        assert float(ds[f"flat_{field}"]) == getattr(AISI_1010, field), field
    assert "flat_density" not in ds.variables
    assert ds["body_E"].attrs["units"] == "Pa"
    table = ds[["e"]].to_dataframe()  # a CSV of the store has the values in every row
    assert (table["flat_yield_strength"] == AISI_1010.yield_strength).all()


def test_a_grid_of_materials_and_a_body_by_values(tmp_path, fake) -> None:
    body = {"body_E": 97e9, "body_nu": 0.31, "body_yield_strength": 310e6, "body_density": 8500.0}
    st = Study(
        name="mixed",
        fixed={**KINEMATICS, **body, "mass": 0.5},  # a rod of another material: its mass
        grid={"vy": [-1.0, -2.0], "flat_material": ["al-6061-t6", "brass-c360"]},
    )
    ds = open_sweep(run_sweep(st, tmp_path / "mixed.zarr", evaluator=fake, quiet=True).path)
    assert str(ds["body_material"].values) == "custom"
    for name, value in body.items():
        assert float(ds[name]) == value  # the given values, stored as the inputs
    assert math.isnan(float(ds["body_brinell_hardness"]))  # not set: recorded as NaN
    assert float(ds["body_meyer_index"]) == 2.2  # the default of a material by values
    assert ds["flat_E"].dims == ("flat_material",)
    np.testing.assert_array_equal(ds["flat_E"].values, [AL_6061_T6.E, BRASS_C360.E])
    hb = ds["flat_brinell_hardness"].values
    assert hb[0] == AL_6061_T6.brinell_hardness and math.isnan(hb[1])  # brass: not in source
    rows = ds[["e"]].to_dataframe().reset_index()
    brass = rows[rows["flat_material"] == "brass-c360"]
    assert len(brass) == 2 and (brass["flat_nu"] == BRASS_C360.nu).all()
    assert (rows["body_E"] == 97e9).all()


def test_a_flat_by_values_on_the_grid_keeps_its_own_values(tmp_path, fake) -> None:
    flat = {"flat_nu": 0.33, "flat_yield_strength": 276e6}
    st = Study(name="f", fixed={**KINEMATICS, **flat, "vy": -1.0},
               grid={"flat_E": [69e9, 70e9]})  # fmt: skip
    ds = open_sweep(run_sweep(st, tmp_path / "f.zarr", evaluator=fake, quiet=True).path)
    np.testing.assert_array_equal(ds["flat_E"].values, [69e9, 70e9])
    assert "resolved_from" not in ds["flat_E"].attrs  # the input itself
    assert float(ds["flat_meyer_index"]) == 2.2 and math.isnan(float(ds["flat_brinell_hardness"]))
    assert float(ds["body_E"]) == AISI_201.E


@pytest.mark.parametrize("side", ["body", "flat"])
def test_every_property_of_a_side_is_in_the_store(tmp_path, fake, side) -> None:
    st = Study(name="s", fixed=KINEMATICS, grid={"vy": [-1.0]})
    ds = open_sweep(run_sweep(st, tmp_path / f"{side}.zarr", evaluator=fake, quiet=True).path)
    fields = BODY_FIELDS if side == "body" else FLAT_FIELDS
    assert all(f"{side}_{f}" in ds.coords for f in fields)
