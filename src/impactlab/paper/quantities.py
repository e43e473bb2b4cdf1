"""What the reproduction compares: the quantities, their display scales, the tolerances, and the
simulated results in the paper's sign convention (dent depth negative, as its tables print it).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from impactlab.contact.verified_ranges import tolerance_text

#: Tolerances of the comparison (relative): simulated e and delta_p, the experimental T.
TOL_SIMULATED = 0.15
TOL_EXPERIMENT_T = 0.05

#: The verdicts of the T check over the rounding of the published T: within the tolerance for
#: every value the printed T stands for, outside it for every one, or neither (the printed
#: digits cannot tell).
PASS, FAIL, UNDECIDED = "PASS", "FAIL", "UNDECIDED"


def rounding_range(T_ms: float, published_ms: float) -> tuple[float, float]:
    """(lowest, highest) ours / published - 1 over the interval the published T stands for:
    printed in ms with two decimals, 1.40 ms is 1.395-1.405 ms."""
    half = 0.005
    return T_ms / (published_ms + half) - 1.0, T_ms / (published_ms - half) - 1.0


def verdict(low: float, high: float, tol: float = TOL_EXPERIMENT_T) -> str:
    """PASS when [``low``, ``high``] lies within +- ``tol``, FAIL when wholly outside it, else
    UNDECIDED."""
    if -tol <= low and high <= tol:
        return PASS
    if high < -tol or low > tol:
        return FAIL
    return UNDECIDED


#: The column of a dent depth in the paper's sign (negative, as its tables print it); impactlab
#: reports delta_p as a positive depth everywhere else (``impactlab.schema``).
PAPER_DEPTH = "delta_p, paper's sign [um]"
#: The note under a table with ``PAPER_DEPTH``.
PAPER_SIGN_NOTE = (
    'Signs: the columns marked "paper\'s sign" print the dent depth as the paper does '
    "(negative); impactlab's delta_p is a positive depth (as in Section 11 and every other "
    "output). L_s is the signed slip up to Section 7: negative when the tip slides towards -x, "
    "as in the paper's tables and impactlab's sliding_length; Section 11 compares the extent "
    "of the mark (a positive length, as a scan measures it). A relative difference is ours / "
    "published - 1, except where a column says otherwise (published / Eq. 12 - 1)."
)

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
    """The acceptance test of one experiment: the inverted T [ms] against the published one."""

    angle_deg: int
    T_ms: float
    published_ms: float
    rel_diff: float

    @property
    def ok(self) -> bool:
        """Within ``TOL_EXPERIMENT_T`` for every value the published T stands for."""
        return self.verdict == PASS

    @property
    def verdict(self) -> str:
        """``PASS``, ``FAIL`` or ``UNDECIDED`` over the rounding of the published T."""
        return verdict(*rounding_range(self.T_ms, self.published_ms))

    def text(self) -> str:
        """``20 deg: T = 4.106 ms vs published 4.30 ms (-4.5%, tolerance 5%): PASS``, the one
        wording of the report and the reproduce command (T to the microsecond, the published
        value as printed; an UNDECIDED verdict with the range over its rounding)."""
        low, high = rounding_range(self.T_ms, self.published_ms)
        over = f", {low:+.1%} to {high:+.1%} over its rounding" if self.verdict == UNDECIDED else ""
        return (
            f"{self.angle_deg} deg: T = {self.T_ms:.3f} ms vs published {self.published_ms:.2f} "
            f"ms ({self.rel_diff:+.1%}{over}, tolerance {TOL_EXPERIMENT_T:.0%}): {self.verdict}"
        )


def duration_checks(experimental: Any) -> list[DurationCheck]:
    """The acceptance tests (20 and 45 deg) from the experimental rows (a DataFrame with the
    columns of ``impactlab.paper.analytic_rows.experimental_rows``)."""
    rows = experimental.set_index("angle [deg]")
    return [
        DurationCheck(
            ang,
            rows.loc[ang]["T [ms]"],
            rows.loc[ang]["T published [ms]"],
            rows.loc[ang]["T rel. diff"],
        )
        for ang in (20, 45)
    ]


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
