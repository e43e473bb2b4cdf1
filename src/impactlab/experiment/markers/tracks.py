"""Marker tracks (positions in metres, occlusions masked) and the length units of marker files."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import PurePath
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.experiment.errors import FileFormatError
from impactlab.units import registry, to_si

__all__ = [
    "RATE_AGREEMENT",
    "MarkerTracks",
    "check_rate_agrees",
    "duplicate_labels",
    "length_factor",
    "parse_rate",
    "rate_argument",
]

#: A frame rate the caller gives agrees with the one a file states when they differ by at most
#: this fraction.
RATE_AGREEMENT = 0.01
#: Marker labels a repr names at most.
_NAMED = 8

#: Spellings of "per second" in a frame rate that pint does not read as a frequency.
_PER_SECOND = re.compile(
    r"(?i)^(?P<number>[^a-z/]*?)\s*(?:fps|frames?\s*(?:/|per)\s*s(?:ec(?:ond)?)?|1\s*/\s*s)$"
)
#: Hz and kHz in any case (pint knows 'Hz' and 'kHz' only).
_HERTZ = re.compile(r"(?i)(?<![a-z])(k?)hz(?![a-z])")
#: How a frame rate is written.
RATE_FORMS = "a number in Hz or a string with its unit: '500 Hz', '0.5 kHz', '500 fps', '500 1/s'"


def parse_rate(text: str, name: str = "rate") -> float:
    """The frame rate [Hz] written as ``text`` (Hz, kHz in any case, 1/s, fps, or a bare number
    in Hz; a unit is never dropped); ValueError naming ``name`` for anything else or a rate that
    is not finite and > 0."""
    value = text.strip()
    m = _PER_SECOND.match(value)
    if m is not None:
        value = f"{m.group('number').strip()} Hz"
    value = _HERTZ.sub(lambda h: "kHz" if h.group(1) else "Hz", value)
    try:
        fr = to_si(value, "Hz", name=name)
    except ValueError as exc:
        raise ValueError(
            f"{name} {text!r} is not a frame rate ({exc}); write {RATE_FORMS}"
        ) from None
    if not (math.isfinite(fr) and fr > 0):
        raise ValueError(f"{name} must be > 0 Hz, got {text!r}")
    return fr


def rate_argument(value: Any, name: str = "rate") -> float | None:
    """``rate=`` of the marker readers as a frame rate [Hz] (None stays None): a number in Hz or
    a string as :func:`parse_rate` reads it; TypeError for another kind (a boolean included),
    ValueError naming ``name`` and the value for one that is not finite and > 0."""
    if value is None:
        return None
    if isinstance(value, str):
        return parse_rate(value, name)
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise TypeError(
            f"{name} must be a frame rate ({RATE_FORMS}), got {type(value).__name__} {value!r}"
        )
    fr = float(value)
    if not (math.isfinite(fr) and fr > 0):
        raise ValueError(f"{name} must be a finite frame rate > 0 Hz, got {value!r}")
    return fr


def check_rate_agrees(path: Any, given: Any, stated: float, where: str) -> None:
    """FileFormatError naming both when the frame rate ``given`` [Hz] (``rate=``) is not a
    number > 0 or differs from the file's ``stated`` [Hz] (``where``: how the file states it)
    by more than ``RATE_AGREEMENT``: the file's rate is the one used."""
    try:
        fr = float(given)
    except (TypeError, ValueError):
        fr = math.nan
    if isinstance(given, bool) or not (math.isfinite(fr) and fr > 0):
        raise FileFormatError(path, f"rate must be a frame rate in Hz (> 0), got {given!r}")
    if abs(fr / stated - 1.0) > RATE_AGREEMENT:
        raise FileFormatError(
            path,
            f"rate={fr:g} Hz disagrees with the file's frame rate {stated:.6g} Hz ({where}): "
            "leave rate= out (the file's own rate is used) or correct it",
        )


def duplicate_labels(
    labels: list[str] | tuple[str, ...], at: Callable[[int], str] = lambda i: f"marker {i + 1}"
) -> str:
    """How ``labels`` repeat a marker's label (``'M1' 2 times (marker 1, marker 4): ...``, each
    place as ``at(index)`` writes it); empty when each label is unique. Labels are compared as
    written (``M1`` and ``m1`` are two markers)."""
    seen: dict[str, list[int]] = {}
    for i, lab in enumerate(labels):
        seen.setdefault(str(lab), []).append(i)
    twice = [
        f"{lab!r} {len(idx)} times ({', '.join(at(i) for i in idx)})"
        for lab, idx in seen.items()
        if len(idx) > 1
    ]
    if not twice:
        return ""
    return "; ".join(twice) + ": each marker needs a label of its own (rename or drop the copy)"


