"""The measurements file: one row per drop, CSV or TOML (schema: docs/calibrate.md).

A row names the drop (``label``), its body and flat (``body``, ``body_material``,
``flat_material`` and any numeric input of the sweep's catalogue, e.g. ``tip_radius``,
``flat_yield_strength``), its incoming kinematics (``angle``, ``vx``, ``vy``, ``spin``, and
``mu`` unless mu is calibrated) and any subset of the measurable quantities
(:data:`impactlab.calibrate.quantities.MEASURABLE`: ``e``, ``e_t``, ``spin_out``,
``delta_p``, ``sliding_length`` (alias ``L_s``), ``duration``, ...), each with its standard
uncertainty ``<name>_sigma`` in the same unit. Units: a CSV header may carry one
(``delta_p [um]``), a TOML file a ``[units]`` table; a value may be a string with units
(``"12 um"``); a bare number is otherwise SI, and an angle is refused bare (``"20 deg"``, or
``angle [deg]`` as the column header), as in study files and on the command line.
"""

from __future__ import annotations

import csv
import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD
from impactlab.calibrate.measurement_files import csv_records, read_text
from impactlab.calibrate.quantities import (
    AMBIGUOUS,
    DROP_CATEGORIES,
    MEASURABLE,
    NUMERIC_INPUTS,
    canonical_output,
)
from impactlab.materials import PRESETS
from impactlab.sweep.dimensions import check_allowed, check_rod_angles
from impactlab.sweep.inputs import INPUTS, UNIT_REQUIRED
from impactlab.units import to_si

__all__ = ["Measurements", "read_measurements"]

_LABEL_KEYS = ("label", "drop", "name")


