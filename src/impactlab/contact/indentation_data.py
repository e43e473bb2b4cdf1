"""Indentation curves for the tabulated law: a loading curve F(delta) and residual depths
delta_r(delta_max), dimensionless in the Jackson-Green critical values of their pair
(delta / delta_c, F / F_c, delta_r / delta_max), with the pair's E*/S_y and nu.

Dimensionless curves of an elastic-perfectly plastic pair depend only on E*/S_y, nu and which
body yields (``yielding``: the flat, or a sphere that yields first, ``yielding_body``), so one
set serves every pair of the same three and any radius. Sources: the FE reference
curves shipped with impactlab (``shipped_curves``; made from ``impactlab.fe``'s data files
by ``impactlab.fe.tabulated``), an FE run of one's own, or measured data
(``IndentationCurves.from_arrays``, ``from_csv``).
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
import warnings
from contextvars import ContextVar
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._validation import check_positive, read_text_file
from impactlab.contact._common import jg_critical
from impactlab.contact.table_input import (
    END_RTOL,
    HERTZ_TOLERANCE,
    MIN_LOADING_POINTS,
    MIN_RESIDUAL_POINTS,
    Rows,
    check_loading,
    check_unloading,
    read_table,
    two,
)
from impactlab.materials import ContactPair, body_yields_first
from impactlab.units import is_quantity, magnitude

#: A delta_r/delta_max raised onto the largest before it (the tabulated law keeps the ratio
#: non-decreasing) by more than this warns (:class:`ResidualRaisedWarning`): the accuracy
#: tolerance of delta_r/delta_max (docs/laws/accuracy.md, ``impactlab.fe.accuracy``).
RESIDUAL_RAISE_TOLERANCE = 0.05


#: True while ``IndentationCurves._checked`` builds curves whose raised ratios it has named by
#: their rows (a CSV line): the constructor then does not name them again.
_ROWS_WARNED: ContextVar[bool] = ContextVar("_ROWS_WARNED", default=False)


class ResidualRaisedWarning(UserWarning):
    """A residual depth of the data falls so far below the ones before it that the tabulated
    law, which raises it onto the largest before it, departs from it by more than
    :data:`RESIDUAL_RAISE_TOLERANCE` in delta_r/delta_max."""


#: Where the shipped curves are (``shipped_curves``).
SHIPPED_PATH = Path(__file__).resolve().parent / "data" / "fe-curves.json"
#: The ``format`` field of a curves file.
FORMAT = "impactlab indentation curves"
FORMAT_VERSION = 1
#: The bodies that may yield in a set of curves (``IndentationCurves.yielding``).
YIELDING = ("flat", "sphere")


def yielding_body(pair: ContactPair) -> str:
    """Which body of ``pair`` yields first, "sphere" or "flat": the smaller C(nu) S_y
    (``materials.body_yields_first``, as ``ContactPair.weaker``)."""
    return "sphere" if body_yields_first(pair.body, pair.flat) else "flat"


def _vector(name: str, value: Any, unit: str = "") -> np.ndarray:
    """``value`` as a read-only float64 vector (1-D) of finite numbers. A pint Quantity is
    converted to ``unit`` (dimensionless without one); ValueError naming ``name`` otherwise."""
    if is_quantity(value):
        try:
            value = magnitude(name, value, unit or "dimensionless")
        except ValueError:
            want = f"a quantity in {unit}" if unit else "dimensionless"
            raise ValueError(f"{name} must be {want}, got one in {value.units}") from None
    try:
        if isinstance(value, str | bytes):
            raise ValueError
        a = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be an array of numbers, got {value!r}") from None
    if a.ndim != 1:
        raise ValueError(
            f"{name} must be 1-D (one value per point), got an array of shape {a.shape}"
            + (": pass one column, e.g. table[:, 0]" if a.ndim == 2 else "")
        )
    bad = ~np.isfinite(a)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{name} must be finite, got {float(a[i])!r} at index {i}")
    a.setflags(write=False)
    return a


def _increasing(name: str, a: np.ndarray) -> None:
    step = np.diff(a)
    if (step <= 0.0).any():
        i = int(np.flatnonzero(step <= 0.0)[0])
        raise ValueError(
            f"{name} must be strictly increasing, got {two(a[i], a[i + 1])} at index {i + 1}"
        )


@dataclass(frozen=True, eq=False)
class IndentationCurves:
    """Dimensionless indentation curves of one pair (see the module docstring).

    ``delta`` (delta/delta_c) and ``force`` (F/F_c): the loading curve, delta strictly
    increasing, F > 0 and non-decreasing. ``delta_max`` (delta_max/delta_c, strictly
    increasing) and ``residual_ratio`` (delta_r/delta_max in [0, 1)): the unloading family.
    ``elastic_limit`` (delta/delta_c): the law is Hertz up to it and the tabulated curve starts
    there, at the Hertz force (points at or below it are left out). ``e_star_over_sy`` and
    ``nu``: the pair the curves belong to; ``yielding``: its body that yields, "flat" or
    "sphere" (``yielding_body``). ``name`` and ``source``: what the curves are and where they
    come from (shown with every model built from them).
    """

    name: str
    source: str
    e_star_over_sy: float
    nu: float
    delta: np.ndarray = field(repr=False)
    force: np.ndarray = field(repr=False)
    delta_max: np.ndarray = field(repr=False)
    residual_ratio: np.ndarray = field(repr=False)
    elastic_limit: float = 1.0
    yielding: str = "flat"

    def __post_init__(self) -> None:
        if not isinstance(self.yielding, str) or self.yielding not in YIELDING:
            raise ValueError(f"yielding must be 'flat' or 'sphere', got {self.yielding!r}")
        check_positive("e_star_over_sy", self.e_star_over_sy)
        if not (math.isfinite(self.nu) and -1.0 < self.nu < 0.5):
            raise ValueError(f"nu must lie in (-1, 0.5), got {self.nu!r}")
        lim = check_positive("elastic_limit", self.elastic_limit)
        d, f = _vector("delta", self.delta), _vector("force", self.force)
        dm, r = _vector("delta_max", self.delta_max), _vector("residual_ratio", self.residual_ratio)
        if d.shape != f.shape:
            raise ValueError(f"delta and force differ in length: {d.size} and {f.size}")
        if dm.shape != r.shape:
            raise ValueError(f"delta_max and delta_r differ in length: {dm.size} and {r.size}")
        if (d <= 0.0).any() or (f <= 0.0).any():
            raise ValueError("delta and force must be > 0 (the loading curve, in contact)")
        _increasing("delta", d)
        drop = np.diff(f) < 0.0
        if drop.any():
            i = int(np.flatnonzero(drop)[0])
            raise ValueError(
                f"force must not decrease along the loading curve, got {two(f[i], f[i + 1])} "
                f"at index {i + 1} (delta/delta_c = {d[i + 1]:.4g})"
            )
        past = int((d > lim).sum())
        if past < MIN_LOADING_POINTS:
            raise ValueError(
                f"the loading curve needs at least {MIN_LOADING_POINTS} points past the elastic "
                f"limit (delta/delta_c = {lim:.4g}), got {past}"
            )
        if dm.size < MIN_RESIDUAL_POINTS:
            raise ValueError(
                f"at least {MIN_RESIDUAL_POINTS} (delta_max, delta_r) pairs are needed, got "
                f"{dm.size}"
            )
        if (dm <= 0.0).any():
            raise ValueError("delta_max must be > 0")
        _increasing("delta_max", dm)
        if (r < 0.0).any() or (r >= 1.0).any():
            i = int(np.flatnonzero((r < 0.0) | (r >= 1.0))[0])
            raise ValueError(
                f"delta_r must lie in [0, delta_max): delta_r / delta_max = {r[i]:.4g} at "
                f"delta_max/delta_c = {dm[i]:.4g}"
            )
        for name, a in (("delta", d), ("force", f), ("delta_max", dm), ("residual_ratio", r)):
            object.__setattr__(self, name, a)
        if not _ROWS_WARNED.get():  # ``_checked`` has named them by their rows
            _warn_raised(self.name, dm, r)

    @property
    def max_delta(self) -> float:
        """Largest interference covered by both the loading and the unloading data
        (delta/delta_c): the tabulated law's hard limit. A loading curve that stops within
        ``END_RTOL`` of the last delta_max counts as reaching it (an FE run's last increment
        lands on its maximum only to rounding)."""
        return float(min(self.delta[-1] * (1.0 + END_RTOL), self.delta_max[-1]))

    @classmethod
    def from_arrays(
        cls,
        pair: ContactPair,
        radius: float,
        delta: Any,
        force: Any,
        delta_max: Any,
        delta_r: Any,
        *,
        name: str = "measured",
        source: str = "measured indentation data",
        yielding: str | None = None,
    ) -> IndentationCurves:
        """Curves from dimensional data of ``pair`` with a sphere of ``radius`` [m]: the
        loading curve ``delta`` [m], ``force`` [N] and the (``delta_max`` [m], ``delta_r`` [m])
        pairs (numbers in SI, or pint Quantities, converted). The law is Hertz up to the first
        loading point, whose force must lie within ``HERTZ_TOLERANCE`` of Hertz's; every
        interference must be below ``radius``, and at least 2 delta_max within the loading
        curve's range (ValueError otherwise: ``contact.table_input``). ``yielding``: the body
        that yields in the data, "flat" or "sphere" (default: ``pair``'s, ``yielding_body``)."""
        d, f = _vector("delta", delta, "m"), _vector("force", force, "N")
        dm, dr = _vector("delta_max", delta_max, "m"), _vector("delta_r", delta_r, "m")
        rows = (Rows(("delta", "force")), Rows(("delta_max", "delta_r")))
        return cls._checked(pair, radius, (d, f, dm, dr), rows, (name, source, yielding))

    @classmethod
    def from_csv(
        cls,
        pair: ContactPair,
        radius: float,
        loading: str | Path,
        unloading: str | Path,
        *,
        name: str = "measured",
        source: str = "measured indentation data",
        yielding: str | None = None,
    ) -> IndentationCurves:
        """Curves from two CSV files (SI units, comma-separated, an optional header line:
        ``read_table``): ``loading`` with columns delta [m], F [N]; ``unloading`` with
        delta_max [m], delta_r [m]. See ``from_arrays``; a message names the file and line."""
        cols: list[np.ndarray] = []
        rows = []
        for what, path, names, header in (
            ("loading", loading, ("delta", "F"), "delta [m], F [N]"),
            ("unloading", unloading, ("delta_max", "delta_r"), "delta_max [m], delta_r [m]"),
        ):
            where = f"{what} CSV {str(path)!r}"
            x, y, lines = read_table(Path(path), where, header)
            cols += [x, y]
            rows.append(Rows(names, where, lines))
        return cls._checked(pair, radius, tuple(cols), (rows[0], rows[1]), (name, source, yielding))

    @classmethod
    def _checked(
        cls,
        pair: ContactPair,
        radius: float,
        cols: tuple[np.ndarray, ...],
        rows: tuple[Rows, Rows],
        labels: tuple[str, str, str | None],
    ) -> IndentationCurves:
        """The curves of SI tables ``cols`` (delta, F, delta_max, delta_r) after the checks of
        ``table_input`` (``check_loading``, ``check_unloading``; ``rows`` name their rows),
        ``labels`` their name, source and yielding body (None: the pair's)."""
        if not isinstance(pair, ContactPair):
            raise ValueError(f"pair must be a ContactPair, got {type(pair).__name__}")
        R = check_positive("radius", radius, "m")
        d, f, dm, dr = cols
        name, source, yielding = labels
        check_loading(pair, R, d, f, rows[0])
        check_unloading(R, dm, dr, (float(d[0]), float(d[-1])), rows[1])
        dc, fc = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)
        _warn_raised(name, dm / dc, dr / dm, rows[1], dm)
        token = _ROWS_WARNED.set(True)
        try:
            ratio, lim = pair.E_star / pair.yield_strength, float(d[0] / dc)
            side = yielding_body(pair) if yielding is None else yielding
            dims = (d / dc, f / fc, dm / dc, dr / dm)
            return cls(name, source, ratio, pair.nu, *dims, elastic_limit=lim, yielding=side)
        finally:
            _ROWS_WARNED.reset(token)

    def with_source(self, source: str) -> IndentationCurves:
        """The same curves with ``source`` (a non-empty string: where they come from)."""
        if not isinstance(source, str) or not source.strip():
            raise ValueError(f"source must be a non-empty string, got {source!r}")
        token = _ROWS_WARNED.set(True)  # the same data: warned about once, when made
        try:
            return dataclasses.replace(self, source=source)
        finally:
            _ROWS_WARNED.reset(token)

    def record(self) -> dict[str, Any]:
        """JSON-ready content (``curves_from_record`` reads it back); ``yielding`` only where
        it is "sphere" (a record without it, as every file before it, is of a yielding flat)."""
        side = {} if self.yielding == "flat" else {"yielding": self.yielding}
        return {
            "name": self.name,
            "source": self.source,
            "e_star_over_sy": self.e_star_over_sy,
            "nu": self.nu,
            "elastic_limit": self.elastic_limit,
            "delta": self.delta.tolist(),
            "force": self.force.tolist(),
            "delta_max": self.delta_max.tolist(),
            "residual_ratio": self.residual_ratio.tolist(),
            **side,
        }


