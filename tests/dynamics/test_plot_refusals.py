"""The figures of one impact refuse what they cannot draw with a TypeError that names what was
passed and what each takes: a batch (no history: simulate the case with history), an
inversion (no simulation), anything else; a drop's refusal is still a ValueError too."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import pytest

import impactlab as il
from impactlab.dynamics import plotting

IMPACT_ONLY = (
    plotting.plot_force_time,
    plotting.plot_force_penetration,
    plotting.plot_contact_path,
)


@pytest.fixture(scope="module")
def batch() -> il.BatchResult:
    return il.simulate_batch(il.Rod.paper(), angle=[0.35, 0.4], vy=-1.41, mu=0.2)


@pytest.fixture(scope="module")
def drops() -> il.DropBatchResult:
    return il.simulate_drops(il.Rod.paper(), angle=[0.35, 0.4], vy=-1.41, mu=0.2)


@pytest.fixture(scope="module")
def inversion() -> Any:
    return il.invert(
        angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1400e-6
    )


@pytest.mark.parametrize("fn", [*IMPACT_ONLY, plotting.plot_dent, plotting.save_figures])
def test_a_batch_is_told_to_simulate_one_case(
    fn: Any, batch: Any, drops: Any, tmp_path: Path
) -> None:
    out = tmp_path / "figures"
    for result, one in ((batch, "impactlab.simulate("), (drops, "impactlab.simulate_drop(")):
        with pytest.raises(TypeError) as err:
            fn(result) if fn is not plotting.save_figures else fn(result, out)
        text = str(err.value)
        assert "\n" not in text and text.startswith(f"{fn.__name__} takes an ImpactResult")
        assert f"got a {type(result).__name__} of 2 cases (a batch keeps no history" in text
        assert "simulate one case with history to plot it" in text and one in text
        assert "law='ghaednia', friction='coulomb', mu=batch.mu[i]" in text
        assert "columns of result.history" not in text  # a batch has no history
    assert not out.exists()


def test_plot_dent_names_what_it_takes(inversion: Any) -> None:
    cases: tuple[tuple[Any, str], ...] = (
        (inversion, "an InversionResult (T and F inverted"),
        ({}, "a dict"),
    )
    for thing, what in cases:
        with pytest.raises(TypeError, match=re.escape(f"got {what}")) as err:
            plotting.plot_dent(thing)
        assert str(err.value).startswith("plot_dent takes an ImpactResult or a DropResult")
    with pytest.raises(TypeError, match="got an InversionResult"):
        plotting.plot_force_time(inversion)


def test_a_drop_is_refused_as_before() -> None:
    drop: Any = il.simulate_drop(il.Rod.paper(), angle=0.35, velocity=(0.0, -1.41), mu=0.2)
    with pytest.raises(ValueError, match="got a DropResult: plot_dent") as err:
        plotting.plot_force_time(drop)
    assert isinstance(err.value, TypeError)
