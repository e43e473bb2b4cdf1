"""Drops of a measurements file that hold the same values under other labels: a drop copied
(a pasted row, an analysis appended twice) would count twice in a calibration and narrow its
intervals as if measured twice. ``analyze --measurements`` refuses such an append
(``measurement_append``); a file that already holds one is read with a
``CalibrationWarning`` naming the drops (:func:`warn_twins`).
"""

from __future__ import annotations

import math
import warnings
from typing import Any

from impactlab.calibrate.calibration_warning import CalibrationWarning

__all__ = ["SAME_VALUE_RTOL", "same_drop", "warn_twins"]


#: The relative difference below which two values of a file are the same measurement: the file
#: holds 12 significant digits, and a unit conversion adds round-off.
SAME_VALUE_RTOL = 1e-9


def same_drop(meas: Any, new: int) -> int | None:
    """The index of an earlier drop of ``meas`` that holds the values of drop ``new`` (the same
    categories, the same inputs, and the same measured values, at least one, each to
    :data:`SAME_VALUE_RTOL`; their uncertainties aside), or None: a drop appended again under
    another label."""
    measured = [k for k, v in meas.observed.items() if math.isfinite(v[new])]
    if not measured:
        return None
    columns = [*meas.observed.values(), *meas.inputs.values()]
    for i in range(new):
        if dict(meas.categories[i]) == dict(meas.categories[new]) and all(
            _same(float(v[i]), float(v[new])) for v in columns
        ):
            return i
    return None


def _same(a: float, b: float) -> bool:
    """Both not given (NaN), or equal to :data:`SAME_VALUE_RTOL`."""
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return math.isclose(a, b, rel_tol=SAME_VALUE_RTOL, abs_tol=0.0)


def warn_twins(meas: Any) -> None:
    """A ``CalibrationWarning`` naming every drop of ``meas`` (``Measurements``) that holds
    the values of an earlier one (``same_drop``)."""
    pairs = [(i, j) for i in range(meas.n_drops) if (j := same_drop(meas, i)) is not None]
    if not pairs:
        return
    said = "; ".join(f"{meas.labels[i]!r} holds the values of {meas.labels[j]!r}" for i, j in pairs)
    warnings.warn(
        f"{meas.source or 'measurements'}: {said}: the same drop under two labels counts twice "
        "in a calibration (its intervals narrow as if it were measured twice); remove the copy, "
        "or keep it if the drops were indeed measured alike",
        CalibrationWarning,
        stacklevel=3,
    )