def _warn_raised(
    name: str, dm: np.ndarray, r: np.ndarray, rows: Rows | None = None, dm_si: Any = None
) -> None:
    """A :class:`ResidualRaisedWarning` naming each ratio ``r`` (delta_r/delta_max at
    ``dm`` = delta_max/delta_c) that the running maximum raises by more than
    :data:`RESIDUAL_RAISE_TOLERANCE`: by its row of ``rows`` (a CSV file's line, an array's
    index) and its delta_max ``dm_si`` [m] where given, else by index and delta_max/delta_c."""
    top = np.maximum.accumulate(r)
    big = np.flatnonzero(top - r > RESIDUAL_RAISE_TOLERANCE)
    if not big.size:
        return
    texts = []
    for i in big:
        what = f"{r[i]:.4g} raised by {top[i] - r[i]:.3g} to {top[i]:.4g}"
        if rows is None or dm_si is None:
            texts.append(f"index {i} (delta_max/delta_c = {dm[i]:.4g}): {what}")
        else:
            texts.append(rows.at(int(i), f"{what} (delta_max = {float(dm_si[i]):.4g} m)"))
    warnings.warn(
        f"curves {name!r}: delta_r/delta_max falls below a value before it and is raised onto "
        f"it (the tabulated law keeps it non-decreasing) by more than "
        f"{RESIDUAL_RAISE_TOLERANCE:g} (the accuracy tolerance of delta_r/delta_max) at "
        f"{len(texts)} point(s), each the data's ratio raised to the law's: {'; '.join(texts)}; "
        "the law's residual depth there is not the data's (check those points)",
        ResidualRaisedWarning,
        stacklevel=4,
    )


