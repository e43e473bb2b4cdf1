"""Study definitions: a grid over inputs and/or a Monte Carlo sample, the outputs to keep, and
the deterministic chunking of the cases.

A study has named dimensions: one per grid axis (in the order given), then ``sample`` when a
Monte Carlo sample is drawn. Sampled inputs depend only on the sample index, so with both a grid
and a sample every grid point sees the same draws (common random numbers). Inputs not on a
dimension are fixed (``fixed``) or left at their defaults (``inputs.INPUTS``).

The cases are cut into chunks: regular blocks of the N-d case array (``Layout``), of about
``chunk_size`` cases, one value of every category input per block. A chunk is the unit of work,
of Zarr storage and of resumption; chunk ``k`` is a pure function of the study and ``k``.
"""

from __future__ import annotations

import hashlib
import json
import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np
import pint

from impactlab.sweep.distributions import (
    Distribution,
    distribution_from_canonical,
    distribution_from_dict,
)
from impactlab.sweep.inputs import INPUTS, OUTPUT_ALIASES, get_input
from impactlab.units import registry as units_registry

#: Version of the study/store format; part of the study hash.
STUDY_FORMAT = "impactlab-sweep/1"
#: Default number of cases per chunk.
DEFAULT_CHUNK_SIZE = 65536
SAMPLE_DIM = "sample"

Value = float | str


def _is_category(name: str) -> bool:
    return get_input(name).kind == "category"


def _check_value(name: str, value: Any) -> Value:
    """A fixed or axis value for input ``name`` (SI float or a category string)."""
    spec = get_input(name)
    if spec.kind == "category":
        if not isinstance(value, str) or not value:
            raise ValueError(f"input {name!r} takes a name (string), got {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise ValueError(f"input {name!r} must be a number in {spec.unit}, got {value!r}")
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"input {name!r} must be finite, got {x!r}")
    return x


@dataclass(frozen=True)
class Axis:
    """One grid dimension: an input and its values (SI floats, or names for a category)."""

    name: str
    values: tuple[Value, ...]

    def __post_init__(self) -> None:
        get_input(self.name)
        if self.name == SAMPLE_DIM:
            raise ValueError(f"{SAMPLE_DIM!r} is reserved")
        vals = tuple(_check_value(self.name, v) for v in np.asarray(self.values).tolist()) \
            if not isinstance(self.values, str) else (_check_value(self.name, self.values),)
        if not vals:
            raise ValueError(f"grid axis {self.name!r} has no values")
        if len(set(vals)) != len(vals):
            raise ValueError(f"grid axis {self.name!r} has repeated values")
        object.__setattr__(self, "values", vals)

    @property
    def is_category(self) -> bool:
        return _is_category(self.name)

    def array(self) -> np.ndarray:
        """The values as an array (float64, or object for names)."""
        if self.is_category:
            return np.array(self.values, dtype=object)
        return np.array(self.values, dtype=np.float64)


@dataclass(frozen=True)
class Sample:
    """A Monte Carlo sample: ``size`` cases, each input drawn from its distribution.

    Draws are seeded by ``seed`` and depend only on (seed, input name, sample index).
    """

    size: int
    seed: int
    inputs: Mapping[str, Distribution]

    def __post_init__(self) -> None:
        if isinstance(self.size, bool) or not isinstance(self.size, int | np.integer) \
                or self.size < 1:
            raise ValueError(f"sample size must be an integer >= 1, got {self.size!r}")
        if isinstance(self.seed, bool) or not isinstance(self.seed, int | np.integer) \
                or self.seed < 0:
            raise ValueError(f"sample seed must be an integer >= 0, got {self.seed!r}")
        if not self.inputs:
            raise ValueError("a sample needs at least one input with a distribution")
        for name, dist in self.inputs.items():
            if _is_category(name):
                raise ValueError(
                    f"input {name!r} is a category; sample numeric inputs only (put categories "
                    f"on the grid to run the sample once per value)"
                )
            if not isinstance(dist, Distribution):
                raise ValueError(f"sample input {name!r} needs a Distribution, got {dist!r}")
        object.__setattr__(self, "size", int(self.size))
        object.__setattr__(self, "seed", int(self.seed))
        object.__setattr__(self, "inputs", dict(self.inputs))

    def draw(self, name: str, start: int, stop: int) -> np.ndarray:
        """Values of input ``name`` for samples ``start..stop-1``."""
        return self.inputs[name].draw(self.seed, name, start, stop)


