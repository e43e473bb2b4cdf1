"""The measurements file: one row per drop, CSV or TOML (schema: docs/calibrate.md).

A row names the drop (``label``), its body and flat (``body``, ``body_material``,
``flat_material`` and any numeric input of the sweep's catalogue, e.g. ``tip_radius``,
``flat_yield_strength``), its incoming kinematics (``angle``, ``vx``, ``vy`` or ``speed`` and
``incidence``, ``spin``, and ``mu`` unless mu is calibrated) and any subset of the measurable
quantities (:data:`impactlab.calibrate.quantities.MEASURABLE`: ``e``, ``e_t``, ``spin_out``,
``delta_p``, ``sliding_length``, ``scar_length``, ``duration``, ...), each with its standard
uncertainty ``<name>_sigma`` (in its quantity's unit unless it names its own). Units: a CSV header
may carry one (``delta_p [um]``), a TOML file a ``[units]`` table (its keys are column names,
aliases too: ``T = "ms"``; an unknown key, or one that is not a quantity, is refused); a value
may be a string with units (``"12 um"``); a bare number is otherwise in the input's unit (SI; a
Brinell hardness in kgf/mm^2, as in the sweep), an angle (``angle``, ``incidence``,
``angle_out``) is refused bare (``"20 deg"``, or ``angle [deg]`` as the column header), as in
study files and on the command line, and a fraction (e, e_t, mu, ...) may be in percent. A
drop's correlated values take ``correlation_<a>_<b>``, the coefficient of the pair (a plain number
in [-1, 1]; ``impactlab.calibrate.correlations``). Rows are read and checked by
``impactlab.calibrate.measurement_rows``.
"""

from __future__ import annotations

import csv
import io
import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._files import write_text_atomic
from impactlab.calibrate.correlations import correlation_column, normalised
from impactlab.calibrate.display import measurements_text
from impactlab.calibrate.measurement_columns import resolve_units
from impactlab.calibrate.measurement_files import csv_records, read_text
from impactlab.calibrate.measurement_rows import Row, parse_row
from impactlab.calibrate.measurement_twins import warn_twins
from impactlab.calibrate.quantities import DROP_CATEGORIES, MEASURABLE, NUMERIC_INPUTS
from impactlab.sweep.inputs import INPUTS

__all__ = ["Measurements", "read_measurements"]


@dataclass(frozen=True, repr=False)
class Measurements:
    """Drops and what was measured on them.

    labels : one name per drop; categories : per drop, its category inputs (``body``,
    ``body_material``, ``flat_material``); inputs : numeric input -> (D,) array in the input's
    unit (SI; the Brinell hardness in kgf/mm^2, as the sweep stores it; NaN: the preset's
    value); observed / sigma : measurable -> (D,) values and standard uncertainties
    (NaN where that drop did not measure it); source : the file read, if any; correlation :
    (a, b) pair of measured quantities -> (D,) correlation coefficients of the drops' values
    of a and b (NaN, or a pair left out: 0, independent; ``impactlab.calibrate.correlations``;
    ValueError naming the drop and the pair for one outside [-1, 1], of a quantity the drop
    does not measure, given twice, or coefficients that form no positive-definite matrix).
    """

    labels: tuple[str, ...]
    categories: tuple[Mapping[str, str], ...]
    inputs: Mapping[str, np.ndarray]
    observed: Mapping[str, np.ndarray]
    sigma: Mapping[str, np.ndarray]
    source: str | None = None
    correlation: Mapping[tuple[str, str], np.ndarray] = field(default_factory=dict)

    def __post_init__(self) -> None:
        pairs = normalised(self.correlation, self.labels, self.observed, self.sigma)
        object.__setattr__(self, "correlation", pairs)

    def __repr__(self) -> str:
        return measurements_text(self)

    @property
    def n_drops(self) -> int:
        """The number of drops D."""
        return len(self.labels)

    @property
    def quantities(self) -> tuple[str, ...]:
        """The measured quantities, in the file's order."""
        return tuple(self.observed)

    @property
    def n_values(self) -> int:
        """The number of measured values (drop, quantity pairs)."""
        return int(sum(np.isfinite(v).sum() for v in self.observed.values()))

    @classmethod
    def from_records(
        cls,
        records: Sequence[Mapping[str, Any]],
        units: Mapping[str, str] | None = None,
        source: str | None = None,
    ) -> Measurements:
        """Measurements from rows (column -> value); ``units``: column -> unit of its bare
        numbers. ValueError naming the row and column for anything not understood."""
        return _from_records(records, units, source)

    @classmethod
    def conditions(
        cls,
        records: Sequence[Mapping[str, Any]],
        units: Mapping[str, str] | None = None,
        source: str | None = None,
    ) -> Measurements:
        """Drops to predict (``Calibration.predict``): rows as ``from_records`` reads them,
        each with its inputs only (measured values, if any, are read and checked too)."""
        return _from_records(records, units, source, measured=False)

    def table(self) -> Any:
        """One row per drop (pandas DataFrame, the units of ``inputs``, ``observed``)."""
        import pandas as pd

        data: dict[str, Any] = {"label": list(self.labels)}
        for c in DROP_CATEGORIES:
            data[c] = [cat[c] for cat in self.categories]
        data.update({k: v for k, v in self.inputs.items() if np.isfinite(v).any()})
        for q in self.quantities:
            data[q], data[f"{q}_sigma"] = self.observed[q], self.sigma[q]
        data.update({correlation_column(*p): x for p, x in self.correlation.items()})
        return pd.DataFrame(data)

    def records(self) -> list[dict[str, Any]]:
        """The drops as rows of ``column [unit]`` -> value (NaN-free), for ``to_csv`` (a
        sphere's angle, which it does not have, is left out)."""
        out: list[dict[str, Any]] = []
        for d, label in enumerate(self.labels):
            row: dict[str, Any] = {"label": label, **self.categories[d]}
            sphere = self.categories[d].get("body") == "sphere"
            for k, v in self.inputs.items():
                if math.isfinite(v[d]) and not (sphere and k == "angle"):
                    row[_header(k, INPUTS[k].unit)] = float(v[d])
            for q in self.quantities:
                if math.isfinite(self.observed[q][d]):
                    unit = MEASURABLE[q].unit
                    row[_header(q, unit)] = float(self.observed[q][d])
                    row[_header(f"{q}_sigma", unit)] = float(self.sigma[q][d])
            for p, x in self.correlation.items():
                if math.isfinite(x[d]):
                    row[correlation_column(*p)] = float(x[d])
            out.append(row)
        return out

    def to_csv(self, path: str | Path) -> Path:
        """Write the drops as a CSV file (UTF-8, units named in the header) whole or not at
        all: a full disk or an interruption leaves a file there as it was; returns the path."""
        rows = self.records()
        header: list[str] = []
        for r in rows:
            header += [k for k in r if k not in header]
        text = io.StringIO(newline="")
        w = csv.DictWriter(text, fieldnames=header)
        w.writeheader()
        w.writerows(rows)
        p = Path(path)
        write_text_atomic(p, text.getvalue())
        return p

    def extended(self, other: Measurements) -> Measurements:
        """These drops followed by ``other``'s."""
        return _assemble(_rows_of(self) + _rows_of(other), self.source)


