"""What a calibrated model predicts for drops that were not measured: each of the model's
outputs (e, delta_p, max_force, ...) at posterior draws, for drops given by their inputs only
(``Measurements.conditions``): ``Calibration.predict``. A prediction keeps the marks a single
result carries: the share of its cases whose contact law was used beyond its verified range
(the advisory LAW_EXTRAPOLATED flag) and why a case was refused, with a CalibrationWarning
when any ok case is extrapolated or every draw of a drop failed."""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._display import format_number
from impactlab.calibrate.calibration_warning import CalibrationWarning
from impactlab.calibrate.case_status import STATUS_REFUSED
from impactlab.calibrate.display import predictions_html, predictions_text
from impactlab.calibrate.input_checks import MAX_SEED, _one_material, check_calibration_inputs
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.calibrate.model_specs import parse_model
from impactlab.calibrate.models import CandidateModel, Prediction, predict, status_message
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.calibrate.result import INTERVAL, ModelPosterior
from impactlab.sweep.engine import ENGINE, Evaluator

__all__ = ["DropPredictions", "predict_drops"]


@dataclass(frozen=True, repr=False)
class DropPredictions:
    """A model's predictions for drops at N posterior draws (SI): ``model``, ``labels`` (D),
    ``values`` quantity -> (N, D) (NaN where the case failed), ``status`` (N, D) (0: finished;
    ``models.status_message``), ``draws`` (N, P), the parameter values used,
    ``extrapolated`` (N, D): True where an ok case's contact law was used beyond its verified
    range (the advisory LAW_EXTRAPOLATED flag, ``impactlab.flags``; the values are kept; None:
    not known) and ``refused``: drop label -> why ``simulate`` refused that drop's cases of
    status STATUS_REFUSED (the commonest reason's first error text)."""

    model: str
    labels: tuple[str, ...]
    values: Mapping[str, np.ndarray]
    status: np.ndarray
    draws: np.ndarray
    extrapolated: np.ndarray | None = None
    refused: Mapping[str, str] = field(default_factory=dict)

    def __repr__(self) -> str:
        return predictions_text(self)

    def _repr_html_(self) -> str:
        return predictions_html(self)

    def summary(self) -> list[dict[str, Any]]:
        """One row per drop and quantity: drop, quantity, unit (SI), median, q05, q95 (the 90 %
        interval of the predictions over the draws that ran), n_draws (the posterior draws
        predicted: ``draws``, or all the posterior holds when it holds fewer), failed (the
        share of draws whose case failed), extrapolated (the share of the draws that ran
        whose contact law was used beyond its verified range; NaN when none ran or not known)
        and reason (the commonest failure; a refused case's names the refusal; "" when none
        failed)."""
        rows = []
        for d, label in enumerate(self.labels):
            st = self.status[:, d]
            failed = float(np.mean(st != 0)) if st.size else math.nan
            extrapolated = self._extrapolated_share(d)
            for q, v in self.values.items():
                x = v[:, d][np.isfinite(v[:, d])]
                q05, med, q95 = (
                    np.quantile(x, [INTERVAL[0], 0.5, INTERVAL[1]]) if x.size else [math.nan] * 3
                )
                row = {"drop": label, "quantity": q, "unit": MEASURABLE[q].unit,
                       "median": float(med), "q05": float(q05), "q95": float(q95),
                       "n_draws": int(st.size), "failed": failed,
                       "extrapolated": extrapolated, "reason": self.reason(d)}  # fmt: skip
                rows.append(row)
        return rows

    def reason(self, d: int) -> str:
        """Why the cases of drop ``d`` (its index) failed: the commonest status's message; for
        a case ``simulate`` refused, its error text. Empty when none failed."""
        st = self.status[:, d]
        if not np.any(st != 0):
            return ""
        codes, counts = np.unique(st[st != 0], return_counts=True)
        code = int(codes[np.argmax(counts)])
        text = self.refused.get(self.labels[d]) if code == STATUS_REFUSED else None
        return f"simulate refused the case: {text}" if text else status_message(code)

    def _extrapolated_share(self, d: int) -> float:
        ok = self.status[:, d] == 0
        if self.extrapolated is None or not ok.any():
            return math.nan
        return float(np.count_nonzero(self.extrapolated[:, d] & ok)) / int(np.count_nonzero(ok))


