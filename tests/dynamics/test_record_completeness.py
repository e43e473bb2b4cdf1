"""A result's record reruns only as it was written: a record that lacks a key is refused, naming
it (never run on a default), one of another impactlab version warns naming both versions, a
malformed velocity or a body without a required size is named with the form expected; a
result's ``to_dict()`` is strict JSON; a saved batch says what was simulated."""

from __future__ import annotations

import copy
import dataclasses
import json
import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.export import batch_setup
from impactlab.dynamics.provenance import KEYS, SIMULATE, SIMULATE_DROP, RecordVersionWarning
from impactlab.materials import AISI_1010


@pytest.fixture(scope="module")
def impact() -> dict[str, Any]:
    """A rod's impact as its JSON reads back (``--json``, ``json.dump(r.to_dict())``)."""
    r = il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    return json.loads(json.dumps(r.to_dict()))  # type: ignore[no-any-return]


@pytest.fixture(scope="module")
def drop() -> dict[str, Any]:
    r = il.simulate_drop(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    return json.loads(json.dumps(r.to_dict()))  # type: ignore[no-any-return]


def _without(record: dict[str, Any], key: str) -> dict[str, Any]:
    out = copy.deepcopy(record)
    del out["input"][key]
    return out


#: The keys whose absence a rerun would fill with a default (body, flat, law and velocity: not
#: a record at all, refused as such)
DEFAULTED = [k for k in KEYS[SIMULATE] if k not in ("body", "flat", "law", "velocity")]


@pytest.mark.parametrize("key", DEFAULTED)
def test_an_impact_record_without_a_key_is_refused_naming_it(
    impact: dict[str, Any], key: str
) -> None:
    with pytest.raises(ValueError, match=f"lacks '{key}'") as err:
        il.rerun(_without(impact, key))
    assert "default" in str(err.value)


@pytest.mark.parametrize("key", ["rate", "stop", "time_limit", "gravity", "rtol", "mu"])
def test_a_drop_record_without_a_key_is_refused_naming_it(drop: dict[str, Any], key: str) -> None:
    assert key in KEYS[SIMULATE_DROP]
    with pytest.raises(ValueError, match=f"lacks '{key}'"):
        il.rerun(_without(drop, key))


def test_a_quantity_that_is_missing_is_named_with_its_form(impact: dict[str, Any]) -> None:
    with pytest.raises(ValueError, match=r"'mu' \(\{\"value\": \.\.\., \"unit\": \"1\"\}\)"):
        il.rerun(_without(impact, "mu"))


def test_the_complete_record_still_reruns_bit_for_bit(impact: dict[str, Any]) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", RecordVersionWarning)  # its own version: no warning
        again = il.rerun(impact)
    assert again.sliding_length == impact["sliding_length"]
    assert again.e == impact["e"]


def test_a_record_of_another_version_warns_naming_both(impact: dict[str, Any]) -> None:
    old = copy.deepcopy(impact)
    old["impactlab_version"] = old["input"]["impactlab_version"] = "0.9.0"
    with pytest.warns(RecordVersionWarning, match="0.9.0") as caught:
        again = il.rerun(old)
    assert il.__version__ in str(caught[0].message)
    assert again.e == impact["e"]  # it runs: the numbers are this version's


def test_a_record_naming_no_version_warns(impact: dict[str, Any]) -> None:
    bare = copy.deepcopy(impact)
    del bare["impactlab_version"], bare["input"]["impactlab_version"]
    with pytest.warns(RecordVersionWarning, match="names no impactlab_version"):
        il.rerun(bare)


@pytest.mark.parametrize(
    "velocity", [{"value": -1.41, "unit": "m/s"}, None, "fast"], ids=["scalar", "null", "text"]
)
def test_a_velocity_that_is_no_pair_is_named_with_its_form(
    impact: dict[str, Any], velocity: Any
) -> None:
    bad = copy.deepcopy(impact)
    bad["input"]["velocity"] = velocity
    with pytest.raises(ValueError, match=r"velocity .* is not a pair .*\[vx, vy\]"):
        il.rerun(bad)


def test_a_body_without_a_required_size_names_it_and_its_unit(impact: dict[str, Any]) -> None:
    bad = copy.deepcopy(impact)
    del bad["input"]["body"]["tip_radius"]
    with pytest.raises(ValueError, match=r"Rod lacks 'tip_radius' .*\"unit\": \"m\""):
        il.rerun(bad)


def test_to_dict_is_strict_json_for_a_law_without_a_verified_range() -> None:
    r = il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), law="tabulated")
    assert math.isinf(r.fitted_delta_ratio_max)
    d = r.to_dict()
    assert d["fitted_delta_ratio_max"] is None
    text = json.dumps(d, allow_nan=False)  # no Infinity, no NaN
    assert il.rerun(json.loads(text)).e == r.e


def test_a_saved_batch_says_what_was_simulated(tmp_path: Path) -> None:
    rod = il.Rod.paper()
    b = il.simulate_batch(rod, angle=0.35, vy=np.array([-1.0, -1.4]), mu=0.2, gravity=False)
    assert b.to_xarray().attrs["impactlab_version"] == il.__version__
    setup = batch_setup(rod, AISI_1010, friction="coulomb", gravity=False, rtol=None,
                        constant_angle=False, law="ghaednia",
                        law_params={"published_switch": 1})  # fmt: skip
    ds = dataclasses.replace(b, setup=setup).to_xarray()
    attrs = ds.attrs
    assert attrs["flat"] == AISI_1010.name and attrs["body"].startswith("Rod")
    assert attrs["gravity"] == 0.0 and attrs["constant_angle"] == 0
    assert attrs["rtol"] > 0
    assert json.loads(attrs["body_record"])["tip_radius"] == {"value": 0.0088, "unit": "m"}
    assert json.loads(attrs["flat_record"])["name"] == AISI_1010.name
    assert json.loads(attrs["law_params"]) == {"published_switch": {"value": 1.0, "unit": "1"}}
    path = tmp_path / "batch.nc"
    ds.to_netcdf(path)  # every attribute is a string or a number netCDF stores
    import xarray as xr

    with xr.open_dataset(path) as back:
        assert back.attrs["body_record"] == attrs["body_record"]
        assert back.attrs["impactlab_version"] == il.__version__
