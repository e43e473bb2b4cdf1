"""A verdict that names (or ranks) a flexible row not converged in its modes says so: its
reason, JSON ``best`` and a note call it provisional; a converged one does not."""

from __future__ import annotations

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import Explanation
from impactlab.explain.configurations import FLEXIBLE, RIGID
from impactlab.explain.modes import MODES_CAVEAT, ModeCheck
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
