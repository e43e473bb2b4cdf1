"""What a drop and a batch of drops say of their inputs: rtol is refused with the drop's own
range, [1e-13, 1e-5], in Python, in a batch and on the command line (a rigid impact keeps its
[1e-13, 1e-3]); a batch's speed warning reads only the cases that run; and a batch whose every
refused angle reads as degrees warns once, its cases' refusals giving the degrees hint."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable

import pytest

import impactlab as il
from impactlab._validation import ImplausibleInputWarning
from impactlab.bodies import FlexibleRod
from impactlab.dynamics.drop_checks import DROP_STATUS_MESSAGES, case_problem, drop_rtol
from impactlab.dynamics.kernels import status as S

CliMain = Callable[..., tuple[int, str, str]]

RANGE = r"rtol must lie in \[1e-13, 1e-05\] for a drop \(the drop's default is 1e-07\), got "
LOOSE = r"is too loose for a drop \(allowed: up to 1e-05, a drop's rtol in \[1e-13, 1e-05\]"
ROD = FlexibleRod.paper(n_axial=2, n_bending=4)


@pytest.mark.parametrize("rtol", [0.0, 1e-20, -1.0, 0.1])
def test_an_rtol_outside_every_range_is_refused_with_the_drop_s(rtol: float) -> None:
    with pytest.raises(ValueError, match=f"^{RANGE}{rtol!r}$"):
        il.simulate_drop(ROD, angle="20 deg", velocity=(0.0, -1.41), rtol=rtol)
    with pytest.raises(ValueError, match=f"^{RANGE}{rtol!r}$"):
        il.simulate_drops(ROD, angle=0.35, vy=-1.41, rtol=rtol)


@pytest.mark.parametrize("rtol", [1e-4, 1e-3])
def test_a_loose_rtol_is_refused_with_the_drop_s_range_too(rtol: float) -> None:
    with pytest.raises(ValueError, match=f"^rtol {rtol:g} {LOOSE}"):
        drop_rtol(rtol)


def test_the_rigid_engine_keeps_its_own_range() -> None:
    with pytest.raises(ValueError, match=r"^rtol must lie in \[1e-13, 0\.001\], got 0\.0$"):
        il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0.0, -1.41), rtol=0.0)
    assert drop_rtol(1e-13) == 1e-13 and drop_rtol(1e-5) == 1e-5


def test_a_drop_s_status_meanings_give_its_rtol_range() -> None:
    said = DROP_STATUS_MESSAGES[S.ST_BAD_INPUT]
    assert said.endswith("rtol in [1e-13, 1e-5] for a drop)") and "1e-3" not in said
    assert {k: v for k, v in DROP_STATUS_MESSAGES.items() if k != S.ST_BAD_INPUT} == {
        k: v for k, v in S.STATUS_MESSAGES.items() if k != S.ST_BAD_INPUT
    }


def test_drop_names_its_range_on_the_command_line(cli_main: CliMain) -> None:
    code, out, err = cli_main("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--rtol", "0")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith("error: --rtol must lie in [1e-13, 1e-05] for a drop"), err


def test_refused_cases_drive_no_speed_warning() -> None:
    """A spin of 1e9 rad/s is refused (status 4), so its 1.6e8 m/s
    contact point is no impact speed of the batch."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        b = il.simulate_drops(ROD, angle=0.35, vy=-1.41, spin=[math.nan, 1e9, 1.0], mu=0.2)
        r = il.simulate_batch(il.Rod.paper(), angle=0.35, vy=[-1.41, -2e4], mu=0.2)
    assert list(b.status) == [S.ST_BAD_INPUT, S.ST_BAD_INPUT, S.ST_OK]
    assert list(r.status) == [S.ST_OK, S.ST_BAD_INPUT]
    with pytest.warns(ImplausibleInputWarning, match=r"largest impact speed of the batch \(150"):
        il.simulate_batch(il.Rod.paper(), angle=0.35, vy=[-1.41, -150.0], mu=0.2)


def test_angles_in_degrees_warn_once() -> None:
    with pytest.warns(ImplausibleInputWarning, match=r"every refused angle \(2 case\(s\), 20 to "
                      r"45\) lies in \(pi/2 \+ 10 deg, 90\]: degrees\?") as said:  # fmt: skip
        b = il.simulate_drops(ROD, angle=[20, 45], vy=-1.41, mu=0.2)
    assert len([w for w in said if w.category is ImplausibleInputWarning]) == 1
    assert list(b.status) == [S.ST_BAD_ANGLE, S.ST_BAD_ANGLE]


def test_an_angle_past_the_normal_draws_no_degrees_warning() -> None:
    """1.7 rad leans past the normal (97 deg), no angle in degrees: no warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        b = il.simulate_drops(ROD, angle=[1.7, 20.0], vy=-1.41, mu=0.2)
    assert list(b.status) == [S.ST_BAD_ANGLE, S.ST_BAD_ANGLE]


def test_a_case_s_angle_refusal_gives_the_degrees_hint() -> None:
    code, text = case_problem(0.15, 0.16, (20.0, 0.0, -1.41, 0.0, 0.2), 9.80665, 1e-7)
    assert code == S.ST_BAD_ANGLE
    assert text.endswith("; if 20.0 is meant in degrees, pass math.radians(20.0) = 0.349066 rad "
                         "or the string '20 deg'")  # fmt: skip
    code, text = case_problem(0.15, 0.16, (1.7, 0.0, -1.41, 0.0, 0.2), 9.80665, 1e-7)
    assert code == S.ST_BAD_ANGLE and "degrees" not in text


def test_a_batch_s_messages_and_stored_status_say_the_drop_s_range_and_degrees() -> None:
    with pytest.warns(ImplausibleInputWarning, match="degrees"):
        b = il.simulate_drops(ROD, angle=[20.0, 45.0], vy=-1.41, mu=0.2)
    assert b.messages[0].endswith("; if 20.0 is meant in degrees, pass math.radians(20.0) = "
                                  "0.349066 rad or the string '20 deg'")  # fmt: skip
    said = b.to_xarray()["status"].attrs["status_messages"]
    assert any("rtol in [1e-13, 1e-5] for a drop" in m for m in said)
    assert not any("1e-3" in m for m in said)


def test_one_refused_angle_is_named_once() -> None:
    with pytest.warns(
        ImplausibleInputWarning, match=r"every refused angle \(1 case\(s\), 30\) lies"
    ):
        il.simulate_drops(ROD, angle=[30.0, 0.35], vy=-1.41, mu=0.2)
