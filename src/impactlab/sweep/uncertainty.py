"""Uncertainty of a Monte Carlo sweep: the spread of the outputs and the inputs that drive it.

For each output (valid cases only: ``status == 0`` and no result flag that says the case is not
plain success, ``impactlab.flags``: energy gain, gravity-dominated, the other end; the advisory
LAW_EXTRAPOLATED keeps a case): mean, standard deviation and percentiles. Flagged cases are
counted (``n_flagged``) and left out unless ``include_flagged=True``; the cases used that carry
LAW_EXTRAPOLATED are counted too (``n_extrapolated``), and the text reports say so.
For each (output, sampled input) pair two sensitivity measures:

- ``rank_corr2``: the squared Spearman rank correlation rho_s^2 (Saltelli et al., Global
  Sensitivity Analysis: The Primer, Wiley 2008, Sec. 1.2.5, doi:10.1002/9780470725184). It captures
  any monotone dependence; the inputs are ranked by it.
- ``src2``: the squared standardised regression coefficient SRC_j^2 = (b_j s_j / s_y)^2 of the
  linear least-squares fit y ~ b_0 + sum_j b_j x_j (same reference, Sec. 1.2.3). For independent
  inputs and a linear model the SRC_j^2 add up to the fit's R^2 (reported as ``r2``); a small R^2
  means the output is non-linear in the inputs and rank_corr2 is the better guide.

The sampled inputs of a study are drawn independently, which both measures assume.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd

from impactlab.flags import ADVISORY_FLAGS, FLAG_LAW_EXTRAPOLATED, invalidating_names
from impactlab.sweep.dimensions import SAMPLE_DIM
from impactlab.sweep.display import value_text
from impactlab.sweep.inputs import OUTPUT_ALIASES, output_spec
from impactlab.sweep.netcdf import as_dataset
from impactlab.sweep.options import (
    DEFAULT_PERCENTILES,
    DEFAULT_UNCERTAINTY_OUTPUTS,
    NOT_SUMMARISED,
    UncertaintySpec,
)
from impactlab.sweep.status import STATUS_NOT_RUN
from impactlab.sweep.study_record import recorded_study


@dataclass(frozen=True)
class UncertaintyReport:
    """Spread of the outputs and sensitivity to the inputs of one Monte Carlo sample.

    summary : one row per output: n (valid cases), mean, std, percentiles ("p2.5", ...), unit.
    sensitivity : one row per (output, input): rank_corr2, src2, and per output r2 of the
        linear fit; sorted by output, then by decreasing rank_corr2.
    n_cases, n_invalid : sample size and cases excluded as invalid (status > 0: the engine's
        failures, the sweep's refusals).
    n_flagged : computed cases carrying a flag that says they are not plain success (energy
        gain, gravity-dominated, other end, beyond the tip, brittle:
        ``impactlab.flags.invalidating_names``), excluded unless the
        report was asked to include them (``flagged_included``).
    n_not_computed : cases of an incomplete store not computed yet (status -1), excluded too.
    n_extrapolated : cases used in the statistics whose law was extrapolated (the advisory
        LAW_EXTRAPOLATED flag: kept, but the law is used beyond its range there).
    """

    summary: pd.DataFrame
    sensitivity: pd.DataFrame
    n_cases: int
    n_invalid: int
    n_flagged: int = 0
    flagged_included: bool = False
    n_not_computed: int = 0
    n_extrapolated: int = 0

    def ranking(self, output: str) -> list[str]:
        """Inputs ordered by decreasing influence (rank_corr2) on ``output``."""
        out = OUTPUT_ALIASES.get(output, output)
        sub = self.sensitivity[self.sensitivity["output"] == out]
        if sub.empty:
            raise ValueError(f"no sensitivity for output {output!r}")
        return list(sub.sort_values("rank_corr2", ascending=False)["input"])

    def dominant(self, output: str) -> str:
        """The input with the largest rank_corr2 for ``output``."""
        return self.ranking(output)[0]

    def to_dict(self) -> dict[str, Any]:
        return {
            "n_cases": self.n_cases,
            "n_invalid": self.n_invalid,
            "n_not_computed": self.n_not_computed,
            "n_flagged": self.n_flagged,
            "flagged_included": self.flagged_included,
            "n_extrapolated": self.n_extrapolated,
            "summary": self.summary.reset_index().to_dict(orient="records"),
            "sensitivity": self.sensitivity.to_dict(orient="records"),
        }


def summarised(ds: Any) -> list[str]:
    """The outputs of the sweep ``ds`` that the report can summarise (quantities: not the
    status, nor the codes of :data:`NOT_SUMMARISED`)."""
    return [str(v) for v in ds.data_vars if v != "status" and v not in NOT_SUMMARISED]


def _check_sample(ds: Any) -> None:
    """Refuse a sweep without a Monte Carlo sample (checked before anything is built)."""
    if SAMPLE_DIM not in ds.dims:
        raise ValueError("the uncertainty report needs a Monte Carlo sweep (a 'sample' dimension)")


def _sampled_inputs(ds: Any) -> list[str]:
    names = []
    for name, var in ds.variables.items():
        if var.dims == (SAMPLE_DIM,) and "distribution" in var.attrs:
            names.append(str(name))
    return names


def uncertainty_report(
    ds: Any,
    outputs: Sequence[str] | None = None,
    inputs: Sequence[str] | None = None,
    percentiles: Sequence[float] = DEFAULT_PERCENTILES,
    include_flagged: bool = False,
) -> UncertaintyReport:
    """Summarise a Monte Carlo sweep (Dataset with the single dimension ``sample``).

    ds : the sweep's Dataset (``run_sweep(...).dataset`` or ``open_sweep(path)``), a store's
        path or ``run_sweep``'s result; select one grid point first for a grid+sample study
        (``ds.isel(law=0)``).
    outputs : outputs to summarise (default: e, delta_p, sliding_length, duration, mean_force,
        those present); the paper's symbols L_s, T, F are accepted; the codes of
        :data:`NOT_SUMMARISED` (regime, flags) are refused (ValueError).
    inputs : sampled inputs to rank (default: all sampled inputs with a spread).
    percentiles : in [0, 100].
    include_flagged : keep the cases whose ``flags`` say they are not plain success (default:
        excluded and counted in ``n_flagged``).
    """
    ds = as_dataset(ds)
    extra = [d for d in ds.dims if d != SAMPLE_DIM]
    _check_sample(ds)
    if any(ds.sizes[d] > 1 for d in extra):
        raise ValueError(
            f"the Dataset has grid dimensions {extra} besides 'sample'; select one grid point "
            f"first, e.g. ds.isel({extra[0]}=0)"
        )
    ds = ds.squeeze([d for d in extra], drop=False) if extra else ds
    for p in percentiles:
        if not 0.0 <= float(p) <= 100.0:
            raise ValueError(f"percentiles must lie in [0, 100], got {p!r}")
    if outputs is None:
        outs = [o for o in DEFAULT_UNCERTAINTY_OUTPUTS if o in ds.data_vars]
    else:
        outs = [OUTPUT_ALIASES.get(o, o) for o in outputs]
        codes = next((o for o in outs if o in NOT_SUMMARISED), None)
        if codes is not None:
            raise ValueError(
                f"output {codes!r} holds {NOT_SUMMARISED[codes]}, not a quantity: a mean, a "
                "spread or a sensitivity of it means nothing; choose among "
                f"{', '.join(summarised(ds))}"
            )
        missing = [o for o in outs if o not in ds.data_vars]
        if missing:
            raise ValueError(
                f"output(s) {missing} not in the sweep; it has: {', '.join(summarised(ds))}"
            )
    if not outs:
        raise ValueError("no outputs to summarise")
    sampled = _sampled_inputs(ds)
    if inputs is None:
        ins = sampled
    else:
        ins = list(inputs)
        bad = [i for i in ins if i not in sampled]
        if bad:
            raise ValueError(f"input(s) {bad} are not sampled; sampled inputs: {sampled}")
    status = np.asarray(ds["status"].values).ravel()
    valid = status == 0
    bits = _flag_bits(ds, status.size)
    flagged = valid & ((bits & ~ADVISORY_FLAGS) != 0)  # not plain success (``ok`` False)
    if not include_flagged:
        valid = valid & ~flagged
    extrapolated = valid & ((bits & FLAG_LAW_EXTRAPOLATED) != 0)  # advisory: kept
    X = (
        np.column_stack([np.asarray(ds[i].values, dtype=np.float64).ravel() for i in ins])
        if ins
        else np.empty((status.size, 0))
    )
    rows = []
    sens = []
    for o in outs:
        y = np.asarray(ds[o].values, dtype=np.float64).ravel()
        ok = valid & np.isfinite(y)
        yv = y[ok]
        row: dict[str, Any] = {"output": o, "unit": output_spec(o).unit, "n": int(ok.sum())}
        if yv.size:
            row["mean"] = float(np.mean(yv))
            row["std"] = float(np.std(yv, ddof=1)) if yv.size > 1 else 0.0
            for p, v in zip(percentiles, np.percentile(yv, list(percentiles)), strict=True):
                row[f"p{float(p):g}"] = float(v)
        rows.append(row)
        sens.extend(_sensitivity(o, yv, X[ok], ins))
    summary = pd.DataFrame(rows).set_index("output")
    sensitivity = pd.DataFrame(sens, columns=["output", "input", "rank_corr2", "src2", "r2"])
    if not sensitivity.empty:
        order = {o: i for i, o in enumerate(outs)}
        sensitivity = (
            sensitivity.assign(_o=sensitivity["output"].map(order))
            .sort_values(["_o", "rank_corr2"], ascending=[True, False])
            .drop(columns="_o")
        )
        sensitivity = sensitivity.reset_index(drop=True)
    n_not_computed = int((status == STATUS_NOT_RUN).sum())  # an incomplete store's
    n_invalid = int((status != 0).sum()) - n_not_computed
    return UncertaintyReport(
        summary,
        sensitivity,
        int(status.size),
        n_invalid,
        int(flagged.sum()),
        include_flagged,
        n_not_computed,
        int(extrapolated.sum()),
    )


def _flag_bits(ds: Any, n: int) -> np.ndarray:
    """(n,) the cases' ``flags`` bitmasks (``impactlab.flags.ResultFlag``) as integers; 0 for
    an uncomputed case (fill value -1, or NaN) and for every case of a sweep without flags."""
    if "flags" not in ds.data_vars:
        return np.zeros(n, dtype=np.int64)
    f = np.asarray(ds["flags"].values, dtype=np.float64).ravel()
    return np.where(np.isfinite(f) & (f > 0), f, 0.0).astype(np.int64)


def extrapolated_note(report: Mapping[str, Any]) -> str | None:
    """The text reports' line on the cases used whose law was extrapolated (``to_dict``'s
    ``n_extrapolated``), worded as ``impactlab sweep run``'s flag counts: "law extrapolated
    (advisory): 50 of the 50 cases used, ..."; None when there is none."""
    n = int(report.get("n_extrapolated", 0))
    if not n:
        return None
    used = int(report["n_cases"]) - int(report["n_invalid"]) - int(report.get("n_not_computed", 0))
    if not report.get("flagged_included"):
        used -= int(report.get("n_flagged", 0))
    return (
        f"law extrapolated (advisory): {n:,} of the {used:,} cases used, kept in the statistics "
        "(beyond the law's range: `impactlab laws --accuracy`)"
    )


