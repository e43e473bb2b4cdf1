"""A verdict that names a flexible row not converged in its modes, or ranks one that more
modes could bring level with the first, says so: its reason, JSON ``best`` and a note call it
provisional; a converged row, or one that no refinement the mode check allows could bring
level, does not."""

from __future__ import annotations

import pytest

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import Explanation, explain
from impactlab.explain.configurations import FLEXIBLE, RIGID
from impactlab.explain.modes import MODE_REACH, MODES_CAVEAT, ModeCheck
from impactlab.explain.notes import explanation_notes
from impactlab.explain.runs import Outcome
from impactlab.explain.tables import comparison_table, summary_table
from impactlab.explain.verdict import verdict

CONFIGS = (RIGID, FLEXIBLE)
DROP = {"label": "s70", "angle": "70 deg", "vy": -0.5, "mu": 0.2, "e": 0.30, "e_sigma": 0.03}


def _explained(shift: float) -> Explanation:
    """The slender rod's drop (e 0.30 +- 0.03): the rigid rod at e 0.430, the flexible rod at
    0.3518 (z +1.73) whose twice the modes move e by ``shift`` sigma."""
    meas = Measurements.from_records([DROP])
    moved = 0.3518 - 0.03 * shift
    check = ModeCheck((16, 28), (32, 56), "ok", {"e": 0.3518}, {"e": moved}, {"e": shift})
    outcomes = {
        ("s70", RIGID.name): Outcome("ok", True, {"e": 0.430}),
        ("s70", FLEXIBLE.name): Outcome("ok", True, {"e": 0.3518}, modes=check),
    }
    comparison = comparison_table(meas, CONFIGS, outcomes)
    summary = summary_table(meas, CONFIGS, outcomes, comparison)
    verdicts = [verdict(summary, comparison, "s70")]
    notes = explanation_notes(outcomes, summary, verdicts)
    return Explanation(comparison, summary, CONFIGS, "ghaednia", "coulomb", notes, None, outcomes)


def test_a_best_row_not_converged_in_modes_is_named_provisionally() -> None:
    x = _explained(1.32)
    v = x.verdict("s70")
    assert v.configuration == x.best("s70") == "flexible rod"  # still named: see docs/explain.md
    assert v.provisional
    assert v.reason.startswith("flexible rod: the most values within 2 sigma")
    assert f"provisional: flexible rod is {MODES_CAVEAT}" in v.reason
    assert "n_axial, n_bending" in v.reason
    assert x.to_dict()["best"][0]["reason"] == v.reason
    assert f"best: {v.reason} (drops: s70)" in x.notes


def test_a_converged_best_row_is_plain() -> None:
    x = _explained(0.1)
    v = x.verdict("s70")
    assert v.configuration == "flexible rod" and not v.provisional
    assert "provisional" not in v.reason and not any(n.startswith("best: ") for n in x.notes)


def _rival(e: float, refined: float) -> Explanation:
    """The drop (e 0.30 +- 0.03): the rigid rod meets it (e 0.31), the flexible rod at ``e``
    not converged in modes, twice its modes moving it to ``refined``."""
    meas = Measurements.from_records([DROP])
    shift = abs(refined - e) / 0.03
    check = ModeCheck((16, 28), (32, 56), "ok", {"e": e}, {"e": refined}, {"e": shift})
    outcomes = {
        ("s70", RIGID.name): Outcome("ok", True, {"e": 0.31}),
        ("s70", FLEXIBLE.name): Outcome("ok", True, {"e": e}, modes=check),
    }
    comparison = comparison_table(meas, CONFIGS, outcomes)
    summary = summary_table(meas, CONFIGS, outcomes, comparison)
    return Explanation(comparison, summary, CONFIGS, "ghaednia", "coulomb", (), None, outcomes)


