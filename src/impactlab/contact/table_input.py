"""Dimensional indentation tables, as measured: the checks of a loading table (delta [m],
F [N]) and an unloading table (delta_max [m], delta_r [m]) before they become
``IndentationCurves`` (``from_arrays``, ``from_csv``), and the reading of their CSV files.

A message names the value as given (in m and N, to 4 significant digits) and where it is:
the array index, or the CSV file and its line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from impactlab._validation import read_text_file
from impactlab.materials import ContactPair

#: Fewest loading points past the elastic limit, and fewest (delta_max, delta_r) pairs.
MIN_LOADING_POINTS = 4
MIN_RESIDUAL_POINTS = 2
#: Relative gap at the end of the loading curve taken as rounding (``max_delta``).
END_RTOL = 1e-6
#: Largest relative difference from Hertz allowed at the first point of measured data.
HERTZ_TOLERANCE = 0.05
#: A loading force that falls by less than this (relative) is most likely the rows' scatter.
SCATTER_DROP = 0.03


def two(a: float, b: float, unit: str = "") -> str:
    """``a then b`` to 4 significant digits, more where 4 would show them equal."""
    n = next((n for n in range(4, 17) if f"{a:.{n}g}" != f"{b:.{n}g}"), 4)
    u = f" {unit}" if unit else ""
    return f"{a:.{n}g}{u} then {b:.{n}g}{u}"


@dataclass(frozen=True)
class Rows:
    """How a message names the rows of one dimensional table: ``where`` (the CSV file, or
    empty for arrays), its line numbers (None: array indices) and its column ``names``."""

    names: tuple[str, str]
    where: str = ""
    lines: np.ndarray | None = None

    def at(self, i: int, text: str) -> str:
        if self.lines is None:
            return f"{text} at index {i}"
        return f"{self.where} line {int(self.lines[i])}: {text}"

    def whole(self, text: str) -> str:
        return f"{self.where}: {text}" if self.where else text


#: Units a table may have been written in by mistake, and their size in m.
_WRONG_UNITS = (("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9))


def _unit_hint(values: np.ndarray, radius: float, span: tuple[float, float] | None) -> str:
    """The unit that would make ``values`` [m] fit (all below ``radius`` and, with ``span``,
    at least 2 inside it), as a hint; a plain reminder of the unit when none does."""
    for unit, size in _WRONG_UNITS:
        v = values * size
        if v.max() < radius and (
            span is None or int(((v >= span[0]) & (v <= span[1])).sum()) >= MIN_RESIDUAL_POINTS
        ):
            return f" (written in {unit}? give them in m)"
    return " (lengths in m)"


def _drop_hint(before: float, after: float) -> str:
    """For a force that falls from ``before`` to ``after`` [N] by less than ``SCATTER_DROP``
    (relative): a hint that the rows' scatter is the likely cause, and what to do."""
    drop = 1.0 - after / before
    if not drop < SCATTER_DROP:
        return ""
    return (
        f"; a drop of {100 * drop:.2g} %, the size of measured scatter between close rows: "
        "average repeated indentations or smooth the forces (docs/laws/user.md, 'Scattered "
        "data')"
    )


def _near_hertz(off: float) -> bool:
    """Whether a force ``off`` (relative) from Hertz's is within a factor ``NEAR_HERTZ``."""
    return 1.0 / NEAR_HERTZ <= 1.0 + off <= NEAR_HERTZ


def _loading_hint(pair: ContactPair, R: float, d: np.ndarray, f: np.ndarray) -> str:
    """Why the loading table's ``d`` [m] reach the radius ``R`` [m], judged by Hertz's force at
    the first point (``f`` [N]): a radius 1000 (or 10^6) times too small where that puts every
    delta below it and the first force near Hertz's; else a unit of the table that does; else
    a reminder that both are in m."""
    d0, f0 = float(d[0]), float(f[0])
    for factor, meant in ((1e3, "'um' for 'mm'"), (1e6, "'um' for 'm'")):
        big = R * factor
        off = hertz_offset(pair, big, d0, f0)[1]
        if d.max() < big <= PLAUSIBLE_RADIUS[1] and _near_hertz(off):
            return (
                f" (the radius looks {factor:g} times too small, not the data: with radius = "
                f'{big:.4g} m, "{big * 1e3:.4g} mm", every delta lies below it and the first '
                f"force is {100 * off:+.1f} % from Hertz's: {meant}?)"
            )
    for unit, size in _WRONG_UNITS:
        if d.max() * size < R and _near_hertz(hertz_offset(pair, R, d0 * size, f0)[1]):
            return f" (written in {unit}? give them in m)"
    return f" (lengths in m: check the unit of the radius, {R:.4g} m, and of the table)"