def _sensitivity(
    output: str, y: np.ndarray, X: np.ndarray, names: Sequence[str]
) -> list[dict[str, Any]]:
    if y.size < 3 or X.shape[1] == 0:
        return []
    sx = X.std(axis=0, ddof=1)
    keep = sx > 1e-12 * np.maximum(np.abs(X.mean(axis=0)), 1e-300)
    sy = y.std(ddof=1)
    out = []
    if not sy > 1e-12 * max(abs(float(y.mean())), 1e-300):  # constant output
        return [
            {"output": output, "input": n, "rank_corr2": 0.0, "src2": 0.0, "r2": 0.0}
            for n, k in zip(names, keep, strict=True)
            if k
        ]
    Xk = X[:, keep]
    kept = [n for n, k in zip(names, keep, strict=True) if k]
    # standardised regression (linear, raw values)
    Z = (Xk - Xk.mean(axis=0)) / sx[keep]
    zy = (y - y.mean()) / sy
    coef, *_ = np.linalg.lstsq(Z, zy, rcond=None)
    resid = zy - Z @ coef
    r2 = float(1.0 - resid @ resid / (zy @ zy))
    from scipy import stats  # here: scipy.stats costs about 0.5 s at `import impactlab.sweep`

    ry = stats.rankdata(y)
    ry = (ry - ry.mean()) / ry.std()
    for j, name in enumerate(kept):
        rx = stats.rankdata(Xk[:, j])
        rx = (rx - rx.mean()) / rx.std()
        rho = float(np.mean(rx * ry))
        out.append(
            {
                "output": output,
                "input": name,
                "rank_corr2": float(rho**2),
                "src2": float(coef[j] ** 2),
                "r2": r2,
            }
        )
    return out


