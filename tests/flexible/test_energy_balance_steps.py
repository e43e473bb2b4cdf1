"""The energy balance's bound grows with the run's steps (docs/flexible.md, "Refused
results"): the error control is local, so a long stop="flight" run of a slender rod drifts in
proportion to rtol times its steps; such a run passes at the default rtol and tighter (up to
the ceiling of 1e-3 of its energy scale, tests/flexible/test_drop_rtol_cap.py), an error that
is no integration error is still refused, the paper's rod's short runs keep the fixed 100 rtol, and
the refusal gives its numbers and advice that holds."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest
from energy_balances import CLOSED

from impactlab.bodies import FlexibleRod
from impactlab.dynamics import drop_run as drop_module
from impactlab.dynamics.drop import DropError, simulate_drop
from impactlab.dynamics.drop_checks import (
    ENERGY_STEP_FACTOR,
    check_energy_balance,
    energy_balance_bound,
    inaccurate_cases,
)
from impactlab.dynamics.flexcore import layout as F
from impactlab.flags import ENERGY_GAIN_RTOL_FACTOR, ENERGY_ROUNDOFF, ResultFlag

#: A 4 mm rod dropped for the whole flight (2 s): 10,000-47,000 steps, 95-167 rtol of drift.
THIN = FlexibleRod(length=0.3048, tip_radius=0.0088, diameter=0.004)
THIN_DROP: dict[str, Any] = {
    "angle": math.radians(26.27),
    "velocity": (0.14, -1.725),
    "mu": 0.276,
    "stop": "flight",
    "time_limit": 2.0,
    "history": False,
}


@pytest.mark.parametrize("rtol", [1e-7, 1e-8])
def test_a_long_flight_of_a_slender_rod_passes(rtol: float) -> None:
    """Refused before at rtol 1e-7 and 1e-8 (122 and 163 rtol against a fixed 100 rtol)."""
    r = simulate_drop(THIN, rtol=rtol, **THIN_DROP)
    assert r.n_contacts > 50
    assert r.energy_error > ENERGY_GAIN_RTOL_FACTOR * rtol  # beyond the fixed bound
    assert ResultFlag.ENERGY_GAIN not in r.flags  # the drift loses energy, it creates none


def test_energy_injected_into_a_long_run_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """A test double that adds 1e-3 E0 to the final rigid kinetic energy of the same run."""
    check = drop_module.check_energy_balance

    def injected(o: dict[str, float], e0: float, rtol: float) -> None:
        check({**o, "rigid_kinetic_energy": o["rigid_kinetic_energy"] + 1e-3 * e0}, e0, rtol)

    monkeypatch.setattr(drop_module, "check_energy_balance", injected)
    with pytest.raises(DropError, match=r"closed to .* steps\) rtol") as exc:
        simulate_drop(THIN, rtol=1e-7, **THIN_DROP)
    assert exc.value.status == F.ST_INACCURATE


def test_the_bound_is_the_fixed_one_up_to_1000_steps() -> None:
    for rtol in (1e-5, 1e-7, 1e-12):
        fixed = ENERGY_GAIN_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF
        for steps in (0, 500, 1000):
            assert float(energy_balance_bound(rtol, steps)) == fixed
    for rtol in (1e-7, 1e-12):  # below the ceiling, ENERGY_BALANCE_MAX
        assert float(energy_balance_bound(rtol, 20_000)) == pytest.approx(
            ENERGY_STEP_FACTOR * 20_000 * rtol + ENERGY_ROUNDOFF
        )


def test_the_refusal_names_its_numbers_and_true_advice() -> None:
    o = {**CLOSED, "energy_error": 1e-3, "n_steps": 20_000.0}
    with pytest.raises(DropError) as exc:
        check_energy_balance(o, 1.0, 1e-7)
    text = str(exc.value)
    assert "0.1 x 20000 steps" in text and "= 0.0002" in text and "rtol = 1e-07" in text
    assert "shrinks in proportion to rtol, so lower rtol" in text
    check_energy_balance({**o, "energy_error": 1e-4}, 1.0, 1e-7)  # within 2000 rtol


def test_batch_reasons_carry_the_numbers() -> None:
    cols = {k: [v, v] for k, v in CLOSED.items()}
    cols["energy_error"] = [1e-4, 1e-4]
    cols["n_steps"] = [20_000.0, 500.0]
    why = inaccurate_cases({k: np.asarray(v) for k, v in cols.items()}, np.ones(2), 1e-7)
    assert list(why) == [1]
    assert why[1].startswith("the energy balance closed to 5.71e-05 of its energy scale")
    assert "0.1 x 500 steps" in why[1] and "{" not in why[1]


def test_paper_drop_at_loose_rtol_is_refused_and_passes_at_the_cap() -> None:
    """At rtol 1e-3 the 20 deg drop closed to 0.21 E0 with 10 contacts: refused now before it
    runs (``input_checks.DROP_RTOL_MAX``); at the cap it keeps its 4 contacts."""
    kw: dict[str, Any] = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}
    kw["history"] = False
    with pytest.raises(ValueError, match="too loose for a drop"):
        simulate_drop(FlexibleRod.paper(), rtol=1e-3, **kw)
    assert simulate_drop(FlexibleRod.paper(), rtol=1e-5, **kw).n_contacts == 4
