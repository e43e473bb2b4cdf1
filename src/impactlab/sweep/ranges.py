"""The values of a study file's range axis: ``start``, ``stop`` and ``num`` or ``step``.

A linear range gives the decimal values the user writes: ``mu = { start = 0.0, stop = 0.7,
step = 0.1 }`` is 0, 0.1, ..., 0.7, each the float of that decimal (``ds.e.sel(mu=0.3)``
finds it; the case labelled 0.6 is ``simulate(mu=0.6)``'s), and a reached stop is the stop as
given. The arithmetic is done in decimal on the numbers as written, in their one unit (bare
numbers in the table's ``unit`` or the input's own; or strings such as ``"10 deg"``), and each
value then converted to SI as that number in that unit would be. A ``num`` range divides
``stop - start`` in decimal too (``num = 8`` from 0 to 0.7: steps of 0.1). Where the three
are written in different units, or for ``spacing = "log"`` (``numpy.geomspace``), the values
are computed in SI, with the stop exact.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from decimal import Decimal, InvalidOperation, localcontext
from typing import Any

import numpy as np

from impactlab.sweep.limits import too_many

__all__ = ["Limit", "range_values"]

#: (max_cases, kept outputs): what an axis's size is checked against before its values exist.
Limit = tuple[int, tuple[str, ...] | None]
Converter = Callable[..., float]

_NUMBER = re.compile(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(?:\s*(\S.*?))?\s*")


def _written(value: Any) -> tuple[Decimal, str] | None:
    """A value as the user wrote it: (its number in decimal, its unit text, "" for a bare
    number); None for what is not one number and one unit."""
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float):
        text = repr(value)
        return (Decimal(text), "") if math.isfinite(value) else None
    match = _NUMBER.fullmatch(str(value))
    if match is None:
        return None
    try:
        return Decimal(match[1]), match[2] or ""
    except InvalidOperation:
        return None


def range_values(
    name: str,
    spec: Mapping[str, Any],
    start: float,
    stop: float,
    conv: Converter,
    spacing: str,
    limit: Limit,
) -> list[float]:
    """The values (SI) of the range axis of input ``name`` given by ``spec`` (``start`` and
    ``stop`` already converted by ``conv``: ``start``, ``stop``); an axis of more values than
    ``max_cases`` is refused before its values are made."""
    if "num" in spec:
        num = spec["num"]
        if isinstance(num, bool) or not isinstance(num, int) or num < 1:
            raise ValueError(f"[grid] {name}: num must be an integer >= 1, got {num!r}")
        if num > limit[0]:
            raise too_many(f"[grid] {name} (num = {num})", num, *limit)
        if spacing == "log":
            if start == 0 or stop == 0 or (start < 0) != (stop < 0):
                raise ValueError(
                    f"[grid] {name}: log spacing needs start and stop of one sign, neither 0 "
                    f"(geomspace), got {spec['start']!r} and {spec['stop']!r}"
                )
            return [float(v) for v in np.geomspace(start, stop, num)]
        return _decimal(spec, ("start", "stop"), conv, num) or _exact_stop(
            np.linspace(start, stop, num), stop
        )
    if spacing == "log":
        raise ValueError(f"[grid] {name}: log spacing takes 'num', not 'step'")
    step = conv(spec["step"], "step")
    if step == 0 or (stop - start) / step < 0:  # the values as written, not in SI
        raise ValueError(
            f"[grid] {name}: step {spec['step']!r} does not lead from start {spec['start']!r} "
            f"to stop {spec['stop']!r}"
        )
    written = [_written(spec[k]) for k in ("start", "stop", "step")]
    if all(written) and len({w[1] for w in written if w}) == 1:
        (a, _), (b, _), (h, _) = (w for w in written if w)
        count = int((b - a) / h) + 1  # exact: a decimal quotient, truncated
    else:
        count = math.floor((stop - start) / step + 1e-9) + 1
    if count > limit[0]:
        raise too_many(f"[grid] {name} (start/stop/step)", count, *limit)
    return _decimal(spec, ("start", "stop", "step"), conv, count) or _exact_stop(
        start + step * np.arange(count), stop
    )


def _decimal(
    spec: Mapping[str, Any], keys: tuple[str, ...], conv: Converter, count: int
) -> list[float] | None:
    """The values in decimal, when ``spec``'s ``keys`` are written in one unit: start + i step
    (``keys`` with "step") or start + i (stop - start) / (count - 1), each converted to SI as
    that number in that unit (the conversion's factor, checked against the converter on the
    given numbers); None otherwise."""
    written = [_written(spec[k]) for k in keys]
    if not all(written) or len({w[1] for w in written if w}) != 1:
        return None
    numbers = [w[0] for w in written if w]
    unit = next(w[1] for w in written if w)

    def si(x: Decimal, key: str = "") -> float:
        return conv(f"{x} {unit}" if unit else float(x), key)

    factor = si(Decimal(1))
    if any(si(x, k) != float(x) * factor for x, k in zip(numbers, keys, strict=True)):
        return None  # a conversion that is no plain factor: every value through it
    with localcontext() as ctx:
        ctx.prec = 40
        a, b = numbers[0], numbers[1]
        h = numbers[2] if len(numbers) == 3 else (b - a) / (count - 1) if count > 1 else b - a
        values = [a + h * i for i in range(count)]
    if len(numbers) == 2 and count > 1:
        values[-1] = b
    return [float(v) * factor for v in values]


def _exact_stop(values: np.ndarray, stop: float) -> list[float]:
    """``values`` (SI) with a last value within rounding of ``stop`` made ``stop`` itself."""
    out = [float(v) for v in values]
    if out and math.isclose(out[-1], stop, rel_tol=1e-9, abs_tol=0.0):
        out[-1] = stop
    return out
