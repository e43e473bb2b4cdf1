"""``stop="flight"``: the energy balance is checked over the whole flight, the reported terms
included, and a balance worse than the tolerance promises is refused; the paper's 20 deg drop
through the other end's impacts closes its balance, is flagged OTHER_END (e and the duration
then span the whole flight) and is not gravity-dominated (docs/flexible.md, "Results")."""

from __future__ import annotations

import pytest
from energy_balances import CLOSED

import impactlab as il
from impactlab.dynamics.drop import DropError
from impactlab.dynamics.drop_checks import balance_residual, check_energy_balance
from impactlab.flags import ENERGY_GAIN_RTOL_FACTOR, ENERGY_ROUNDOFF, ResultFlag


def test_a_closed_balance_passes() -> None:
    assert balance_residual(CLOSED, 1.0) == pytest.approx(0.0, abs=1e-15)
    check_energy_balance(CLOSED, 1.0, 1e-7)


def test_reported_terms_that_do_not_close_are_refused() -> None:
    """The running error of the steps may miss what the reported terms show (the state after
    the last contact): both are checked."""
    open_balance = {**CLOSED, "work_friction": -0.01}  # 1 % of E0 unaccounted for
    with pytest.raises(DropError, match="energy balance closed to"):
        check_energy_balance(open_balance, 1.0, 1e-7)


def test_the_running_error_is_refused_too() -> None:
    with pytest.raises(DropError, match="lower rtol"):
        check_energy_balance({**CLOSED, "energy_error": 1e-3}, 1.0, 1e-7)


def test_paper_20_deg_flight_closes_its_balance_and_is_not_gravity_dominated() -> None:
    r = il.simulate(il.FlexibleRod.paper(), angle="20 deg", velocity=(0.0, -1.41), mu=0.2,
                    stop="flight", history=False)  # fmt: skip
    ends = [c.end for c in r.contacts]
    assert 1 in ends and ends[-1] == 0  # the other end landed, the tip touched again after it
    rtol = r.input["rtol"]["value"]
    bound = ENERGY_GAIN_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF
    assert abs(r.energy_balance["residual"]) <= bound * r.initial_energy
    assert r.energy_error <= bound
    assert ResultFlag.OTHER_END in r.flags and not r.ok
    assert ResultFlag.GRAVITY_DOMINATED not in r.flags
    assert ResultFlag.ENERGY_GAIN not in r.flags
    last = r.contacts[-1]
    assert r.sequence_duration == pytest.approx(last.start + last.duration, rel=1e-12)
    assert r.next_end == -1  # nothing left to land: the whole flight was integrated
