"""Numbers in messages in fixed point (110 %, not 1.1e+02 %); a zero sigma of the angle accepted
as every other zero sigma; the angle's range explained at the end that was crossed."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from impactlab.experiment.kinematics.impulse import ImpulseCheck
from impactlab.experiment.uncertainty import fixed

CliMain = Callable[..., tuple[int, str, str]]
INVERT = ("invert", "--angle", "20 deg", "--vi", "-1.41", "--e", "0.5", "--mu", "0.2",
          "--delta-p", "22 um", "--ls", "1400 um")  # fmt: skip


@pytest.mark.parametrize(
    ("x", "text"), [(110.4, "110"), (220.0, "220"), (5.26, "5.3"), (0.052, "0.052"), (-12.6, "-13")]
)
def test_fixed_point(x: float, text: str) -> None:
    assert fixed(x) == text


def test_the_impulse_check_says_110_percent() -> None:
    assert "differing by 110 %" in ImpulseCheck(10.0, -1.0, 0.1).text()


@pytest.mark.parametrize("sigma", ["0 deg", "0 rad", "0.5 deg"])
def test_a_zero_sigma_of_the_angle_is_accepted(cli_main: CliMain, sigma: str) -> None:
    code, _, err = cli_main(*INVERT, "--sigma-angle", sigma)
    assert code == 0, err


def test_a_negative_sigma_of_the_angle_is_refused(cli_main: CliMain) -> None:
    code, _, err = cli_main(*INVERT, "--sigma-angle", "-1 deg")
    assert code == 2
    assert "--sigma-angle must be a standard deviation >= 0 deg" in err and "-1 deg" in err


@pytest.mark.parametrize(
    ("angle", "says"),
    [("0 deg", "at 0 deg it lies on the flat"), ("-5 deg", "below 0 its tip points up"),
     ("90 deg", "at 90 deg it stands vertical")],
)  # fmt: skip
def test_the_angle_range_is_explained_at_the_end_crossed(
    cli_main: CliMain, angle: str, says: str
) -> None:
    args = list(INVERT)
    args[2] = angle
    code, _, err = cli_main(*args)
    assert code == 2 and says in err and "must lie in (0, 90) deg" in err
