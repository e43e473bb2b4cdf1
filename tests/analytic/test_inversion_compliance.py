"""The inversion's advice on a tangentially compliant contact (docs/analytic.md, Sec. 7): T
comes out ``COMPLIANCE_LEVEL`` % or more too long from the measured mu/mu_c on; the warning is
advice, never a doubt, and the paper's own drops draw none."""

from __future__ import annotations

import json
import math
import re
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from impactlab import ImplausibleInputWarning
from impactlab.analytic import critical_friction, invert
from impactlab.analytic._compliance import (
    COMPLIANCE_ANGLES,
    COMPLIANCE_LEVEL,
    COMPLIANCE_SPEEDS,
    COMPLIANCE_THRESHOLD,
    check_compliance,
    compliance_threshold,
)
from impactlab.cli.invert_output import inversion_doubts
from impactlab.experiment.analysis import IMPOSSIBLE_PHRASES
from impactlab.paper.data import EXPERIMENTS

CliMain = Callable[..., tuple[int, str, str]]
_NOTE = "tangentially compliant contact"
#: A dent of the paper's size: T is what it is, only the warning matters here.
_DENT: dict[str, Any] = dict(e=0.5, delta_p=22e-6, sliding_length=1400e-6, n_samples=200)


def _notes(res: Any) -> list[str]:
    return [w for w in res.warnings if _NOTE in w]


def test_the_level_is_ten_percent_and_the_table_is_its_shape() -> None:
    assert COMPLIANCE_LEVEL == 10.0
    assert np.shape(COMPLIANCE_THRESHOLD) == (len(COMPLIANCE_SPEEDS), len(COMPLIANCE_ANGLES))
    table = np.array(COMPLIANCE_THRESHOLD)
    # a steeper rod and a faster drop stick less: the threshold rises with both
    assert np.all(np.diff(table, axis=1) > 0) and np.all(np.diff(table, axis=0) > 0)


def test_the_threshold_is_the_table_at_its_points() -> None:
    for i, v in enumerate(COMPLIANCE_SPEEDS):
        for j, deg in enumerate(COMPLIANCE_ANGLES):
            got = compliance_threshold(math.radians(deg), v)
            assert got == pytest.approx(COMPLIANCE_THRESHOLD[i][j], rel=1e-12)


def test_the_threshold_is_linear_in_the_angle_and_in_log_speed() -> None:
    row = COMPLIANCE_THRESHOLD[1]
    mid_angle = compliance_threshold(math.radians(25.0), 1.41)  # between 20 and 30 deg
    assert mid_angle == pytest.approx((row[3] + row[4]) / 2, rel=1e-12)
    # the geometric mean of two measured speeds is half-way between their rows
    mid_speed = compliance_threshold(math.radians(20.0), math.sqrt(0.5 * 1.41))
    assert mid_speed == pytest.approx(
        (COMPLIANCE_THRESHOLD[0][3] + COMPLIANCE_THRESHOLD[1][3]) / 2, rel=1e-12
    )
    # not linear in the speed itself: the arithmetic mean lies past half-way
    assert compliance_threshold(math.radians(20.0), (0.5 + 1.41) / 2) > mid_speed


def test_outside_the_table_the_nearest_edge_holds() -> None:
    first, last = COMPLIANCE_THRESHOLD[0], COMPLIANCE_THRESHOLD[-1]
    assert compliance_threshold(math.radians(1.0), 0.5) == pytest.approx(first[0])
    assert compliance_threshold(math.radians(89.0), 4.0) == pytest.approx(last[-1])
    assert compliance_threshold(math.radians(20.0), 0.01) == pytest.approx(first[3])
    assert compliance_threshold(math.radians(20.0), 0.0) == pytest.approx(first[3])
    assert compliance_threshold(math.radians(20.0), 100.0) == pytest.approx(last[3])
    assert compliance_threshold(1e-9, 1e9) == pytest.approx(last[0])


def test_check_compliance_warns_from_the_threshold_on() -> None:
    th = math.radians(20.0)
    limit = compliance_threshold(th, 1.41)
    with pytest.warns(ImplausibleInputWarning, match=r"10 % or more too long"):
        check_compliance(1.001 * limit, 1.0, th, 1.41)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_compliance(0.999 * limit, 1.0, th, 1.41)
        check_compliance(0.0, 0.5, th, 1.41)
        check_compliance(0.1, math.inf, th, 1.41)


@pytest.mark.parametrize("deg", [20, 45, 70])
def test_the_papers_drops_draw_no_warning(deg: int) -> None:
    """Measured +5.7 %, +1.4 %, +2.5 % on their simulated twins: below the level."""
    x = EXPERIMENTS[deg]
    res = invert(angle=x.angle, v_i=x.v_i, e=x.e, mu=x.mu, delta_p=abs(x.delta_p),
                 sliding_length=abs(x.L_s), n_samples=200)  # fmt: skip
    assert not _notes(res)


@pytest.mark.parametrize(("deg", "mu"), [(10, 0.353), (20, 0.457)])
def test_a_mu_near_mu_c_draws_the_advice_not_a_doubt(deg: int, mu: float) -> None:
    """0.6 mu_c: on a compliant contact T came out +54 % (10 deg) and +40 % (20 deg) long."""
    th = math.radians(deg)
    assert mu / float(critical_friction(th)) == pytest.approx(0.6, abs=0.002)
    with pytest.warns(ImplausibleInputWarning, match=_NOTE):
        res = invert(angle=th, v_i=-1.41, mu=mu, **_DENT)
    (note,) = _notes(res)
    assert re.match(rf"mu = {mu:.4g} is 0\.(6|599) mu_c \(mu_c = ", note)
    assert f"from mu/mu_c = {compliance_threshold(th, 1.41):.3g}" in note
    assert "docs/analytic.md, Sec. 7" in note
    assert inversion_doubts([note], []) == []  # the command line's rule
    assert not any(p in note for p in IMPOSSIBLE_PHRASES)  # analyze's rule


def test_the_command_line_lists_it_and_stays_ok(cli_main: CliMain) -> None:
    code, out, err = cli_main(
        "invert", "--angle", "10 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.353",
        "--delta-p", "22 um", "--ls", "1400 um", "--samples", "200", "--json",
    )  # fmt: skip
    assert code == 0, err
    data = json.loads(out)
    assert data["ok"] is True and data["doubts"] == []
    assert [w for w in data["warnings"] if _NOTE in w]


def test_hidden_advice_is_not_shown_but_still_listed() -> None:
    """compliance_advice_hidden: no warning shown, the result's warnings still hold the note."""
    from impactlab.analytic import compliance_advice_hidden

    th = math.radians(10)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        with compliance_advice_hidden():
            res = invert(angle=th, v_i=-1.41, mu=0.353, **_DENT)
    assert len(_notes(res)) == 1


def test_the_paper_reproduction_shows_no_advice() -> None:
    """The reproduction's inversions over inputs no drop measured (curves over e, the
    simulations' own e) do not flood the report's command with the advice."""
    from impactlab.paper.analytic_rows import invert_case
    from impactlab.paper.physics import eq12_duration

    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        for e in (0.1, 0.3, 0.5):
            assert eq12_duration(20, e, 22e-6, 1400e-6) > 0.0
        x = EXPERIMENTS[20]
        assert invert_case(x.__class__(**{**x.__dict__, "mu": 0.6})).duration > 0.0
