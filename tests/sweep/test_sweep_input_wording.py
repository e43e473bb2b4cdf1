"""The wording of refused study inputs and damaged metadata: a lognormal's sigma is
dimensionless (no unit in its message), a bare angle that reads as degrees gets the hint that
``simulate`` gives, and a JSON error names its position once."""

from __future__ import annotations

import math

import pytest

from impactlab.sweep import CorruptStoreError, Study, open_sweep, run_sweep
from impactlab.sweep.distributions import distribution_from_dict
from impactlab.units import magnitude

_VY_MU = {"vy": -1.41, "mu": 0.2}


def _lognormal(**params: object) -> None:
    def convert(value: object, key: str) -> float:
        return float(magnitude(key, value, "rad"))

    distribution_from_dict({"dist": "lognormal", **params}, convert, "angle")


@pytest.mark.parametrize("sigma", [-0.1, math.nan])
def test_a_lognormal_sigma_has_no_unit(sigma: float) -> None:
    with pytest.raises(ValueError, match="sample input 'angle': sigma must be") as caught:
        _lognormal(median="20 deg", sigma=sigma)
    assert "rad" not in str(caught.value)


def test_a_lognormal_without_probability_is_said_in_its_values() -> None:
    with pytest.raises(ValueError, match="no probability") as caught:
        _lognormal(median="20 deg", sigma=0.01, low="50 deg", high="60 deg")
    assert str(caught.value) == (
        "sample input 'angle': lognormal distribution (median=0.349066, sigma=0.01) has no "
        "probability in [low, high] = [0.872665, 1.0472] (in rad, the input's SI unit)"
    )


def test_a_bare_grid_angle_in_degrees_gets_the_hint() -> None:
    with pytest.raises(ValueError, match="meant in degrees") as caught:
        Study(grid={"angle": [10, 20]}, fixed=_VY_MU)
    assert str(caught.value) == (
        "grid dimension 'angle': angle must lie in (0, 90] deg, got 572.96, 1145.9 deg "
        "(2 of 2 values); if 10.0 is meant in degrees, pass math.radians(10.0) = 0.174533 rad "
        "or the string '10 deg'"
    )


def test_a_bare_fixed_angle_in_degrees_gets_the_hint() -> None:
    with pytest.raises(ValueError, match=r"^input 'angle': angle must lie in \(0, 90\] deg") as e:
        Study(grid={"mu": [0.1, 0.2]}, fixed={"vy": -1.41, "angle": 20})
    assert str(e.value).endswith(
        "; if 20.0 is meant in degrees, pass math.radians(20.0) = 0.349066 rad or the string "
        "'20 deg'"
    )


@pytest.mark.parametrize("angle", ["600 deg", 120.0, 1.7])
def test_no_degrees_hint_where_none_is_meant(angle: object) -> None:
    # a unit given (600 deg is what it says), a number past 90, one just past the normal
    with pytest.raises(ValueError, match="angle must lie in") as caught:
        Study(grid={"angle": [0.3, angle]}, fixed=_VY_MU)
    assert "meant in degrees" not in str(caught.value)


def test_a_json_error_names_its_position_once(tmp_path, fake) -> None:
    path = tmp_path / "s.zarr"
    study = Study(name="s", grid={"angle": [0.3, 0.5]}, fixed=_VY_MU)
    run_sweep(study, path, evaluator=fake, quiet=True)
    (path / "e" / "zarr.json").write_bytes(b'{"x": "\x01"}')
    with pytest.raises(CorruptStoreError) as caught:
        open_sweep(path)
    assert "(Invalid control character at line 1, column 8)" in str(caught.value)
    assert " at at " not in str(caught.value)