def _header(name: str, unit: str) -> str:
    return name if unit in ("1", "") else f"{name} [{unit}]"


def read_measurements(path: str | Path, *, measured: bool = True) -> Measurements:
    """Read a measurements file (``.csv`` or ``.toml``; schema in the module docstring);
    ``measured=False``: drops without measured values are taken (``Measurements.conditions``)."""
    p = Path(path)
    if p.is_dir():
        raise IsADirectoryError(f"measurements file {str(p)!r} is a directory; give the file")
    if not p.is_file():
        raise FileNotFoundError(f"measurements file not found: {p}")
    suffix = p.suffix.lower()
    if suffix == ".csv":
        numbered = csv_records(p)
        meas = _from_records(
            [r for _, r in numbered], None, str(p), [n for n, _ in numbered], measured
        )
        warn_twins(meas)
        return meas
    if suffix == ".toml":
        try:
            doc = tomllib.loads(read_text(p, "TOML"))
        except tomllib.TOMLDecodeError as exc:
            raise ValueError(f"{p}: not valid TOML ({exc})") from None
        unknown = set(doc) - {"drop", "units"}
        if unknown:
            what = "key(s)" if any(not isinstance(doc[k], dict) for k in unknown) else "table(s)"
            invert = (
                " (it looks like an input file of impactlab invert --file, one impact's values; "
                "a measurements file holds a [[drop]] table per drop)"
                if "drop" not in doc and {"angle", "mu"} & set(doc)
                else ""
            )
            raise ValueError(
                f"{p}: unknown {what} {sorted(unknown)}; expected [[drop]], [units]{invert}"
            )
        drops = doc.get("drop", [])
        if not isinstance(drops, list):
            raise ValueError(f"{p}: 'drop' must be an array of tables ([[drop]])")
        _refuse_nan(p, drops)
        try:
            units = resolve_units(doc.get("units", {}))
            meas = _from_records(drops, units, str(p), measured=measured)
        except ValueError as exc:  # each error names the file
            text = str(exc)
            raise ValueError(text if text.startswith(f"{p}: ") else f"{p}: {text}") from None
        warn_twins(meas)
        return meas
    hint = (
        ": a results.json is no measurements file (an analysis's holds one drop: append it to "
        "a CSV file with impactlab analyze MARKERS SCAN --measurements drops.csv --label NAME, "
        "or calibrate.experiment_rows.append_experiment, and calibrate that; a calibration's "
        "holds its settings, which a --config TOML repeats)"
        if suffix == ".json"
        else ""
    )
    raise ValueError(f"measurements file must end in .csv or .toml, got {p.name!r}{hint}")