def predict_drops(
    posteriors: Mapping[str, ModelPosterior],
    settings: Mapping[str, Any],
    conditions: Measurements | Sequence[Mapping[str, Any]] | Mapping[str, Any] | str | Path,
    quantities: Sequence[str],
    *,
    model: str | None = None,
    draws: int = 200,
    seed: int | None = 0,
    evaluator: Evaluator = ENGINE,
    calibrated: Measurements | None = None,
) -> DropPredictions:
    """``Calibration.predict``: the ``quantities`` of the drops ``conditions`` (Measurements,
    records or a file, read by ``Measurements.conditions``; one record alone is one drop) under
    ``model`` (a calibrated model's name; None: the first of ``posteriors``, the best-ranked) at
    ``draws`` posterior draws chosen at random (``seed``: an integer in [0, 2^32), or None for
    fresh entropy; all of them, with a CalibrationWarning, when there are fewer), with the
    calibration's ``settings`` (each model's definition, the engine options). ValueError
    naming a model that was not calibrated, a quantity the model does not predict, a draws
    count below 1, a seed that is not such an integer, conditions that are no records, and
    drops without mu where mu was not calibrated; as ``calibrate`` (``input_checks``),
    ValueError for a drop on another material than the ``calibrated`` drops (the
    calibration's measurements) where a property of that material was calibrated, and for a
    rod of another material or length without its mass, and a CalibrationWarning for a drop's
    value of a calibrated parameter (the posterior draws replace it), for ok cases whose
    contact law was extrapolated (advisory, kept) and for a drop whose every draw failed."""
    name = model if model is not None else next(iter(posteriors))
    if name not in posteriors:
        raise ValueError(f"model {name!r} was not calibrated; calibrated: {', '.join(posteriors)}")
    if isinstance(draws, bool) or not isinstance(draws, int) or draws < 1:
        raise ValueError(f"draws must be an integer >= 1, got {draws!r}")
    _check_seed(seed)
    post = posteriors[name]
    meas = _conditions(conditions)
    if "mu" not in post.names and not np.isfinite(meas.inputs["mu"]).all():
        missing = [lab for lab, m in zip(meas.labels, meas.inputs["mu"], strict=True)
                   if math.isnan(m)]  # fmt: skip
        raise ValueError(
            f"drops {missing} give no mu, and mu was not calibrated: give each drop its mu"
        )
    definition = dict(settings["model_definitions"][name])
    cand = parse_model({**definition, "name": name})
    _check_conditions(name, cand, post, meas, calibrated)
    engine = {k: v for k, v in dict(settings.get("engine", {})).items() if v is not None}
    rng = np.random.default_rng(seed)
    n = len(post.samples)
    if n < draws:
        warnings.warn(
            f"model {name!r}: {draws} draws asked, the posterior holds {n}: all {n} used "
            f"(summary()'s n_draws; its q05 and q95 rest on {n} draws; more walkers or steps "
            "give more)",
            CalibrationWarning,
            stacklevel=3,  # the caller of Calibration.predict
        )
    pick = rng.choice(n, size=min(draws, n), replace=False) if n else np.zeros(0, dtype=int)
    theta = post.samples[np.sort(pick)]
    run: dict[str, Any] = {"evaluator": evaluator, "engine": engine, "quantities": quantities}
    if cand.batched or not meas.n_drops:
        pred = predict(cand, meas, post.params, theta, **run)
        refused: dict[str, str] = {}
    else:  # one simulate call per case anyway: by drop, so that each names its own refusal
        pred, refused = _by_drop(cand, meas, post, theta, run)
    out = DropPredictions(name, meas.labels, dict(pred.values), pred.status, theta,
                          pred.extrapolated, refused)  # fmt: skip
    _warn_marks(name, cand.law, out)
    return out


def _by_drop(
    cand: CandidateModel,
    meas: Measurements,
    post: ModelPosterior,
    theta: np.ndarray,
    run: Mapping[str, Any],
) -> tuple[Prediction, dict[str, str]]:
    """``predict`` one drop at a time (a model that runs ``simulate`` case by case), and each
    drop's commonest refusal text, by label."""
    parts, refused = [], {}
    for d, label in enumerate(meas.labels):
        one = Measurements((label,), (meas.categories[d],),
                           {k: v[d : d + 1] for k, v in meas.inputs.items()}, {}, {})  # fmt: skip
        part = predict(cand, one, post.params, theta, **run)
        if part.refused:
            refused[label] = max(part.refused.values(), key=lambda nt: nt[0])[1]
        parts.append(part)
    values = {q: np.hstack([p.values[q] for p in parts]) for q in parts[0].values}
    status = np.hstack([p.status for p in parts])
    marks = [p.extrapolated for p in parts if p.extrapolated is not None]
    extrapolated = np.hstack(marks) if len(marks) == len(parts) else None
    return Prediction(values, status, extrapolated), refused


