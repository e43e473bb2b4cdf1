"""Messages of the inversion's command line and the experiment's Python side: one true range
for the angle of `impactlab invert`, a TypeError naming the figure's argument, and no ± where no
sigma is computed."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from impactlab.experiment import analyze, read_scan
from impactlab.experiment.plots import plot_dent, plot_kinematics
from impactlab.experiment.uncertainty import Estimate

CliMain = Callable[..., tuple[int, str, str]]
INVERT = ("invert", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2", "--delta-p", "22 um",
          "--ls", "1400 um", "--samples", "200")  # fmt: skip
RANGE = "--angle must lie in (0, 90) deg, open at both ends"


@pytest.mark.parametrize("angle", ["0 deg", "90 deg", "-5 deg", "1.6 rad"])
def test_an_angle_outside_the_inversions_range_gives_that_range(
    cli_main: CliMain, angle: str
) -> None:
    """'0 deg' said '(0, 90]' and '90 deg' '(0, 90), open at both ends': one range, the true one."""
    code, _, err = cli_main(*INVERT, "--angle", angle)
    assert code == 2
    why = (
        "at 90 deg it stands vertical and its tip cannot slide"
        if angle in ("90 deg", "1.6 rad")
        else "at 0 deg it lies on the flat, and below 0 its tip points up"
    )  # the end that was crossed
    assert err.strip().startswith(f"error: {RANGE} (the rod tilted: {why}), got {angle}")
    past_normal = "; the rod leans past the flat's normal" in err  # 1.6 rad: the mirror drop
    assert past_normal == (angle == "1.6 rad")


def test_an_angle_inside_the_range_is_inverted(cli_main: CliMain, tmp_path: Path) -> None:
    code, _, err = cli_main(*INVERT, "--angle", "89 deg", "--mu", "0.0005", "--json")
    assert code == 0, err
    (tmp_path / "m.toml").write_text(
        'angle = "90 deg"\nvi = "-1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\nls = "1400 um"\n'
    )
    code, _, err = cli_main("invert", "--file", str(tmp_path / "m.toml"))
    assert code == 2 and "angle in the measurement file must lie in (0, 90) deg" in err


def test_a_figure_of_the_wrong_object_is_a_type_error(scans: dict) -> None:
    hm = read_scan(scans[20].files["x3p"])
    with pytest.raises(TypeError, match=r"^dent must be a DentMetrics \(measure one with"):
        plot_dent(hm)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"^kin must be an ImpactKinematics \(measure one with"):
        plot_kinematics(hm)  # type: ignore[arg-type]


def test_the_pileup_is_shown_without_a_sigma(scans: dict) -> None:
    """'pileup 1.56e-06 ± 0 m' claimed an exact value: none is computed."""
    res = analyze(None, scans[20].files["x3p"])
    pileup = res.summary()["pileup"]
    assert pileup.sigma == 0.0
    assert str(pileup) == f"{pileup.value:.4g} m" and "±" not in f"{pileup:.3g}"
    assert str(res.summary()["sliding_length"]).count("±") == 1
    assert str(Estimate(0.5, 0.01)) == "0.5 ± 0.01"