@dataclass(frozen=True)
class EngineOptions:
    """Options passed to the impact engine unchanged (None: the engine's default)."""

    gravity: bool | float | None = None
    constant_angle: bool | None = None
    rtol: float | None = None

    def __post_init__(self) -> None:
        if self.rtol is not None:
            r = float(self.rtol)
            if not (0.0 < r < 1.0):
                raise ValueError(f"engine rtol must lie in (0, 1), got {self.rtol!r}")
        if self.gravity is not None and not isinstance(self.gravity, bool):
            g = float(self.gravity)
            if not (math.isfinite(g) and g >= 0.0):
                raise ValueError(f"engine gravity must be true/false or >= 0 m/s^2, got {g!r}")
        if self.constant_angle is not None and not isinstance(self.constant_angle, bool):
            raise ValueError(
                f"engine constant_angle must be true or false, got {self.constant_angle!r}"
            )

    def kwargs(self) -> dict[str, Any]:
        return {k: v for k, v in self.to_dict().items() if v is not None}

    def to_dict(self) -> dict[str, Any]:
        return {"gravity": self.gravity, "constant_angle": self.constant_angle, "rtol": self.rtol}


@dataclass(frozen=True)
class UncertaintySpec:
    """What the uncertainty report summarises (see ``impactlab.sweep.uncertainty``)."""

    outputs: tuple[str, ...] = ("e", "delta_p", "sliding_length", "duration", "mean_force")
    percentiles: tuple[float, ...] = (2.5, 50.0, 97.5)

    def __post_init__(self) -> None:
        outs = tuple(OUTPUT_ALIASES.get(o, o) for o in self.outputs)
        if not outs:
            raise ValueError("uncertainty outputs must not be empty")
        object.__setattr__(self, "outputs", outs)
        ps = tuple(float(p) for p in self.percentiles)
        for p in ps:
            if not 0.0 <= p <= 100.0:
                raise ValueError(f"uncertainty percentiles must lie in [0, 100], got {p!r}")
        object.__setattr__(self, "percentiles", ps)


