"""mu from the Kharaz-Gorham-Salman rebound data against their independently measured 0.092.

Every model runs in the batch engine; the partial-slip model, about 35 times the cost of
Mindlin per impact, takes about half a minute (marked slow). Measured
with 8 walkers x 200 steps (docs/calibrate.md): partial slip 0.094 [0.090, 0.098], Mindlin
0.092 [0.088, 0.096], Coulomb 0.095 [0.090, 0.100]; PSIS-LOO ranks partial slip first.
"""

from __future__ import annotations

import math

import pytest

from impactlab.verification.kharaz_calibration import (
    KGS_MU,
    kharaz_calibration,
    kharaz_measurements,
    summary_rows,
)


def test_measurements_from_the_digitised_data():
    m = kharaz_measurements()
    assert m.n_drops == 15 and m.n_values == 15
    assert m.categories[0]["body"] == "sphere"
    assert m.inputs["vx"][0] == pytest.approx(3.9 * math.sin(math.radians(1.84)))
    assert (m.observed["spin_out"][8:] < 0).all()  # clockwise for a sphere moving to +x


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")
def test_batched_models_find_the_measured_mu():
    cal = kharaz_calibration(("hertz/mindlin", "hertz/coulomb"), walkers=8, steps=60)
    for row in summary_rows(cal):
        assert abs(row["mu_median"] - KGS_MU) < 0.01, row
    assert cal.ranking[0]["model"] == "hertz/mindlin"


@pytest.mark.slow
def test_partial_slip_finds_the_measured_mu_and_ranks_first():
    cal = kharaz_calibration(walkers=8, steps=200)
    rows = {r["model"]: r for r in summary_rows(cal)}
    assert rows["hertz/partial_slip"]["holds_measured"]
    assert cal.ranking[0]["model"] == "hertz/partial_slip"
