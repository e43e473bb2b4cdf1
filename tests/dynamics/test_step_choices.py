"""The step-size choices that avoid rejected steps: the step carried onto the
unloading branch at the turning point, the first step of the final approach in w, and the
opening through an early switch to the elastic-plastic curve (``ends.THROUGH_SWITCH``)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_accuracy import SAMPLE, TIGHT, relative_errors

from impactlab.bodies import PAPER_ROD
from impactlab.dynamics import simulate
from impactlab.dynamics.core.driver import _unloading_factor
from impactlab.dynamics.core.ends import OPENING, THROUGH_SWITCH
from impactlab.dynamics.kernels.layout import M_DM, M_DR, M_PHASE, NM


def _mode(phase: float, dm: float, dr: float) -> np.ndarray:
    md = np.zeros(NM)
    md[M_PHASE], md[M_DM], md[M_DR] = phase, dm, dr
    return md


def test_unloading_factor_is_one_without_a_dent() -> None:
    assert _unloading_factor(_mode(0.0, 0.0, 0.0)) == 1.0
    assert _unloading_factor(_mode(1.0, 1e-5, 0.0)) == 1.0


@pytest.mark.parametrize("ratio", [0.1, 0.5, 0.8, 0.95])
def test_unloading_factor_follows_the_stiffness_ratio(ratio: float) -> None:
    """sqrt(k_load / k_unload) with k_load <= 1.5 F_m / delta_m and k_unload = 1.5 F_m /
    (delta_m - delta_r); never below 0.2 (the controller's own lower bound)."""
    got = _unloading_factor(_mode(1.0, 2e-5, ratio * 2e-5))
    assert got == pytest.approx(math.sqrt(1.0 - ratio), rel=1e-12)


def test_unloading_factor_is_bounded_below() -> None:
    assert _unloading_factor(_mode(1.0, 2e-5, 2e-5)) == pytest.approx(0.2)


def test_sample_step_count() -> None:
    """The 60 seeded random impacts of the accuracy contract take 22.1 steps on average (23.8
    before these step choices; the errors are held by ``test_accuracy``): at most 22.7."""
    steps = []
    for body, kw in SAMPLE:
        try:
            steps.append(simulate(body, **kw, history=False).n_steps)
        except ValueError:
            continue
    assert np.mean(steps) <= 22.7, np.mean(steps)


def test_benchmark_steps_hold_without_history_and_with() -> None:
    kw = {"law": "ghaednia", "friction": "coulomb", "mu": 0.2, "angle": math.radians(20.0)}
    a = simulate(PAPER_ROD, **kw, velocity=(0.0, -1.41), history=False)
    b = simulate(PAPER_ROD, **kw, velocity=(0.0, -1.41), history=True)
    assert a.n_steps == b.n_steps <= 19


@pytest.mark.parametrize("law", ["ghaednia", "brake", "thornton", "jackson-green"])
@pytest.mark.parametrize("speed", [0.05, 0.3, 1.41, 6.0])
@pytest.mark.parametrize("friction", ["coulomb", "impulse_ratio", "mindlin"])
def test_opening_through_the_switch_holds_the_accuracy_contract(
    law: str, speed: float, friction: str
) -> None:
    """Switches from far below THROUGH_SWITCH of the opening (run through) to beyond the
    opening (an event of the time integration), every output within 1e-5 of rtol = 1e-11;
    Mindlin friction stops at the switch."""
    kw = {"law": law, "friction": friction, "mu": 0.3, "angle": math.radians(25.0)}
    vel = (0.4 * speed, -speed)
    r = simulate(PAPER_ROD, **kw, velocity=vel, history=False)
    ref = simulate(PAPER_ROD, **kw, velocity=vel, rtol=TIGHT, history=False)
    errors = relative_errors(r, ref)
    assert max(errors.values()) < 1e-5, errors


def test_through_switch_is_a_fraction_of_the_opening() -> None:
    assert 0.0 < THROUGH_SWITCH < 1.0
    assert 0.0 < OPENING < 1.0