@dataclass(frozen=True)
class Layout:
    """Dimensions, shape and regular chunk grid of a study's case array."""

    dims: tuple[str, ...]
    shape: tuple[int, ...]
    chunks: tuple[int, ...]

    @property
    def n_cases(self) -> int:
        return int(np.prod(self.shape, dtype=np.int64))

    @property
    def chunk_grid(self) -> tuple[int, ...]:
        return tuple(-(-n // c) for n, c in zip(self.shape, self.chunks, strict=True))

    @property
    def n_chunks(self) -> int:
        return int(np.prod(self.chunk_grid, dtype=np.int64))

    def block(self, index: int) -> tuple[slice, ...]:
        """The region of chunk ``index`` (C order over the chunk grid)."""
        if not 0 <= index < self.n_chunks:
            raise IndexError(f"chunk index {index} outside [0, {self.n_chunks})")
        pos = np.unravel_index(index, self.chunk_grid)
        return tuple(
            slice(int(p) * c, min((int(p) + 1) * c, n))
            for p, c, n in zip(pos, self.chunks, self.shape, strict=True)
        )

    def block_size(self, index: int) -> int:
        return int(np.prod([s.stop - s.start for s in self.block(index)], dtype=np.int64))


def chunk_shape(shape: Sequence[int], category: Sequence[bool], target: int) -> tuple[int, ...]:
    """Regular chunk shape of about ``target`` cases: whole trailing dimensions first, extent 1
    along category dimensions (one engine call per chunk)."""
    chunks = [1] * len(shape)
    room = max(1, int(target))
    for j in range(len(shape) - 1, -1, -1):
        if category[j]:
            continue
        c = max(1, min(shape[j], room))
        chunks[j] = c
        room = max(1, room // c)
    return tuple(chunks)


@dataclass(frozen=True)
class Study:
    """A sweep: grid axes and/or a Monte Carlo sample over the inputs, fixed values for others.

    Python API (SI units; angles in radians)::

        Study(name="map", grid={"angle": np.radians(np.linspace(5, 85, 81)),
                                "mu": np.linspace(0, 0.5, 51)},
              fixed={"vy": -1.41}, outputs=["e", "regime"])

    name : label (also the default store name).
    grid : input -> values, in dimension order (or a sequence of ``Axis``).
    sample : a ``Sample`` (dimension ``sample``, after the grid dimensions).
    fixed : input -> value for inputs that do not vary.
    outputs : engine outputs to keep (None: all; the paper's symbols L_s, T, F are accepted).
    engine : ``EngineOptions`` passed to the engine.
    law_params : parameters of the contact law (``impactlab laws``), fixed for the study.
    chunk_size : target number of cases per chunk (the unit of work, storage and resumption).
    uncertainty : what ``impactlab sweep`` reports at the end of a Monte Carlo study.
    """

    name: str = "study"
    grid: Any = ()
    sample: Sample | None = None
    fixed: Mapping[str, Value] = field(default_factory=dict)
    outputs: Sequence[str] | None = None
    engine: EngineOptions = field(default_factory=EngineOptions)
    law_params: Mapping[str, float] = field(default_factory=dict)
    chunk_size: int = DEFAULT_CHUNK_SIZE
    description: str = ""
    uncertainty: UncertaintySpec | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise ValueError(f"study name must be a non-empty string, got {self.name!r}")
        grid = self.grid
        if isinstance(grid, Mapping):
            axes = tuple(Axis(k, tuple(np.atleast_1d(np.asarray(v, dtype=object)).tolist())
                              if not isinstance(v, str) else (v,))
                         for k, v in grid.items())
        else:
            axes = tuple(a if isinstance(a, Axis) else Axis(*a) for a in grid)
        object.__setattr__(self, "grid", axes)
        fixed = {k: _check_value(k, v) for k, v in dict(self.fixed).items()}
        object.__setattr__(self, "fixed", fixed)
        if self.sample is not None and not isinstance(self.sample, Sample):
            raise ValueError(f"sample must be a Sample, got {self.sample!r}")
        # every input is set at most once
        seen: dict[str, str] = {}
        sources = [("grid", a.name) for a in axes] + [("fixed", k) for k in fixed]
        if self.sample is not None:
            sources += [("sample", k) for k in self.sample.inputs]
        for where, name in sources:
            get_input(name)
            if name in seen:
                raise ValueError(f"input {name!r} is set twice (in {seen[name]} and {where})")
            seen[name] = where
        missing = [s.name for s in INPUTS.values() if s.required and s.name not in seen]
        if missing:
            raise ValueError(
                f"input(s) {missing} have no value: set them in [fixed], [grid] or [sample]"
            )
        if not axes and self.sample is None:
            raise ValueError(
                "a study needs a [grid] or a [sample] (for a single impact use "
                "`impactlab simulate`)"
            )
        if self.outputs is not None:
            outs = tuple(OUTPUT_ALIASES.get(o, o) for o in self.outputs)
            if not outs:
                raise ValueError("outputs must not be empty (omit it to keep all outputs)")
            if len(set(outs)) != len(outs):
                raise ValueError(f"outputs lists a name twice: {list(self.outputs)}")
            object.__setattr__(self, "outputs", outs)
        if not isinstance(self.engine, EngineOptions):
            raise ValueError(f"engine must be EngineOptions, got {self.engine!r}")
        lp = {}
        for k, v in dict(self.law_params).items():
            if isinstance(v, bool) or not isinstance(v, int | float):
                raise ValueError(f"law parameter {k!r} must be a number, got {v!r}")
            lp[str(k)] = float(v)
        object.__setattr__(self, "law_params", lp)
        if isinstance(self.chunk_size, bool) or not isinstance(self.chunk_size, int) \
                or self.chunk_size < 1:
            raise ValueError(f"chunk_size must be an integer >= 1, got {self.chunk_size!r}")
        if self.uncertainty is not None and self.sample is None:
            raise ValueError("an [uncertainty] report needs a [sample]")

    # -- structure -----------------------------------------------------------------------------

    @property
    def axes(self) -> tuple[Axis, ...]:
        return tuple(self.grid)

    @cached_property
    def layout(self) -> Layout:
        dims = tuple(a.name for a in self.axes)
        shape = tuple(len(a.values) for a in self.axes)
        category = [a.is_category for a in self.axes]
        if self.sample is not None:
            dims += (SAMPLE_DIM,)
            shape += (self.sample.size,)
            category.append(False)
        return Layout(dims, shape, chunk_shape(shape, category, self.chunk_size))

    @property
    def n_cases(self) -> int:
        return self.layout.n_cases

    @property
    def mode(self) -> str:
        """"grid", "sample" or "grid+sample"."""
        if self.sample is None:
            return "grid"
        return "grid+sample" if self.axes else "sample"

    def value_of(self, name: str) -> Value | None:
        """The fixed value (or default) of an input not on a dimension; None if preset."""
        if name in self.fixed:
            return self.fixed[name]
        return get_input(name).default

    def varying(self) -> tuple[str, ...]:
        """Inputs that vary over the cases (grid axes and sampled inputs)."""
        names = [a.name for a in self.axes]
        if self.sample is not None:
            names += list(self.sample.inputs)
        return tuple(names)

    def chunk_cases(self, index: int) -> tuple[dict[str, np.ndarray], dict[str, str],
                                               tuple[int, ...]]:
        """The cases of chunk ``index``: (numeric input -> 1-D float64 array, category input ->
        its single value, block shape). Unset numeric inputs with a preset default are NaN."""
        lay = self.layout
        block = lay.block(index)
        bshape = tuple(s.stop - s.start for s in block)
        n = int(np.prod(bshape, dtype=np.int64))
        numeric: dict[str, np.ndarray] = {}
        categories: dict[str, str] = {}
        for j, axis in enumerate(self.axes):
            vals = axis.array()[block[j]]
            if axis.is_category:
                categories[axis.name] = str(vals[0])
                continue
            shp = [1] * len(bshape)
            shp[j] = bshape[j]
            numeric[axis.name] = np.broadcast_to(vals.reshape(shp), bshape).ravel()
        if self.sample is not None:
            sl = block[-1]
            shp = [1] * len(bshape)
            shp[-1] = bshape[-1]
            for name in self.sample.inputs:
                vals = self.sample.draw(name, sl.start, sl.stop)
                numeric[name] = np.broadcast_to(vals.reshape(shp), bshape).ravel()
        for spec in INPUTS.values():
            if spec.name in numeric or spec.name in categories:
                continue
            v = self.value_of(spec.name)
            if spec.kind == "category":
                categories[spec.name] = str(v)
            else:
                numeric[spec.name] = np.full(n, math.nan if v is None else float(v))
        return numeric, categories, bshape

    # -- canonical form, hash ------------------------------------------------------------------

    def to_dict(self) -> dict[str, Any]:
        """Canonical description (SI values, ``units = "si"``): the study hash is computed from
        it and ``Study.from_dict`` reads it back."""
        d: dict[str, Any] = {
            "format": STUDY_FORMAT,
            "study": {"name": self.name, "description": self.description,
                      "chunk_size": self.chunk_size, "units": "si"},
            "fixed": dict(self.fixed),
            "grid": {a.name: list(a.values) for a in self.axes},
            "engine": {k: v for k, v in self.engine.to_dict().items() if v is not None},
            "law_params": dict(self.law_params),
        }
        # the dimension order is meaningful: keep it explicit (JSON objects are sorted)
        d["grid_order"] = [a.name for a in self.axes]
        if self.sample is not None:
            d["sample"] = {"size": self.sample.size, "seed": self.sample.seed,
                           **{k: v.to_dict() for k, v in self.sample.inputs.items()}}
        if self.outputs is not None:
            d["outputs"] = {"keep": list(self.outputs)}
        if self.uncertainty is not None:
            d["uncertainty"] = {"outputs": list(self.uncertainty.outputs),
                                "percentiles": list(self.uncertainty.percentiles)}
        return d

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), sort_keys=True, separators=(",", ":"))

    def hash(self, extra: str = "") -> str:
        """SHA-256 (hex, 16 digits) of the canonical study (plus ``extra``: the engine identity).

        The description is not part of the hash (changing it does not change any result).
        """
        d = self.to_dict()
        d["study"].pop("description", None)
        text = json.dumps(d, sort_keys=True, separators=(",", ":")) + extra
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], *, source: str = "study") -> Study:
        """Build a study from a study-file table (see docs/sweep.md) or ``to_dict()`` output."""
        return _parse(data, source)

    @classmethod
    def from_toml(cls, path: str | Path) -> Study:
        """Read a study file (TOML)."""
        p = Path(path)
        if p.is_dir():
            raise ValueError(f"{str(p)!r} is a directory (a sweep store?); give the study file "
                             f"(TOML)")
        if not p.is_file():
            raise ValueError(f"study file {str(p)!r} does not exist")
        try:
            with p.open("rb") as fh:
                data = tomllib.load(fh)
        except tomllib.TOMLDecodeError as exc:
            raise ValueError(f"study file {str(p)!r} is not valid TOML: {exc}") from None
        data = dict(data)
        study_tab = dict(data.get("study", {})) if isinstance(data.get("study"), dict) else {}
        study_tab.setdefault("name", p.stem)
        data["study"] = study_tab
        return _parse(data, str(p))


