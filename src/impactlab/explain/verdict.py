"""Which configuration explains a drop best, like with like: the configurations whose result
is ok are ranked over the measured quantities that all of them predict (the most values within
2 sigma, then the lowest sum of z^2 over those quantities), never over different ones; a
quantity that one of them does not predict (a flexible rod's duration) is left out, and the
verdict says so. The first of that ranking is named only if it agrees within 2 sigma with at
least one of the values it was ranked over and no other ok configuration agrees with more of
the drop's measured values (it can then only be with quantities left out). A first that
agrees with none of the values ranked over is never named, whatever it agrees with among the
values left out: the verdict says that no configuration agrees and names it as the least
disagreeing one, as it would without the values left out, so that measuring a quantity only
one configuration predicts never turns the verdict to it. None is named when the ok
configurations share no measured quantity.

Named is not consistent: the first of the ranking can still be rejected by the measurements.
Its chi2 over the n measured values it predicts (``Verdict.consistency_chi2`` over
``Verdict.predicted_over``: those ranked over and those left out of the ranking because another
row does not predict them; z^T R^-1 z for correlated values) is set against the chi-square
distribution with n degrees of freedom, nothing being fitted (Pearson's
goodness-of-fit test: K. Pearson, Phil. Mag. 50, 157-175 (1900),
doi:10.1080/14786440009463897; Particle Data Group, "Statistics",
Prog. Theor. Exp. Phys. 2022, 083C01, doi:10.1093/ptep/ptac097): where its p-value, the
probability of a chi2 at least as large, is below :data:`LEVEL` = 0.01 (chi2 above the 99 %
quantile: 6.63 for one value, 11.34 for three), the row is inconsistent with the measurements
(``Verdict.consistent`` False). A named row that is inconsistent is worded as ranking first,
"but is itself inconsistent with the measurements (chi2 X over n values, p = ...)" ("over n
values it predicts" where some were left out of the ranking), and the table marks it
``first, inconsistent``, not ``best``. A named row whose contact law is used
beyond its verified range (law_extrapolated) says so in its reason too.

Near the 2-sigma line the verdict does not turn on a hair: where the first ranks above
another by its count within 2 sigma alone, the other's chi2 is lower, and the counts could
tie or turn with values within :data:`NEAR` sigma of |z| = 2, the verdict is undecided between
them (and names neither).

For a drop with correlation coefficients the sum of z^2 is z^T R^-1 z over those quantities
(``explain.correlated``). A flexible row not converged in its modes (``explain.modes``) stays in
the ranking with its numbers and may be named; the verdict is then provisional where more
modes could change it (``explain.modes``: the row decides the verdict, or its values,
moved as far as its mode check allows, could bring it level with the first), and its reason
(and a note) says so: leaving the row out would hand the verdict to another configuration for
a numerical shortfall of this one, whose refined values may agree better still. A named row
with another caveat (a rigid rod whose rod the flexible rows refuse) makes it provisional too,
and the reason names the caveat."""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import pandas as pd
from scipy.special import chdtrc

from impactlab.explain.correlated import Pairs, correlated_chi2
from impactlab.explain.modes import ModeCheck, Standing, provisional_text
from impactlab.explain.tables import WITHIN

__all__ = ["LEVEL", "NEAR", "Verdict", "drop_modes", "p_value", "verdict"]

#: Values within this many sigma of |z| = 2 do not decide a verdict against chi2 [1].
NEAR = 0.05
#: A first of the ranking whose chi2 has a p-value below this is inconsistent with the
#: measurements [1] (module docstring).
LEVEL = 0.01


def p_value(chi2: float, n: int) -> float:
    """The probability of a chi2 at least ``chi2`` with ``n`` degrees of freedom [1]."""
    return float(chdtrc(n, chi2))


def _p_text(p: float) -> str:
    return "p < 1e-300" if p < 1e-300 else f"p = {p:.2g}"


