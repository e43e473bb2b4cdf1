"""A drop's time limit is ``time_limit`` (``t_max`` is the result field of the time of the
largest interference): ``t_max=``, its name before 0.3, still reads as ``time_limit`` in
``simulate_drop``, ``simulate_drops``, ``simulate`` of a FlexibleRod and ``rerun``, with a
DeprecationWarning at the caller's line and the same result; both given are refused naming
both; a record written with ``t_max`` reruns as recorded, without a word."""

from __future__ import annotations

import copy
import inspect
import json
import warnings
from typing import Any

import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop_checks import DropError
from impactlab.dynamics.time_limit import DEFAULT_TIME_LIMIT

FLEX = FlexibleRod.paper(n_axial=1, n_bending=2)
KW: dict[str, Any] = {"angle": 0.35, "velocity": (0.0, -1.41), "mu": 0.2, "history": False}
#: The deprecation's words: the old name, the new one.
RENAMED = r"keyword 't_max' is renamed 'time_limit'"


def _same(a: il.DropResult, b: il.DropResult) -> None:
    for name in ("e", "e_raw", "dent_depth", "delta_max", "n_contacts", "velocity_out"):
        assert getattr(a, name) == getattr(b, name), name


@pytest.fixture(scope="module")
def drop() -> il.DropResult:
    return il.simulate_drop(PAPER_ROD, **KW, stop="flight", time_limit=0.4)


def test_the_new_name_is_the_signatures() -> None:
    for function in (il.simulate_drop, il.simulate_drops):
        params = inspect.signature(function).parameters
        assert params["time_limit"].default == DEFAULT_TIME_LIMIT == 0.5
        assert "t_max" not in params


def test_simulate_drop_reads_t_max_as_time_limit_with_a_warning(drop: il.DropResult) -> None:
    with pytest.warns(DeprecationWarning, match=f"simulate_drop {RENAMED}") as said:
        old = il.simulate_drop(PAPER_ROD, **KW, stop="flight", t_max=0.4)
    assert [w.filename for w in said] == [__file__]  # at the caller's line
    _same(old, drop)
    assert old.input["time_limit"] == {"value": 0.4, "unit": "s"} and "t_max" not in old.input
    with pytest.warns(DeprecationWarning, match=RENAMED), pytest.raises(DropError) as err:
        il.simulate_drop(PAPER_ROD, **KW, t_max=1e-5)
    assert str(err.value).endswith(": raise time_limit")


@pytest.mark.parametrize("function", ["simulate_drop", "simulate_drops", "simulate", "rerun"])
def test_both_names_are_refused_naming_both(function: str, drop: il.DropResult) -> None:
    calls = {
        "simulate_drop": lambda: il.simulate_drop(PAPER_ROD, **KW, time_limit=1.0, t_max=1.0),
        "simulate_drops": lambda: il.simulate_drops(
            PAPER_ROD, angle=0.35, vy=-1.41, time_limit=1.0, t_max=1.0
        ),
        "simulate": lambda: il.simulate(FLEX, **KW, time_limit=1.0, t_max=1.0),
        "rerun": lambda: il.rerun(drop, time_limit=1.0, t_max=1.0),
    }
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # refused before any warning
        with pytest.raises(TypeError) as err:
            calls[function]()
    text = str(err.value)
    assert text.startswith(f"{function}() got time_limit= and t_max=, its name before 0.3")
    assert text.endswith("give time_limit only")


def test_simulate_drops_reads_t_max_and_its_setup_key() -> None:
    new = il.simulate_drops(PAPER_ROD, angle=0.35, vy=[-0.001, -1.41], time_limit=0.01)
    with pytest.warns(DeprecationWarning, match=f"simulate_drops {RENAMED}") as said:
        old = il.simulate_drops(PAPER_ROD, angle=0.35, vy=[-0.001, -1.41], t_max=0.01)
    assert [w.filename for w in said] == [__file__]
    assert old.messages == new.messages and old["e"][1] == new["e"][1]
    assert old.setup["time_limit"] == 0.01 and "t_max" not in old.setup
    assert "t_max" not in old.to_xarray().attrs
    with pytest.warns(DeprecationWarning, match="setup key 't_max' is renamed 'time_limit'"):
        assert old.setup["t_max"] == 0.01


def test_simulate_of_a_flexible_rod_reads_t_max() -> None:
    new = il.simulate(FLEX, **KW, stop="flight", time_limit=0.3)
    with pytest.warns(DeprecationWarning, match=f"simulate {RENAMED}") as said:
        old = il.simulate(FLEX, **KW, stop="flight", t_max=0.3)
    assert [w.filename for w in said] == [__file__]
    _same(old, new)
    with pytest.raises(TypeError, match="got t_max: options of a FlexibleRod's drop"):
        il.simulate(PAPER_ROD, **KW, t_max=0.3)


def test_rerun_reads_t_max(drop: il.DropResult) -> None:
    new = il.rerun(drop, time_limit=0.3)
    with pytest.warns(DeprecationWarning, match=f"rerun {RENAMED}") as said:
        old = il.rerun(drop, t_max=0.3)
    assert [w.filename for w in said] == [__file__]
    _same(old, new)
    assert old.input["time_limit"]["value"] == 0.3


def test_a_record_written_with_t_max_reruns_as_recorded(drop: il.DropResult) -> None:
    """A record of a version before 0.3 names the time limit t_max: read as time_limit, without
    a warning (the record was written by impactlab); one with both is refused."""
    d = json.loads(json.dumps(drop.to_dict()))
    old = copy.deepcopy(d)
    old["input"]["t_max"] = old["input"].pop("time_limit")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        again = il.rerun(old)
    _same(again, drop)
    assert again.input["time_limit"] == d["input"]["time_limit"]
    both = copy.deepcopy(d)
    both["input"]["t_max"] = both["input"]["time_limit"]
    with pytest.raises(ValueError, match=r"holds 'time_limit' and 't_max', its name before 0\.3"):
        il.rerun(both)


def test_the_old_constant_still_imports() -> None:
    with pytest.warns(DeprecationWarning, match="'DEFAULT_T_MAX' is renamed 'DEFAULT_TIME_LIMIT'"):
        from impactlab.dynamics.drop import DEFAULT_T_MAX
    assert DEFAULT_T_MAX == DEFAULT_TIME_LIMIT
    with pytest.raises(AttributeError):
        il.dynamics.drop.NO_SUCH_NAME  # noqa: B018
