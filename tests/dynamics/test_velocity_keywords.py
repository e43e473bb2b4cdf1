"""A velocity given in a batch's form (``vx=``, ``vy=``) to a one-impact function: simulate,
simulate_drop and rerun say, in the one sentence of ``keyword_hints.split_velocity``, that they
take it as one pair, ``velocity=(vx, vy)``; rerun gives the recorded pair it would replace."""

from __future__ import annotations

import re

import pytest

import impactlab as il
from impactlab.dynamics.keyword_hints import split_velocity

PAIR = "takes the velocity as one pair, velocity=(vx, vy) [m/s], not "


def test_simulate_drop_explains_as_simulate_does() -> None:
    with pytest.raises(ValueError, match="simulate_drop takes") as drop:
        il.simulate_drop(il.FlexibleRod.paper(), angle=0.35, vy=-1.41)
    assert str(drop.value) == split_velocity("simulate_drop", ["vy"], "simulate_drops")
    assert str(drop.value).startswith(f"simulate_drop {PAIR}vy= ")
    with pytest.raises(ValueError, match="simulate takes") as rigid:
        il.simulate(il.Rod.paper(), angle=0.35, vy=-1.41)
    assert str(rigid.value) == split_velocity("simulate", ["vy"])
    with pytest.raises(ValueError, match=re.escape(f"{PAIR}vx= and vy= ")):
        il.simulate_drop(il.Rod.paper(), angle=0.35, vx=0.1, vy=-1.41)
    with pytest.raises(TypeError, match=r"unexpected keyword argument\(s\) vz; it takes "):
        il.simulate_drop(il.Rod.paper(), angle=0.35, vz=-1.41)  # type: ignore[call-arg]


def test_rerun_says_velocity_replaces_the_recorded_one() -> None:
    r = il.simulate(il.Rod.paper(), angle=0.35, velocity=(0.0, -1.41), history=False)
    with pytest.raises(ValueError, match="rerun takes") as err:
        il.rerun(r, vy=-2.0)
    assert str(err.value) == (
        f"{split_velocity('rerun', ['vy'])}: velocity=(vx, vy) replaces the recorded velocity "
        "(0, -1.41) m/s"
    )
    drop = il.simulate_drop(il.Rod.paper(), angle=0.35, velocity=(0.1, -1.41), history=False)
    with pytest.raises(ValueError, match=r"simulate_drops\): .* recorded velocity \(0.1, -1.41\)"):
        il.rerun(drop.to_dict(), vx=0.2, vy=-2.0)
    again = il.rerun(r, velocity=(0.0, -2.0)).input
    assert again is not None and again["velocity"]["value"] == [0.0, -2.0]
