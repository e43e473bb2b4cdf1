"""``Calibration.predict`` asked for more draws than the posterior holds uses all it holds,
says so with a CalibrationWarning, and each ``summary()`` row carries the number of draws its
interval rests on (``n_draws``)."""

from __future__ import annotations

import re
import warnings

from impactlab.calibrate import Calibration, CalibrationWarning

NEW = {"label": "new", "angle": "30 deg", "vy": -2.0}


def _held(mu_calibration: Calibration) -> int:
    return len(next(iter(mu_calibration.posteriors.values())).samples)


def test_more_draws_than_the_posterior_holds_warns_and_uses_all(
    mu_calibration: Calibration,
) -> None:
    n = _held(mu_calibration)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        got = mu_calibration.predict([NEW], ["e"], draws=n + 1000)
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


def test_fewer_draws_than_held_are_not_warned_about(mu_calibration: Calibration) -> None:
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        got = mu_calibration.predict([NEW, {**NEW, "label": "other", "vy": -2.5}], ["e"], draws=3)
    assert not [w for w in seen if "draws asked" in str(w.message)]
    assert [r["n_draws"] for r in got.summary()] == [3, 3]