@dataclass(frozen=True, repr=False)
class Verdict:
    """Which configuration explains ``drop`` best (module docstring).

    ``configuration``: its name (None: none is named, ``reason`` says why); ``ranked_over``:
    the measured quantities the ranking is over; ``left_out``: those not predicted by every ok
    configuration; ``reason``: the verdict in words; ``provisional``: a ranked flexible row not
    converged in modes could move level with the first, or the named row has a caveat;
    ``least_disagreeing``: the first of the ranking where none agrees with a value ranked over
    within 2 sigma; ``undecided``: the configurations it is undecided between (near the 2-sigma
    line).

    Of the first of the ranking (the row the reason names): ``within_2_sigma`` and ``chi2``,
    its count within 2 sigma and its chi2 over ``ranked_over`` (what it was ranked by);
    ``predicted_over``, every measured quantity it predicts (``ranked_over`` and those of
    ``left_out`` it predicts); ``consistency_chi2``, its chi2 over ``predicted_over``;
    ``p_value``, the p-value of ``consistency_chi2`` with ``len(predicted_over)`` degrees of
    freedom; ``consistent``, whether ``p_value`` >= :data:`LEVEL` (None: nothing was ranked);
    its ``caveat``; ``agreements``, its values within 2 sigma among all the drop's measured
    quantities."""

    drop: str
    configuration: str | None
    ranked_over: tuple[str, ...]
    left_out: tuple[str, ...]
    reason: str
    provisional: bool = False
    least_disagreeing: str | None = None
    undecided: tuple[str, ...] = ()
    within_2_sigma: int | None = None
    chi2: float = math.nan
    caveat: str = ""
    agreements: int | None = None
    p_value: float = math.nan
    consistent: bool | None = None
    consistency_chi2: float = math.nan
    predicted_over: tuple[str, ...] = ()

    @property
    def quantities(self) -> tuple[str, ...]:
        """Deprecated: :attr:`ranked_over` (this name is removed in the next release)."""
        warnings.warn(
            "Verdict.quantities is deprecated: use Verdict.ranked_over",
            DeprecationWarning,
            stacklevel=2,
        )
        return self.ranked_over

    @property
    def agrees(self) -> bool | None:
        """Whether the first of the ranking agrees with a measured value within 2 sigma, any of
        the drop's, ranked over or left out (``agreements`` of them; None: nothing was
        ranked)."""
        if self.agreements is None:
            return None
        return self.agreements > 0

    @property
    def note(self) -> str:
        """The line ``notes`` gives the verdict ("" when a configuration is named, consistent
        with the measurements, ranked over every measured quantity, and not provisional)."""
        plain = self.configuration is not None and self.consistent is not False
        if plain and not self.left_out and not self.provisional:
            return ""
        return f"best: {self.reason}"

    def __repr__(self) -> str:
        """One short line: the drop, the first of the ranking (or none), whether it is
        consistent with the measurements (p to 2 digits) and its agreements (``reason``: the
        verdict in words)."""
        if self.configuration is not None:
            first = f"first {self.configuration!r}"
        elif self.undecided:
            first = f"none named: undecided between {_names(list(self.undecided))}"
        elif self.least_disagreeing is not None:
            first = f"none named: none agrees, least disagreeing {self.least_disagreeing!r}"
        else:
            first = "none named"
        parts = [f"drop {self.drop!r}", first]
        if self.consistent is not None:
            word = "consistent" if self.consistent else "inconsistent"
            parts.append(f"{word} ({_p_text(self.p_value)})")
        if self.agreements is not None:
            n = len(self.ranked_over) + len(self.left_out)
            parts.append(f"{self.agreements} of {n} values within 2 sigma")
        if self.provisional:
            parts.append("provisional")
        return f"Verdict({', '.join(parts)})"

    def to_dict(self) -> dict[str, object]:
        """JSON ``best``'s entry (numbers plain; ``Explanation.to_dict`` gives chi2,
        consistency_chi2 and p_value their unit)."""
        return {
            "drop": self.drop, "configuration": self.configuration,
            "consistent": self.consistent, "agrees": self.agrees,
            "agreements": self.agreements, "least_disagreeing": self.least_disagreeing,
            "undecided": list(self.undecided), "ranked_over": list(self.ranked_over),
            "left_out": list(self.left_out), "within_2_sigma": self.within_2_sigma,
            "chi2": self.chi2, "predicted_over": list(self.predicted_over),
            "consistency_chi2": self.consistency_chi2, "p_value": self.p_value,
            "provisional": self.provisional,
            "caveat": self.caveat or None, "reason": self.reason,
        }  # fmt: skip


def _names(items: list[str]) -> str:
    return ", ".join(items)