def _from_records(
    records: Sequence[Mapping[str, Any]],
    units: Mapping[str, str] | None,
    source: str | None,
    lines: Sequence[int] | None = None,
    measured: bool = True,
) -> Measurements:
    """``Measurements.from_records``; ``lines``: the file's line of each record, which an
    error then names (``"m.csv: line 3: drop 2 (b): ..."``); ``measured=False``: drops
    without measured values are taken."""
    if not records:
        raise ValueError(f"{source or 'measurements'}: no drops (rows) found")
    table = resolve_units(units or {})
    rows = []
    for i, r in enumerate(records):
        try:
            rows.append(parse_row(i, r, table))
        except ValueError as exc:
            if lines is None:
                raise
            raise ValueError(f"{source}: line {lines[i]}: {exc}") from None
    return _assemble(rows, source, lines, measured)


def _refuse_nan(path: Path, drops: Sequence[Any]) -> None:
    """A TOML drop leaves out what it did not measure: ``nan`` is refused, naming the key."""
    for i, drop in enumerate(drops):
        if not isinstance(drop, Mapping):
            continue
        for key, v in drop.items():
            if isinstance(v, float) and math.isnan(v):
                raise ValueError(
                    f"{path}: drop {i + 1}: {key} = nan is not a number; leave the key out for "
                    "a drop that did not measure it"
                )


def _assemble(
    rows: Sequence[Row],
    source: str | None,
    lines: Sequence[int] | None = None,
    measured: bool = True,
) -> Measurements:
    labels = tuple(r.label for r in rows)
    _refuse_duplicates(labels, source, lines)
    cats = tuple(
        {c: r.categories.get(c, str(INPUTS[c].default)) for c in DROP_CATEGORIES} for r in rows
    )
    inputs: dict[str, np.ndarray] = {}
    for name in NUMERIC_INPUTS:
        default = INPUTS[name].default
        fill = math.nan if default is None else float(default)
        inputs[name] = np.array([r.inputs.get(name, fill) for r in rows], dtype=np.float64)
    names = list(dict.fromkeys(q for r in rows for q in r.observed))
    if not names and measured:
        raise ValueError(
            f"{source or 'measurements'}: no measured quantity in any drop (drops to predict, "
            "without measurements, are Measurements.conditions)"
        )
    for d, r in enumerate(rows):  # it would add nothing but zeros to the model ranking
        if not r.observed and measured:
            line = "" if lines is None else f"{source}: line {lines[d]}: "
            raise ValueError(
                f"{line}drop {d + 1} ({r.label}) has no measured value: give "
                f"{' or '.join(names)} with its uncertainty where it was measured, or leave the "
                "drop out"
            )
    observed = {q: np.array([r.observed.get(q, math.nan) for r in rows]) for q in names}
    sigma = {q: np.array([r.sigma.get(q, math.nan) for r in rows]) for q in names}
    pairs = list(dict.fromkeys(p for r in rows for p in r.correlation))
    corr = {p: np.array([r.correlation.get(p, math.nan) for r in rows]) for p in pairs}
    return Measurements(labels, cats, inputs, observed, sigma, source, corr)


def _refuse_duplicates(
    labels: Sequence[str], source: str | None, lines: Sequence[int] | None
) -> None:
    """Drops of one label refused, naming each such label with its drops (and, with
    ``lines``, the lines of the file ``source``)."""
    where = []
    for label in sorted({x for x in labels if labels.count(x) > 1}):
        at = [d for d, x in enumerate(labels) if x == label]
        drops = f"(drops {_and([d + 1 for d in at])})"
        rows = "" if lines is None else f" on lines {_and([lines[d] for d in at])}"
        where.append(f"{label!r}{rows} {drops}")
    if where:
        file = "" if lines is None else f"{source}: "
        raise ValueError(
            f"{file}duplicate drop labels: {'; '.join(where)}: give each drop its own label "
            "(a drop without one is named 'drop N', N its place in the file)"
        )


def _and(numbers: Sequence[int]) -> str:
    """``[2, 3, 5]`` -> ``"2, 3 and 5"``."""
    return " and ".join([", ".join(map(str, numbers[:-1])), str(numbers[-1])])


def _rows_of(m: Measurements) -> list[Row]:
    rows = []
    for d, label in enumerate(m.labels):
        inputs = {k: float(v[d]) for k, v in m.inputs.items() if math.isfinite(v[d])}
        obs = {q: float(v[d]) for q, v in m.observed.items() if math.isfinite(v[d])}
        sig = {q: float(m.sigma[q][d]) for q in obs}
        corr = {p: float(x[d]) for p, x in m.correlation.items() if math.isfinite(x[d])}
        rows.append(Row(label, dict(m.categories[d]), inputs, obs, sig, correlation=corr))
    return rows