def length_factor(unit: str, *, name: str = "units") -> float:
    """Metres per ``unit`` (e.g. "mm" -> 1e-3). ValueError naming ``name`` for a unit that is not
    a length, and for one whose lower-case spelling is another length ('MM' is megamolar, 'Mm'
    megametres, 'CM' unknown: each refused with the lower-case unit suggested, not guessed)."""
    text = str(unit).strip().replace("µ", "u").replace("μ", "u")
    if not text:
        raise ValueError(f"{name} is empty; expected a length unit such as 'mm' or 'm'")
    fac, called = _metres(text)
    lower = text.lower()
    if lower != text:
        meant, lower_called = _metres(lower)
        if meant is not None and meant != fac:  # 'MM' (megamolar), 'Mm' (megametres), 'CM'
            reads = (
                "is not a known unit"
                if not called
                else f"is {called}, not a length"
                if fac is None
                else f"is {called} ({fac:g} m)"
            )
            raise ValueError(
                f"{name}: {unit!r} {reads}; unit names are case-sensitive and not read in "
                f"another case: write {lower!r} ({lower_called})"
            )
    if not called:
        raise ValueError(
            f"{name}: {unit!r} is not a known unit; expected a length unit such as 'mm' or 'm'"
        )
    if fac is None:
        raise ValueError(f"{name}: {unit!r} is not a length unit; expected e.g. 'mm' or 'm'")
    return fac


def _metres(text: str) -> tuple[float | None, str]:
    """(metres per the unit ``text``, None where it is not a length; its pint name, empty
    where pint does not know it)."""
    ureg = registry()
    try:
        u = ureg.Unit(text)
    except Exception:  # pint's parser raises assorted types (TokenError, AssertionError, ...)
        return None, ""
    if u.dimensionality != ureg.Unit("m").dimensionality:
        return None, str(u)
    return float((1.0 * u).to("m").magnitude), str(u)


@dataclass(frozen=True, repr=False)
class MarkerTracks:
    """Marker positions over time (SI).

    Attributes
    ----------
    time : (n,) frame times [s], strictly increasing.
    positions : (n, m, 3) marker positions [m] in the camera (lab) frame; NaN where a marker is
        occluded or invalid.
    labels : the m marker labels.
    source : where the data came from (a file path), for messages.
    """

    time: np.ndarray
    positions: np.ndarray
    labels: tuple[str, ...]
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        t = np.array(self.time, dtype=np.float64).reshape(-1)
        p = np.array(self.positions, dtype=np.float64)
        where = f" ({self.source})" if self.source else ""
        if p.ndim != 3 or p.shape[2] != 3:
            raise ValueError(
                f"positions must have shape (frames, markers, 3), got {p.shape}{where}"
            )
        if p.shape[0] != t.size:
            raise ValueError(
                f"time has {t.size} entries but positions has {p.shape[0]} frames{where}"
            )
        if t.size < 2:
            raise ValueError(f"marker tracks need at least 2 frames, got {t.size}{where}")
        if not np.all(np.isfinite(t)):
            raise ValueError(f"time must be finite{where}")
        if np.any(np.diff(t) <= 0):
            k = int(np.flatnonzero(np.diff(t) <= 0)[0])
            raise ValueError(
                f"time must increase strictly; frame {k + 1} ({t[k + 1]!r} s) does "
                f"not follow frame {k} ({t[k]!r} s){where}"
            )
        labels = tuple(str(s) for s in self.labels)
        if len(labels) != p.shape[1]:
            raise ValueError(f"{len(labels)} labels for {p.shape[1]} markers{where}")
        twice = duplicate_labels(labels)
        if twice:
            raise ValueError(f"marker labels must be unique, got {twice}{where}")
        p = p.copy()
        bad = ~np.all(np.isfinite(p), axis=2)
        p[bad] = np.nan
        t.setflags(write=False)
        p.setflags(write=False)
        object.__setattr__(self, "time", t)
        object.__setattr__(self, "positions", p)
        object.__setattr__(self, "labels", labels)

    def __repr__(self) -> str:
        """One line: the file, frames, rate, span, markers and how many positions are
        missing (never the arrays)."""
        span = display_unit("duration", "s")
        labels = ", ".join(self.labels[:_NAMED]) + (", ..." if self.n_markers > _NAMED else "")
        missing = int(self.valid.size - np.count_nonzero(self.valid))
        seen = f"{missing} of {self.valid.size} positions occluded" if missing else "all seen"
        where = f"{PurePath(self.source).name}: " if self.source else ""
        return (
            f"MarkerTracks({where}{self.n_frames} frames at {format_number(self.rate, 4)} Hz over "
            f"{format_number((self.time[-1] - self.time[0]) * span.scale, 4)} {span.unit}, "
            f"{self.n_markers} marker{'s' * (self.n_markers != 1)} {labels}, {seen}; "
            "positions in m)"
        )

    @property
    def n_frames(self) -> int:
        return int(self.time.size)

    @property
    def n_markers(self) -> int:
        return int(self.positions.shape[1])

    @property
    def valid(self) -> np.ndarray:
        """(n, m) True where the marker was seen."""
        return np.all(np.isfinite(self.positions), axis=2)

    @property
    def rate(self) -> float:
        """Frame rate [Hz] (median of 1/dt)."""
        return float(1.0 / np.median(np.diff(self.time)))

    def select(self, labels: list[str] | tuple[str, ...]) -> MarkerTracks:
        """The tracks of the named markers only (in that order)."""
        missing = [s for s in labels if s not in self.labels]
        if missing:
            raise ValueError(
                f"markers {missing} not in {self.source or 'the tracks'}; "
                f"available: {list(self.labels)}"
            )
        idx = [self.labels.index(s) for s in labels]
        return MarkerTracks(
            self.time, self.positions[:, idx, :], tuple(labels), self.source, dict(self.meta)
        )