def check_loading(pair: ContactPair, R: float, d: np.ndarray, f: np.ndarray, rows: Rows) -> None:
    """The loading table (delta [m], F [N]) of ``pair`` with a sphere of radius ``R`` [m]:
    delta, F > 0 (its first point is the elastic limit, where the law leaves Hertz), delta
    strictly increasing and below ``R``, F non-decreasing, at least ``MIN_LOADING_POINTS``
    points past the first, whose force lies within ``HERTZ_TOLERANCE`` of Hertz's. ValueError
    naming the row (``rows``) and its values otherwise."""
    D, F = rows.names
    if d.shape != f.shape:
        raise ValueError(f"{D} and {F} differ in length: {d.size} and {f.size}")
    bad = (d <= 0.0) | (f <= 0.0)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(
            rows.at(
                i,
                f"{D} and {F} must be > 0, got {d[i]:.4g} m, {f[i]:.4g} N"
                " (the first point is the elastic limit, where the law leaves "
                "Hertz: leave out a row at 0)",
            )
        )
    step = np.diff(d)
    if (step <= 0.0).any():
        i = int(np.flatnonzero(step <= 0.0)[0]) + 1
        raise ValueError(
            rows.at(i, f"{D} must be strictly increasing, got {two(d[i - 1], d[i], 'm')}")
        )
    drop = np.diff(f) < 0.0
    if drop.any():
        i = int(np.flatnonzero(drop)[0]) + 1
        raise ValueError(
            rows.at(
                i,
                f"{F} must not decrease along the loading curve, got "
                f"{two(f[i - 1], f[i], 'N')} ({D} = {d[i]:.4g} m)" + _drop_hint(f[i - 1], f[i]),
            )
        )
    if d.size and d[-1] >= R:
        i = int(np.flatnonzero(d >= R)[0])
        raise ValueError(
            rows.at(
                i,
                f"{D} = {d[i]:.4g} m is not smaller than the sphere radius "
                f"{R:.4g} m" + _loading_hint(pair, R, d, f),
            )
        )
    if d.size - 1 < MIN_LOADING_POINTS:
        first = f" (its first point, {D} = {d[0]:.4g} m)" if d.size else ""
        raise ValueError(
            rows.whole(
                f"the loading curve needs at least {MIN_LOADING_POINTS} "
                f"points past the elastic limit{first}, got "
                f"{max(d.size - 1, 0)}"
            )
        )
    d0, f0 = float(d[0]), float(f[0])
    hertz, off = hertz_offset(pair, R, d0, f0)
    if not abs(off) <= HERTZ_TOLERANCE:
        raise ValueError(
            rows.at(
                0,
                f"{F} at the first loading point ({D} = {d0:.4g} m) is "
                f"{f0:.4g} N, {100 * off:+.1f} % from Hertz's {hertz:.4g} N "
                "for this pair and radius: the data must start in the "
                f"elastic range (within {100 * HERTZ_TOLERANCE:g} %)" + radius_hint(off, R, pair),
            )
        )


#: Plausible sphere radius [m] (``impactlab.bodies._checks.PLAUSIBLE_RADIUS``, repeated: the
#: contact layer does not import the bodies).
PLAUSIBLE_RADIUS = (1e-6, 0.5)
#: A force this many times Hertz's at the first loading point, or this many times smaller,
#: is most likely a unit mistake (of the radius, or of the tables) or a wrong material rather
#: than data.
UNIT_MISMATCH = 3.0
#: A unit that puts the first loading force within this factor of Hertz's is the one a hint
#: suggests.
NEAR_HERTZ = 1.5


def hertz_offset(pair: ContactPair, R: float, d0: float, f0: float) -> tuple[float, float]:
    """(Hertz's force [N] at ``d0`` [m] for ``pair`` and a sphere of radius ``R`` [m], and
    ``f0`` [N] relative to it minus 1)."""
    hertz = 4.0 / 3.0 * pair.E_star * math.sqrt(R) * d0**1.5
    return hertz, f0 / hertz - 1.0


