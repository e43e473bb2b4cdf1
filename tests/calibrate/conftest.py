"""Shared drops for the calibration tests: the paper's rod at three angles."""

from __future__ import annotations

import pytest

from impactlab.calibrate import Measurements

#: e, spin_out [rad/s] and sliding_length [m] uncertainties of the synthetic drops.
SIGMAS = {"e": 0.01, "spin_out": 0.3, "sliding_length": 3e-6}


def paper_drops(angles=(20, 45, 70), vy=-1.4, sigmas=SIGMAS, **extra) -> Measurements:
    """A template of drops of the paper's rod (values are placeholders: 0)."""
    recs = []
    for a in angles:
        r = {"label": f"{a} deg", "angle": f"{a} deg", "vy": vy, **extra}
        for q, s in sigmas.items():
            r[q], r[f"{q}_sigma"] = (0.5 if q == "e" else 0.0), s
        recs.append(r)
    return Measurements.from_records(recs)


@pytest.fixture
def template() -> Measurements:
    return paper_drops()
