"""The paper's drops written as a measurements file give, row by row, the predictions of the
reproduction's "Can physics explain" table (paper.physics: the same simulations), and the
calibration's predict (its batch engines, no free parameter) gives the same numbers."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.calibrate import CandidateModel
from impactlab.calibrate.measurements import read_measurements
from impactlab.calibrate.models import predict
from impactlab.paper import data as D
from impactlab.paper.physics import (
    CONFIGURATIONS,
    RATE_LOWER,
    apparent_mu,
    rigid_e_gravity_removed,
    run_physics,
)

#: explain's configuration -> the reproduction's row of the same physics.
SAME = {
    "rigid body": CONFIGURATIONS[0],
    "flexible rod": CONFIGURATIONS[1],
    "flexible rod + rate-dependent flat (cowper-symonds, upper estimate)": CONFIGURATIONS[2],
    "flexible rod + rate-dependent flat (johnson-cook, lower estimate)": RATE_LOWER,
}
LABELS = {20: "20 deg", 45: "45 deg", 70: "70 deg"}


@pytest.fixture(scope="module")
def reproduction():
    return run_physics(configurations=tuple(SAME.values()), history_angle=None)


def _reproduced(cfg, res) -> dict[str, float]:
    if not cfg.flexible:
        return {"e": rigid_e_gravity_removed(res), "delta_p": res.delta_p,
                "scar_length": abs(res.contact_travel), "n_contacts": 1}  # fmt: skip
    return {"e": res.e, "delta_p": res.dent_depth, "scar_length": res.scar_length,
            "n_contacts": res.n_contacts}  # fmt: skip


def test_every_row_is_the_reproductions(paper_explained, reproduction) -> None:
    x = paper_explained
    assert [c.name for c in x.configurations] == list(SAME)
    for name, cfg in SAME.items():
        for ang, label in LABELS.items():
            res = reproduction[(cfg.name, ang)]
            want = _reproduced(cfg, res)
            rows = x.comparison[(x.comparison["drop"] == label)
                                & (x.comparison["configuration"] == name)]  # fmt: skip
            got = dict(zip(rows["quantity"], rows["predicted"], strict=True))
            for q in ("e", "delta_p", "scar_length"):
                assert got[q] == pytest.approx(want[q], rel=1e-12), (name, ang, q)
            s = x.summary[(x.summary["drop"] == label) & (x.summary["configuration"] == name)]
            assert int(s["n_contacts"].iloc[0]) == want["n_contacts"]
            assert s["mu"].iloc[0] == D.EXPERIMENTS[ang].mu  # measured mu beside Eq. 28's
            assert s["mu_apparent"].iloc[0] == pytest.approx(apparent_mu(res), rel=1e-12)
            assert bool(s["ok"].iloc[0]) and s["law_extrapolated"].iloc[0]


def test_the_flexible_rod_touches_again(paper_explained) -> None:
    """The ringing rod's re-contacts are counted (the paper's drops: 4, 4 and 2)."""
    s = paper_explained.summary
    flexible = s[s["configuration"] == "flexible rod"]
    assert list(flexible["n_contacts"]) == [4, 4, 2]


@pytest.mark.parametrize(
    ("body", "rate"),
    [(None, None), ("flexible_rod", None), ("flexible_rod", "cowper-symonds"),
     ("flexible_rod", "johnson-cook")],
)  # fmt: skip
def test_explain_and_calibrate_predict_alike(paper_file, paper_explained, body, rate) -> None:
    """The calibration's predict with its own engines (the batch engine, the flexible batch)
    at no free parameter gives explain's predictions."""
    meas = read_measurements(paper_file)
    pred = predict(CandidateModel(body=body, rate=rate), meas, (), np.empty((1, 0)))
    name = next(n for n, c in SAME.items() if c.flexible == (body is not None)
                and (c.rate or None) == rate)  # fmt: skip
    x = paper_explained.comparison
    for q, values in pred.values.items():
        rows = x[(x["configuration"] == name) & (x["quantity"] == q)]
        np.testing.assert_allclose(rows["predicted"].to_numpy(), values[0], rtol=1e-9)
