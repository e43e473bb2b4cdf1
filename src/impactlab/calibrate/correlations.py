"""Correlated measured values of a drop: the correlation coefficients of pairs of its measured
quantities (one marker fit gives e and spin_out together: correlated, -0.97 in the example drop).

A drop gives a pair's coefficient as the column ``correlation_<a>_<b>`` (``correlation_e_spin_out
= -0.97``; aliases allowed, ``correlation_e_T``), a plain number in [-1, 1] without a unit; the
order of the two names is free (``correlation_spin_out_e`` is the same column) and a missing or
blank one is 0 (independent). ``Measurements.correlation`` holds them as pair -> (D,) array, the
pair in the order of ``quantities.MEASURABLE`` (NaN: not given). Refused, naming the drop and the
pair: a coefficient outside [-1, 1], a pair naming a quantity the drop does not measure (with its
sigma), a pair given twice, and coefficients that form no positive-definite correlation matrix.
The likelihood of a drop with a coefficient other than 0 is the multivariate normal of its
measured values with covariance D R D (D = diag(sigma), R the correlation matrix), through the
Cholesky factor of R (``correlated_loglik``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab.calibrate.quantities import MEASURABLE, OUTPUT_ALIASES, canonical_output

__all__ = [
    "PREFIX",
    "check_drop",
    "coefficient",
    "correlation_column",
    "correlation_pair",
    "normalised",
    "ordered",
]

#: The start of a correlation column's name: ``correlation_e_spin_out``.
PREFIX = "correlation_"
#: The smallest eigenvalue a correlation matrix may have: below, two values are one.
_EIGEN_MIN = 1e-12
_NAMES = (*MEASURABLE, *OUTPUT_ALIASES)
_ORDER = {q: i for i, q in enumerate(MEASURABLE)}


def ordered(a: str, b: str) -> tuple[str, str]:
    """The pair (a, b) of measured quantities in the order of ``MEASURABLE``."""
    return (a, b) if _ORDER[a] <= _ORDER[b] else (b, a)


def correlation_column(a: str, b: str) -> str:
    """The column of the pair's coefficient: ``correlation_e_spin_out``."""
    a, b = ordered(a, b)
    return f"{PREFIX}{a}_{b}"


def correlation_pair(where: str, name: str) -> tuple[str, str]:
    """The pair of measured quantities (canonical, ordered) that the column ``name``
    (``correlation_<a>_<b>``) names; ValueError naming ``where`` and the column when it names
    no two measured quantities, or one quantity twice."""
    rest = name[len(PREFIX) :]
    splits = [
        (rest[:i], rest[i + 1 :])
        for i, c in enumerate(rest)
        if c == "_" and rest[:i] in _NAMES and rest[i + 1 :] in _NAMES
    ]
    if len(splits) != 1:
        raise ValueError(
            f"{where}: column {name!r}: a correlation column is correlation_<a>_<b> with two "
            f"measured quantities a and b ({', '.join(MEASURABLE)}), e.g. correlation_e_spin_out"
        )
    a, b = (str(canonical_output(x)) for x in splits[0])
    if a == b:
        raise ValueError(
            f"{where}: column {name!r} names {a} twice: a correlation is of two different "
            "measured quantities"
        )
    return ordered(a, b)


def coefficient(where: str, name: str, v: Any, unit: str | None) -> float:
    """The coefficient ``v`` of the column ``name`` (a number, or text holding one; ``unit``:
    the column's, none or ``1``); ValueError naming ``where`` and the column for anything else
    and for a value outside [-1, 1]."""
    if unit is not None and unit.strip() not in ("1", "-", ""):
        raise ValueError(
            f"{where}: column {name!r} [{unit}]: a correlation coefficient is a plain number in "
            f"[-1, 1] and takes no unit; write the header {name!r}"
        )
    try:
        if isinstance(v, bool) or not isinstance(v, int | float | str):
            raise TypeError
        x = float(v)
    except (TypeError, ValueError):
        raise ValueError(
            f"{where}: {name} must be a plain number in [-1, 1] (a correlation coefficient), "
            f"got {v!r}"
        ) from None
    if not -1.0 <= x <= 1.0:
        raise ValueError(
            f"{where}: {name} = {x:g} lies outside [-1, 1] (a correlation coefficient)"
        )
    return x


