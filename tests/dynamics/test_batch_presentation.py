"""How a batch and a one-impact result present themselves: the notebook summary counts as the
``repr`` and ``ok`` do (statistics over the ok cases alone), a batch of drops records what it
simulated and words a failed drop as ``simulate_drop`` does, the names of one quantity on both
sides are pointed to, ``to_dataframe`` and ``to_xarray`` hold the same columns, and a result
says the SI unit of each field."""

from __future__ import annotations

import inspect
import json
import math
import re

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics import BatchResult, DropBatchResult
from impactlab.dynamics.drop_checks import DropError
from impactlab.flags import ResultFlag

ROD = il.Rod.paper()
ANGLE = math.radians(20)


@pytest.fixture(scope="module")
def gain() -> BatchResult:
    """mu 0.9 with the impulse-ratio model gains energy (not ok); mu 0.2 is ok (advisory)."""
    return il.simulate_batch(ROD, friction="impulse_ratio", mu=[0.2, 0.9], angle=ANGLE, vy=-1.41)


@pytest.fixture(scope="module")
def drops() -> DropBatchResult:
    """One drop stopped by time_limit (it leaves the flat too slowly), one computed."""
    return il.simulate_drops(ROD, angle=0.35, vy=[-0.001, -1.41], time_limit=0.01)


def test_the_notebook_summary_counts_as_the_repr_and_ok(gain: BatchResult) -> None:
    assert gain.ok.tolist() == [True, False]
    assert gain.flags[1] & ResultFlag.ENERGY_GAIN
    html = gain._repr_html_()
    counts = "2 cases, 2 computed, 1 ok (1 marked: law extrapolated), 1 not ok (energy gain: 1)"
    assert counts in repr(gain) and f"<p>{counts}; " in html
    assert "over the 1 ok case;" in html and "2 ok" not in html
    # min = median = max: the energy-gaining case is left out of the statistics
    e = f"{gain.e[0]:.5g}"
    assert f"<tr><td>e</td><td>{e}</td><td>{e}</td><td>{e}</td>" in html


def test_a_drop_batch_summary_counts_as_its_repr(drops: DropBatchResult) -> None:
    html = drops._repr_html_()
    counts = "2 cases, 1 computed, 1 ok (1 marked: law extrapolated), 0 not ok"
    assert counts in repr(drops) and f"<p>{counts}; " in html and "over the 1 ok case;" in html


def test_a_drop_batch_records_what_it_simulated(gain: BatchResult, drops: DropBatchResult) -> None:
    attrs = drops.to_xarray().attrs
    assert attrs["impactlab_version"] == il.__version__
    assert attrs["flat"] == il.AISI_1010.name and attrs["body"] == drops.body
    body = json.loads(attrs["body_record"])
    assert body["type"] == "Rod" and body["mass"]["value"] == ROD.mass
    assert body["tip_radius"]["value"] == ROD.tip_radius and "material" in body
    assert json.loads(attrs["flat_record"])["name"] == il.AISI_1010.name
    assert (attrs["stop"], attrs["time_limit"]) == ("sequence", 0.01)
    assert attrs["rtol"] == drops.rtol and attrs["gravity"] == drops.gravity
    rigid = set(gain.to_xarray().attrs) - {"constant_angle", "source"}
    assert rigid <= set(attrs)  # the set-up attributes of BatchResult's
    assert dict(drops.setup) == {k: attrs[k] for k in drops.setup}


def test_a_failed_drop_of_a_batch_is_worded_as_simulate_drop_words_it(
    drops: DropBatchResult,
) -> None:
    with pytest.raises(DropError) as err:
        il.simulate_drop(ROD, angle=0.35, velocity=(0.0, -0.001), time_limit=0.01)
    single = str(err.value).removeprefix("drop: ")
    assert "steps" in single and "raise time_limit" in single
    assert drops.messages == [single, "ok"]


def test_the_names_of_one_quantity_are_pointed_to_on_both_sides(gain: BatchResult) -> None:
    with pytest.raises(AttributeError, match=r"velocity_in -> vx, vy\); its fields"):
        gain.velocity_in  # noqa: B018
    with pytest.raises(AttributeError, match=r"spin_in -> spin\)"):
        gain.spin_in  # noqa: B018
    r = il.simulate(ROD, angle=ANGLE, velocity=(0.0, -1.41), mu=0.2, history=False)
    for name, where in (("vx_out", "velocity_out[0]"), ("vy", "velocity_in[1]")):
        with pytest.raises(AttributeError, match=rf"{name} -> {re.escape(where)}"):
            getattr(r, name)
    d = il.simulate_drop(ROD, angle=0.35, velocity=(0.0, -1.41))
    with pytest.raises(AttributeError, match=r"vx_out -> velocity_out\[0\]"):
        d.vx_out  # noqa: B018
    assert getattr(r, "no_such_field", None) is None  # other names: a plain AttributeError


def test_diagnostics_that_are_not_computed_are_left_out(gain: BatchResult) -> None:
    for name in ("energy_rise", "friction_excess"):
        assert np.isnan(gain[name]).all()  # readable, never computed by simulate_batch
        assert name not in gain.to_dataframe().columns
        assert name not in gain.to_xarray().data_vars
        assert name not in gain.to_pint() and name not in dir(gain)


def test_dataframe_and_dataset_hold_the_same_columns(
    gain: BatchResult, drops: DropBatchResult
) -> None:
    for batch in (gain, drops):
        columns = list(batch.to_dataframe().columns)
        assert columns == list(batch.to_xarray().data_vars), type(batch).__name__
        assert columns[-2:] == ["max_delta_ratio", "status"] and "flags" in columns
    assert "initial_energy" in drops.to_dataframe().columns


def test_a_result_says_the_si_unit_of_each_field() -> None:
    r = il.simulate(ROD, angle=ANGLE, velocity=(0.0, -1.41), mu=0.2, history=False)
    d = il.simulate_drop(ROD, angle=0.35, velocity=(0.0, -1.41))
    assert r.units["duration"] == "s" and r.units["delta_p"] == "m"
    assert r.units["velocity_out"] == "m/s" and r.units["e"] == "1"
    assert d.units["sequence_duration"] == "s" and d.units["dent_depth"] == "m"
    assert " ms" in str(r) and " um" in str(r)  # the display's units; the values are SI
    for result in (r, d):
        numeric = [k for k, v in result.summary().items() if isinstance(v, float)]
        assert set(numeric) <= set(result.units), type(result).__name__
    assert "UNITS" not in (type(d).__doc__ or "").split("\n")[0]


def test_simulate_batch_documents_every_parameter_and_what_it_returns() -> None:
    doc = il.simulate_batch.__doc__ or ""
    missing = [n for n in inspect.signature(il.simulate_batch).parameters if f"``{n}``" not in doc]
    assert not missing and "Returns a ``BatchResult``" in doc
