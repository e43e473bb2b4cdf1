"""What the reproduction compares: the quantities, their display scales, the tolerances, and the
simulated results in the paper's sign convention (dent depth negative, as its tables print it).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from impactlab.contact.verified_ranges import tolerance_text

if TYPE_CHECKING:
    import pandas as pd

#: Tolerances of the comparison (relative), each stated with its reason in
#: docs/paper/reproduction.md. The experimental T (pass/fail): a check of the inversion's
#: arithmetic with the paper's own inputs; 5 % leaves room for the paper's unstated choices
#: (I_C, the reading of L) and is far below the -21 % / -35 % of the misprinted Eq. 13.
TOL_EXPERIMENT_T = 0.05
#: The published simulated rows (e, delta_p, L_s, T, F; compared, not pass/fail): 15 %, for
#: the details of the paper's simulations it does not give (solver, time step, end of contact).
TOL_SIMULATED = 0.15
#: The experimental F (compared, not pass/fail): 15 %, as the simulated rows; the published F
#: comes from centre-of-mass velocities (Eq. 29) the paper does not give, impactlab's from the
#: rigid-body identity F T = (1 + e)|v_i|/K_y.
TOL_EXPERIMENT_F = 0.15
#: The verdicts of the T check over the rounding of the printed numbers: within the tolerance
#: for every value they stand for, outside it for every one, or neither (the printed digits
#: cannot tell).
PASS, FAIL, UNDECIDED = "PASS", "FAIL", "UNDECIDED"

#: What each verdict says, after it in the ``reason`` of a checked row.
VERDICT_WORDS = {
    PASS: "within the tolerance for every value the printed numbers stand for",
    FAIL: "outside the tolerance for every value the printed numbers stand for",
    UNDECIDED: "the printed digits cannot tell whether it is within the tolerance",
}
#: ``reproduced`` of a checked row by its verdict: True only for PASS, None (neither) for
#: UNDECIDED.
REPRODUCED_BY_VERDICT: dict[str, bool | None] = {PASS: True, FAIL: False, UNDECIDED: None}

#: Half a unit of the last printed digit of the published T [ms] (two decimals: 1.40 ms is
#: 1.395-1.405 ms).
T_ROUNDING_MS = 0.005


def rounding_range(low_ms: float, high_ms: float, published_ms: float) -> tuple[float, float]:
    """(lowest, highest) ours / published - 1 when ours lies in [``low_ms``, ``high_ms``] (the
    inverted T over the rounding of its inputs) and the published T anywhere in the interval it
    stands for (``published_ms`` +- ``T_ROUNDING_MS``)."""
    return (
        low_ms / (published_ms + T_ROUNDING_MS) - 1.0,
        high_ms / (published_ms - T_ROUNDING_MS) - 1.0,
    )


def verdict(low: float, high: float, tol: float = TOL_EXPERIMENT_T) -> str:
    """PASS when [``low``, ``high``] lies within +- ``tol``, FAIL when wholly outside it, else
    UNDECIDED."""
    if -tol <= low and high <= tol:
        return PASS
    if high < -tol or low > tol:
        return FAIL
    return UNDECIDED


#: Half a unit of the last printed digit of the measured velocities [m/s] and of e (two
#: decimals: v_Of = 1.08 m/s stands for 1.075-1.085 m/s).
PRINTED_HALF_UNIT = 0.005


def rebound_ratio_range(v_rebound: float, v_i: float) -> tuple[float, float]:
    """(lowest, highest) v_Of / |v_i| over the rounding of the printed ``v_rebound`` (v_Of) and
    ``v_i`` [m/s] (``PRINTED_HALF_UNIT`` each)."""
    h = PRINTED_HALF_UNIT
    return (v_rebound - h) / (abs(v_i) + h), (v_rebound + h) / (abs(v_i) - h)


#: Caveats of impactlab's own numbers that rest on a method applied outside its assumption,
#: by angle [deg]: (the quantities concerned, ``QUANTS`` keys; the words). At 70 deg Eq. 12
#: assumes sliding throughout, while the paper reads the dent as sliding, then sticking.
ESTIMATE_CAVEATS: Mapping[int, tuple[tuple[str, ...], str]] = {
    70: (
        ("T", "F"),
        "an estimate outside Eq. 12's assumption: Eq. 12 assumes sliding throughout, the paper "
        "reads this dent (Fig. 8) as sliding, then sticking or rolling; F follows from this T",
    ),
}


def caveat(angle: int, q: str) -> str:
    """The caveat of the experimental ``q`` (a ``QUANTS`` key) at ``angle`` [deg]; ``""``:
    none."""
    quantities, words = ESTIMATE_CAVEATS.get(angle, ((), ""))
    return words if q in quantities else ""


#: The column of a dent depth in the paper's sign (negative, as its tables print it); impactlab
#: reports delta_p as a positive depth everywhere else (``impactlab.schema``).
PAPER_DEPTH = "delta_p, paper's sign [um]"
#: The note under a table with ``PAPER_DEPTH``.
PAPER_SIGN_NOTE = (
    'Signs: the columns marked "paper\'s sign" print the dent depth as the paper does '
    "(negative); impactlab's delta_p is a positive depth (as in every other output). L_s is "
    "the signed slip: negative when the tip slides towards -x, as in the paper's tables and "
    "impactlab's sliding_length; where the simulations are set against the measured scar "
    "(the simulated rows' experiment-vs-simulation table, the contact patch's travel; the "
    "section that sets the drops beside the rigid and the flexible rod, its column "
    "scar_length, a positive length), the extent of the mark is compared instead, as a "
    "scan measures it. A relative "
    "difference is ours / published - 1, except where a column says otherwise (published / "
    "Eq. 12 - 1)."
)


#: The start of the ``reason`` of a published number within its tolerance that is not counted
#: as reproduced: a probable copy of another row's value, so the agreement is most likely chance.
COINCIDENCE = "most likely a coincidence, not a reproduction"
#: The ``reason`` of a published simulated number that was not compared: the simulations were
#: skipped (``reproduce(simulate=False)``, ``--no-simulate``).
NOT_SIMULATED = "not simulated"
#: The columns that name one published number (its two friction models' rows count once).
PUBLISHED_KEY = ["source", "angle [deg]", "model", "quantity"]


def comparison_counts(comparison: pd.DataFrame) -> tuple[int, int]:
    """(published numbers not reproduced, published numbers not compared because the
    simulations were skipped) in a comparison table (``comparison.comparison_table``), each
    number once whichever friction model it is compared with."""
    bad = comparison[comparison["reproduced"] == False]  # noqa: E712
    skipped = comparison.iloc[:0]  # a table without reasons: every number was compared
    if {"reason", "published"} <= set(comparison.columns):
        not_run = comparison["reason"] == NOT_SIMULATED
        skipped = comparison[not_run & comparison["published"].notna()]
    return len(bad.drop_duplicates(PUBLISHED_KEY)), len(skipped.drop_duplicates(PUBLISHED_KEY))


def verdict_counts(comparison: pd.DataFrame) -> tuple[int, int]:
    """(published numbers reproduced, published numbers UNDECIDED: the printed digits allow
    either) in a comparison table, each number once as in ``comparison_counts``; a number
    within its tolerance but not counted as reproduced (``COINCIDENCE``) is neither."""
    good = comparison[comparison["reproduced"] == True]  # noqa: E712
    undecided = comparison.iloc[:0]
    if "verdict" in comparison.columns:
        undecided = comparison[comparison["verdict"] == UNDECIDED]
    return len(good.drop_duplicates(PUBLISHED_KEY)), len(undecided.drop_duplicates(PUBLISHED_KEY))


def coincidence_count(comparison: pd.DataFrame) -> int:
    """Published numbers within their tolerance but not counted as reproduced (a ``reason``
    starting with ``COINCIDENCE``), each number once as in ``comparison_counts``."""
    if "reason" not in comparison.columns:
        return 0
    chance = comparison["reason"].fillna("").astype(str).str.startswith(COINCIDENCE)
    return len(comparison[chance].drop_duplicates(PUBLISHED_KEY))


def not_reproduced_line(
    n: int,
    not_compared: int = 0,
    reproduced: int | None = None,
    undecided: int = 0,
    coincidences: int = 0,
) -> str:
    """The reproduce command's line on the published numbers: ``reproduced`` (where given)
    and ``undecided`` ones first, then those not reproduced (``n``), singular or plural as the
    first count asks, the ``coincidences`` (within tolerance, not counted as reproduced) and
    the ``not_compared`` ones (simulations skipped) when there are any (``comparison_counts``,
    ``verdict_counts`` and ``coincidence_count`` give them)."""
    if reproduced is None:
        what = "published number" if n == 1 else "published numbers"
        line = f"{n} {what} not reproduced within the stated tolerances"
    else:
        what = "published number" if reproduced == 1 else "published numbers"
        line = (
            f"{reproduced} {what} reproduced within the stated tolerances, {undecided} "
            f"undecided (the printed digits allow either), {n} not reproduced"
        )
    if coincidences:
        its = "its tolerance" if coincidences == 1 else "their tolerances"
        line += (
            f", {coincidences} within {its} but not counted as reproduced (most likely a "
            "coincidence)"
        )
    if not not_compared:
        return f"{line} (explained in Section 5 of the report)"
    return (
        f"{line}, and {not_compared} not compared: the simulations were skipped "
        "(--no-simulate; Section 5 of the report lists them)"
    )


def summary_line(comparison: pd.DataFrame) -> str:
    """The reproduce command's line: how many published numbers ``comparison`` reproduces,
    leaves UNDECIDED, does not reproduce, finds within tolerance by coincidence and does not
    compare (``not_reproduced_line``)."""
    n_bad, n_skipped = comparison_counts(comparison)
    good, undecided = verdict_counts(comparison)
    return not_reproduced_line(n_bad, n_skipped, good, undecided, coincidence_count(comparison))


#: The column of a published L_s relative to Eq. 12 on its own row (published / Eq. 12 - 1).
EQ12_REL = "published / Eq. 12 - 1"

#: The compared quantities: (attribute of ``PublishedRow``, column label, display scale).
QUANTS: tuple[tuple[str, str, float], ...] = (
    ("delta_p", PAPER_DEPTH, 1e6),
    ("L_s", "L_s [um]", 1e6),
    ("e", "e", 1.0),
    ("T", "T [ms]", 1e3),
    ("F", "F [N]", 1.0),
)

#: Simulations keyed by (angle [deg], law, friction), values ``ImpactResult``.
Simulations = Mapping[tuple[int, str, str], Any]


@dataclass(frozen=True)
class DurationCheck:
    """The acceptance test of one experiment: the inverted T [ms] against the published one.
    ``T_low_ms``, ``T_high_ms``: the inverted T's extremes over the rounding of its printed
    inputs (None: the inputs taken as exact)."""

    angle_deg: int
    T_ms: float
    published_ms: float
    rel_diff: float
    T_low_ms: float | None = None
    T_high_ms: float | None = None

    @property
    def range(self) -> tuple[float, float]:
        """(lowest, highest) ours / published - 1 over the rounding of the inputs and of the
        published T (``rounding_range``)."""
        low = self.T_ms if self.T_low_ms is None else self.T_low_ms
        high = self.T_ms if self.T_high_ms is None else self.T_high_ms
        return rounding_range(low, high, self.published_ms)

    @property
    def ok(self) -> bool:
        """Within ``TOL_EXPERIMENT_T`` for every value the printed numbers stand for."""
        return self.verdict == PASS

    @property
    def verdict(self) -> str:
        """``PASS``, ``FAIL`` or ``UNDECIDED`` over the rounding of the printed numbers."""
        return verdict(*self.range)

    def reason(self) -> str:
        """The check in words, as the ``reason`` of its row of the comparison: ``-5.7% to -3.3%
        from the published T over the rounding of the printed inputs and of the published T
        (tolerance 5%): UNDECIDED, ...``."""
        low, high = self.range
        return (
            f"{low:+.1%} to {high:+.1%} from the published T over the rounding of the printed "
            f"inputs and of the published T (tolerance {TOL_EXPERIMENT_T:.0%}): {self.verdict}, "
            + VERDICT_WORDS[self.verdict]
        )

    def text(self) -> str:
        """``20 deg: T = 4.106 ms vs published 4.30 ms (-4.5%; -5.7% to -3.3% over the printed
        digits, tolerance 5%): UNDECIDED``, the one wording of the report and the reproduce
        command (T to the microsecond, the published value as printed, the range over the
        rounding of the inputs and of the published T)."""
        low, high = self.range
        return (
            f"{self.angle_deg} deg: T = {self.T_ms:.3f} ms vs published {self.published_ms:.2f} "
            f"ms ({self.rel_diff:+.1%}; {low:+.1%} to {high:+.1%} over the printed digits, "
            f"tolerance {TOL_EXPERIMENT_T:.0%}): {self.verdict}"
        )


#: The columns of ``experimental_rows`` with the inverted T's extremes over the rounding of the
#: printed inputs.
T_LOW, T_HIGH = "T low, inputs' rounding [ms]", "T high, inputs' rounding [ms]"


def duration_checks(experimental: Any) -> list[DurationCheck]:
    """The acceptance tests (20 and 45 deg) from the experimental rows (a DataFrame with the
    columns of ``impactlab.paper.analytic_rows.experimental_rows``)."""
    rows = experimental.set_index("angle [deg]")
    checks = []
    for ang in (20, 45):
        r = rows.loc[ang]
        lo, hi = (r[T_LOW], r[T_HIGH]) if T_LOW in rows else (None, None)
        checks.append(
            DurationCheck(ang, r["T [ms]"], r["T published [ms]"], r["T rel. diff"], lo, hi)
        )
    return checks


def scaled(x: float | None, scale: float) -> float | None:
    """``x * scale`` (None stays None)."""
    return None if x is None else x * scale


def rel_diff(ours: float | None, pub: float | None) -> float | None:
    """Relative difference ours / pub - 1 (for the negative depths and lengths: the difference in
    magnitude, negative when impactlab's is smaller)."""
    if ours is None or pub is None or pub == 0:
        return None
    return ours / pub - 1.0


def paper_depth(res: Any) -> float:
    """The simulated dent depth in the paper's sign convention (negative; the engine reports the
    residual depth of the unloading branch as a magnitude) [m]."""
    return -abs(float(res.delta_p))


def sim_value(res: Any, q: str) -> float:
    """The simulated value of quantity ``q`` (a ``QUANTS`` key) in SI, paper signs."""
    return {
        "delta_p": paper_depth(res),
        "L_s": res.sliding_length,
        "e": res.e,
        "T": res.duration,
        "F": res.mean_force,
    }[q]


#: The mark of a simulated row whose impact left its law's verified range (LAW_EXTRAPOLATED).
EXTRAPOLATED_MARK = "\u2020"


def flag_names(res: Any) -> str:
    """The flags of a result as names joined by ``|`` (``""``: none), e.g. ``LAW_EXTRAPOLATED``."""
    return "|".join(f.name for f in type(res.flags) if f.value and f in res.flags and f.name)


def flag_columns(res: Any) -> dict[str, Any]:
    """The ``flags`` (names) and ``max_delta_ratio`` (delta_max / delta_ref, the law's own
    reference) of a simulated result, as the reproduction's tables carry them."""
    return {"flags": flag_names(res), "max_delta_ratio": float(res.max_delta_ratio)}


def is_extrapolated(res: Any) -> bool:
    """Whether a simulated result is flagged LAW_EXTRAPOLATED."""
    return "LAW_EXTRAPOLATED" in flag_names(res).split("|")


def reference_of(law: str) -> str:
    """The name of ``law``'s ratio reference (``LawRange.reference``: ``delta_c`` or
    ``delta_y``; ``delta_ref`` for a law without a registered range)."""
    from impactlab.contact.ranges import law_range

    try:
        return law_range(law).reference
    except ValueError:
        return "delta_ref"


def extrapolation_label(res: Any) -> str:
    """`` (extrapolated: 178 delta_c)`` for a result flagged LAW_EXTRAPOLATED (its
    ``max_delta_ratio`` in its law's own reference), ``""`` otherwise: the mark of a curve in a
    figure's legend or title."""
    if not is_extrapolated(res):
        return ""
    return f" (extrapolated: {float(res.max_delta_ratio):.0f} {reference_of(str(res.law))})"


def count_extrapolated(simulations: Any) -> tuple[int, int]:
    """(flagged LAW_EXTRAPOLATED, all) simulated impacts of a simulation table (a DataFrame with
    a ``flags`` column, as ``impactlab.paper.simulations.simulation_table`` makes it)."""
    if simulations is None or len(simulations) == 0:
        return 0, 0
    flagged = simulations["flags"].fillna("").str.contains("LAW_EXTRAPOLATED")
    return int(flagged.sum()), len(simulations)


def extrapolation_line(simulations: Any) -> str:
    """The one line the reproduce command prints about the flagged simulated impacts."""
    n, m = count_extrapolated(simulations)
    return (
        f"{n} of {m} simulated impacts lie beyond their law's verified range "
        f"({tolerance_text()}); see report"
    )