def check_drop(
    where: str, pairs: Mapping[tuple[str, str], float], measured: Sequence[str]
) -> np.ndarray:
    """The correlation matrix of a drop's ``measured`` quantities (in that order) with the
    coefficients ``pairs`` (ordered pair -> coefficient; the rest 0). ValueError naming
    ``where`` and the pair for a coefficient outside [-1, 1], a pair naming a quantity not in
    ``measured``, and coefficients that form no positive-definite matrix."""
    index = {q: i for i, q in enumerate(measured)}
    r = np.eye(len(measured))
    if not pairs:
        return r
    for (a, b), x in pairs.items():
        name = correlation_column(a, b)
        if not -1.0 <= x <= 1.0:
            raise ValueError(
                f"{where}: {name} = {x:g} lies outside [-1, 1] (a correlation coefficient)"
            )
        missing = [q for q in (a, b) if q not in index]
        if missing:
            raise ValueError(
                f"{where}: {name} = {x:g} names {' and '.join(missing)}, which the drop does not "
                f"measure: give {' and '.join(f'{q} with {q}_sigma' for q in missing)}, or leave "
                "the coefficient out"
            )
        r[index[a], index[b]] = r[index[b], index[a]] = x
    low = float(np.linalg.eigvalsh(r).min()) if len(measured) else 1.0
    if low <= _EIGEN_MIN:
        given = ", ".join(f"{correlation_column(a, b)} = {x:g}" for (a, b), x in pairs.items())
        raise ValueError(
            f"{where}: the coefficients {given} form no positive-definite correlation matrix "
            f"(smallest eigenvalue {low:.3g}): no measured values have them (a coefficient of "
            "+-1 makes two values one); check their values and signs"
        )
    return r


def normalised(
    correlation: Mapping[Any, Any],
    labels: Sequence[str],
    observed: Mapping[str, np.ndarray],
    sigma: Mapping[str, np.ndarray],
) -> dict[tuple[str, str], np.ndarray]:
    """``Measurements.correlation`` checked: pair -> (D,) coefficients (NaN: not given), each
    pair of two measured quantities ordered as ``MEASURABLE``; ValueError naming the pair (and
    the drop) for a pair given twice, an array of another length and what ``check_drop``
    refuses."""
    out: dict[tuple[str, str], np.ndarray] = {}
    for key, values in correlation.items():
        pair = tuple(key) if isinstance(key, tuple | list) else ()
        names = [canonical_output(str(q)) for q in pair]
        if len(names) != 2 or None in names or names[0] == names[1]:
            raise ValueError(
                f"correlation: key {key!r} must be a pair of two different measured quantities "
                f"(e.g. ('e', 'spin_out')) of {', '.join(observed)}"
            )
        a, b = ordered(str(names[0]), str(names[1]))
        if (a, b) in out:
            raise ValueError(f"correlation: the pair ({a}, {b}) is given twice; keep one")
        x = np.array(values, dtype=np.float64).reshape(-1)
        if x.shape != (len(labels),):
            raise ValueError(
                f"correlation of ({a}, {b}): {x.size} coefficients for "
                f"{len(labels)} drops; give one per drop (NaN where not given)"
            )
        out[(a, b)] = x
    for d, label in enumerate(labels if out else ()):
        pairs = {p: float(x[d]) for p, x in out.items() if not math.isnan(x[d])}
        measured = [
            q for q in observed if math.isfinite(observed[q][d]) and math.isfinite(sigma[q][d])
        ]
        check_drop(f"drop {d + 1} ({label})", pairs, measured)
    return out