def curves_from_record(d: dict[str, Any]) -> IndentationCurves:
    """Curves from ``IndentationCurves.record`` output; without ``yielding``, of a yielding
    flat (the shipped curves, and FE curves cached before the field: their records name no
    materials to tell otherwise)."""
    kw: dict[str, Any] = {k: str(d[k]) for k in ("name", "source")}
    kw |= {k: float(d[k]) for k in ("e_star_over_sy", "nu", "elastic_limit")}
    kw |= {k: d[k] for k in ("delta", "force", "delta_max", "residual_ratio")}
    return IndentationCurves(**kw, yielding=d.get("yielding", "flat"))


def curves_file_record(curves: list[IndentationCurves]) -> dict[str, Any]:
    """The content of a curves file holding ``curves``."""
    return {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "units": "delta / delta_c, F / F_c (Jackson-Green 2005), delta_r / delta_max",
        "curves": [c.record() for c in curves],
    }


def read_curves(path: str | Path) -> tuple[IndentationCurves, ...]:
    """Every curve set in the curves file ``path``; ValueError naming the file for another
    format, a file that is not UTF-8 JSON text, or JSON that is not a curves record (not an
    object, ``curves`` missing or not a list of curve sets)."""
    text = read_text_file(path, "JSON", f"curves file {str(path)!r}")
    what = f"{str(path)!r} is not an indentation curves file of version {FORMAT_VERSION}"
    try:
        record = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ValueError(f"{what}: not valid JSON ({exc})") from None
    if not isinstance(record, dict):
        raise ValueError(f"{what}: its JSON is a {type(record).__name__}, not an object")
    if record.get("format") != FORMAT or record.get("version") != FORMAT_VERSION:
        raise ValueError(what)
    sets = record.get("curves")
    if not isinstance(sets, list):
        raise ValueError(f"{what}: 'curves' is not a list")
    try:
        return tuple(curves_from_record(c) for c in sets)
    except (KeyError, TypeError, AttributeError) as exc:
        raise ValueError(f"{what}: a curve set lacks or mistypes {exc}") from None


@functools.cache
def shipped_curves() -> tuple[IndentationCurves, ...]:
    """The FE reference curves shipped with impactlab (``impactlab.fe.curves``' cases)."""
    return read_curves(SHIPPED_PATH)


__all__ = [
    "HERTZ_TOLERANCE",
    "RESIDUAL_RAISE_TOLERANCE",
    "YIELDING",
    "IndentationCurves",
    "ResidualRaisedWarning",
    "curves_file_record",
    "curves_from_record",
    "read_curves",
    "shipped_curves",
    "yielding_body",
]