def study_uncertainty_spec(ds: Any) -> UncertaintySpec | None:
    """The ``[uncertainty]`` table of the study that wrote the sweep's Dataset (None: none, or
    no readable study in the attributes)."""
    try:
        return recorded_study(json.loads(ds.attrs["study"])).uncertainty
    except (KeyError, ValueError):
        return None


def uncertainty_reports(
    ds: Any,
    outputs: Sequence[str] | None = None,
    percentiles: Sequence[float] | None = None,
    include_flagged: bool = False,
) -> dict[str, UncertaintyReport]:
    """One :func:`uncertainty_report` per grid point of a (grid+)sample sweep, keyed by a title
    naming the point in display units ("law = brake, angle = 20 deg"; the study's title for a
    pure sample). ``outputs`` and
    ``percentiles`` default to the study's ``[uncertainty]`` table, else the defaults. A sweep
    without a sample is refused first, before its grid points are listed. ``ds`` as in
    ``uncertainty_report``."""
    ds = as_dataset(ds)
    _check_sample(ds)
    spec = study_uncertainty_spec(ds)
    outs = list(outputs) if outputs else (list(spec.outputs) if spec else None)
    pcts = (
        list(percentiles)
        if percentiles
        else list(spec.percentiles)
        if spec
        else list(DEFAULT_PERCENTILES)
    )
    grid_dims = [d for d in ds.dims if d != SAMPLE_DIM]
    points: list[dict[str, int]] = [{}]
    for d in grid_dims:
        points = [{**p, d: i} for p in points for i in range(ds.sizes[d])]
    titles = _point_titles(ds, points)
    return {
        title: uncertainty_report(ds.isel(p) if p else ds, outs, None, pcts, include_flagged)
        for title, p in zip(titles, points, strict=True)
    }


