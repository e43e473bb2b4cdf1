"""``Calibration.predict`` asked for more draws than the posterior holds uses all it holds,
says so with a CalibrationWarning, and each ``summary()`` row carries the number of draws its
interval rests on (``n_draws``)."""

from __future__ import annotations

import re
import warnings

import pytest

from impactlab.calibrate import Calibration, CalibrationWarning, Measurements, calibrate
from impactlab.calibrate import parse_parameter as parameter

MU = parameter("mu", "uniform(0, 0.6)")
DROP = {"angle": "20 deg", "vy": -1.41, "e": 0.45, "e_sigma": 0.02}
NEW = {"label": "new", "angle": "30 deg", "vy": -2.0}


@pytest.fixture(scope="module")
def cal() -> Calibration:
    drops = [{**DROP, "label": "a"}, {**DROP, "label": "b", "angle": "45 deg", "vy": -2.18}]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return calibrate(Measurements.from_records(drops), [MU], walkers=6, steps=12, n_ppc=0)


def _held(cal: Calibration) -> int:
    return len(next(iter(cal.posteriors.values())).samples)


def test_more_draws_than_the_posterior_holds_warns_and_uses_all(cal: Calibration) -> None:
    n = _held(cal)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        got = cal.predict([NEW], ["e"], draws=n + 1000)
    mine = [w for w in seen if "draws asked" in str(w.message)]
    assert len(mine) == 1 and issubclass(mine[0].category, CalibrationWarning)
    assert mine[0].filename == __file__  # the warning points at the caller
    assert re.fullmatch(
        rf"model 'ghaednia/coulomb': {n + 1000} draws asked, the posterior holds {n}: all {n} "
        rf"used \(summary\(\)'s n_draws; its q05 and q95 rest on {n} draws; more walkers or "
        r"steps give more\)",
        str(mine[0].message),
    )
    assert got.draws.shape[0] == n and got.values["e"].shape == (n, 1)
    assert [r["n_draws"] for r in got.summary()] == [n]


def test_fewer_draws_than_held_are_not_warned_about(cal: Calibration) -> None:
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        got = cal.predict([NEW, {**NEW, "label": "other", "vy": -2.5}], ["e"], draws=3)
    assert not [w for w in seen if "draws asked" in str(w.message)]
    assert [r["n_draws"] for r in got.summary()] == [3, 3]
