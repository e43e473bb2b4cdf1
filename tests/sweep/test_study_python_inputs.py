"""A Study built in Python takes what the rest of the Python API takes (text with units, pint
Quantities of any registry, scalars and arrays) and refuses, before anything is computed,
what a study file would refuse: an input that no body of the study has, the flexible rod's
inputs without it. The store keeps only what defines the cases."""

from __future__ import annotations

import math

import numpy as np
import pint
import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import EngineOptions, Study, run_sweep

Q = pint.UnitRegistry().Quantity  # a registry of the user's, not impactlab's


def test_quantities_are_converted_to_si() -> None:
    st = Study(name="q", grid={"angle": Q(np.array([20.0, 45.0]), "deg"),
                               "length": Q(np.array([300.0]), "mm")},
               fixed={"vy": "-1.41 m/s", "mu": 0.1, "tip_radius": Q(8.8, "mm"),
                      "mass": Q(450.0, "g")})  # fmt: skip
    d = st.to_dict()
    assert d["grid"]["angle"] == pytest.approx([math.radians(20), math.radians(45)])
    assert d["grid"]["length"] == [pytest.approx(0.3)]
    assert d["fixed"]["vy"] == -1.41 and d["fixed"]["tip_radius"] == pytest.approx(0.0088)
    same = Study(name="q", grid={"angle": ["20 deg", "45 deg"], "length": [0.3]},
                 fixed={"vy": -1.41, "mu": 0.1, "tip_radius": 0.0088, "mass": 0.45})  # fmt: skip
    assert same.hash() == st.hash()


@pytest.mark.parametrize(
    ("fixed", "message"),
    [
        ({"angle": "20"}, r"input 'angle' 20 has no unit: give a unit, e.g. '20 deg'"),
        ({"angle": 0.35, "vy": "-1,4 m/s"}, r"input 'vy': '-1,4 m/s' holds a comma"),
        ({"angle": 0.35, "vy": Q(-1.4, "deg")}, r"input 'vy'.*wrong dimension"),
    ],
)
def test_quantities_that_do_not_read_are_refused(fixed, message) -> None:
    args = {"vy": -1.41, "mu": 0.1} | fixed
    with pytest.raises(ValueError, match=message):
        Study(name="q", grid={"spin": [0.0, 1.0]}, fixed=args)


def test_a_sphere_radius_without_a_sphere_is_refused() -> None:
    with pytest.raises(ValueError, match=r"radius: the radius of a sphere.*tip_radius"):
        Study(name="r", grid={"angle": [0.35]}, fixed={"vy": -1.41, "mu": 0.2, "radius": 0.005})
    Study(name="r", grid={"body": ["rod", "sphere"]},
          fixed={"vy": -1.41, "mu": 0.2, "angle": 0.35, "radius": 0.005})  # fmt: skip


def test_flexible_inputs_are_checked_by_the_study_itself() -> None:
    with pytest.raises(ValueError, match="n_axial: inputs of a flexible rod"):
        Study(name="f", grid={"angle": [0.35]}, fixed={"vy": -1.41, "mu": 0.2, "n_axial": 2.0})
    with pytest.raises(ValueError, match="constant_angle = true"):
        Study(name="f", grid={"angle": [0.35]},
              fixed={"vy": -1.41, "mu": 0.2, "body": "flexible_rod"},
              engine=EngineOptions(constant_angle=True))  # fmt: skip


def test_speed_and_incidence_store_no_velocity_components(tmp_path) -> None:
    """vx and vy follow from speed and incidence case by case: their defaults (vx = 0) are not
    stored as if they were the cases' values."""
    st = Study(name="s", grid={"incidence": [0.0, 0.5]}, fixed={"speed": 2.0, "mu": 0.2,
                                                                "angle": 0.35})  # fmt: skip
    ds = run_sweep(st, tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True).dataset
    assert "vx" not in ds and "vy" not in ds
    assert float(ds["speed"]) == 2.0 and list(ds["incidence"].values) == [0.0, 0.5]


def test_a_material_fixed_by_values_that_is_none_is_refused() -> None:
    """Every case would fail (status 101) with exit 0: refused when the study is built."""
    with pytest.raises(ValueError, match=r"\[fixed\] flat_\*: yield_strength .* smaller than E"):
        Study(name="m", grid={"angle": [0.35, 0.5]},
              fixed={"vy": -1.41, "mu": 0.2, "flat_E": 200e6, "flat_nu": 0.3,
                     "flat_yield_strength": 305e6})  # fmt: skip
    Study(name="m", grid={"flat_E": [200e9, 210e9]},  # varied: checked case by case
          fixed={"angle": 0.35, "vy": -1.41, "mu": 0.2, "flat_nu": 0.3,
                 "flat_yield_strength": 305e6})  # fmt: skip
