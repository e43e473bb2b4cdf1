"""A drop's correlation coefficients in explain: its chi2 (summary and the verdict's ranking)
is z^T R^-1 z over the values compared, each z stays its value's own, a note says so; a drop
without coefficients keeps the sum of z^2 bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.calibrate.measurements import Measurements
from impactlab.explain import Explanation, explain
from impactlab.explain.configurations import FLEXIBLE, RIGID
from impactlab.explain.correlated import drop_pairs
from impactlab.explain.notes import explanation_notes
from impactlab.explain.runs import Outcome, drop_alone
from impactlab.explain.tables import comparison_table, summary_table

RHO = -0.97
CONFIGS = (RIGID, FLEXIBLE)
DROP = {"label": "d", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.5, "e_sigma": 0.03,
        "spin_out": -10.5, "spin_out_sigma": 0.5}  # fmt: skip


def _explained(
    rho: float | None, rigid: tuple[float, float], flexible: tuple[float, float]
) -> Explanation:
    """The drop (with the coefficient ``rho``; None: none) and two configurations whose z of e
    and spin_out are ``rigid`` and ``flexible``."""
    drop = dict(DROP) if rho is None else {**DROP, "correlation_e_spin_out": rho}
    meas = Measurements.from_records([drop])

    def values(z: tuple[float, float]) -> dict[str, float]:
        return {"e": 0.5 + 0.03 * z[0], "spin_out": -10.5 + 0.5 * z[1]}

    outcomes = {("d", RIGID.name): Outcome("ok", True, values(rigid)),
                ("d", FLEXIBLE.name): Outcome("ok", True, values(flexible))}  # fmt: skip
    comparison = comparison_table(meas, CONFIGS, outcomes)
    summary = summary_table(meas, CONFIGS, outcomes, comparison)
    pairs = {"d": drop_pairs(meas, 0)}
    notes = explanation_notes(outcomes, summary, (), pairs)
    return Explanation(comparison, summary, CONFIGS, "ghaednia", "coulomb", notes, None,
                       outcomes, pairs)  # fmt: skip


def _mahalanobis(z1: float, z2: float, rho: float) -> float:
    return (z1 * z1 + z2 * z2 - 2 * rho * z1 * z2) / (1 - rho * rho)


def test_chi2_and_the_ranking_take_the_correlation() -> None:
    """Same-sign errors against a correlation of -0.97 are far less likely than opposite ones
    of a larger sum of z^2: with the coefficient the ranking turns to the second."""
    rigid, flexible = (1.5, 1.5), (1.9, -1.9)
    plain = _explained(None, rigid, flexible)
    chi2 = plain.summary.set_index("configuration")["chi2"]
    assert chi2.tolist() == pytest.approx([2 * 1.5**2, 2 * 1.9**2], rel=1e-12)
    assert plain.best("d") == "rigid body"
    assert not any("correlation" in n for n in plain.notes)
    x = _explained(RHO, rigid, flexible)
    chi2 = x.summary.set_index("configuration")["chi2"]
    assert chi2["rigid body"] == pytest.approx(_mahalanobis(*rigid, RHO), rel=1e-12)
    assert chi2["flexible rod"] == pytest.approx(_mahalanobis(*flexible, RHO), rel=1e-12)
    np.testing.assert_allclose(x.comparison["z"], [*rigid, *flexible], atol=1e-12)  # marginal
    assert x.best("d") == "flexible rod"
    assert x.to_dict()["best"][0]["configuration"] == "flexible rod"
    assert x.notes == (
        "chi2 takes the drop's correlation coefficients (correlation_e_spin_out = -0.97): "
        "z^T R^-1 z over the values compared, R their correlation matrix; each z is of its "
        "value alone (drops: d)",
    )
    # a coefficient of 0 is independence: the sum of z^2, bit for bit
    zero = _explained(0.0, rigid, flexible)
    assert zero.summary["chi2"].tolist() == plain.summary["chi2"].tolist() and not zero.notes


def test_explain_reads_the_coefficients_of_a_drop() -> None:
    """The measured drop with its coefficient: the one-drop Measurements keep it, and the
    rigid rod's chi2 is the Mahalanobis form of its two z (about 37, against 8.06 as a sum)."""
    meas = Measurements.from_records([{**DROP, "correlation_e_spin_out": RHO}])
    assert drop_alone(meas, 0).correlation[("e", "spin_out")].tolist() == [RHO]
    x = explain(meas, rate_laws=[])
    z = x.comparison.set_index(["configuration", "quantity"])["z"]
    chi2 = x.summary.set_index("configuration")["chi2"]
    for name in ("rigid body", "flexible rod"):
        assert chi2[name] == pytest.approx(_mahalanobis(z[(name, "e")], z[(name, "spin_out")],
                                                        RHO), rel=1e-12)  # fmt: skip
    assert (
        30 < chi2["rigid body"] < 45
        and z[("rigid body", "e")] ** 2 + z[("rigid body", "spin_out")] ** 2 < 9
    )
    assert any(n.startswith("chi2 takes the drop's correlation coefficients") for n in x.notes)
