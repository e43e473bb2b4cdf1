"""Input checks shared by the public API: one rule for numbers, clear errors that name the
parameter, and :class:`ImplausibleInputWarning` for inputs that are possible but implausible.

The one input rule of the Python API (:func:`check_finite` and everything built on it):

- a dimensionless parameter (mu, e, rtol, ...; no ``unit``) is a real number: a Python or numpy
  int or float, a 0-d numeric array or a dimensionless pint Quantity. A bool, a string
  (``"0.2"``), None or anything else is refused with a ``ValueError`` naming the parameter;
- a dimensional parameter (called with its ``unit``, e.g. ``check_positive("length", v, "m")``)
  is a number in that unit (SI), a string with units (``"8.8 mm"``) or a pint Quantity of any
  registry, converted by ``impactlab.units.magnitude`` (dimension checked); a bare number string
  is refused (it names no unit);
- flags are bools (:func:`check_flag`), seeds None or integers >= 0 (:func:`check_seed`).

A user's text file (TOML, JSON, CSV) is read by :func:`read_text_file`: one ``ValueError`` line
naming the file and the first byte that is not UTF-8 text.
"""

from __future__ import annotations

import functools
import inspect
import math
import os
import sys
import warnings
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any, ParamSpec, TypeVar

import numpy as np

from impactlab._input_limits import MAX_GRAVITY
from impactlab.units import is_quantity, magnitude


class MissingExtraError(ImportError, ValueError):
    """An optional extra that is not installed; the message names the package and the pip
    command. A ValueError too: the command line says it in one line (exit status 2)."""


class ImplausibleInputWarning(UserWarning):
    """An input that is possible but implausible (most likely a unit mistake): a tip radius
    over half a metre, a rod longer than 10 m, an impact faster than 100 m/s, ... The
    computation goes on; each public function states its bounds in its docstring."""


