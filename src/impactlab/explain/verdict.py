"""Which configuration explains a drop best, like with like: the configurations whose result
is ok are ranked over the measured quantities that all of them predict (the most values within
2 sigma, then the lowest sum of z^2 over those quantities), never over different ones; a
quantity that one of them does not predict (a flexible rod's duration) is left out, and the
verdict says so. The first of that ranking is named best only if it agrees within 2 sigma
with at least one of the drop's measured values and no other ok configuration agrees with
more of them (it can then only be with quantities left out). A first that agrees with none is
never named: the verdict says that no configuration agrees and names it as the least
disagreeing one. None is named when the ok configurations share no measured quantity.

Near the 2-sigma line the verdict does not turn on a hair: where the first ranks above
another by its count within 2 sigma alone, the other's chi2 is lower, and the counts could
tie or turn with values within :data:`NEAR` sigma of |z| = 2, the verdict is undecided between
them (and names neither).

For a drop with correlation coefficients the sum of z^2 is z^T R^-1 z over those quantities
(``explain.correlated``). A flexible row not converged in its modes (``explain.modes``) stays in
the ranking with its numbers and may be named; the verdict is then provisional, and its
reason (and a note) says so: leaving the row out would hand the verdict to another
configuration for a numerical shortfall of this one, whose refined values may agree better
still. A named row with another caveat (a rigid rod whose rod the flexible rows refuse, a
flexible row at the mode limit whose last doubling moved a value) makes it provisional too,
and the reason names the caveat."""

from __future__ import annotations

import math
from dataclasses import dataclass

import pandas as pd

from impactlab.explain.correlated import Pairs, correlated_chi2
from impactlab.explain.modes import MODE_SHIFT_MAX, MODES_CAVEAT, MODES_UNCHECKED, MODES_UNSETTLED
from impactlab.explain.tables import WITHIN

__all__ = ["NEAR", "Verdict", "verdict"]

#: Values within this many sigma of |z| = 2 do not decide a verdict against chi2 [1].
NEAR = 0.05


@dataclass(frozen=True)
class Verdict:
    """Which configuration explains ``drop`` best: its name (``configuration``; None: none is
    named, ``reason`` says why), the measured ``quantities`` it was ranked over, those
    ``left_out`` (not predicted by every ok configuration), the ``reason`` in words, whether
    it is ``provisional`` (a ranked flexible row not converged in modes, or a named row with a
    caveat), the ``least_disagreeing`` configuration where none agrees with any measured
    value within 2 sigma, the configurations it is ``undecided`` between (near the 2-sigma
    line), and of the row the reason names (the first of the ranking) its count
    ``within_2_sigma`` and ``chi2`` over ``quantities``, its ``caveat`` and its
    ``agreements`` within 2 sigma over all the drop's measured quantities."""

    drop: str
    configuration: str | None
    quantities: tuple[str, ...]
    left_out: tuple[str, ...]
    reason: str
    provisional: bool = False
    least_disagreeing: str | None = None
    undecided: tuple[str, ...] = ()
    within_2_sigma: int | None = None
    chi2: float = math.nan
    caveat: str = ""
    agreements: int | None = None

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
        """The line ``notes`` gives the verdict ("" when a configuration is named, ranked over
        every measured quantity, and not provisional)."""
        if self.configuration is not None and not self.left_out and not self.provisional:
            return ""
        return f"best: {self.reason}"

    def to_dict(self) -> dict[str, object]:
        """JSON ``best``'s entry (numbers plain; ``Explanation.to_dict`` gives chi2 its unit)."""
        return {
            "drop": self.drop, "configuration": self.configuration, "agrees": self.agrees,
            "least_disagreeing": self.least_disagreeing, "undecided": list(self.undecided),
            "ranked_over": list(self.quantities), "left_out": list(self.left_out),
            "within_2_sigma": self.within_2_sigma, "chi2": self.chi2,
            "provisional": self.provisional, "caveat": self.caveat or None,
            "reason": self.reason,
        }  # fmt: skip


def _names(items: list[str]) -> str:
    return ", ".join(items)


def _is(rows: list[str]) -> str:
    return "is" if len(rows) == 1 else "are"