# -- study-file parsing -------------------------------------------------------------------------

_TABLES = ("study", "fixed", "grid", "sample", "outputs", "engine", "law_params", "uncertainty",
           "format", "grid_order")


def _quantity(value: Any, unit: str, bare_unit: str, label: str) -> float:
    """``value`` (a number in ``bare_unit`` or a quantity string) as a float in ``unit``."""
    ureg = units_registry()
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise ValueError(f"{label}: expected a number or a quantity string, got {value!r}")
    q: Any
    try:
        if isinstance(value, str):
            q = ureg.Quantity(value.strip())
            if q.unitless:
                q = float(q.magnitude) * ureg.Unit(bare_unit)
        else:
            q = float(value) * ureg.Unit(bare_unit)
        x = float(q.to(unit).magnitude)
    except pint.DimensionalityError:
        raise ValueError(f"{label}: {value!r} is not convertible to {unit}") from None
    except Exception as exc:  # pint raises several unrelated types for unparsable text
        raise ValueError(f"{label}: cannot parse {value!r} as a quantity ({exc})") from None
    if not math.isfinite(x):
        raise ValueError(f"{label} must be finite, got {value!r}")
    return x


def _converter(name: str, si: bool, unit: str | None, where: str) -> Any:
    """Converter of input ``name``'s numbers: bare numbers are in ``unit`` if given, else in the
    input's file unit (SI, degrees for the angle); with ``si`` bare numbers are SI."""
    spec = get_input(name)
    storage = "dimensionless" if spec.unit == "1" else spec.unit
    bare = unit or ("dimensionless" if spec.unit == "1" else spec.parse_unit)
    if si and unit is None:
        bare = storage

    def convert(value: Any, key: str = "") -> float:
        label = f"{where} {name}" + (f".{key}" if key else "")
        return _quantity(value, storage, bare, label)

    return convert