def did_you_mean(name: Any, known: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the known name nearest to ``name`` (a mistyped or
    ``-``/``_``-swapped or differently cased name), or ``""``."""
    import difflib

    if not isinstance(name, str):
        return ""
    names = list(known)

    def key(text: str) -> str:  # "HERTZ", "Kogut_Komvopoulos": the same name
        return text.replace("-", "_").lower()

    swapped = [k for k in names if key(k) == key(name)]
    near = swapped or [
        names[[key(k) for k in names].index(m)]
        for m in difflib.get_close_matches(key(name), [key(k) for k in names], n=1, cutoff=0.6)
    ]
    return f" (did you mean {near[0]!r}?)" if near else ""


def unexpected_keywords(
    function: str, given: Iterable[str], known: Iterable[str], notes: Mapping[str, str]
) -> str:
    """The TypeError text of ``function`` called with keywords it does not take (``given``):
    each with its note (``notes``: what to use instead) or the nearest known name
    (:func:`did_you_mean`), then the keywords it takes, as ``simulate`` words it."""
    names = sorted(known)
    hints = [f"{k} ({notes[k]})" if k in notes else f"{k}{did_you_mean(k, names)}" for k in given]
    return (
        f"{function}() got unexpected keyword argument(s) {', '.join(hints)}; it takes "
        f"{', '.join(names)}"
    )


_P = ParamSpec("_P")
_R = TypeVar("_R")


def refuse_unknown_keywords(
    notes: Mapping[str, str] | None = None,
) -> Callable[[Callable[_P, _R]], Callable[_P, _R]]:
    """Decorate a public function so that a keyword it does not take raises a TypeError in the
    words of :func:`unexpected_keywords` (``notes``: keyword -> what to use instead) rather
    than Python's bare one; the signature and docstring stay the function's."""

    def decorate(function: Callable[_P, _R]) -> Callable[_P, _R]:
        kinds = (inspect.Parameter.POSITIONAL_OR_KEYWORD, inspect.Parameter.KEYWORD_ONLY)
        params = inspect.signature(function).parameters
        known = frozenset(k for k, p in params.items() if p.kind in kinds)
        name = getattr(function, "__name__", "function")

        @functools.wraps(function)
        def checked(*args: _P.args, **kwargs: _P.kwargs) -> _R:
            extra = [k for k in kwargs if k not in known]
            if extra:
                raise TypeError(unexpected_keywords(name, extra, known, notes or {}))
            return function(*args, **kwargs)

        return checked

    return decorate


def _caller_level() -> int:
    """The ``stacklevel`` of the first frame outside impactlab, counted from the caller of this
    function (so that a warning points at the user's line, however deep it was raised)."""
    frame = sys._getframe(2)
    level = 2
    while frame.f_back is not None and str(frame.f_globals.get("__name__", "")).startswith(
        "impactlab"
    ):
        frame = frame.f_back
        level += 1
    return level


def warn_implausible(message: str) -> None:
    """Issue an :class:`ImplausibleInputWarning` with ``message``, attributed to the first line
    outside impactlab (the user's call of the public function)."""
    warnings.warn(message, ImplausibleInputWarning, stacklevel=_caller_level())


#: What an array of a non-numeric dtype kind holds (for the error message).
_KINDS = {"b": "bools", "U": "strings", "S": "bytes", "O": "objects", "c": "complex numbers"}


def _not_a_number(name: str, value: Any) -> ValueError | None:
    """The error for what the number rule refuses outright (None when ``value`` may be one):
    None, bools, strings, bytes and arrays that do not hold real numbers."""
    if value is None:
        return ValueError(f"{name} must be a real number, got None")
    if isinstance(value, bool | np.bool_):
        return ValueError(f"{name} must be a real number, got the bool {value!r}")
    if isinstance(value, str | bytes):
        try:
            number = float(value)
        except ValueError:
            number = math.nan
        hint = f": write {name}={number!r}, not {value!r}" if math.isfinite(number) else ""
        return ValueError(f"{name} must be a real number, got the string {value!r}{hint}")
    if isinstance(value, np.ndarray) and value.dtype.kind not in "iuf":
        what = _KINDS.get(value.dtype.kind, f"dtype {value.dtype}")
        return ValueError(f"{name} must hold real numbers, got an array of {what}: {value!r}")
    return None


def check_finite(name: str, value: Any, unit: str = "") -> float:
    """The rule (module docstring): ``value`` as a float if it is a finite real number --
    with a ``unit``, also a string with units or a pint Quantity, converted to ``unit`` -- and
    ValueError naming ``name`` otherwise. Bools and strings are never coerced to numbers
    (``"0.2"`` and ``True`` are refused)."""
    if unit:
        value = magnitude(name, value, unit)
    else:
        _refuse_dimension(name, value)
        value = percent_fraction(value)
    err = _not_a_number(name, value)
    if err is not None:
        raise err
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return x


def percent_fraction(value: Any) -> Any:
    """A string in percent (``"20 %"``, ``"20 percent"``) as its fraction (0.2), as a percent
    Quantity reads; anything else unchanged (refused as a string after)."""
    if not (isinstance(value, str) and ("%" in value or "percent" in value)):
        return value
    from impactlab.units import registry

    try:
        q: Any = registry().Quantity(value.strip().replace("%", " percent"))
    except Exception:  # not a quantity pint reads: the string's own error follows
        return value
    return float(q.to("dimensionless").magnitude) if str(q.units) == "percent" else value


def _suffix(unit: str) -> str:
    """The unit after a number in a message, ``" Pa"``; none for a dimensionless value (``""``,
    ``"1"``)."""
    return f" {unit}" if unit not in ("", "1") else ""


def value_text(x: float, unit: str = "") -> str:
    """``x`` as the shortest text that reads back as ``x`` (exponent form for |x| >= 1e6 or
    < 1e-4) and its ``unit``, for messages: ``value_text(-69e9, "Pa") == "-6.9e+10 Pa"``; a
    value that needs more than 12 significant digits, the round-off of a unit conversion
    (-50 um is -4.9999999999999996e-05 m), is shown to 12 (``-5e-05 m``)."""
    x = float(x)
    if x == 0.0 or not math.isfinite(x):
        return repr(x) + _suffix(unit)
    digits = next(n for n in range(17) if float(f"{x:.{n}e}") == x)
    if digits >= 12:
        text = f"{x:.12g}"
    elif 1e-4 <= abs(x) < 1e6:
        text = repr(x)
    else:
        text = f"{x:.{digits}e}"
    return text + _suffix(unit)


def check_positive(name: str, value: Any, unit: str = "") -> float:
    """Finite and > 0 (in ``unit``: :func:`check_finite`)."""
    x = check_finite(name, value, unit)
    if x <= 0.0:
        raise ValueError(f"{name} must be > 0{_suffix(unit)}, got {value_text(x, unit)}")
    return x


def check_nonnegative(name: str, value: Any, unit: str = "") -> float:
    """Finite and >= 0 (in ``unit``: :func:`check_finite`)."""
    x = check_finite(name, value, unit)
    if x < 0.0:
        raise ValueError(f"{name} must be >= 0{_suffix(unit)}, got {value_text(x, unit)}")
    return x


def check_gravity(name: str, value: Any) -> float:
    """A gravitational acceleration [m/s^2]: finite, in [0, ``MAX_GRAVITY``] (a million g, the
    engine's bound: ``impactlab._input_limits``)."""
    x = check_nonnegative(name, value, "m/s^2")
    if x > MAX_GRAVITY:
        raise ValueError(
            f"{name} must lie in [0, {MAX_GRAVITY:g}] m/s^2 (a million g), got "
            f"{value_text(x, 'm/s^2')}"
        )
    return x


def check_range(
    name: str,
    value: Any,
    low: float,
    high: float,
    *,
    low_inclusive: bool = True,
    high_inclusive: bool = True,
    unit: str = "",
) -> float:
    """Finite and inside the stated interval (in ``unit``: :func:`check_finite`)."""
    x = check_finite(name, value, unit)
    lo_ok = x >= low if low_inclusive else x > low
    hi_ok = x <= high if high_inclusive else x < high
    if not (lo_ok and hi_ok):
        lb = "[" if low_inclusive else "("
        hb = "]" if high_inclusive else ")"
        raise ValueError(
            f"{name} must lie in {lb}{low}, {high}{hb}{_suffix(unit)}, got {value_text(x, unit)}"
        )
    return x


def check_flag(name: str, value: Any) -> bool:
    """``value`` if it is a bool (Python or numpy); ValueError naming ``name`` otherwise (a
    string such as ``"no"`` is not silently true)."""
    if not isinstance(value, bool | np.bool_):
        raise ValueError(f"{name} must be True or False, got {value!r}")
    return bool(value)


def check_seed(name: str, value: Any) -> int | None:
    """A random seed: None or an integer >= 0 (not a bool); ValueError naming ``name``."""
    if value is None:
        return None
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | np.integer):
        raise ValueError(f"{name} must be None or an integer >= 0, got {value!r}")
    if value < 0:
        raise ValueError(f"{name} must be None or an integer >= 0, got {value!r}")
    return int(value)


def _refuse_dimension(name: str, value: Any) -> None:
    """ValueError naming ``name`` when ``value``, given for a dimensionless parameter, is a pint
    Quantity with a dimension (``mu = 0.2 m/s``); a dimensionless one passes (percent reads as
    a fraction, as ``float()`` of it does)."""
    if is_quantity(value) and not getattr(value, "dimensionless", False):
        raise ValueError(
            f"{name} is a pure number: pass a plain number or a dimensionless Quantity (a "
            f"fraction, or percent), got {value!r} (dimension {value.dimensionality})"
        )


def _plain(name: str, value: Any) -> Any:
    """A dimensionless pint Quantity (any registry, scalar or array) as its pure number (20
    percent -> 0.2, as ``float()`` of it reads); anything else unchanged."""
    _refuse_dimension(name, value)
    if not is_quantity(value):
        return value
    m = value.to("dimensionless").magnitude
    return float(m) if np.ndim(m) == 0 else np.asarray(m, dtype=np.float64)


def _holds_quantities(values: Any) -> bool:
    """Whether ``values`` is a list, a tuple or a 1-D array of strings that holds a string or a
    pint Quantity among its elements (each one a quantity with its own unit)."""
    if isinstance(values, np.ndarray):
        return values.ndim == 1 and values.dtype.kind == "U"
    return isinstance(values, list | tuple) and any(
        isinstance(v, str) or is_quantity(v) for v in values
    )


def check_array(name: str, values: Any, unit: str = "") -> np.ndarray:
    """The rule applied to an array: a float64 array of ``values`` (NaN allowed; with a
    ``unit``, a pint Quantity array, a string with units, or a list of them, each element in
    its own unit (``["20 deg", 0.5]``: a bare number in ``unit``), is converted; without one, a
    dimensionless Quantity is read as its pure number, percent as a fraction, and one with a
    dimension is refused, as :func:`check_finite` reads a scalar); ValueError naming ``name``
    for None, bools, strings or anything that is not numeric."""
    if unit and _holds_quantities(values):  # ["20 deg", "45 deg"]: each read in its unit
        values = [magnitude(f"{name}[{i}]", v, unit) for i, v in enumerate(values)]
    if not unit and _holds_quantities(values):  # ["10 %", 0.2]: percent as a fraction
        values = [percent_fraction(v) for v in values]
    values = magnitude(name, values, unit) if unit else percent_fraction(_plain(name, values))
    err = _not_a_number(name, values)
    if err is not None:
        raise err
    try:
        arr = np.asarray(values)
    except (TypeError, ValueError):
        raise ValueError(
            f"{name} must be a number or an array of numbers, got {values!r}"
        ) from None
    err = _not_a_number(name, arr)
    if err is not None:
        raise err
    return arr.astype(np.float64)


def check_array_finite(name: str, values: Any, unit: str = "") -> np.ndarray:
    """Return a float64 array; raise ValueError naming ``name`` if any entry is NaN or infinite
    (or is not a number: :func:`check_array`)."""
    arr = check_array(name, values, unit)
    bad = ~np.isfinite(arr)
    if bad.any():
        idx = int(np.flatnonzero(bad.ravel())[0])
        raise ValueError(f"{name} must be finite; entry {idx} is {arr.ravel()[idx]!r}")
    return arr


def read_text_file(path: str | os.PathLike[str], kind: str, what: str = "") -> str:
    """The UTF-8 text of a user's file (a leading byte order mark dropped). ``kind`` is its
    format (``"TOML"``, ``"JSON"``, ``"CSV"``), ``what`` how a message names it (``"--config
    'a.toml'"``). ValueError, one line, when it is not UTF-8 text: ``"--config 'a.toml' is not a
    text file (TOML is UTF-8 text; byte 1 is 0xff)"`` (``"not a text file (...)"`` without
    ``what``); UTF-16 text (a byte order mark FF FE or FE FF) and Windows-1252 text
    (:func:`_not_utf8`) are named as such. OSError (a missing or unreadable file) passes
    through."""
    data = Path(path).read_bytes()
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):  # Excel's "Unicode Text", Notepad's "Unicode"
        how = "Excel: 'CSV UTF-8'; an editor" if kind == "CSV" else "an editor"
        problem = (
            f"UTF-16 text: save the file as UTF-8 ({kind} is read as UTF-8; {how}: encoding UTF-8)"
        )
        raise ValueError(f"{what} is {problem}" if what else problem)
    skip = 3 if data.startswith(b"\xef\xbb\xbf") else 0
    try:
        return data[skip:].decode("utf-8")
    except UnicodeDecodeError as exc:
        problem = _not_utf8(data, skip + exc.start, kind)
        raise ValueError(f"{what} is {problem}" if what else problem) from None


def _not_utf8(data: bytes, at: int, kind: str) -> str:
    """Why ``data`` (a ``kind`` file whose byte ``at`` is the first that is not UTF-8) cannot be
    read: Windows-1252 text (a spreadsheet's export or an editor's file in a Western European
    locale: no control byte but tab, line breaks and form feed, every byte a Windows-1252
    character) named as such, with how to save it as UTF-8; anything else is not a text file."""
    byte = f"byte {at} is 0x{data[at]:02x}"
    controls = set(range(32)) - set(b"\t\n\r\f")
    try:
        text = None if controls.intersection(data) else data.decode("cp1252")
    except UnicodeDecodeError:
        text = None
    if text is None:
        return f"not a text file ({kind} is UTF-8 text; {byte})"
    how = "Excel: 'CSV UTF-8'; an editor" if kind == "CSV" else "an editor"
    line = data[:at].count(b"\n") + 1
    return (
        f"not UTF-8 text ({kind} is read as UTF-8): line {line}, {byte}, {text[at]!r} in "
        "Windows-1252, the encoding of a spreadsheet or editor set to a Western European "
        f"language; save the file as UTF-8 ({how}: encoding UTF-8)"
    )
