"""The paper's durations: the corrected analytic inversion (``impactlab.analytic.invert``) against
the published 4.30 ms and 1.40 ms (doi:10.1007/s00419-015-1108-2, Tables 2-3)."""

from __future__ import annotations

from typing import Any

from impactlab.paper.analytic_rows import duration_range, invert_case
from impactlab.paper.data import EXPERIMENTS, TABLE_ROWS
from impactlab.paper.quantities import (
    FAIL,
    TOL_EXPERIMENT_T,
    UNDECIDED,
    rounding_range,
    verdict,
)
from impactlab.verification.table import TOLERANCES, VerificationTable, columns, worst_of

__all__ = ["verify_paper_durations"]


def verify_paper_durations(n_samples: int = 2000) -> VerificationTable:
    """The paper's three experiments through ``impactlab.analytic.invert`` (corrected Eq. 12,
    I_C = m L^2/12, gravity neglected as in the paper): T against the published 4.30 and
    1.40 ms; F (rigid-body identity) shown against the published 79 and 595 N.

    The checked number is T at the printed (nominal) values. Each row also carries the range of
    T / T_published - 1 over the rounding of the printed inputs and of the published T, and the
    reproduction's verdict over it (``impactlab.paper.quantities.verdict``: PASS, FAIL or
    UNDECIDED; 20 deg is UNDECIDED), both named in ``metric``; ``passed`` is False when the
    nominal value exceeds the tolerance or any verdict is FAIL."""
    published = {(row.angle_deg, row.model): row for row in TABLE_ROWS}
    records: list[dict[str, Any]] = []
    for ang, x in sorted(EXPERIMENTS.items()):
        # the paper prints the dent's depth and length negative; impactlab takes magnitudes
        res = invert_case(x, n_samples=n_samples)
        row = published.get((ang, "experiment"))
        T_pub = row.T if row is not None else None
        F_pub = row.F if row is not None else None
        low = high = None
        if T_pub is not None:
            T_lo, T_hi = duration_range(x)
            low, high = rounding_range(T_lo * 1e3, T_hi * 1e3, T_pub * 1e3)
        records.append(
            {
                "angle": float(ang),
                "alpha": res.alpha,
                "mu_c": res.mu_c,
                "T_pub": None if T_pub is None else T_pub * 1e3,
                "T": res.duration * 1e3,
                "err_T": None if T_pub is None else res.duration / T_pub - 1.0,
                "low": low,
                "high": high,
                "verdict": None if low is None or high is None else verdict(low, high),
                "F_pub": F_pub,
                "F": res.mean_force,
                "err_F": None if F_pub is None else res.mean_force / F_pub - 1.0,
            }
        )
    checked = [abs(r["err_T"]) for r in records if r["err_T"] is not None]
    worst = worst_of(checked)
    tol = TOLERANCES["paper_duration"]
    assert tol == TOL_EXPERIMENT_T  # the reproduction's tolerance: one verdict everywhere
    verdicts = ", ".join(f"{r['angle']:.0f} deg {r['verdict']}" for r in records if r["verdict"])
    cols = columns(
        """
        angle   | angle [deg]                     | .3g
        mu_c    | mu_c                            | .4f
        alpha   | alpha                           | .4f
        T_pub   | T published [ms]                | .3g
        T       | T impactlab [ms]                | .4g
        err_T   | rel. diff. T (checked)          | +.1%
        low     | rel. diff. T, printed digits low | +.1%
        high    | high                            | +.1%
        verdict | verdict over the printed digits
        F_pub   | F published [N]                 | .4g
        F       | F impactlab [N]                 | .4g
        err_F   | rel. diff. F (not checked)      | +.1%
        """
    )
    undecided = " and ".join(f"{r['angle']:.0f}" for r in records if r["verdict"] == UNDECIDED)
    undecided_words = (
        f"At {undecided} deg it is **UNDECIDED**: the printed digits cannot tell whether the "
        "inversion\nmeets the paper's T within 5 %.\n"
        if undecided
        else ""
    )
    text = f"""
The paper's measured inputs (Sec. 5.1.3: angle, v_i, e, mu, delta_p, L_s) through
`impactlab.analytic.invert`: Eq. 12 with the corrected alpha (Eq. 13 with its sign and the
(L cos theta)^2 term fixed, see the [errata](../paper/errata.md)), the slender-rod
I_C = m L^2/12 (the paper does not give I_C), gravity neglected as in the paper. T is compared
with the published 4.30 ms (Table 2) and 1.40 ms (Table 3); the paper prints no T at 70 deg.

**This row checks the nominal value only**: T from the inputs exactly as printed, within 5 % of
the published T. Over the rounding of the printed inputs (half a unit of each one's last digit)
and of the published T, T / T_published - 1 spans the range shown, and the verdict over it is
the [reproduction's](../paper/reproduction.md): PASS when the whole range lies within 5 %, FAIL
when it lies wholly outside, UNDECIDED when it straddles 5 %.
{undecided_words}The row passes when the nominal value is within 5 % and no verdict is FAIL.

F uses the rigid-body identity F T = (1 + e) abs(v_i) / K_y because the centre-of-mass
velocities of the paper's Eq. 29 are not printed; its difference from the published F is
explained in [the analytic method](../analytic.md) (Sec. 6) and is not a tolerance check.
"""
    return VerificationTable(
        "paper_duration",
        "Analytic inversion vs the paper's T",
        text,
        cols,
        tuple(records),
        f"abs(T / T_published - 1) at the printed values; over their rounding: {verdicts}",
        worst,
        tol,
        worst <= tol and all(r["verdict"] != FAIL for r in records),
    )
