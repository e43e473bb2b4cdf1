"""Drops from ``impactlab.experiment.analyze``: an ExperimentResult as one row of a
measurements file, so that analysed experiment files can be appended to it directly, with the
rod the analysis used and the correlation coefficients of the values one marker fit gives
together (e and spin_out). A result that is not ok (a doubt, a failed stage) is refused unless
asked for, and then marked."""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.calibrate.calibration_warning import CalibrationWarning
from impactlab.calibrate.correlations import correlation_column
from impactlab.calibrate.measurement_append import append_record
from impactlab.calibrate.measurements import Measurements
from impactlab.experiment.result import ExperimentResult
from impactlab.materials import PRESETS

__all__ = ["append_experiment", "experiment_record", "not_ok"]

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
    (v_c_in) and spin, its measured mu as the drop's mu, the rod it used (mass, length,
    tip_radius; inertia where it is not the uniform rod's m L^2/12), the flat's material when
    the analysis named a library one (``flat=``), and the measured e, spin_out, delta_p
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
    rec.update(_rod(result))
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


def _rod(result: Any) -> dict[str, Any]:
    """The rod the analysis used (``result.rod``, SI) and its flat's library material: mass,
    length, tip_radius; inertia when it differs from m L^2/12 (a blank inertia is that);
    flat_material when ``result.options["flat"]`` names a preset."""
    rod = dict(getattr(result, "rod", {}) or {})
    out: dict[str, Any] = {k: rod[k] for k in ("mass", "length", "tip_radius") if k in rod}
    inertia = rod.get("inertia")
    if inertia is not None and {"mass", "length"} <= set(rod):
        uniform = rod["mass"] * rod["length"] ** 2 / 12.0
        if not math.isclose(inertia, uniform, rel_tol=1e-9):
            out["inertia"] = inertia
    flat = (getattr(result, "options", None) or {}).get("flat")
    names = {k: k for k in PRESETS} | {m.name: k for k, m in PRESETS.items()}
    if isinstance(flat, str) and flat in names:  # a preset by its key or a Material's name
        out["flat_material"] = names[flat]
    return out


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
    path: str | Path,
    result: ExperimentResult,
    label: str,
    *,
    include_doubtful: bool = False,
    **drop: Any,
) -> Measurements:
    """Append the drop of ``result`` (:func:`experiment_record`) to the CSV measurements file
    ``path`` (created if missing) as one line in the file's units, the rest of the file left as
    written (``measurement_append``); returns the file's drops. A result that is not ok (its
    ``doubts``, a stage's ``errors``) is refused, naming why: its values would be taken as
    exact measurements; with ``include_doubtful`` it is appended after a ``#`` comment line
    that names the doubts, with a CalibrationWarning. ValueError also for a label the file has
    already and a file that is not CSV."""
    rec = experiment_record(result, label, **drop)
    why = not_ok(result)
    if why and not include_doubtful:
        raise ValueError(
            f"experiment {label!r}: its analysis is not ok ({'; '.join(why)}): its values would "
            "be taken as exact measurements; check the files, or append it anyway, marked, "
            "with include_doubtful=True (impactlab analyze --include-doubtful)"
        )
    note = f"doubtful drop {label!r} (its analysis is not ok): {'; '.join(why)}" if why else None
    meas = append_record(path, rec, comment=note)
    for text in _default_materials(meas, rec, label):
        warnings.warn(f"{path}: {text}", CalibrationWarning, stacklevel=2)
    if why:
        warnings.warn(
            f"{path}: drop {label!r} appended though its analysis is not ok ({'; '.join(why)}); "
            "a comment line above it says so",
            CalibrationWarning,
            stacklevel=2,
        )
    return meas


#: The material columns a drop without them takes by default, and how to name them.
_MATERIALS = {
    "flat_material": ("the flat", "--flat NAME (flat= in Python)"),
    "body_material": ("the rod", "body_material= in Python"),
}


def _default_materials(meas: Measurements, rec: dict[str, Any], label: str) -> list[str]:
    """The warnings for a drop ``rec`` (the drop ``label`` of ``meas``, found by its label)
    that names no material of a column whose other drops name another one: it takes the
    calibration's default."""
    out = []
    new = meas.labels.index(str(label))
    rest = [c for i, c in enumerate(meas.categories) if i != new]
    for column, (what, how) in _MATERIALS.items():
        if column in rec or not rest:
            continue
        taken = meas.categories[new].get(column)
        others = sorted({str(c[column]) for c in rest if c.get(column)} - {taken})
        if others:
            out.append(
                f"drop {label!r} names no material of {what} and takes the default {taken}, "
                f"while earlier drops name {', '.join(others)}: give {how}, or edit "
                f"its {column} field"
            )
    return out


def not_ok(result: Any) -> list[str]:
    """Why an analysed experiment is not ok: its stages' errors (``stage failed: text``) and
    its doubts; empty when it is ok."""
    errors = dict(getattr(result, "errors", None) or {})
    doubts = tuple(getattr(result, "doubts", ()) or ())
    return [f"{k} failed: {v}" for k, v in errors.items()] + [str(d) for d in doubts]