def _value(name: str, value: Any, si: bool, where: str, unit: str | None = None) -> Value:
    spec = get_input(name)
    if spec.kind == "category":
        if not isinstance(value, str):
            raise ValueError(f"{where} {name}: expected a name (string), got {value!r}")
        return value
    return _converter(name, si, unit, where)(value)


def _axis(name: str, spec: Any, si: bool) -> Axis:
    where = "[grid]"
    if isinstance(spec, list):
        return Axis(name, tuple(_value(name, v, si, where) for v in spec))
    if not isinstance(spec, dict):
        raise ValueError(
            f"[grid] {name}: expected a list of values or a table with start/stop/num, "
            f"got {spec!r}"
        )
    allowed = {"values", "start", "stop", "num", "step", "spacing", "unit"}
    unknown = sorted(set(spec) - allowed)
    if unknown:
        raise ValueError(f"[grid] {name}: unknown key(s) {unknown}; allowed: {sorted(allowed)}")
    unit = spec.get("unit")
    if "values" in spec:
        extra = sorted(set(spec) - {"values", "unit"})
        if extra:
            raise ValueError(f"[grid] {name}: 'values' cannot be combined with {extra}")
        if not isinstance(spec["values"], list):
            raise ValueError(f"[grid] {name}: 'values' must be a list")
        return Axis(name, tuple(_value(name, v, si, where, unit) for v in spec["values"]))
    if get_input(name).kind == "category":
        raise ValueError(f"[grid] {name}: a category axis takes a list of names")
    for key in ("start", "stop"):
        if key not in spec:
            raise ValueError(f"[grid] {name}: missing {key!r} (or give 'values')")
    conv = _converter(name, si, unit, where)
    start, stop = conv(spec["start"], "start"), conv(spec["stop"], "stop")
    spacing = spec.get("spacing", "linear")
    if spacing not in ("linear", "log"):
        raise ValueError(f"[grid] {name}: spacing must be 'linear' or 'log', got {spacing!r}")
    if ("num" in spec) == ("step" in spec):
        raise ValueError(f"[grid] {name}: give exactly one of 'num' and 'step'")
    if "num" in spec:
        num = spec["num"]
        if isinstance(num, bool) or not isinstance(num, int) or num < 1:
            raise ValueError(f"[grid] {name}: num must be an integer >= 1, got {num!r}")
        if spacing == "log":
            if start <= 0 or stop <= 0 or (start < 0) != (stop < 0):
                raise ValueError(f"[grid] {name}: log spacing needs start and stop > 0")
            vals = np.geomspace(start, stop, num)
        else:
            vals = np.linspace(start, stop, num)
    else:
        if spacing == "log":
            raise ValueError(f"[grid] {name}: log spacing takes 'num', not 'step'")
        step = conv(spec["step"], "step")
        if step == 0 or (stop - start) / step < 0:
            raise ValueError(
                f"[grid] {name}: step {step!r} does not lead from start {start!r} to stop {stop!r}"
            )
        count = int(math.floor((stop - start) / step + 1e-9)) + 1
        if count > 100_000_000:
            raise ValueError(f"[grid] {name}: {count} values is too many")
        vals = start + step * np.arange(count)
    return Axis(name, tuple(float(v) for v in vals))