def _point_titles(ds: Any, points: Sequence[dict[str, int]]) -> list[str]:
    """Each grid point named by its values in their display units ("law = brake, angle =
    20 deg"; more digits where five would name two points alike); the study's title for the
    point of a pure sample."""
    for digits in range(5, 18):
        titles = [
            ", ".join(value_text(ds, d, _plain(ds[d].values[i]), digits) for d, i in p.items())
            or str(ds.attrs.get("title"))
            for p in points
        ]
        if len(set(titles)) == len(titles):
            break
    return titles


def _plain(value: Any) -> Any:
    """A coordinate's value as Python's float or str."""
    return value.item() if isinstance(value, np.generic) else value


def format_report(rep: UncertaintyReport, title: str = "") -> str:
    """Plain-text tables of a report (what ``impactlab sweep uncertainty`` prints)."""
    lines = []
    if title:
        lines.append(title)
    flagged = (
        f"flagged (not plain success: {invalidating_names()}): "
        f"{rep.n_flagged}, {'included' if rep.flagged_included else 'excluded'}"
    )
    lines.append(
        f"cases: {rep.n_cases}, excluded: {rep.n_invalid} invalid (status > 0), "
        f"{rep.n_not_computed} not computed (status -1); {flagged}"
    )
    note = extrapolated_note(rep.to_dict())
    if note is not None:
        lines.append(note)
    lines.append("")
    lines.append(rep.summary.to_string(float_format=lambda v: f"{v:.4g}"))
    lines.append("")
    lines.append(
        "sensitivity (rank_corr2: squared Spearman correlation; src2: squared "
        "standardised regression coefficient; r2: linear fit):"
    )
    for o, sub in rep.sensitivity.groupby("output", sort=False):
        ranked = ", ".join(f"{r.input} {r.rank_corr2:.3f}" for r in sub.itertuples())
        lines.append(f"  {o}: {ranked}  (r2 = {sub['r2'].iloc[0]:.3f})")
    return "\n".join(lines)