def _warn_marks(name: str, law: str, got: DropPredictions) -> None:
    """A CalibrationWarning when an ok case used the contact ``law`` beyond its verified range
    (advisory: the values are kept), and one naming each drop whose every draw failed."""
    stack = 4  # the caller of Calibration.predict
    ok = got.status == 0
    if got.extrapolated is not None and np.any(got.extrapolated & ok):
        share = float(np.count_nonzero(got.extrapolated & ok)) / int(np.count_nonzero(ok))
        drops = [
            lab for d, lab in enumerate(got.labels) if np.any(got.extrapolated[:, d] & ok[:, d])
        ]
        warnings.warn(
            f"model {name!r}: the contact law {law!r} is extrapolated in "
            f"{format_number(100 * share, 2)} % of the {int(np.count_nonzero(ok))} predicted "
            f"cases (drops {', '.join(map(repr, drops))}; flag LAW_EXTRAPOLATED: used beyond "
            "its verified range, impactlab.contact.ranges): those predictions rest on the law "
            "where it is not validated (advisory: they are kept; summary()'s extrapolated gives "
            "each drop's share)",
            CalibrationWarning,
            stacklevel=stack,
        )
    n = got.status.shape[0]
    dead = [d for d in range(len(got.labels)) if n and not ok[:, d].any()]
    if dead:
        each = "; ".join(f"{got.labels[d]!r}: {got.reason(d)}" for d in dead)
        warnings.warn(
            f"model {name!r} predicts nothing for {len(dead)} drop(s): every one of the {n} "
            f"posterior draws failed ({each}); their values are NaN",
            CalibrationWarning,
            stacklevel=stack,
        )


def _check_seed(seed: Any) -> None:
    """ValueError naming ``seed`` unless it is None or an integer in [0, MAX_SEED]."""
    whole = isinstance(seed, int | np.integer) and not isinstance(seed, bool)
    if seed is not None and not (whole and 0 <= seed <= MAX_SEED):
        raise ValueError(
            f"seed must be an integer in [0, {MAX_SEED}] (or None: fresh entropy), got {seed!r}"
        )


def _check_conditions(
    name: str,
    cand: CandidateModel,
    post: ModelPosterior,
    meas: Measurements,
    calibrated: Measurements | None,
) -> None:
    """``calibrate``'s checks of the drops' inputs, applied to the drops to predict: one
    material per calibrated material property over the calibrated drops and these, a rod's
    mass; a warning for each drop value a calibrated parameter replaces."""
    if calibrated is not None:
        labels = tuple(f"{x} (calibrated)" for x in calibrated.labels) + meas.labels
        both = Measurements(labels, calibrated.categories + meas.categories, {}, {}, {})
        try:
            _one_material(both, post.params)
        except ValueError as err:
            raise ValueError(f"model {name!r} cannot predict these drops: {err}") from None
    notes: list[str] = []
    check_calibration_inputs(meas, post.params, [cand], notes)
    if notes:
        for text in notes:
            text = text.replace("in the measurements", "to predict")
            warnings.warn(
                f"{text}: model {name!r} predicts with its posterior draws",
                CalibrationWarning,
                stacklevel=4,
            )


def _conditions(given: Any) -> Measurements:
    """The drops to predict: Measurements as they are, a file read, one record (a Mapping) as
    one drop, a list of records; ValueError naming ``conditions`` for anything else."""
    if isinstance(given, Measurements):
        return given
    if isinstance(given, str | Path):
        return read_measurements(given, measured=False)
    allowed = (
        "records (a list of dicts, one per drop, such as {'label': 'new', 'angle': '30 deg', "
        "'vy': -2.0}), one such dict, a measurements file or Measurements"
    )
    if isinstance(given, Mapping):
        given = [given]
    elif hasattr(given, "to_dict") and hasattr(given, "columns"):  # a pandas DataFrame
        raise ValueError(
            f"conditions must be {allowed}, got a {type(given).__name__}: pass "
            "df.to_dict('records')"
        )
    if isinstance(given, bytes) or not isinstance(given, Iterable):
        shown = "" if given is None else f" (a {type(given).__name__})"
        raise ValueError(f"conditions must be {allowed}, got {given!r}{shown}")
    records = list(given)
    for i, rec in enumerate(records):
        if not isinstance(rec, Mapping):
            raise ValueError(
                f"conditions must be {allowed}; item {i + 1} is {rec!r} (a {type(rec).__name__})"
            )
    return Measurements.conditions(records)