def _sample(tab: Any, si: bool) -> Sample:
    if not isinstance(tab, dict):
        raise ValueError("[sample] must be a table")
    if "size" not in tab:
        raise ValueError("[sample] needs 'size' (number of Monte Carlo cases)")
    size, seed = tab["size"], tab.get("seed", 0)
    inputs: dict[str, Distribution] = {}
    for name, spec in tab.items():
        if name in ("size", "seed"):
            continue
        if name not in INPUTS:
            raise ValueError(
                f"[sample] unknown input {name!r}; known inputs: {', '.join(INPUTS)} "
                f"(and the keys size, seed)"
            )
        if not isinstance(spec, dict):
            raise ValueError(
                f"[sample] {name}: expected a table such as {{ dist = \"normal\", mean = ..., "
                f"std = ... }}, got {spec!r}"
            )
        if get_input(name).kind == "category":
            raise ValueError(
                f"[sample] input {name!r} is a category; put it on the [grid] instead"
            )
        conv = _converter(name, si, spec.get("unit"), "[sample]")
        inputs[name] = distribution_from_canonical(spec) if si else \
            distribution_from_dict(spec, conv, name)
    return Sample(size=size, seed=seed, inputs=inputs)


def _parse(data: Mapping[str, Any], source: str) -> Study:
    unknown = sorted(set(data) - set(_TABLES))
    if unknown:
        raise ValueError(
            f"{source}: unknown table(s) {unknown}; known: "
            f"{', '.join(t for t in _TABLES if t not in ('format', 'grid_order'))}"
        )
    if "format" in data and data["format"] != STUDY_FORMAT:
        raise ValueError(f"{source}: unsupported study format {data['format']!r}")

    def table(key: str) -> dict[str, Any]:
        t = data.get(key, {})
        if not isinstance(t, dict):
            raise ValueError(f"{source}: [{key}] must be a table, got {t!r}")
        return dict(t)

    st = table("study")
    allowed_study = {"name", "description", "chunk_size", "units"}
    bad = sorted(set(st) - allowed_study)
    if bad:
        raise ValueError(f"[study] unknown key(s) {bad}; allowed: {sorted(allowed_study)}")
    si = st.get("units", "file") == "si"
    fixed: dict[str, Value] = {}
    for name, value in table("fixed").items():
        if name not in INPUTS:
            raise ValueError(f"[fixed] unknown input {name!r}; known inputs: {', '.join(INPUTS)}")
        fixed[name] = _value(name, value, si, "[fixed]")
    grid_tab = table("grid")
    order = data.get("grid_order", list(grid_tab))
    axes = []
    for name in order:
        if name not in INPUTS:
            raise ValueError(f"[grid] unknown input {name!r}; known inputs: {', '.join(INPUTS)}")
        axes.append(_axis(name, grid_tab[name], si))
    sample = _sample(data["sample"], si) if "sample" in data else None
    outputs = None
    if "outputs" in data:
        ot = table("outputs")
        bad = sorted(set(ot) - {"keep"})
        if bad or "keep" not in ot or not isinstance(ot["keep"], list):
            raise ValueError("[outputs] takes one key: keep = [\"e\", \"delta_p\", ...]")
        outputs = tuple(str(o) for o in ot["keep"])
    et = table("engine")
    bad = sorted(set(et) - {"gravity", "constant_angle", "rtol"})
    if bad:
        raise ValueError(
            f"[engine] unknown key(s) {bad}; allowed: gravity, constant_angle, rtol"
        )
    engine = EngineOptions(**et)
    unc = None
    if "uncertainty" in data:
        ut = table("uncertainty")
        bad = sorted(set(ut) - {"outputs", "percentiles"})
        if bad:
            raise ValueError(
                f"[uncertainty] unknown key(s) {bad}; allowed: outputs, percentiles"
            )
        for k, v in ut.items():
            if not isinstance(v, list):
                raise ValueError(f"[uncertainty] {k} must be a list, got {v!r}")
        unc = UncertaintySpec(**{k: tuple(v) for k, v in ut.items()})
    return Study(
        name=str(st.get("name", "study")),
        description=str(st.get("description", "")),
        chunk_size=st.get("chunk_size", DEFAULT_CHUNK_SIZE),
        fixed=fixed,
        grid=tuple(axes),
        sample=sample,
        outputs=outputs,
        engine=engine,
        law_params=table("law_params"),
        uncertainty=unc,
    )


def load_study(source: str | Path | Mapping[str, Any] | Study) -> Study:
    """A ``Study`` from a study file path, a parsed table, or a ``Study`` (returned as is)."""
    if isinstance(source, Study):
        return source
    if isinstance(source, Mapping):
        return Study.from_dict(source)
    return Study.from_toml(source)
