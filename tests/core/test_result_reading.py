"""What a result gives a user who reads it: a wrong history column names the columns, and a
sphere's result is strict JSON (it has no angle: left out, not NaN)."""

from __future__ import annotations

import pytest

import impactlab as il


def test_a_history_names_its_columns_for_a_wrong_one() -> None:
    r = il.simulate(il.Rod.paper(), angle=0.35, velocity=(0.0, -1.41))
    with pytest.raises(AttributeError, match=r"no attribute 'force'; columns: t, penetration"):
        r.history.force  # noqa: B018
    assert not hasattr(r.history, "force")


def test_a_spheres_result_is_strict_json() -> None:
    """A sphere has no angle: left out of ``to_dict`` (as by ``simulate --json``), not NaN
    (which strict JSON refuses); its ``input`` records the angle as None."""
    import json

    r = il.simulate(il.Sphere(radius=0.005), velocity=(0.3, -1.0), mu=0.2)
    d = r.to_dict()
    assert "angle" not in d and "angle_out" not in d and d["input"]["angle"] is None
    json.dumps(d, allow_nan=False)
    assert il.rerun(d).e == r.e
