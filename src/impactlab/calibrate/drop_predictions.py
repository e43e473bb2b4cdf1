"""What a calibrated model predicts for drops that were not measured: each of the model's
outputs (e, delta_p, max_force, ...) at posterior draws, for drops given by their inputs only
(``Measurements.conditions``): ``Calibration.predict``."""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.calibrate.calibration_warning import CalibrationWarning
from impactlab.calibrate.input_checks import _one_material, check_calibration_inputs
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.calibrate.model_specs import parse_model
from impactlab.calibrate.models import CandidateModel, predict, status_message
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.calibrate.result import INTERVAL, ModelPosterior
from impactlab.sweep.engine import ENGINE, Evaluator

__all__ = ["DropPredictions", "predict_drops"]


@dataclass(frozen=True)
class DropPredictions:
    """A model's predictions for drops at N posterior draws (SI): ``model``, ``labels`` (D),
    ``values`` quantity -> (N, D) (NaN where the case failed), ``status`` (N, D) (0: finished;
    ``models.status_message``) and ``draws`` (N, P), the parameter values used."""

    model: str
    labels: tuple[str, ...]
    values: Mapping[str, np.ndarray]
    status: np.ndarray
    draws: np.ndarray

    def summary(self) -> list[dict[str, Any]]:
        """One row per drop and quantity: drop, quantity, unit (SI), median, q05, q95 (the 90 %
        interval of the predictions over the draws that ran), failed (the share of draws whose
        case failed) and, when some did, reason (the commonest)."""
        rows = []
        for d, label in enumerate(self.labels):
            st = self.status[:, d]
            failed = float(np.mean(st != 0)) if st.size else math.nan
            for q, v in self.values.items():
                x = v[:, d][np.isfinite(v[:, d])]
                q05, med, q95 = (
                    np.quantile(x, [INTERVAL[0], 0.5, INTERVAL[1]]) if x.size else [math.nan] * 3
                )
                row = {"drop": label, "quantity": q, "unit": MEASURABLE[q].unit,
                       "median": float(med), "q05": float(q05), "q95": float(q95),
                       "failed": failed}  # fmt: skip
                if failed > 0:
                    codes, counts = np.unique(st[st != 0], return_counts=True)
                    row["reason"] = status_message(int(codes[np.argmax(counts)]))
                rows.append(row)
        return rows


def predict_drops(
    posteriors: Mapping[str, ModelPosterior],
    settings: Mapping[str, Any],
    conditions: Measurements | Sequence[Mapping[str, Any]] | str | Path,
    quantities: Sequence[str],
    *,
    model: str | None = None,
    draws: int = 200,
    seed: int = 0,
    evaluator: Evaluator = ENGINE,
    calibrated: Measurements | None = None,
) -> DropPredictions:
    """``Calibration.predict``: the ``quantities`` of the drops ``conditions`` (Measurements,
    records or a file, read by ``Measurements.conditions``) under ``model`` (a calibrated
    model's name; None: the first of ``posteriors``, the best-ranked) at ``draws`` posterior
    draws chosen at random (``seed``; all of them when there are fewer), with the calibration's
    ``settings`` (each model's definition, the engine options). ValueError naming a model that
    was not calibrated, a quantity the model does not predict, a draws count below 1 and drops
    without mu where mu was not calibrated; as ``calibrate`` (``input_checks``), ValueError for
    a drop on another material than the ``calibrated`` drops (the calibration's measurements)
    where a property of that material was calibrated, and for a rod of another material or
    length without its mass, and a CalibrationWarning for a drop's value of a calibrated
    parameter (the posterior draws replace it)."""
    name = model if model is not None else next(iter(posteriors))
    if name not in posteriors:
        raise ValueError(f"model {name!r} was not calibrated; calibrated: {', '.join(posteriors)}")
    if isinstance(draws, bool) or not isinstance(draws, int) or draws < 1:
        raise ValueError(f"draws must be an integer >= 1, got {draws!r}")
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
    pick = rng.choice(n, size=min(draws, n), replace=False) if n else np.zeros(0, dtype=int)
    theta = post.samples[np.sort(pick)]
    pred = predict(cand, meas, post.params, theta, evaluator=evaluator, engine=engine,
                   quantities=quantities)  # fmt: skip
    return DropPredictions(name, meas.labels, dict(pred.values), pred.status, theta)


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
    if isinstance(given, Measurements):
        return given
    if isinstance(given, str | Path):
        return read_measurements(given, measured=False)
    return Measurements.conditions(list(given))