def radius_hint(off: float, R: float, pair: ContactPair | None = None) -> str:
    """A hint that a unit or the materials are wrong where the force is off Hertz's by more
    than a factor ``UNIT_MISMATCH`` (``off``: relative difference): the radius in mm or um
    where that puts the force near Hertz's (Hertz's force grows as sqrt(R)), the interferences
    in mm or um where that does (it grows as delta^1.5), else every unit
    and ``pair``'s E* (Hertz's force grows as E*) with the E* the force would fit; empty when
    the force is nearer."""
    ratio = 1.0 + off
    if not ratio > 0.0 or 1.0 / UNIT_MISMATCH <= ratio <= UNIT_MISMATCH:
        return ""
    factor = f"; a factor {max(ratio, 1.0 / ratio):.3g} from Hertz's is most likely a unit mistake"
    for unit, size in (("mm", 1e-3), ("um", 1e-6)):
        fits = ratio / math.sqrt(size)
        if _near_hertz(fits - 1.0) and PLAUSIBLE_RADIUS[0] <= R * size <= PLAUSIBLE_RADIUS[1]:
            return (
                f"{factor}: radius = {R:.4g} m is in metres (a bare number is metres); with "
                f'radius = "{R:.4g} {unit}" the force is {100 * (fits - 1.0):+.1f} % from Hertz\'s'
            )
    for unit, size in (("mm", 1e-3), ("um", 1e-6)):  # Hertz's force grows as delta^1.5
        fits = ratio / size**1.5
        if _near_hertz(fits - 1.0):
            return (
                f"{factor}: the interferences look written in {unit} (numbers are metres); "
                f"in {unit} the force is {100 * (fits - 1.0):+.1f} % from Hertz's: convert "
                f"every length of the table to m (x {size:g})"
            )
    if pair is None:
        return (
            f"{factor}: check radius = {R:.4g} m (a bare number is metres), and that the "
            "interferences are in m and the forces in N"
        )
    return (
        f"{factor} or a wrong pair of materials: the pair's E* is {pair.E_star / 1e9:.4g} GPa "
        f"({pair.body.name} on {pair.flat.name}) and the force would fit E* = "
        f"{ratio * pair.E_star / 1e9:.4g} GPa (Hertz's force grows as E*); check radius = "
        f"{R:.4g} m (a bare number is metres), the materials, and that the interferences are in "
        "m and the forces in N"
    )


def check_unloading(
    R: float, dm: np.ndarray, dr: np.ndarray, span: tuple[float, float], rows: Rows
) -> None:
    """The unloading table (delta_max [m], delta_r [m]) for a sphere of radius ``R`` [m] and a
    loading curve over ``span`` [m]: at least ``MIN_RESIDUAL_POINTS`` pairs, 0 <= delta_r <
    delta_max (delta_r = 0 up to the elastic limit, ``span[0]``), delta_max strictly
    increasing and below ``R``, at least ``MIN_RESIDUAL_POINTS`` of them within ``span`` (a
    table in another unit than m fails here: the message suggests which). ValueError naming
    the row (``rows``) otherwise."""
    M, Rr = rows.names
    if dm.shape != dr.shape:
        raise ValueError(f"{M} and {Rr} differ in length: {dm.size} and {dr.size}")
    if dm.size < MIN_RESIDUAL_POINTS:
        raise ValueError(
            rows.whole(
                f"at least {MIN_RESIDUAL_POINTS} ({M}, {Rr}) pairs are needed, got {dm.size}"
            )
        )
    for bad, text in (
        (dm <= 0.0, f"{M} must be > 0, got {{m:.4g}} m"),
        (dr < 0.0, f"{Rr} must be >= 0, got {{r:.4g}} m"),
        (dr >= dm, f"{Rr} must be < {M}, got {Rr} = {{r:.4g}} m at {M} = {{m:.4g}} m"),
    ):
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(rows.at(i, text.format(m=dm[i], r=dr[i])))
    step = np.diff(dm)
    if (step <= 0.0).any():
        i = int(np.flatnonzero(step <= 0.0)[0]) + 1
        raise ValueError(
            rows.at(i, f"{M} must be strictly increasing, got {two(dm[i - 1], dm[i], 'm')}")
        )
    lo, hi = span[0], span[1] * (1.0 + END_RTOL)
    early = (dm <= lo) & (dr > 0.0)
    if early.any():
        i = int(np.flatnonzero(early)[0])
        raise ValueError(
            rows.at(
                i,
                f"{Rr} must be 0 up to the elastic limit (the first loading point, "
                f"{lo:.4g} m), got {Rr} = {dr[i]:.4g} m at {M} = {dm[i]:.4g} m",
            )
        )
    if dm[-1] >= R:
        i = int(np.flatnonzero(dm >= R)[0])
        raise ValueError(
            rows.at(
                i,
                f"{M} = {dm[i]:.4g} m is not smaller than the sphere "
                f"radius {R:.4g} m" + _unit_hint(dm, R, (lo, hi)),
            )
        )
    inside = int(((dm >= lo) & (dm <= hi)).sum())
    if inside < MIN_RESIDUAL_POINTS:
        raise ValueError(
            rows.whole(
                f"{inside} {M} within the loading curve's range, {span[0]:.4g}-{span[1]:.4g} m, "
                f"at least {MIN_RESIDUAL_POINTS} needed; got {M} from {dm[0]:.4g} to "
                f"{dm[-1]:.4g} m" + _unit_hint(dm, R, (lo, hi))
            )
        )


