"""Indentation curves for the tabulated law: a loading curve F(delta) and residual depths
delta_r(delta_max), dimensionless in the Jackson-Green critical values of their pair
(delta / delta_c, F / F_c, delta_r / delta_max), with the pair's E*/S_y and nu.

Dimensionless curves of an elastic-perfectly plastic pair depend only on E*/S_y and nu, so
one set serves every pair of the same two numbers and any radius. Sources: the FE reference
curves shipped with impactlab (``shipped_curves``; made from ``impactlab.fe``'s data files
by ``impactlab.fe.tabulated``), an FE run of one's own, or measured data
(``IndentationCurves.from_arrays``, ``from_csv``).
"""

from __future__ import annotations

import functools
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._validation import check_positive, read_text_file
from impactlab.contact._common import jg_critical
from impactlab.materials import ContactPair

#: Where the shipped curves are (``shipped_curves``).
SHIPPED_PATH = Path(__file__).resolve().parent / "data" / "fe-curves.json"
#: The ``format`` field of a curves file.
FORMAT = "impactlab indentation curves"
FORMAT_VERSION = 1
#: Fewest loading points past the elastic limit, and fewest (delta_max, delta_r) pairs.
MIN_LOADING_POINTS = 4
MIN_RESIDUAL_POINTS = 2
#: Relative gap at the end of the loading curve taken as rounding (``max_delta``).
END_RTOL = 1e-6
#: Largest relative difference from Hertz allowed at the first point of measured data.
HERTZ_TOLERANCE = 0.05


def _vector(name: str, value: Any) -> np.ndarray:
    try:
        a = np.array(value, dtype=np.float64).ravel()
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be an array of numbers, got {value!r}") from None
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
            f"{name} must be strictly increasing, got {float(a[i])!r} then {float(a[i + 1])!r} at "
            f"index {i + 1}"
        )


@dataclass(frozen=True, eq=False)
class IndentationCurves:
    """Dimensionless indentation curves of one pair (see the module docstring).

    ``delta`` (delta/delta_c) and ``force`` (F/F_c): the loading curve, delta strictly
    increasing, F > 0 and non-decreasing. ``delta_max`` (delta_max/delta_c, strictly
    increasing) and ``residual_ratio`` (delta_r/delta_max in [0, 1)): the unloading family.
    ``elastic_limit`` (delta/delta_c): the law is Hertz up to it and the tabulated curve starts
    there, at the Hertz force (points at or below it are left out). ``e_star_over_sy`` and
    ``nu``: the pair the curves belong to. ``name`` and ``source``: what the curves are and
    where they come from (shown with every model built from them).
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

    def __post_init__(self) -> None:
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
                f"force must not decrease along the loading curve, got {float(f[i])!r} then "
                f"{float(f[i + 1])!r} at index {i + 1} (delta/delta_c = {float(d[i + 1])!r})"
            )
        past = int((d > lim).sum())
        if past < MIN_LOADING_POINTS:
            raise ValueError(
                f"the loading curve needs at least {MIN_LOADING_POINTS} points past the elastic "
                f"limit (delta/delta_c = {lim!r}), got {past}"
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
                f"delta_r must lie in [0, delta_max): delta_r / delta_max = {float(r[i])!r} at "
                f"delta_max/delta_c = {float(dm[i])!r}"
            )
        for name, a in (("delta", d), ("force", f), ("delta_max", dm), ("residual_ratio", r)):
            object.__setattr__(self, name, a)

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
    ) -> IndentationCurves:
        """Curves from dimensional data of ``pair`` with a sphere of ``radius`` [m]: the
        loading curve ``delta`` [m], ``force`` [N] and the (``delta_max`` [m], ``delta_r`` [m])
        pairs. The law is Hertz up to the first loading point, whose force must lie within
        ``HERTZ_TOLERANCE`` of Hertz's (ValueError otherwise)."""
        if not isinstance(pair, ContactPair):
            raise ValueError(f"pair must be a ContactPair, got {type(pair).__name__}")
        R = check_positive("radius", radius, "m")
        dc, fc = jg_critical(pair.E_star, R, pair.yield_strength, pair.nu)
        d, f = _vector("delta", delta), _vector("force", force)
        dm, dr = _vector("delta_max", delta_max), _vector("delta_r", delta_r)
        if dm.shape != dr.shape:
            raise ValueError(f"delta_max and delta_r differ in length: {dm.size} and {dr.size}")
        if d.size and f.size == d.size and d[0] > 0.0:
            d0, f0 = float(d[0]), float(f[0])
            hertz = 4.0 / 3.0 * pair.E_star * math.sqrt(R) * d0**1.5
            off = f0 / hertz - 1.0
            if not abs(off) <= HERTZ_TOLERANCE:
                raise ValueError(
                    f"force at the first loading point (delta = {d0!r} m) is {f0!r} N, "
                    f"{100 * off:+.1f} % from Hertz's {hertz:.6g} N for this pair and radius: "
                    f"the data must start in the elastic range (within "
                    f"{100 * HERTZ_TOLERANCE:g} %)"
                )
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = dr / dm
        if ((dr >= dm) & (dm > 0.0)).any():
            i = int(np.flatnonzero(dr >= dm)[0])
            raise ValueError(
                f"delta_r must be < delta_max, got delta_r = {float(dr[i])!r} m at delta_max = "
                f"{float(dm[i])!r} m"
            )
        return cls(
            name,
            source,
            pair.E_star / pair.yield_strength,
            pair.nu,
            d / dc,
            f / fc,
            dm / dc,
            ratio,
            elastic_limit=float(d[0] / dc) if d.size else 1.0,
        )

    @classmethod
    def from_csv(
        cls,
        pair: ContactPair,
        radius: float,
        loading: str | Path,
        unloading: str | Path,
        **kwargs: str,
    ) -> IndentationCurves:
        """Curves from two CSV files (SI units, one header line, comma-separated):
        ``loading`` with columns delta [m], F [N]; ``unloading`` with delta_max [m],
        delta_r [m]. See ``from_arrays``."""
        cols = []
        for what, path, names in (
            ("loading", loading, "delta [m], F [N]"),
            ("unloading", unloading, "delta_max [m], delta_r [m]"),
        ):
            cols += read_two_columns(Path(path), f"{what} CSV {str(path)!r}", names)
        return cls.from_arrays(pair, radius, *cols, **kwargs)

    def record(self) -> dict[str, Any]:
        """JSON-ready content (``curves_from_record`` reads it back)."""
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
        }


