"""A study file's range axis gives the decimal values the user writes (``0.3``, not
``0.30000000000000004``), the stop exactly as given, each value the SI value of that number in
its unit."""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import Study, run_sweep


def _axis(name: str, spec: str, **fixed) -> tuple[float, ...]:
    fixed = fixed or {"angle": "20 deg", "vy": -1.41, "mu": 0.2}
    table = {"fixed": fixed, "grid": {name: tomllib.loads(f"x = {spec}")["x"]}}
    return Study.from_dict(table).axes[0].values


@pytest.mark.parametrize(
    ("spec", "values"),
    [
        ("{ start = 0.0, stop = 0.7, step = 0.1 }", [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]),
        ("{ start = 0.0, stop = 0.7, num = 8 }", [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]),
        ("{ start = 0.7, stop = 0.1, step = -0.2 }", [0.7, 0.5, 0.3, 0.1]),
        ("{ start = 0.05, stop = 0.6, step = 0.1 }", [0.05, 0.15, 0.25, 0.35, 0.45, 0.55]),
        ("{ start = 0, stop = 1, num = 4 }", [0.0, 1 / 3, 2 / 3, 1.0]),
        ("{ start = 10, stop = 30, step = 10, unit = 'percent' }", [0.1, 0.2, 0.3]),
    ],
)
def test_mu_ranges_are_the_written_decimals(spec, values) -> None:
    assert list(_axis("mu", spec, angle="20 deg", vy=-1.41)) == values  # exactly, not approximately


@pytest.mark.parametrize(
    "spec",
    [
        "{ start = 10, stop = 80, step = 10, unit = 'deg' }",
        "{ start = '10 deg', stop = '80 deg', step = '10 deg' }",
        "{ start = 10, stop = 80, num = 8, unit = 'deg' }",
    ],
)
def test_angles_are_the_written_degrees(spec) -> None:
    got = _axis("angle", spec, mu=0.2, vy=-1.41)
    listed = _axis("angle", str([f"{a} deg" for a in range(10, 90, 10)]), mu=0.2, vy=-1.41)
    assert got == listed  # each value as "30 deg" written alone gives it


def test_other_units_and_a_stop_in_another_unit() -> None:
    assert _axis("tip_radius", "{ start = '0.3 mm', stop = '0.9 mm', step = '0.3 mm' }") == (
        _axis("tip_radius", "['0.3 mm', '0.6 mm', '0.9 mm']")
    )
    mixed = _axis("tip_radius", "{ start = '0.3 mm', stop = '0.0009 m', step = '0.3 mm' }")
    assert len(mixed) == 3 and mixed[-1] == 0.0009  # the stop as given
    assert math.isclose(mixed[1], 0.0006, rel_tol=1e-12)


def test_a_value_of_a_range_is_found_by_sel_and_is_its_case(tmp_path) -> None:
    table = {
        "study": {"name": "rng"},
        "fixed": {"angle": "20 deg", "vy": -1.41},
        "grid": {"mu": {"start": 0.0, "stop": 0.7, "step": 0.1}},
    }
    ds = run_sweep(Study.from_dict(table), tmp_path / "r.zarr", evaluator=FakeEvaluator(),
                   quiet=True).dataset  # fmt: skip
    assert float(ds.mu.sel(mu=0.3)) == 0.3 and float(ds.mu[-1]) == 0.7
    one = Study.from_dict({**table, "grid": {"mu": [0.6]}})
    alone = run_sweep(one, tmp_path / "one.zarr", evaluator=FakeEvaluator(), quiet=True).dataset
    np.testing.assert_array_equal(ds.e.sel(mu=0.6).values, alone.e.values[0])
