"""Which configuration explains a drop best, like with like: the configurations whose result
is ok are ranked over the measured quantities that all of them predict (the most values within
2 sigma, then the lowest sum of z^2 over those quantities), never over different ones; a
quantity that one of them does not predict (a flexible rod's duration) is left out, and the
verdict says so. The first of that ranking is named best only if no other ok configuration
agrees within 2 sigma with more of the drop's measured values (it can then only be with
quantities left out: a model that agrees with nothing is never named beside one that agrees
with something), and none is named when the ok configurations share no measured quantity."""

from __future__ import annotations

from dataclasses import dataclass

import pandas as pd

__all__ = ["Verdict", "verdict"]


@dataclass(frozen=True)
class Verdict:
    """Which configuration explains ``drop`` best: its name (``configuration``; None: none),
    the measured ``quantities`` it was ranked over, those ``left_out`` (not predicted by every
    ok configuration), and the ``reason`` in words."""

    drop: str
    configuration: str | None
    quantities: tuple[str, ...]
    left_out: tuple[str, ...]
    reason: str

    @property
    def note(self) -> str:
        """The line ``notes`` gives the verdict ("" when a configuration is named, ranked over
        every measured quantity)."""
        if self.configuration is not None and not self.left_out:
            return ""
        return f"best: {self.reason}"


def _names(items: list[str]) -> str:
    return ", ".join(items)


def verdict(summary: pd.DataFrame, comparison: pd.DataFrame, drop: str) -> Verdict:
    """The verdict on ``drop`` from an explanation's ``summary`` and ``comparison`` (module
    docstring). KeyError naming the known drops for a drop not in them."""
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
    first = min(names, key=lambda n: (-int(total.loc[n, "within_2_sigma"]), total.loc[n, "chi2"]))
    agrees = {n: int(got.loc[got["configuration"] == n, "within_2_sigma"].sum()) for n in names}
    left = tuple(q for q in measured if q not in common)
    lacking = [f"{q} (not predicted by {_names([n for n in names if q not in predicts[n]])})"
               for q in left]  # fmt: skip
    shared = _names(list(common)) + (", the quantities all ok ones predict" if left else "")
    out = f"; left out: {'; '.join(lacking)}" if left else ""
    more = [n for n in names if agrees[n] > agrees[first]]
    if more:
        why = (f"none is named: {first} ranks first over {shared}, but {_names(more)} agrees "
               f"with more of the measured values ({max(agrees[n] for n in more)} against "
               f"{agrees[first]}), with ones {first} does not predict{out}")  # fmt: skip
        return Verdict(drop, None, common, left, why)
    why = f"{first}: the most values within 2 sigma, then the lowest chi2, over {shared}{out}"
    return Verdict(drop, first, common, left, why)
