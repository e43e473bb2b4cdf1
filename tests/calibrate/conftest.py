"""Shared drops for the calibration tests: the paper's rod at three angles; a small calibration
of mu on two drops for the prediction tests."""

from __future__ import annotations

import warnings

import pytest

from impactlab.calibrate import Calibration, Measurements, calibrate
from impactlab.calibrate import parse_parameter as parameter

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


@pytest.fixture(scope="session")
def mu_calibration() -> Calibration:
    """mu (uniform in [0, 0.6]) calibrated on two drops of the paper's rod with a measured e
    (6 walkers, 12 steps: a small posterior, for what predictions do with it)."""
    drop = {"angle": "20 deg", "vy": -1.41, "e": 0.45, "e_sigma": 0.02}
    drops = [{**drop, "label": "a"}, {**drop, "label": "b", "angle": "45 deg", "vy": -2.18}]
    mu = parameter("mu", "uniform(0, 0.6)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return calibrate(Measurements.from_records(drops), [mu], walkers=6, steps=12, n_ppc=0)
