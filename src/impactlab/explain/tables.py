"""The comparison as tables: one row per (drop, configuration, measured quantity), and one per
(drop, configuration) that sums it up with what the run's sequence says.

z = (predicted - measured) / sigma uses the measurement's standard uncertainty alone: a model's
own error (its law beyond the verified range, ...) is a flag beside it, never part of sigma. A
configuration that did not run, was refused or is flagged invalidating has no prediction: its
rows carry the reason and count as no agreement. chi2 sums z^2 over every measured value of a
drop (for a drop with correlation coefficients, z^T R^-1 z: ``explain.correlated``): a
configuration that leaves one unpredicted has none (NaN), so that configurations are never
ranked by sums over different quantities.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.explain.configurations import Configuration
from impactlab.explain.correlated import correlated_chi2, drop_pairs
from impactlab.explain.runs import Outcome, sequence_values
from impactlab.flags import ResultFlag

__all__ = [
    "BODY_CAVEAT",
    "COMPARISON_COLUMNS",
    "SUMMARY_COLUMNS",
    "WITHIN",
    "comparison_table",
    "summary_table",
]

#: A prediction agrees with a measurement when |z| is at most this many sigma.
WITHIN = 2.0
#: The columns of the comparison (one row per drop, configuration and measured quantity; SI).
COMPARISON_COLUMNS = ("drop", "configuration", "quantity", "measured", "sigma", "predicted", "z",
                      "within_2_sigma", "unit", "status")  # fmt: skip
#: The columns of the summary (one row per drop and configuration).
SUMMARY_COLUMNS = (
    "drop", "configuration", "status", "ok", "within_2_sigma", "compared", "n_measured", "chi2",
    "n_contacts", "mu", "mu_apparent", "max_delta_ratio", "fitted_delta_ratio_max", "delta_c",
    "law_range", "law_extrapolated", "rate_factor", "strain_rate", "flags", "flag_names",
    "modes_converged", "caveat",
)  # fmt: skip
#: The caveat of an ok rigid row whose drop's rod the flexible rows refuse as a body.
BODY_CAVEAT = (
    "the flexible rows refuse this drop's rod as a body (their status says why); the rigid rod "
    "runs the same rod without that check, so its agreement does not vouch for the rod"
)


def _row_status(outcome: Outcome, quantity: str) -> str:
    if not outcome.ok:
        return outcome.status
    if quantity in outcome.unsupported:
        return "not predicted: this configuration does not define it"
    return "ok"


def comparison_table(
    meas: Measurements,
    configs: Sequence[Configuration],
    outcomes: Mapping[tuple[str, str], Outcome],
) -> pd.DataFrame:
    """Every measured value beside each configuration's prediction (SI, in ``unit``)."""
    rows: list[dict[str, Any]] = []
    for d, label in enumerate(meas.labels):
        for cfg in configs:
            out = outcomes[(label, cfg.name)]
            for q in meas.quantities:
                measured = float(meas.observed[q][d])
                if not math.isfinite(measured):
                    continue
                sigma = float(meas.sigma[q][d])
                status = _row_status(out, q)
                predicted = out.values.get(q, math.nan) if status == "ok" else math.nan
                z = (predicted - measured) / sigma
                rows.append({
                    "drop": label, "configuration": cfg.name, "quantity": q,
                    "measured": measured, "sigma": sigma, "predicted": predicted, "z": z,
                    "within_2_sigma": bool(abs(z) <= WITHIN),  # NaN: False
                    "unit": MEASURABLE[q].unit, "status": status,
                })  # fmt: skip
    return pd.DataFrame(rows, columns=list(COMPARISON_COLUMNS))


def flag_text(flags: int | None) -> str:
    """The names of the flags set (``"law_extrapolated, other_end"``), ``"none"``; "" for
    a run that did not happen."""
    if flags is None:
        return ""
    names = [str(f.name).lower() for f in ResultFlag if f.value and flags & f.value]
    return ", ".join(names) or "none"


def _caveat(config: Configuration, outcome: Outcome, body_refused: bool) -> str:
    """What stands against an ok row ("" for none)."""
    if not outcome.ok:
        return ""
    if not config.flexible:
        return BODY_CAVEAT if body_refused else ""
    return "" if outcome.modes is None else str(outcome.modes.caveat())


def summary_table(
    meas: Measurements,
    configs: Sequence[Configuration],
    outcomes: Mapping[tuple[str, str], Outcome],
    comparison: pd.DataFrame,
) -> pd.DataFrame:
    """Per drop and configuration: the values within 2 sigma, of those ``compared`` (predicted)
    and ``n_measured``; chi2 = sum of z^2 over the measured ones, z^T R^-1 z where the drop
    gives correlation coefficients (NaN when one has no prediction); the run's number of
    contacts ``n_contacts``, Eq. 28's ``mu_apparent`` beside the drop's measured ``mu``,
    ``max_delta_ratio`` and the law's verified range, the pair's ``delta_c``, the ``law_range``
    in words, ``law_extrapolated`` (None where no result came), the rate factor and a rate
    row's ``strain_rate``, the ``flags`` (bitmask) and their ``flag_names``,
    ``modes_converged`` (an ok flexible row checked with twice its modes, ``explain.modes``;
    None where not checked) and a ``caveat`` ("" for none): :data:`BODY_CAVEAT` on an ok
    rigid row whose rod the flexible rows refuse, what twice the modes change on a flexible
    row not converged in them, that a row at the mode limit is not checked."""
    rows: list[dict[str, Any]] = []
    grouped = dict(tuple(comparison.groupby(["drop", "configuration"], sort=False)))
    for d, label in enumerate(meas.labels):
        refused = any(outcomes[(label, c.name)].body_refused for c in configs if c.flexible)
        pairs = drop_pairs(meas, d)
        for cfg in configs:
            out = outcomes[(label, cfg.name)]
            part = grouped[(label, cfg.name)]
            compared = part[part["status"] == "ok"]
            seq = sequence_values(out.result)
            whole = out.ok and len(compared) == len(part) > 0
            chi2 = float((compared["z"] ** 2).sum()) if whole else math.nan
            joint = correlated_chi2(dict(zip(compared["quantity"], compared["z"], strict=True)),
                                    pairs) if whole else None  # fmt: skip
            chi2 = chi2 if joint is None else joint
            rows.append({
                "drop": label, "configuration": cfg.name, "status": out.status, "ok": out.ok,
                "within_2_sigma": int(compared["within_2_sigma"].sum()),
                "compared": len(compared), "n_measured": len(part), "chi2": chi2,
                "n_contacts": seq["n_contacts"], "mu": float(meas.inputs["mu"][d]),
                "mu_apparent": seq["mu_apparent"], "max_delta_ratio": seq["max_delta_ratio"],
                "fitted_delta_ratio_max": seq["fitted_delta_ratio_max"],
                "delta_c": seq["delta_c"], "law_range": seq["law_range"],
                "law_extrapolated": out.law_extrapolated if out.ran else None,
                "rate_factor": seq["rate_factor"], "strain_rate": seq["strain_rate"],
                "flags": seq["flags"],
                "flag_names": flag_text(seq["flags"]),
                "modes_converged": None if out.modes is None else out.modes.converged,
                "caveat": _caveat(cfg, out, refused),
            })  # fmt: skip
    table = pd.DataFrame(rows, columns=list(SUMMARY_COLUMNS))
    for name in ("n_contacts", "flags"):  # blank where nothing ran
        table[name] = table[name].astype("Int64")
    return table