def _law_text(row: pd.Series) -> str:
    """What the reason adds for a named row whose contact law is used beyond its verified
    range ("" for none)."""
    flag = row["law_extrapolated"]
    if flag is None or pd.isna(flag) or not bool(flag):
        return ""
    ratio, verified = float(row["max_delta_ratio"]), float(row["fitted_delta_ratio_max"])
    numbers = (f": max_delta_ratio {ratio:.4g}, verified up to {verified:.4g}"
               if math.isfinite(ratio) and math.isfinite(verified) else "")  # fmt: skip
    return ("; it uses the contact law beyond its verified range "
            f"(law_extrapolated{numbers}), its own error unknown")  # fmt: skip


def _score(within: int, n: int, chi2: float) -> str:
    return f"{within} of {n} within 2 sigma, chi2 {chi2:.4g}"


def _undecided(first: str, names: list[str], total: pd.DataFrame, rows: pd.DataFrame) -> list[str]:
    """The configurations whose rank below ``first`` turns on values within :data:`NEAR` of
    the 2-sigma line alone, against their lower chi2."""
    z = {n: rows.loc[rows["configuration"] == n, "z"].abs() for n in names}
    lead = int(total.loc[first, "within_2_sigma"])
    lead_low = lead - int(((z[first] <= WITHIN) & (z[first] >= WITHIN - NEAR)).sum())
    out = []
    for n in names:
        count = int(total.loc[n, "within_2_sigma"])
        if n == first or count >= lead or not total.loc[n, "chi2"] < total.loc[first, "chi2"]:
            continue
        high = count + int(((z[n] > WITHIN) & (z[n] <= WITHIN + NEAR)).sum())
        if high >= lead_low:
            out.append(n)
    return out


def drop_modes(outcomes: Mapping[tuple[str, str], Any], drop: str) -> dict[str, ModeCheck | None]:
    """Each configuration's mode check on ``drop`` (``Outcome.modes``), as ``verdict`` takes
    them."""
    return {name: out.modes for (d, name), out in outcomes.items() if d == drop}