def test_a_rival_more_modes_cannot_bring_level_leaves_the_verdict_plain() -> None:
    """The flexible rod at z +10, twice its modes moving it by 1 sigma: at most 4 more shifts
    bring it to z +5, still outside 2 sigma and above the rigid rod's chi2 0.11: the verdict
    is not provisional, the row keeps its caveat."""
    x = _rival(0.60, 0.57)
    v = x.verdict("s70")
    assert v.configuration == RIGID.name and not v.provisional
    assert "provisional" not in v.reason
    s = x.summary.set_index("configuration").loc[FLEXIBLE.name]
    assert s["modes_converged"] is False and s["caveat"].startswith(MODES_CAVEAT)
    check = x.outcomes[("s70", FLEXIBLE.name)].modes
    assert check.least_z("e", 10.0) == pytest.approx(9.0 - MODE_REACH * 1.0)
    # without the mode checks the verdict cannot tell, and stays provisional
    bare = verdict(x.summary, x.comparison, "s70", None, None)
    assert bare.provisional and f"{FLEXIBLE.name} is {MODES_CAVEAT}" in bare.reason
    head, rows = x.display_rows()
    assert rows[1][head.index("verdict")] == "best"


def test_a_rival_more_modes_can_bring_level_makes_it_provisional() -> None:
    """The flexible rod at z +2.33, twice its modes moving it to z +1.67 (0.67 sigma): more
    modes could bring it to z 0, below the rigid rod's z +0.33: provisional. Moved to z +2.0
    (0.33 sigma) it could come no nearer than z +0.67 and stays below the rigid rod."""
    near = _rival(0.37, 0.36).verdict("s70")
    assert near.configuration == RIGID.name and not near.provisional
    x = _rival(0.37, 0.35)
    v = x.verdict("s70")
    assert v.configuration == RIGID.name and v.provisional
    assert f"provisional: {FLEXIBLE.name} is {MODES_CAVEAT}" in v.reason
    head, rows = x.display_rows()
    assert rows[1][head.index("verdict")] == "best, provisional"


def test_the_reach_of_a_row_at_the_mode_limit_is_from_its_own_value() -> None:
    capped = ModeCheck((128, 128), (64, 64), "ok", {"e": 0.52}, {"e": 0.49}, {"e": 1.0}, True)
    assert capped.least_z("e", 7.0) == pytest.approx(7.0 - MODE_REACH)
    assert capped.least_z("e", -1.0) == 0.0
    assert capped.least_z("delta_p", 7.0) is None  # not checked: no bound
    failed = ModeCheck((8, 12), (16, 24), "not ok: flagged", {"e": 0.5}, {}, {})
    assert failed.least_z("e", 7.0) is None


def test_an_unconverged_row_far_off_does_not_make_a_real_verdict_provisional(tmp_path) -> None:
    """A synthetic drop at 45 deg (examples/data/drops.csv with mu 0.2): the Johnson-Cook row
    is not converged in modes (its scar moves from 877.4 to 845.6 um, 6.4 sigma, at z +158),
    the rigid rod meets all four values (chi2 1.965): the verdict is plain."""
    (tmp_path / "d45.csv").write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma,spin_out [rad/s],spin_out_sigma,delta_p [um],"
        "delta_p_sigma,scar_length [um],scar_length_sigma\n"
        "d45,45,-2.18,0.2,0.416,0.02,-15.11,0.3,113.8,3,88.9,5\n"
    )
    x = explain(tmp_path / "d45.csv")
    s = x.summary.set_index("configuration")
    jc = next(n for n in s.index if "johnson-cook" in n)
    assert s.loc[jc, "modes_converged"] is False
    # as docs/explain.md states them
    assert "scar_length moves from 877.4 um to 845.6 um (6.37 sigma)" in s.loc[jc, "caveat"]
    z = x.comparison.set_index(["configuration", "quantity"]).loc[(jc, "scar_length"), "z"]
    assert round(z) == 158
    v = x.verdict("d45")
    assert v.configuration == RIGID.name and v.consistent is True
    assert not v.provisional and "provisional" not in v.reason
