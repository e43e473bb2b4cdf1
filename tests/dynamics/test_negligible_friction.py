"""A friction coefficient below ``MU_NEGLIGIBLE`` (1e-9) runs frictionless: the stick/slip
switches of so small a friction force are decided by round-off (found by hypothesis: Mindlin,
mu = 1e-14, the contact point starting at rest, failed with "too many switches"), and the
friction force, below 1e-9 of the normal force, moves no output beyond the tolerance."""

from __future__ import annotations

import math
import warnings

import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD
from impactlab.dynamics import simulate
from impactlab.dynamics.kernels.layout import MU_NEGLIGIBLE

KW = {"law": "hertz", "angle": 1.0, "velocity": (0.0, -1.0), "history": False}
OUTPUTS = ("e", "e_energy", "delta_max", "delta_p", "duration", "max_force", "normal_impulse")


#: The warning of a reference run at mu = 0 with a friction model: expected there.
UNUSED_MODEL = "ignore:friction = .* with mu = 0 is frictionless"


@pytest.mark.filterwarnings(UNUSED_MODEL)
@pytest.mark.parametrize("friction", ["mindlin", "coulomb", "impulse_ratio", "partial_slip"])
@pytest.mark.parametrize("mu", [1e-14, 1e-11, 0.5 * MU_NEGLIGIBLE])
def test_negligible_friction_runs_frictionless(friction: str, mu: float) -> None:
    r = simulate(PAPER_ROD, friction=friction, mu=mu, **KW)
    ref = simulate(PAPER_ROD, friction=friction, mu=0.0, **KW)
    assert r.regime == "frictionless"
    for k in OUTPUTS:
        assert getattr(r, k) == getattr(ref, k), k


@pytest.mark.filterwarnings(UNUSED_MODEL)
@pytest.mark.parametrize("friction", ["mindlin", "coulomb"])
def test_small_friction_above_the_threshold_is_kept(friction: str) -> None:
    """2e-9 still runs with friction; its outputs lie within ~mu of the frictionless ones."""
    r = simulate(PAPER_ROD, friction=friction, mu=2.0 * MU_NEGLIGIBLE, **KW)
    ref = simulate(PAPER_ROD, friction=friction, mu=0.0, **KW)
    assert r.regime != "frictionless"
    for k in OUTPUTS:
        assert getattr(r, k) == pytest.approx(getattr(ref, k), rel=1e-6, abs=1e-15), k


@pytest.mark.parametrize("angle", [0.3, 0.7, 1.0, 1.4])
def test_mindlin_at_rest_with_tiny_friction_does_not_chatter(angle: float) -> None:
    kw = {**KW, "angle": angle, "law": "ghaednia"}
    r = simulate(PAPER_ROD, friction="mindlin", mu=1e-12, **kw)
    assert math.isfinite(r.e)


@pytest.mark.filterwarnings(UNUSED_MODEL)
@pytest.mark.parametrize("friction", ["mindlin", "partial_slip"])
def test_drop_with_negligible_friction_runs_frictionless(friction: str) -> None:
    """The drop integrator applies the same rule (it chattered at mu = 1e-14, Mindlin)."""
    from impactlab.dynamics.drop import simulate_drop

    kw = {"law": "hertz", "angle": 1.0, "velocity": (0.0, -1.0)}
    r = simulate_drop(PAPER_ROD, friction=friction, mu=1e-14, **kw)
    ref = simulate_drop(PAPER_ROD, friction=friction, mu=0.0, **kw)
    for k in ("e", "delta_max", "dent_depth", "sequence_duration", "max_force"):
        assert getattr(r, k) == getattr(ref, k), k


@pytest.mark.parametrize("friction", ["mindlin", "partial_slip", "impulse_ratio"])
def test_a_friction_model_without_mu_warns_that_it_is_unused(friction: str) -> None:
    """mu's default is 0: `--friction mindlin` without `--mu` ran frictionless without a word."""
    with pytest.warns(il.ImplausibleInputWarning, match=f"friction = '{friction}' with mu = 0"):
        r = il.simulate(il.Rod.paper(), friction=friction, angle=0.8, velocity=(0.0, -1.41))
    assert r.regime == "frictionless"


def test_coulomb_without_mu_stays_silent() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        il.simulate(il.Rod.paper(), angle=0.8, velocity=(0.0, -1.41))


def test_a_drop_with_a_friction_model_without_mu_warns_too() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match="friction = 'mindlin' with mu = 0"):
        il.simulate_drop(il.FlexibleRod.paper(), friction="mindlin", angle=0.8,
                         velocity=(0.0, -1.41), history=False)  # fmt: skip
