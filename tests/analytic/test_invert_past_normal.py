"""An inversion's angle just past the flat's normal is explained as the mirror drop, in the API
(a bare angle up to 10 deg past pi/2) and on the command line (any angle with a unit in
(90, 180) deg); 90 deg itself and farther bare angles keep their own messages."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from impactlab import ImplausibleInputWarning, invert

CliMain = Callable[..., tuple[int, str, str]]
MEASURED = {"v_i": 1.41, "e": 0.5, "mu": 0.2, "delta_p": 5e-6, "sliding_length": 1.4e-3}


def test_api_names_the_mirror_angle() -> None:
    with pytest.raises(ValueError, match=r"mirror of one at 85 deg, with the same magnitudes"):
        invert(angle=math.radians(95), **MEASURED)
    with pytest.raises(ValueError, match="open at both ends") as exc:
        invert(angle=math.pi / 2, **MEASURED)
    assert "mirror" not in str(exc.value)


def test_mirror_inversion_is_an_inversion() -> None:
    """The hint's angle inverts: the mirror drop's T and F."""
    with pytest.warns(ImplausibleInputWarning, match="ill-conditioned"):  # 5 deg from vertical
        result = invert(angle=math.radians(85), **(MEASURED | {"mu": 0.02}))  # sliding there
    assert math.isfinite(result.duration) and result.duration > 0.0


@pytest.mark.parametrize(("angle", "mirror"), [("95 deg", "85 deg"), ("120 deg", "60 deg")])
def test_cli_names_the_mirror_angle(cli_main: CliMain, angle: str, mirror: str) -> None:
    args = ("--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2", "--delta-p", "5 um")
    code, out, err = cli_main("invert", "--angle", angle, *args, "--ls", "1400 um")
    assert code == 2 and out == ""
    assert f"got {angle}; the rod leans past the flat's normal" in err
    assert f"mirror of one at {mirror}" in err


@pytest.mark.parametrize("angle", [0.0, -0.1])
def test_api_explains_the_lying_end_for_an_angle_at_or_below_zero(angle: float) -> None:
    """At or below 0 the reason is the rod lying on the flat, as on the command line (it gave
    the reason for 90 deg)."""
    with pytest.raises(ValueError, match="at 0 deg it lies on the flat") as exc:
        invert(angle=angle, **MEASURED)
    assert "vertical" not in str(exc.value)


def test_api_refuses_a_sample_count_that_would_not_fit_in_memory() -> None:
    """The command line's bound, in the API (10**9 samples got the process killed)."""
    with pytest.raises(ValueError, match=r"^n_samples must be at most 10,000,000 \(about 1.2 GB"):
        invert(angle=math.radians(20), **MEASURED, n_samples=10**9)
