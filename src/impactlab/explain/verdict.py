"""Which configuration explains a drop best, like with like: the configurations whose result
is ok are ranked over the measured quantities that all of them predict (the most values within
2 sigma, then the lowest sum of z^2 over those quantities), never over different ones; a
quantity that one of them does not predict (a flexible rod's duration) is left out, and the
verdict says so. The first of that ranking is named best only if no other ok configuration
agrees within 2 sigma with more of the drop's measured values (it can then only be with
quantities left out: a model that agrees with nothing is never named beside one that agrees
with something), and none is named when the ok configurations share no measured quantity.

For a drop with correlation coefficients the sum of z^2 is z^T R^-1 z over those quantities
(``explain.correlated``). A flexible row not converged in its modes (``explain.modes``) stays in
the ranking with its numbers and may be named; the verdict is then provisional, and its
reason (and a note) says so: leaving the row out would hand the verdict to another
configuration for a numerical shortfall of this one, whose refined values may agree better
still."""

from __future__ import annotations

from dataclasses import dataclass

import pandas as pd

from impactlab.explain.correlated import Pairs, correlated_chi2
from impactlab.explain.modes import MODE_SHIFT_MAX, MODES_CAVEAT

__all__ = ["Verdict", "verdict"]


@dataclass(frozen=True)
class Verdict:
    """Which configuration explains ``drop`` best: its name (``configuration``; None: none),
    the measured ``quantities`` it was ranked over, those ``left_out`` (not predicted by every
    ok configuration), the ``reason`` in words, and whether it is ``provisional`` (an ok
    flexible row it ranked is not converged in modes)."""

    drop: str
    configuration: str | None
    quantities: tuple[str, ...]
    left_out: tuple[str, ...]
    reason: str
    provisional: bool = False

    @property
    def note(self) -> str:
        """The line ``notes`` gives the verdict ("" when a configuration is named, ranked over
        every measured quantity, and not provisional)."""
        if self.configuration is not None and not self.left_out and not self.provisional:
            return ""
        return f"best: {self.reason}"


def _names(items: list[str]) -> str:
    return ", ".join(items)


def _unconverged(ok: pd.DataFrame, names: list[str]) -> str:
    """What the reason adds when a ranked row is not converged in modes ("" for none)."""
    flagged = {str(n) for n, v in zip(ok["configuration"], ok["modes_converged"], strict=True)
               if not pd.isna(v) and not v}  # fmt: skip
    rows = [n for n in names if n in flagged]
    if not rows:
        return ""
    return (
        f"; provisional: {_names(rows)} {'is' if len(rows) == 1 else 'are'} {MODES_CAVEAT} "
        f"(twice the modes move a value by more than {MODE_SHIFT_MAX} sigma: see the "
        "caveat), and more modes (the drop's n_axial, n_bending) can change this verdict"
    )


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
    left = tuple(q for q in measured if q not in common)
    lacking = [f"{q} (not predicted by {_names([n for n in names if q not in predicts[n]])})"
               for q in left]  # fmt: skip
    shared = _names(list(common)) + (", the quantities all ok ones predict" if left else "")
    out = f"; left out: {'; '.join(lacking)}" if left else ""
    more = [n for n in names if agrees[n] > agrees[first]]
    modes = _unconverged(ok, names)
    if more:
        why = (f"none is named: {first} ranks first over {shared}, but {_names(more)} agrees "
               f"with more of the measured values ({max(agrees[n] for n in more)} against "
               f"{agrees[first]}), with ones {first} does not predict{out}{modes}")  # fmt: skip
        return Verdict(drop, None, common, left, why, bool(modes))
    why = (f"{first}: the most values within 2 sigma, then the lowest chi2, over "
           f"{shared}{out}{modes}")  # fmt: skip
    return Verdict(drop, first, common, left, why, bool(modes))
