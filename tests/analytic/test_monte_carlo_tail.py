"""The Monte Carlo where the inputs' distribution reaches mu_c: T ~ 1/|alpha| has a heavy tail
there (no finite variance), so any sample in the sticking regime draws a warning that the spread
is unreliable, and the median and the 95 % interval, which are stable, are given beside the
mean and the standard deviation. A spread that is only rounding is reported as 0."""

from __future__ import annotations

import json
import math
import warnings
from collections.abc import Callable
from typing import Any

import pytest

import impactlab as il
from impactlab.analytic import invert
from impactlab.analytic.result import MC_INTERVAL

CliMain = Callable[..., tuple[int, str, str]]

#: A 70 deg drop whose mu distribution reaches mu_c = 0.257.
NEAR_MU_C: dict[str, Any] = {
    "angle": math.radians(70),
    "v_i": -3.45,
    "e": 0.05,
    "mu": (0.10, 0.05),
    "delta_p": 105e-6,
    "sliding_length": 200e-6,
}
PAPER_20 = {"angle": math.radians(20), "v_i": -1.41, "mu": 0.2, "delta_p": 22e-6}


def test_samples_in_the_sticking_regime_warn_that_the_spread_is_unreliable() -> None:
    results = []
    for seed in range(4):
        with pytest.warns(il.ImplausibleInputWarning, match="heavy tail") as rec:
            results.append(invert(**NEAR_MU_C, seed=seed))
        text = " ".join(str(w.message) for w in rec)
        assert "reached alpha >= 0 (the sticking regime)" in text
        assert "sigma_T_mc and T_mc depend on the seed" in text and "T_median_mc" in text
        assert "the first-order sigma_T (a linearisation) does not describe" in text
        assert results[-1].mc_rejected < 0.05  # below the share that warned before
    sigmas = [r.sigma_T_mc for r in results]
    assert max(sigmas) > 3 * min(sigmas)  # the spread follows the seed: what the warning says
    medians = [r.T_median_mc for r in results]
    assert max(medians) / min(medians) - 1 < 0.01  # the median does not
    for end in (0, 1):
        ends = [r.T_interval_mc[end] for r in results]
        assert max(ends) / min(ends) - 1 < 0.03
    r = results[0]
    assert r.T_interval_mc[0] < r.T_median_mc < r.T_interval_mc[1]
    assert r.F_interval_mc[0] < r.F_median_mc < r.F_interval_mc[1]


def test_no_warning_while_no_sample_sticks() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = invert(**PAPER_20, e=(0.5, 0.02), sliding_length=(1400e-6, 50e-6), n_samples=4000)
    assert r.mc_rejected == 0.0
    assert r.T_median_mc == pytest.approx(r.duration, rel=0.01)
    assert MC_INTERVAL == (2.5, 97.5)
    assert r.T_interval_mc[0] < r.T_median_mc < r.T_interval_mc[1]
    d = r.to_dict()
    assert d["T_median_mc"] == r.T_median_mc and d["F_median_mc"] == r.F_median_mc
    assert "median" in str(r) and "95 % in [" in str(r)


def test_a_spread_of_rounding_is_zero() -> None:
    """T does not depend on dv_cy: with only dv_cy uncertain its spread is rounding (it showed
    as 4.106 ± 8.7e-16 ms)."""
    r = invert(**PAPER_20, sliding_length=1400e-6, dv_cy=(0.618, 0.01), n_samples=2000)
    assert r.sigma_T_mc == 0.0 and r.sigma_T_linear == 0.0
    assert r.sigma_F_mc > 0.0
    t_line = next(line for line in str(r).splitlines() if line.startswith("  T = "))
    assert "±" not in t_line and "e-1" not in str(r)


def test_cli_shows_the_median_and_the_interval(cli_main: CliMain) -> None:
    args = ("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--mu", "0.2", "--delta-p",
            "22 um", "--ls", "1400 um", "--samples", "2000")  # fmt: skip
    code, out, err = cli_main(*args, "--dv-cy", "0.618 m/s", "--sigma-dv-cy", "0.01")
    assert code == 0, err
    rows = {line.split("│")[1].strip(): line.split("│")[2].strip() for line in out.splitlines()
            if line.count("│") == 4}  # fmt: skip
    assert rows["T_mc"] == "4.106" and rows["duration"] == "4.106"  # no "± 8.7e-16"
    assert "±" in rows["F_mc"] and rows["F_median_mc"] and rows["T_interval_mc"].startswith("(")
    assert "95 % (2.5-97.5 percentiles)" in " ".join(out.split())
    code, out, err = cli_main(*args, "--e", "0.5", "--sigma-mu", "0.01", "--json")
    data = json.loads(out)
    assert data["T_median_mc"]["unit"] == "s" and data["F_median_mc"]["unit"] == "N"
    lo, hi = data["T_interval_mc"]["value"]
    assert lo < data["T_median_mc"]["value"] < hi and data["T_interval_mc"]["unit"] == "s"


def test_cli_warns_of_the_heavy_tail(cli_main: CliMain) -> None:
    code, out, err = cli_main(
        "invert", "--angle", "70 deg", "--vi", "-3.45 m/s", "--e", "0.05", "--mu", "0.10",
        "--sigma-mu", "0.05", "--delta-p", "105 um", "--ls", "200 um", "--json",
    )  # fmt: skip
    assert code == 0, err
    assert any("heavy tail" in w for w in json.loads(out)["warnings"])
    assert "warning: " in err and "heavy tail" in err