def verdict(
    summary: pd.DataFrame,
    comparison: pd.DataFrame,
    drop: str,
    correlation: Pairs | None = None,
    modes: Mapping[str, ModeCheck | None] | None = None,
) -> Verdict:
    """The verdict on ``drop`` from an explanation's ``summary`` and ``comparison`` (module
    docstring), ``correlation`` the drop's coefficients (None: none), ``modes`` each
    configuration's mode check on the drop (None: not known; a row not converged in modes then
    always makes the verdict provisional). KeyError naming the known drops for a drop not in
    them."""
    if drop not in set(summary["drop"]):
        known = list(dict.fromkeys(summary["drop"]))
        raise KeyError(f"no drop {drop!r}; drops: {known}")
    ok = summary[(summary["drop"] == drop) & summary["ok"].astype(bool)]
    mine = comparison[comparison["drop"] == drop]
    measured = [str(q) for q in dict.fromkeys(mine["quantity"])]
    got = mine[(mine["status"] == "ok") & mine["configuration"].isin(ok["configuration"])]
    predicts = {str(n): set(got.loc[got["configuration"] == n, "quantity"])
                for n in ok["configuration"]}  # fmt: skip
    names = [n for n, qs in predicts.items() if qs]  # an ok one predicting nothing: no rival
    if not names:
        why = "no configuration's result is ok and predicts a measured value: none is named"
        return Verdict(drop, None, (), (), why)
    common = tuple(q for q in measured if all(q in predicts[n] for n in names))
    if not common:
        return Verdict(drop, None, (), (), f"the ok configurations ({_names(names)}) predict no "
                       "measured quantity in common: none is named")  # fmt: skip
    rows = got[got["configuration"].isin(names) & got["quantity"].isin(common)]
    score = rows.assign(chi2=rows["z"] ** 2).groupby("configuration")[["within_2_sigma", "chi2"]]
    total = score.sum().reindex(names)
    for n in names:
        mine_n = rows[rows["configuration"] == n]
        z = dict(zip(mine_n["quantity"], mine_n["z"], strict=True))
        joint = correlated_chi2(z, correlation or {})
        if joint is not None:
            total.loc[n, "chi2"] = joint
    first = min(names, key=lambda n: (-int(total.loc[n, "within_2_sigma"]), total.loc[n, "chi2"]))
    agrees = {n: int(got.loc[got["configuration"] == n, "within_2_sigma"].sum()) for n in names}
    k, chi2 = int(total.loc[first, "within_2_sigma"]), float(total.loc[first, "chi2"])
    row = ok[ok["configuration"] == first].iloc[0]
    # its consistency over every measured value it predicts, those left out of the ranking too
    own = got[got["configuration"] == first]
    z_own = dict(zip(own["quantity"], own["z"], strict=True))
    chi2_own = correlated_chi2(z_own, correlation or {})
    chi2_own = float((own["z"] ** 2).sum()) if chi2_own is None else chi2_own
    p = p_value(chi2_own, len(z_own))
    predicted = tuple(q for q in measured if q in z_own)
    scored = _score(k, len(common), chi2)
    left = tuple(q for q in measured if q not in common)
    lacking = [f"{q} (not predicted by {_names([n for n in names if q not in predicts[n]])})"
               for q in left]  # fmt: skip
    shared = _names(list(common)) + (", the quantities all ok ones predict" if left else "")
    out = f"; left out: {'; '.join(lacking)}" if left else ""
    standing = Standing(common, k, chi2, agrees[first], got, modes, correlation or {})

    def made(
        named: str | None, why: str, tail: str, least: str | None = None,
        undecided: tuple[str, ...] = (),
    ) -> Verdict:  # fmt: skip
        return Verdict(
            drop, named, common, left, why, bool(tail), least, undecided, within_2_sigma=k,
            chi2=chi2, caveat=str(row["caveat"]), agreements=agrees[first], p_value=p,
            consistent=p >= LEVEL, consistency_chi2=chi2_own, predicted_over=predicted,
        )  # fmt: skip

    def extra(deciding: list[str], named: list[str]) -> str:
        return provisional_text(ok, names, deciding, named, standing)

    if k == 0:  # none agrees with a value ranked over: as without the values left out
        tail = extra([first], [first])
        within = got[got["within_2_sigma"].astype(bool)]
        agreeing = {n: list(within.loc[within["configuration"] == n, "quantity"]) for n in names}
        elsewhere = [f"{n} with {_names(qs)}" for n, qs in agreeing.items() if qs]
        if elsewhere:
            why = (f"no configuration agrees within 2 sigma with a value ranked over: {first} "
                   f"disagrees least, over {shared} ({scored}); within 2 sigma only with values "
                   f"left out, which not every ok configuration predicts: "
                   f"{'; '.join(elsewhere)}{out}{tail}")  # fmt: skip
        else:
            why = (f"no configuration agrees with any measured value within 2 sigma: {first} "
                   f"disagrees least, over {shared} ({scored}){out}{tail}")  # fmt: skip
        return made(None, why, tail, first)
    more = [n for n in names if agrees[n] > agrees[first]]
    if more:
        tail = extra([first, *more], [])
        why = (f"none is named: {first} ranks first over {shared} ({scored}), but "
               f"{_names(more)} agrees with more of the measured values "
               f"({max(agrees[n] for n in more)} against {agrees[first]}), with ones {first} "
               f"does not predict{out}{tail}")  # fmt: skip
        return made(None, why, tail)
    rivals = _undecided(first, names, total, rows)
    if rivals:
        both = [first, *rivals]
        tail = extra(both, both)
        theirs = "; ".join(
            f"{n}: {_score(int(total.loc[n, 'within_2_sigma']), len(common), total.loc[n, 'chi2'])}"
            for n in both
        )
        why = (f"undecided between {_names(both)}: {first} has more values within 2 sigma over "
               f"{shared}, but only by values within {NEAR} sigma of the 2-sigma line, and the "
               f"chi2 ranks them the other way ({theirs}){out}{tail}")  # fmt: skip
        return made(None, why, tail, undecided=tuple(both))
    tail = extra([first], [first])
    ranks = f"the most values within 2 sigma, then the lowest chi2, over {shared} ({scored})"
    if p < LEVEL:
        ranks = (f"ranks first by {ranks}, but is itself inconsistent with the measurements "
                 f"(chi2 {chi2_own:.4g} over {len(z_own)} value{'s' * (len(z_own) > 1)}"
                 f"{' it predicts' if len(z_own) > len(common) else ''}, "
                 f"{_p_text(p)}, below {LEVEL})")  # fmt: skip
    why = f"{first}: {ranks}{out}{_law_text(row)}{tail}"
    return made(first, why, tail)
