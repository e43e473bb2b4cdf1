"""``simulate_drop`` checks its inputs as ``impactlab.simulate`` and ``simulate_drops`` do: the
partial-slip tolerance's cap of the rigid engine, the warning of an implausible speed, a bool
``history``; a failed drop names the keyword to change (``DropError.worded``)."""

from __future__ import annotations

import math
import warnings

import pytest

import impactlab as il
from impactlab import FlexibleRod, ImplausibleInputWarning, Rod
from impactlab.dynamics import simulate_drop, simulate_drops
from impactlab.dynamics.drop_checks import DropError, drop_rtol
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.input_checks import PARTIAL_SLIP_RTOL_MAX, check_partial_slip_rtol
from impactlab.friction import get_friction

#: A small flexible rod: few modes, fast drops.
ROD = FlexibleRod.paper(n_axial=1, n_bending=3, axial_residual=True)
#: The paper's 20 deg drop.
PAPER_20 = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}


def test_partial_slip_tolerance_is_capped_as_in_the_rigid_engine() -> None:
    """rtol 1e-3 with partial slip gave 8 contacts and an energy error of 9 % as plain success
    (5 contacts at the default); it is refused with the rigid engine's cap, by name."""
    with pytest.raises(ValueError, match="too loose for friction 'partial_slip'"):
        check_partial_slip_rtol(1e-3)  # the rigid engine's refusal
    for run in (
        lambda: simulate_drop(FlexibleRod.paper(), friction="partial_slip", rtol=1e-3, **PAPER_20),
        lambda: simulate_drops(ROD, angle=0.35, vy=-1.41, friction="partial_slip", rtol=1e-3),
        lambda: il.simulate(ROD, angle=0.35, velocity=(0, -1.41), friction="partial_slip",
                            rtol=2e-5),
    ):  # fmt: skip
        with pytest.raises(ValueError, match=r"^rtol .* too loose for friction 'partial_slip'"):
            run()
    assert f"up to {PARTIAL_SLIP_RTOL_MAX:g}" in _message(1e-3)
    assert drop_rtol(PARTIAL_SLIP_RTOL_MAX, get_friction("partial_slip")) == PARTIAL_SLIP_RTOL_MAX
    assert drop_rtol(1e-5, get_friction("mindlin")) == 1e-5  # every drop's cap, not beyond
    with pytest.raises(ValueError, match=r"^rtol 0.001 is too loose for a drop"):
        drop_rtol(1e-3, get_friction("mindlin"))
    assert drop_rtol(None, get_friction("partial_slip")) == F.DROP_DEFAULT_RTOL


def _message(rtol: float) -> str:
    try:
        drop_rtol(rtol, get_friction("partial_slip"))
    except ValueError as exc:
        return str(exc)
    return ""


def test_partial_slip_at_the_cap_keeps_the_contacts() -> None:
    """At rtol 1e-5 the paper's 20 deg drop with partial slip keeps the default's contacts and
    its e and dent depth within 0.1 %."""
    ref = simulate_drop(FlexibleRod.paper(), friction="partial_slip", history=False, **PAPER_20)
    r = simulate_drop(FlexibleRod.paper(), friction="partial_slip", rtol=1e-5, history=False,
                      **PAPER_20)  # fmt: skip
    assert r.n_contacts == ref.n_contacts == 5
    assert r.e == pytest.approx(ref.e, rel=1e-3)
    assert r.dent_depth == pytest.approx(ref.dent_depth, rel=1e-3)


def test_an_implausible_speed_warns() -> None:
    """Above 100 m/s (most likely m/s for mm/s) the drop warns, as simulate does."""
    kw = {"angle": 0.35, "velocity": (0, -120), "law": "hertz", "history": False}
    with pytest.warns(ImplausibleInputWarning, match=r"impact speed \(120 m/s\) exceeds 100"):
        simulate_drop(ROD, **kw)
    with pytest.warns(ImplausibleInputWarning, match="exceeds 100"):
        il.simulate(ROD, **kw)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        simulate_drop(ROD, angle=0.35, velocity=(0, -1.41), history=False)


def test_the_tip_speed_from_the_spin_warns() -> None:
    """The contact point's speed counts, hypot(vx + spin b, vy - spin a), as in simulate: the
    centre of mass at 1 m/s, the tip at 125 m/s with 800 rad/s (94 m/s with 600: no warning)."""
    kw = {"angle": 0.35, "velocity": (0, -1.0), "law": "hertz", "history": False}
    with pytest.warns(ImplausibleInputWarning, match=r"impact speed \(125\.\d* m/s\)"):
        simulate_drop(Rod.paper(), spin=800.0, **kw)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        simulate_drop(Rod.paper(), spin=600.0, **kw)


@pytest.mark.parametrize("history", ["yes", 1, None])
def test_history_must_be_a_bool(history: object) -> None:
    with pytest.raises(ValueError, match=rf"^history must be True or False, got {history!r}$"):
        simulate_drop(ROD, angle=0.35, velocity=(0, -1.41), history=history)


def test_a_failed_drop_names_the_keyword_to_change() -> None:
    """time_limit reached: 'raise time_limit' in Python, the option where a command words it."""
    with pytest.raises(DropError) as exc:
        simulate_drop(ROD, angle=0.35, velocity=(0, -1.41), time_limit=1e-5, history=False)
    err = exc.value
    assert err.status == F.ST_TMAX
    assert str(err).endswith(": raise time_limit") and "{" not in str(err)
    # after the time, not before it
    assert "ms after the first touch (its last step ended past time_limit)" in str(err)
    assert err.worded(lambda k: "--" + k.replace("_", "-")).endswith(": raise --time-limit")
    assert DropError("drop: {odd} text", 3).worded(str) == "drop: {odd} text"
