"""docs/paper/reproduction.md on the paper's 70 deg statements: the reason it gives for what
the report checks holds, and its numbers for Sec. 5.2's comparative statements (simulated /
measured at 70 deg against 20 and 45 deg) are the reproduction's."""

from __future__ import annotations

import math

import pytest

from impactlab.paper import data as D
from impactlab.paper.analytic_rows import experimental_rows
from impactlab.paper.quantities import PAPER_DEPTH, TOL_SIMULATED

NUMBER = r"[-+]?\d+(?:\.\d+)?"


@pytest.fixture(scope="module")
def ratios(sims):
    """Simulated / measured per (quantity, angle): a Series over the laws."""
    exp = experimental_rows().set_index("angle [deg]")
    out = {}
    for ang in (20, 45, 70):
        x, s = D.EXPERIMENTS[ang], sims.loc[ang]
        out[("delta_p", ang)] = s[PAPER_DEPTH].abs() / (abs(x.delta_p) * 1e6)
        # the scar against the contact patch's travel, as the report compares it
        out[("L_s", ang)] = s["contact travel [um]"].abs() / (abs(x.L_s) * 1e6)
        out[("T", ang)] = s["T [ms]"] / exp.loc[ang, "T [ms]"]
        out[("F", ang)] = s["F [N]"] / exp.loc[ang, "F [N]"]
    return out


def test_the_reason_given_is_no_longer_the_unprinted_numbers(page):
    text = " ".join(page.reproduction.split())
    assert "refers to numbers the paper never printed" not in text
    assert "against impactlab's own Table 4, since the paper's has a caption and no rows" in text


def test_the_comparative_statements_numbers(page, ratios, sims):
    text = " ".join(page.reproduction.split())
    n = NUMBER
    found = page.numbers(
        rf"delta_p is closer at 70 deg \(({n})-({n})\) than at 20 deg \(({n})-({n})\) and 45 deg "
        rf"\(({n})-({n})\), and still different; L_s, the scar set against the simulations' "
        rf"contact travel \(({n})-({n}), against ({n})-({n}) and ({n})-({n})\), is closer, but "
        rf"no longer different: within 15 % for all three laws \(the slip, which the scar does "
        rf"not measure, would put Brake's at \+({n}) %\); T \(({n})-({n}), against "
        rf"({n})-({n}) and ({n})-({n})\) and F \(({n})-({n}), "
        rf"against ({n})-({n}) and ({n})-({n})\) are closer as well",
        text,
    )
    order = [
        ("delta_p", 70), ("delta_p", 20), ("delta_p", 45),
        ("L_s", 70), ("L_s", 20), ("L_s", 45),
    ]  # fmt: skip
    quoted = list(found)
    for key in order:
        lo, hi = quoted.pop(0), quoted.pop(0)
        page.check(lo, ratios[key].min(), f"{key} low")
        page.check(hi, ratios[key].max(), f"{key} high")
    brake = quoted.pop(0)
    slip = sims.loc[70]["L_s [um]"]["brake"] / D.EXPERIMENTS[70].L_s / 1e6
    page.check(brake, 100 * (abs(slip) - 1), "Brake's slip at 70 deg")
    for key in [("T", 70), ("T", 20), ("T", 45), ("F", 70), ("F", 20), ("F", 45)]:
        lo, hi = quoted.pop(0), quoted.pop(0)
        page.check(lo, ratios[key].min(), f"{key} low")
        page.check(hi, ratios[key].max(), f"{key} high")


def test_the_comparative_statements_hold_as_written(ratios):
    far = {k: v.map(lambda r: abs(math.log(r))) for k, v in ratios.items()}
    for q in ("delta_p", "L_s", "T", "F"):  # each law closer at 70 deg than at 20 and 45
        assert (far[(q, 70)] < far[(q, 20)]).all() and (far[(q, 70)] < far[(q, 45)]).all(), q
    assert (abs(ratios[("delta_p", 70)] - 1) > TOL_SIMULATED).all()  # still different
    off = abs(ratios[("L_s", 70)] - 1)
    assert not [law for law, d in off.items() if d > TOL_SIMULATED]  # the slip: Brake's beyond
