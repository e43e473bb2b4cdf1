"""The numeric options of :func:`~impactlab.experiment.kinematics.measure_impact`, checked
before any work: a TypeError (wrong kind of value) or ValueError (out of range) naming the
option, the value given and what is allowed."""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from typing import Any

__all__ = ["FLOAT_OPTIONS", "INT_OPTIONS", "check_kinematics_options"]

#: Integer options -> (smallest allowed value, what they count).
INT_OPTIONS: dict[str, tuple[int, str]] = {
    "guard": (1, "frames left out on each side of the impact"),
    "window": (2, "frames per side of the impact detector"),
    "min_fit_frames": (4, "frames of a free-flight fit, at least"),
    "max_fit_frames": (4, "frames of a free-flight fit, at most"),
    "rigidity_window": (3, "samples of the rigidity check's running median"),
}
#: Options that are a length or an acceleration (finite, > 0) -> (unit, example).
FLOAT_OPTIONS: dict[str, tuple[str, str]] = {
    "g": ("m/s^2", "9.81: gravity's magnitude, its direction is up="),
    "rigidity_tolerance": ("m", "1e-3 for 1 mm"),
    "max_com_sigma": ("m", "5e-3 for 5 mm"),
}


def _kind(value: Any) -> str:
    return f"{type(value).__name__} {value!r}"


def _integer(name: str, value: Any, label: str) -> int:
    least, what = INT_OPTIONS[name]
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{label} must be an integer >= {least} ({what}), got {_kind(value)}")
    if value < least:
        raise ValueError(f"{label} must be an integer >= {least} ({what}), got {value!r}")
    return int(value)


def _positive(name: str, value: Any, label: str) -> float:
    unit, example = FLOAT_OPTIONS[name]
    wanted = f"a finite number > 0 in {unit} (e.g. {example})"
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{label} must be {wanted}, got {_kind(value)}")
    x = float(value)
    if not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"{label} must be {wanted}, got {value!r}")
    return x


def check_kinematics_options(options: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """The numeric options among ``options`` checked (others are passed through unchanged);
    ``prefix`` spells them in messages (``"kinematics_options: "``)."""
    out = dict(options)
    for name, value in options.items():
        if name in INT_OPTIONS:
            out[name] = _integer(name, value, f"{prefix}{name}")
        elif name in FLOAT_OPTIONS:
            out[name] = _positive(name, value, f"{prefix}{name}")
    lo, hi = out.get("min_fit_frames"), out.get("max_fit_frames")
    if lo is not None and hi is not None and hi < lo:
        raise ValueError(f"{prefix}max_fit_frames ({hi}) must be >= min_fit_frames ({lo})")
    return out