@dataclass(frozen=True)
class Measurements:
    """Drops and what was measured on them (SI units).

    labels : one name per drop; categories : per drop, its category inputs (``body``,
    ``body_material``, ``flat_material``); inputs : numeric input -> (D,) array (NaN: the
    preset's value); observed / sigma : measurable -> (D,) values and standard uncertainties
    (NaN where that drop did not measure it); source : the file read, if any.
    """

    labels: tuple[str, ...]
    categories: tuple[Mapping[str, str], ...]
    inputs: Mapping[str, np.ndarray]
    observed: Mapping[str, np.ndarray]
    sigma: Mapping[str, np.ndarray]
    source: str | None = None

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
        if not records:
            raise ValueError(f"{source or 'measurements'}: no drops (rows) found")
        rows = [_parse_row(i, r, units or {}) for i, r in enumerate(records)]
        return _assemble(rows, source)

    def table(self) -> Any:
        """One row per drop (pandas DataFrame, SI units)."""
        import pandas as pd

        data: dict[str, Any] = {"label": list(self.labels)}
        for c in DROP_CATEGORIES:
            data[c] = [cat[c] for cat in self.categories]
        data.update({k: v for k, v in self.inputs.items() if np.isfinite(v).any()})
        for q in self.quantities:
            data[q], data[f"{q}_sigma"] = self.observed[q], self.sigma[q]
        return pd.DataFrame(data)

    def records(self) -> list[dict[str, Any]]:
        """The drops as rows of ``column [SI unit]`` -> value (NaN-free), for ``to_csv``."""
        out: list[dict[str, Any]] = []
        for d, label in enumerate(self.labels):
            row: dict[str, Any] = {"label": label, **self.categories[d]}
            for k, v in self.inputs.items():
                if math.isfinite(v[d]):
                    row[_header(k, INPUTS[k].unit)] = float(v[d])
            for q in self.quantities:
                if math.isfinite(self.observed[q][d]):
                    unit = MEASURABLE[q].unit
                    row[_header(q, unit)] = float(self.observed[q][d])
                    row[_header(f"{q}_sigma", unit)] = float(self.sigma[q][d])
            out.append(row)
        return out

    def to_csv(self, path: str | Path) -> Path:
        """Write the drops as a CSV file (SI units named in the header); returns the path."""
        rows = self.records()
        header: list[str] = []
        for r in rows:
            header += [k for k in r if k not in header]
        p = Path(path)
        with p.open("w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=header)
            w.writeheader()
            w.writerows(rows)
        return p

    def extended(self, other: Measurements) -> Measurements:
        """These drops followed by ``other``'s."""
        return _assemble(_rows_of(self) + _rows_of(other), self.source)


def _header(name: str, unit: str) -> str:
    return name if unit in ("1", "") else f"{name} [{unit}]"


def read_measurements(path: str | Path) -> Measurements:
    """Read a measurements file (``.csv`` or ``.toml``; schema in the module docstring)."""
    p = Path(path)
    if not p.is_file():
        raise FileNotFoundError(f"measurements file not found: {p}")
    suffix = p.suffix.lower()
    if suffix == ".csv":
        return Measurements.from_records(csv_records(p), source=str(p))
    if suffix == ".toml":
        try:
            doc = tomllib.loads(read_text(p, "TOML"))
        except tomllib.TOMLDecodeError as exc:
            raise ValueError(f"{p}: not valid TOML ({exc})") from None
        unknown = set(doc) - {"drop", "units"}
        if unknown:
            raise ValueError(f"{p}: unknown table(s) {sorted(unknown)}; expected [[drop]], [units]")
        drops = doc.get("drop", [])
        if not isinstance(drops, list):
            raise ValueError(f"{p}: 'drop' must be an array of tables ([[drop]])")
        return Measurements.from_records(drops, doc.get("units", {}), source=str(p))
    raise ValueError(f"measurements file must end in .csv or .toml, got {p.name!r}")


# -- one row -------------------------------------------------------------------------------------


@dataclass
class _Row:
    label: str
    categories: dict[str, str]
    inputs: dict[str, float]
    observed: dict[str, float]
    sigma: dict[str, float]


def _split_header(key: str) -> tuple[str, str | None]:
    """``"delta_p [um]"`` -> ("delta_p", "um")."""
    key = key.strip()
    if key.endswith("]") and "[" in key:
        name, unit = key[:-1].split("[", 1)
        return name.strip(), unit.strip()
    return key, None


def _blank(v: Any) -> bool:
    return (
        v is None
        or (isinstance(v, str) and not v.strip())
        or (isinstance(v, float) and math.isnan(v))
    )


def _value(where: str, name: str, v: Any, column_unit: str | None, si_unit: str) -> float:
    """``v`` in SI (``si_unit``): a bare number is in ``column_unit`` (the column header's or
    the ``[units]`` table's; None: SI) and must fit its dimension, as a unit in a value must."""
    if isinstance(v, bool) or not isinstance(v, int | float | str):
        raise ValueError(f"{where}: {name} must be a number or a quantity string, got {v!r}")
    try:
        if column_unit and _bare(v):
            return to_si(f"{str(v).strip()} {column_unit}", si_unit, name=name)
        if column_unit:
            to_si(f"1 {column_unit}", si_unit, name=f"{name} (column unit [{column_unit}])")
        return to_si(float(v) if isinstance(v, str) and _is_number(v) else v, si_unit, name=name)
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None


def _bare(v: Any) -> bool:
    """A plain number, or text that is only a number (no unit)."""
    return isinstance(v, int | float) or (isinstance(v, str) and _is_number(v))


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _category(where: str, name: str, value: str) -> str:
    known = ("rod", "sphere") if name == "body" else tuple(PRESETS)
    if value not in known:
        raise ValueError(f"{where}: unknown {name} {value!r}; known: {', '.join(known)}")
    return value


def _parse_row(i: int, record: Mapping[str, Any], units: Mapping[str, str]) -> _Row:
    where = f"drop {i + 1}"
    label, cats, inputs, obs, sig = f"drop {i + 1}", {}, {}, {}, {}
    for key, v in record.items():
        name, unit = _split_header(str(key))
        # a TOML file's [units] entry of a quantity is its uncertainty's too
        unit = unit or units.get(name) or units.get(name.removesuffix("_sigma"))
        if name in _LABEL_KEYS:
            if not _blank(v):
                label = str(v).strip()
            continue
        if _blank(v):
            continue
        if name in ("law", "friction"):
            raise ValueError(
                f"{where}: {name!r} is not a property of a drop: the contact law and the "
                "friction model are chosen by the candidate models of the calibration"
            )
        ambiguous = AMBIGUOUS.get(name.removesuffix("_sigma"))
        if ambiguous:
            raise ValueError(f"{where}: column {name!r}: {ambiguous}")
        if name in DROP_CATEGORIES:
            cats[name] = _category(where, name, str(v).strip())
        elif name in NUMERIC_INPUTS:
            if name in UNIT_REQUIRED and not unit and _bare(v):
                raise ValueError(
                    f"{where}: {name}: the bare number {v!r} has no unit; an angle needs one, "
                    f"e.g. '20 deg', or a unit in the column header ('{name} [deg]')"
                )
            inputs[name] = _value(where, name, v, unit, INPUTS[name].parse_unit)
        elif name.endswith("_sigma") and canonical_output(name[: -len("_sigma")]):
            q = str(canonical_output(name[: -len("_sigma")]))
            sig[q] = _value(where, name, v, unit, MEASURABLE[q].unit)
        elif canonical_output(name):
            q = str(canonical_output(name))
            obs[q] = _value(where, name, v, unit, MEASURABLE[q].unit)
        elif ";" in name or "\t" in name:
            raise ValueError(
                f"{where}: the header is one column {name!r}: the file separates its columns "
                "with ';' or tabs; a measurements CSV separates them with commas"
            )
        else:
            raise ValueError(
                f"{where}: unknown column {name!r}; a drop takes label, "
                f"{', '.join(DROP_CATEGORIES)}, the numeric inputs ({', '.join(NUMERIC_INPUTS)}) "
                f"and measured quantities ({', '.join(MEASURABLE)}) with <name>_sigma"
            )
    if cats.get("body") == "sphere":
        inputs.setdefault("angle", math.pi / 2.0)  # a sphere has no axis: the angle is unused
    row = _Row(label, cats, inputs, obs, sig)
    _check_row(where, row)
    return row


def _check_row(where: str, row: _Row) -> None:
    for req in ("angle", "vy"):
        if req not in row.inputs:
            raise ValueError(f"{where} ({row.label}): the drop needs {req!r}")
    _check_inputs(f"{where} ({row.label})", row)
    if row.inputs["vy"] >= 0.0:
        raise ValueError(
            f"{where} ({row.label}): vy = {row.inputs['vy']:g} m/s must be < 0 (towards the flat)"
        )
    for q, x in row.observed.items():
        s = row.sigma.get(q)
        if s is None:
            raise ValueError(
                f"{where} ({row.label}): {q} = {x:g} has no standard uncertainty; add the "
                f"column {q}_sigma (same unit), > 0"
            )
        if not (math.isfinite(s) and s > 0.0):
            raise ValueError(f"{where} ({row.label}): {q}_sigma must be finite and > 0, got {s!r}")
        m = MEASURABLE[q]
        if (m.low is not None and x < m.low) or (m.high is not None and x > m.high):
            raise ValueError(
                f"{where} ({row.label}): {q} = {x:g}{_unit_text(m.unit)} lies outside the "
                "possible range "
                f"[{m.low}, {m.high}] ({m.description})"
            )
        if q == "e_t" and row.inputs.get("vx", 0.0) == 0.0:
            raise ValueError(f"{where} ({row.label}): e_t needs a drop with vx != 0")
    for q in row.sigma:
        if q not in row.observed:
            raise ValueError(f"{where} ({row.label}): {q}_sigma is given without {q}")
    _check_depths(where, row)


def _check_inputs(where: str, row: _Row) -> None:
    """The values a single impact refuses (the sweep's rules: ``sweep.dimensions``): an angle
    of a rod outside (0, 90] deg, mu < 0, a size, mass or material property <= 0, ..."""
    for name, x in row.inputs.items():
        check_allowed(name, [x], f"{where}, column {name!r}")
    if row.categories.get("body", "rod") != "sphere":
        check_rod_angles([row.inputs["angle"]], f"{where}, column 'angle'")


def _unit_text(unit: str) -> str:
    return "" if unit in ("1", "") else f" {unit}"


def _check_depths(where: str, row: _Row) -> None:
    """A dent deeper than the tip radius is a unit mistake (e.g. um read as m)."""
    radius = row.inputs.get("tip_radius", row.inputs.get("radius"))
    if radius is None and row.categories.get("body", "rod") != "sphere":
        radius = PAPER_ROD.tip_radius
    if radius is None:
        return
    for q in ("delta_p", "delta_max"):
        x = row.observed.get(q)
        if x is not None and x > radius:
            raise ValueError(
                f"{where} ({row.label}): {q} = {x:g} m exceeds the tip radius {radius:g} m; "
                "give its unit (e.g. '12 um' or a header 'delta_p [um]')"
            )


def _assemble(rows: Sequence[_Row], source: str | None) -> Measurements:
    labels = tuple(r.label for r in rows)
    dup = {x for x in labels if labels.count(x) > 1}
    if dup:
        raise ValueError(f"duplicate drop labels: {sorted(dup)}")
    cats = tuple(
        {c: r.categories.get(c, str(INPUTS[c].default)) for c in DROP_CATEGORIES} for r in rows
    )
    inputs: dict[str, np.ndarray] = {}
    for name in NUMERIC_INPUTS:
        default = INPUTS[name].default
        fill = math.nan if default is None else float(default)
        inputs[name] = np.array([r.inputs.get(name, fill) for r in rows], dtype=np.float64)
    names = list(dict.fromkeys(q for r in rows for q in r.observed))
    if not names:
        raise ValueError(f"{source or 'measurements'}: no measured quantity in any drop")
    observed = {q: np.array([r.observed.get(q, math.nan) for r in rows]) for q in names}
    sigma = {q: np.array([r.sigma.get(q, math.nan) for r in rows]) for q in names}
    return Measurements(labels, cats, inputs, observed, sigma, source)


def _rows_of(m: Measurements) -> list[_Row]:
    rows = []
    for d, label in enumerate(m.labels):
        inputs = {k: float(v[d]) for k, v in m.inputs.items() if math.isfinite(v[d])}
        obs = {q: float(v[d]) for q, v in m.observed.items() if math.isfinite(v[d])}
        sig = {q: float(m.sigma[q][d]) for q in obs}
        rows.append(_Row(label, dict(m.categories[d]), inputs, obs, sig))
    return rows