def _provisional(ok: pd.DataFrame, ranked: list[str], named: list[str]) -> str:
    """What the reason adds when a ranked row is not converged in modes, a ranked row at the
    mode limit may not be, or a ``named`` row carries another caveat ("" for none)."""
    caveats = {str(n): str(c) for n, c in zip(ok["configuration"], ok["caveat"], strict=True)}
    flagged = {str(n) for n, v in zip(ok["configuration"], ok["modes_converged"], strict=True)
               if not pd.isna(v) and not v}  # fmt: skip
    parts = []
    rows = [n for n in ranked if n in flagged]
    if rows:
        parts.append(
            f"{_names(rows)} {_is(rows)} {MODES_CAVEAT} (its mode check moves a value by more "
            f"than {MODE_SHIFT_MAX} sigma: see the caveat), and more modes (the drop's n_axial, "
            "n_bending) can change this verdict"
        )
    rows = [n for n in ranked if caveats.get(n, "").startswith(MODES_UNSETTLED)]
    if rows:
        parts.append(
            f"{_names(rows)} {_is(rows)} {MODES_UNCHECKED} (at the mode limit), and the last "
            f"doubling of the modes moved a value by more than {MODE_SHIFT_MAX} sigma (see the "
            "caveat)"
        )
    for n in named:
        c = caveats.get(n, "")
        if c and n not in flagged and not c.startswith(MODES_UNCHECKED):
            parts.append(f"{n} carries a caveat: {c}")
    return f"; provisional: {'; '.join(parts)}" if parts else ""


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


def verdict(
    summary: pd.DataFrame, comparison: pd.DataFrame, drop: str, correlation: Pairs | None = None
) -> Verdict:
    """The verdict on ``drop`` from an explanation's ``summary`` and ``comparison`` (module
    docstring), ``correlation`` the drop's coefficients (None: none). KeyError naming the
    known drops for a drop not in them."""
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
    caveat = str(ok.loc[ok["configuration"] == first, "caveat"].iloc[0])
    scored = _score(k, len(common), chi2)
    left = tuple(q for q in measured if q not in common)
    lacking = [f"{q} (not predicted by {_names([n for n in names if q not in predicts[n]])})"
               for q in left]  # fmt: skip
    shared = _names(list(common)) + (", the quantities all ok ones predict" if left else "")
    out = f"; left out: {'; '.join(lacking)}" if left else ""
    more = [n for n in names if agrees[n] > agrees[first]]
    if more:
        extra = _provisional(ok, names, [])
        why = (f"none is named: {first} ranks first over {shared} ({scored}), but "
               f"{_names(more)} agrees with more of the measured values "
               f"({max(agrees[n] for n in more)} against {agrees[first]}), with ones {first} "
               f"does not predict{out}{extra}")  # fmt: skip
        return Verdict(
            drop, None, common, left, why, bool(extra), within_2_sigma=k, chi2=chi2, caveat=caveat,
            agreements=agrees[first],
        )  # fmt: skip
    if agrees[first] == 0:
        extra = _provisional(ok, names, [first])
        why = (f"no configuration agrees with any measured value within 2 sigma: {first} "
               f"disagrees least, over {shared} ({scored}){out}{extra}")  # fmt: skip
        return Verdict(
            drop,
            None,
            common,
            left,
            why,
            bool(extra),
            first,
            within_2_sigma=k,
            chi2=chi2,
            caveat=caveat,
            agreements=0,
        )
    rivals = _undecided(first, names, total, rows)
    if rivals:
        both = [first, *rivals]
        extra = _provisional(ok, names, both)
        theirs = "; ".join(
            f"{n}: {_score(int(total.loc[n, 'within_2_sigma']), len(common), total.loc[n, 'chi2'])}"
            for n in both
        )
        why = (f"undecided between {_names(both)}: {first} has more values within 2 sigma over "
               f"{shared}, but only by values within {NEAR} sigma of the 2-sigma line, and the "
               f"chi2 ranks them the other way ({theirs}){out}{extra}")  # fmt: skip
        return Verdict(
            drop,
            None,
            common,
            left,
            why,
            bool(extra),
            None,
            tuple(both),
            within_2_sigma=k,
            chi2=chi2,
            caveat=caveat,
            agreements=agrees[first],
        )
    extra = _provisional(ok, names, [first])
    if k == 0:  # its agreement lies in quantities left out, which the others do not predict
        own = got[got["configuration"] == first]
        alone = [q for q in left if bool(own.loc[own["quantity"] == q, "within_2_sigma"].any())]
        why = (f"{first}: ranks first by the lowest chi2 over {shared} ({scored}); it agrees "
               f"within 2 sigma only with {_names(alone)}, which the others do not predict"
               f"{out}{extra}")  # fmt: skip
    else:
        why = (f"{first}: the most values within 2 sigma, then the lowest chi2, over {shared} "
               f"({scored}){out}{extra}")  # fmt: skip
    return Verdict(
        drop, first, common, left, why, bool(extra), within_2_sigma=k, chi2=chi2, caveat=caveat,
        agreements=agrees[first],
    )  # fmt: skip