def read_two_columns(path: Path, where: str, names: str) -> list[np.ndarray]:
    """The two columns (``names``, for the messages) of the comma-separated file ``path``: one
    header line, then one row of two numbers per line (blank lines and ``#`` comments
    skipped). ValueError starting with ``where`` for a file that is missing, a folder, not UTF-8
    text, empty, without data rows, or with a row of another width or a text that is not a
    number."""
    try:
        text = read_text_file(path, "CSV", where)
    except OSError as exc:
        if path.is_dir():
            why = "is a folder, not a CSV file"
        elif not path.exists():
            why = "does not exist"
        else:
            why = f"cannot be read ({exc.strerror or exc})"
        raise ValueError(f"{where} {why}") from None
    lines = text.splitlines()
    if not lines or not text.strip():
        raise ValueError(f"{where}: the file is empty (expected a header line, then rows of "
                         f"{names})")  # fmt: skip
    rows: list[tuple[float, float]] = []
    for number, line in enumerate(lines[1:], start=2):
        content = line.split("#", 1)[0].strip()
        if not content:
            continue
        cells = [c.strip() for c in content.split(",")]
        if len(cells) != 2:
            raise ValueError(
                f"{where}: line {number} has {len(cells)} column(s), must have 2 columns "
                f"({names}); is the file truncated?"
            )
        try:
            rows.append((float(cells[0]), float(cells[1])))
        except ValueError:
            raise ValueError(
                f"{where}: line {number} is not two numbers ({names}), got {content!r}"
            ) from None
    if not rows:
        raise ValueError(f"{where}: no data rows after the header line (expected {names})")
    table = np.array(rows, dtype=np.float64)
    return [table[:, 0], table[:, 1]]


def curves_from_record(d: dict[str, Any]) -> IndentationCurves:
    """Curves from ``IndentationCurves.record`` output."""
    return IndentationCurves(
        str(d["name"]),
        str(d["source"]),
        float(d["e_star_over_sy"]),
        float(d["nu"]),
        d["delta"],
        d["force"],
        d["delta_max"],
        d["residual_ratio"],
        elastic_limit=float(d["elastic_limit"]),
    )


def curves_file_record(curves: list[IndentationCurves]) -> dict[str, Any]:
    """The content of a curves file holding ``curves``."""
    return {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "units": "delta / delta_c, F / F_c (Jackson-Green 2005), delta_r / delta_max",
        "curves": [c.record() for c in curves],
    }


def read_curves(path: str | Path) -> tuple[IndentationCurves, ...]:
    """Every curve set in the curves file ``path`` (ValueError for another format or a file
    that is not UTF-8 text)."""
    record = json.loads(read_text_file(path, "JSON", f"curves file {str(path)!r}"))
    if record.get("format") != FORMAT or record.get("version") != FORMAT_VERSION:
        raise ValueError(
            f"{str(path)!r} is not an indentation curves file of version {FORMAT_VERSION}"
        )
    return tuple(curves_from_record(c) for c in record["curves"])


@functools.cache
def shipped_curves() -> tuple[IndentationCurves, ...]:
    """The FE reference curves shipped with impactlab (``impactlab.fe.curves``' cases)."""
    return read_curves(SHIPPED_PATH)


__all__ = [
    "HERTZ_TOLERANCE",
    "IndentationCurves",
    "curves_file_record",
    "curves_from_record",
    "read_curves",
    "shipped_curves",
]