def read_table(path: Path, where: str, names: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(first column, second column, line numbers) of the comma-separated file ``path``: rows
    of two finite numbers (``names``, for the messages); blank lines and ``#`` comments are
    skipped, and the first other line is a header unless it is all numbers (then it is the
    first row). ValueError starting with ``where`` for a file that is missing, a folder, not
    UTF-8 text, empty, without data rows, or with a row of another width or a text that is not
    a finite number."""
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
    if not text.strip():
        raise ValueError(
            f"{where}: the file is empty (expected rows of {names}, after an optional header line)"
        )
    rows: list[tuple[float, float]] = []
    numbers: list[int] = []
    first = True
    for number, line in enumerate(text.splitlines(), start=1):
        content = line.split("#", 1)[0].strip()
        if not content:
            continue
        cells = [c.strip() for c in content.split(",")]
        if first:
            first = False
            if any(_number(c) is None for c in cells):
                continue  # the header line
        if len(cells) != 2:
            raise ValueError(
                f"{where} line {number} has {len(cells)} column(s), must have 2 columns "
                f"({names}); " + _separator_hint(content, len(cells))
            )
        x, y = (_number(c) for c in cells)
        if x is None or y is None or not (math.isfinite(x) and math.isfinite(y)):
            what = "two numbers" if x is None or y is None else "two finite numbers"
            raise ValueError(f"{where} line {number} is not {what} ({names}), got {content!r}")
        rows.append((x, y))
        numbers.append(number)
    if not rows:
        raise ValueError(f"{where}: no data rows after the header line (expected {names})")
    table = np.array(rows, dtype=np.float64)
    return table[:, 0], table[:, 1], np.array(numbers)


def _separator_hint(content: str, columns: int) -> str:
    """Why a row of ``columns`` comma-separated cells may not have 2: another separator, a
    cut file (fewer), or columns the table does not take (more)."""
    for sep, what in ((";", "';'"), ("\t", "a tab")):
        if sep in content:
            return f"the line holds {what}: the file must be comma-separated"
    if columns > 2:
        return "the table takes exactly two: leave out the others (and write decimals with '.')"
    return "is the file truncated?"


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def read_two_columns(path: Path, where: str, names: str) -> list[np.ndarray]:
    """The two columns of ``read_table``."""
    x, y, _lines = read_table(path, where, names)
    return [x, y]


__all__ = [
    "END_RTOL",
    "HERTZ_TOLERANCE",
    "MIN_LOADING_POINTS",
    "MIN_RESIDUAL_POINTS",
    "NEAR_HERTZ",
    "PLAUSIBLE_RADIUS",
    "SCATTER_DROP",
    "UNIT_MISMATCH",
    "Rows",
    "check_loading",
    "check_unloading",
    "hertz_offset",
    "radius_hint",
    "read_table",
    "read_two_columns",
    "two",
]
