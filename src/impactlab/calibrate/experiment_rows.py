"""Drops from ``impactlab.experiment.analyze``: an ExperimentResult as one row of a
measurements file, so that analysed experiment files can be appended to it directly, with the
correlation coefficients of the values one marker fit gives together (e and spin_out)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.calibrate.correlations import correlation_column
from impactlab.calibrate.measurements import Measurements, read_measurements
from impactlab.experiment.result import ExperimentResult

__all__ = ["append_experiment", "experiment_record"]

#: ExperimentResult.summary() key -> measured quantity of the calibration.
_MEASURED = {
    "e": "e",
    "spin_out": "spin_out",
    "delta_p": "delta_p",
    "sliding_length": "scar_length",
}
#: Measured quantity of the calibration -> its name in the marker fit's covariance
#: (``ImpactKinematics.derived_names``): the values whose errors are correlated.
_KINEMATIC = {"e": "e", "spin_out": "spin_out"}


def experiment_record(result: ExperimentResult, label: str, **drop: Any) -> dict[str, Any]:
    """One drop (column -> SI value) from an analysed experiment: its angle, incoming velocity
    (v_c_in) and spin, its measured mu as the drop's mu, and the measured e, spin_out, delta_p
    and sliding_length (as ``scar_length``, the mark's extent, a magnitude) with their standard
    uncertainties, and the correlation coefficient of e and spin_out (``correlation_e_spin_out``,
    from the marker fit's covariance; delta_p and scar_length come from the scan, independent);
    ``drop`` adds or replaces columns (``body_material``, ``flat_material``, ``mass``, ...;
    ``correlation_e_spin_out=None`` leaves the coefficient out). ValueError when the experiment
    has no kinematics."""
    k = result.kinematics
    if k is None:
        raise ValueError(
            f"experiment {label!r} has no kinematics (stage errors: {result.errors or 'none'}); "
            "a drop needs its angle and incoming velocity"
        )
    rec: dict[str, Any] = {
        "label": label,
        "angle": f"{k.angle_in.value} rad",
        "vx": k.v_c_in[0].value,
        "vy": k.v_c_in[1].value,
        "spin": k.spin_in.value,
        "mu": k.mu.value,
    }
    rec.update({name: result.rod[name] for name in ("mass", "length", "tip_radius")
                if name in result.rod})  # fmt: skip
    summary = result.summary()
    for key, quantity in _MEASURED.items():
        est = summary.get(key)
        if est is None or not math.isfinite(est.value) or not est.sigma > 0:
            continue
        value = abs(est.value) if quantity == "scar_length" else est.value
        rec[quantity], rec[f"{quantity}_sigma"] = value, est.sigma
    rec.update(_correlations(k, [q for q in _KINEMATIC if q in rec]))
    rec.update(drop)
    return rec


def _correlations(k: Any, measured: list[str]) -> dict[str, float]:
    """``correlation_<a>_<b>`` -> coefficient of each pair of ``measured`` (quantities of
    ``_KINEMATIC``) from the kinematics' covariance; none where it holds no covariance."""
    names = list(getattr(k, "derived_names", ()))
    if not all(_KINEMATIC[q] in names for q in measured):
        return {}
    corr = np.clip(np.asarray(k.correlation, dtype=np.float64), -1.0, 1.0)
    at = [names.index(_KINEMATIC[q]) for q in measured]
    return {
        correlation_column(a, b): float(corr[at[i], at[j]])
        for i, a in enumerate(measured)
        for j, b in enumerate(measured[i + 1 :], start=i + 1)
    }


def append_experiment(
    path: str | Path, result: ExperimentResult, label: str, **drop: Any
) -> Measurements:
    """Append the drop of ``result`` to the CSV measurements file ``path`` (created if missing;
    rewritten in SI units with the units in its header); returns the whole set."""
    p = Path(path)
    new = Measurements.from_records([experiment_record(result, label, **drop)], source=str(p))
    both = read_measurements(p).extended(new) if p.exists() else new
    both.to_csv(p)
    return both
