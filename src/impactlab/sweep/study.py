"""Study definitions: a grid over inputs and/or a Monte Carlo sample, the outputs to keep, and
the deterministic chunking of the cases.

A study has named dimensions: one per grid axis (in the order given), then ``sample`` when a
Monte Carlo sample is drawn. Sampled inputs depend only on the sample index, so with both a grid
and a sample every grid point sees the same draws (common random numbers). Inputs not on a
dimension are fixed (``fixed``) or left at their defaults (``inputs.INPUTS``).

The cases are cut into chunks: regular blocks of the N-d case array (``Layout``), of about
``chunk_size`` cases, one value of every category input per block. A chunk is the unit of work,
of Zarr storage and of resumption; chunk ``k`` is a pure function of the study and ``k``.
Study files are read by :mod:`impactlab.sweep.studyfile`.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.contact.registry import ensure_laws, law_records
from impactlab.sweep.dimensions import (
    Axis,
    Layout,
    Sample,
    Value,
    block_values,
    check_kinematics,
    check_value,
    layout,
)
from impactlab.sweep.display import study_html, study_repr
from impactlab.sweep.flexible import check_flexible_study
from impactlab.sweep.inputs import INPUTS, OUTPUT_ALIASES, get_input
from impactlab.sweep.limits import DEFAULT_MAX_CASES, check_max_cases, check_size
from impactlab.sweep.material_inputs import check_material_inputs
from impactlab.sweep.models import check_study_laws
from impactlab.sweep.options import (
    STUDY_FORMAT,
    EngineOptions,
    UncertaintySpec,
    default_chunk_size,
)
from impactlab.sweep.study_bodies import check_study_bodies
from impactlab.sweep.study_rules import check_law_params, check_study_rules
from impactlab.sweep.studyfile import read_study_file, study_arguments
from impactlab.units import is_quantity


def _listed(values: Any) -> Any:
    """The values of one grid axis as a tuple (one value or many); a set or a mapping is passed
    on as it is, for ``Axis`` to refuse (it has no order)."""
    if isinstance(values, set | frozenset | Mapping):
        return values
    return tuple(np.atleast_1d(np.asarray(values, dtype=object)).tolist())


def _axes(grid: Any) -> tuple[Axis, ...]:
    """Grid axes from a mapping input -> values, or a sequence of ``Axis`` / (name, values)."""
    if isinstance(grid, Mapping):
        return tuple(
            Axis(k, v if isinstance(v, str) or is_quantity(v) else _listed(v))
            for k, v in grid.items()
        )
    return tuple(a if isinstance(a, Axis) else Axis(*a) for a in grid)


def _check_sources(axes: Sequence[Axis], fixed: Mapping[str, Value], sample: Sample | None) -> None:
    """Every input is set at most once, every required input is set, something varies."""
    seen: dict[str, str] = {}
    sources = [("grid", a.name) for a in axes] + [("fixed", k) for k in fixed]
    if sample is not None:
        sources += [("sample", k) for k in sample.inputs]
    for where, name in sources:
        get_input(name)
        if name in seen:
            raise ValueError(f"input {name!r} is set twice (in {seen[name]} and {where})")
        seen[name] = where
    by_speed = [n for n in ("speed", "incidence") if n in seen]
    if by_speed:
        if len(by_speed) == 1:
            other = "incidence" if by_speed[0] == "speed" else "speed"
            raise ValueError(f"speed and incidence go together: {other} has no value")
        both = [n for n in ("vx", "vy") if n in seen]
        if both:
            raise ValueError(
                f"{', '.join(both)} and speed/incidence both set: they say the same thing; "
                "give (vx, vy) or speed and incidence"
            )
        seen["vy"] = "speed"  # vy = -speed cos(incidence)
    bodies = next((a.values for a in axes if a.name == "body"), (fixed.get("body", "rod"),))

    spheres = all(b == "sphere" for b in bodies)  # a sphere has no angle to the flat
    missing = [
        s.name
        for s in INPUTS.values()
        if s.required and s.name not in seen and not (spheres and s.name == "angle")
    ]
    if missing:
        raise ValueError(
            f"input(s) {missing} have no value: set them in [fixed], [grid] or [sample]"
        )
    if not axes and sample is None:
        raise ValueError(
            "a study needs a [grid] or a [sample] (for a single impact use `impactlab simulate`)"
        )


def _check_outputs(outputs: Sequence[str]) -> tuple[str, ...]:
    outs = tuple(OUTPUT_ALIASES.get(o, o) for o in outputs)
    if not outs:
        raise ValueError("outputs must not be empty (omit it to keep all outputs)")
    if len(set(outs)) != len(outs):
        raise ValueError(f"outputs lists a name twice: {list(outputs)}")
    return outs


#: A study name: letters, digits, '-', '_' and '.', not starting with '.' (it names files).
_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9._-]{0,199}")


def _check_name(name: Any) -> str:
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise ValueError(
            f"study name must be letters, digits, '-', '_' and '.' (not starting with '.'; no "
            f"spaces or path separators; at most 200 characters), got {name!r}"
        )
    return name


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
    laws : the user's laws (``impactlab.contact.register_law``) the study uses, name -> record;
        filled from the registry, and registered from it where the study runs (a worker
        process), so the law's data travel with the study and enter its hash.
    chunk_size : target number of cases per chunk (the unit of work, storage and resumption);
        None: ``options.default_chunk_size`` of what a case costs (``cases_per_chunk``).
    uncertainty : what ``impactlab sweep`` reports at the end of a Monte Carlo study.
    max_cases : the largest number of cases accepted (a bigger study is refused with an estimate
        of its time and disk); not part of the study hash.
    """

    name: str = "study"
    grid: Any = ()
    sample: Sample | None = None
    fixed: Mapping[str, Value] = field(default_factory=dict)
    outputs: Sequence[str] | None = None
    engine: EngineOptions = field(default_factory=EngineOptions)
    law_params: Mapping[str, float] = field(default_factory=dict)
    laws: Mapping[str, Any] = field(default_factory=dict)
    chunk_size: int | None = None
    description: str = ""
    uncertainty: UncertaintySpec | None = None
    max_cases: int = DEFAULT_MAX_CASES

    def __post_init__(self) -> None:
        _check_name(self.name)
        object.__setattr__(self, "max_cases", check_max_cases(self.max_cases))
        axes = _axes(self.grid)
        object.__setattr__(self, "grid", axes)
        fixed = {k: check_value(k, v) for k, v in dict(self.fixed).items()}
        object.__setattr__(self, "fixed", fixed)
        if self.sample is not None and not isinstance(self.sample, Sample):
            raise ValueError(f"sample must be a Sample, got {self.sample!r}")
        _check_sources(axes, fixed, self.sample)
        varied = [a.name for a in axes] + ([] if self.sample is None else list(self.sample.inputs))
        categories = {a.name: a.values for a in axes if a.is_category}
        categories.update({k: (v,) for k, v in fixed.items() if isinstance(v, str)})
        fixed = check_material_inputs(fixed, varied, categories)
        object.__setattr__(self, "fixed", fixed)
        check_kinematics(fixed, axes, () if self.sample is None else tuple(self.sample.inputs))
        if self.outputs is not None:
            object.__setattr__(self, "outputs", _check_outputs(self.outputs))
        if not isinstance(self.engine, EngineOptions):
            raise ValueError(f"engine must be EngineOptions, got {self.engine!r}")
        check_flexible_study(
            {"fixed": fixed, "grid": axes, "sample": self.sample, "engine": self.engine}
        )
        check_study_rules(fixed, axes, self.sample)  # bodies' inputs, sampled values
        if not isinstance(self.laws, Mapping):
            raise ValueError(f"laws must be a mapping of law names to records, got {self.laws!r}")
        ensure_laws(self.laws)
        laws = next((a.values for a in axes if a.name == "law"), (self.value_of("law"),))
        object.__setattr__(self, "laws", law_records(laws))
        object.__setattr__(self, "law_params", check_law_params(self.law_params, laws))
        sampled = () if self.sample is None else tuple(self.sample.inputs)
        check_study_bodies(fixed, axes, sampled)  # every case refused: say so
        check_study_laws(fixed, axes, sampled, self.law_params)
        size = self.chunk_size
        if size is not None and (isinstance(size, bool) or not isinstance(size, int) or size < 1):
            raise ValueError(f"chunk_size must be an integer >= 1, got {size!r}")
        if self.uncertainty is not None and self.sample is None:
            raise ValueError("an [uncertainty] report needs a [sample]")
        check_size(self, default_chunk_size(self))  # max_cases; tiny chunks warn

    def __repr__(self) -> str:
        return study_repr(self)

    def _repr_html_(self) -> str:
        return study_html(self)

    # -- structure -----------------------------------------------------------------------------

    @property
    def axes(self) -> tuple[Axis, ...]:
        return tuple(self.grid)

    @property
    def cases_per_chunk(self) -> int:
        """Target cases per chunk: ``chunk_size``, or, unset, the default for what a case
        costs (``options.default_chunk_size``: a few seconds of one core per chunk)."""
        return self.chunk_size or default_chunk_size(self)

    @cached_property
    def layout(self) -> Layout:
        return layout(self.axes, self.sample, self.cases_per_chunk)

    @property
    def n_cases(self) -> int:
        return self.layout.n_cases

    @property
    def mode(self) -> str:
        """ "grid", "sample" or "grid+sample"."""
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

    def chunk_cases(
        self, index: int
    ) -> tuple[dict[str, np.ndarray], dict[str, str], tuple[int, ...]]:
        """The cases of chunk ``index``: (numeric input -> 1-D float64 array, category input ->
        its single value, block shape). Unset numeric inputs with a preset default are NaN."""
        block = self.layout.block(index)
        bshape = tuple(s.stop - s.start for s in block)
        n = int(np.prod(bshape, dtype=np.int64))
        numeric, categories = block_values(self.axes, self.sample, block)
        for spec in INPUTS.values():
            if spec.name in numeric or spec.name in categories:
                continue
            v = self.value_of(spec.name)
            if spec.kind == "category":
                categories[spec.name] = str(v)
            else:
                numeric[spec.name] = np.full(n, math.nan if v is None else float(v))
        if not np.isnan(numeric["speed"]).all():  # speed and incidence: (vx, vy)
            speed, incidence = numeric["speed"], numeric["incidence"]
            numeric["vx"] = speed * np.sin(incidence)
            numeric["vy"] = -speed * np.cos(incidence)
        if categories.get("body") == "sphere" and np.isnan(numeric["angle"]).all():
            numeric["angle"] = np.full(n, 0.5 * math.pi)  # a sphere's angle plays no part
        return numeric, categories, bshape

    # -- canonical form, hash ------------------------------------------------------------------

    def to_dict(self) -> dict[str, Any]:
        """Canonical description (SI values, ``units = "si"``): the study hash is computed from
        it and ``Study.from_dict`` reads it back."""
        d: dict[str, Any] = {
            "format": STUDY_FORMAT,
            "study": {
                "name": self.name,
                "description": self.description,
                "chunk_size": self.cases_per_chunk,
                "units": "si",
                **({"max_cases": self.max_cases} if self.max_cases != DEFAULT_MAX_CASES else {}),
            },
            "fixed": dict(self.fixed),
            "grid": {a.name: list(a.values) for a in self.axes},
            "engine": {k: v for k, v in self.engine.to_dict().items() if v is not None},
            "law_params": dict(self.law_params),
        }
        if self.laws:  # only then: the hash of a study of built-in laws stays as it was
            d["laws"] = {k: dict(v) for k, v in self.laws.items()}
        # the dimension order is meaningful: keep it explicit (JSON objects are sorted)
        d["grid_order"] = [a.name for a in self.axes]
        if self.sample is not None:
            d["sample"] = {
                "size": self.sample.size,
                "seed": self.sample.seed,
                **{k: v.to_dict() for k, v in self.sample.inputs.items()},
            }
        if self.outputs is not None:
            d["outputs"] = {"keep": list(self.outputs)}
        if self.uncertainty is not None:
            d["uncertainty"] = {
                "outputs": list(self.uncertainty.outputs),
                "percentiles": list(self.uncertainty.percentiles),
            }
        return d

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), sort_keys=True, separators=(",", ":"))

    def hash(self, extra: str = "") -> str:
        """SHA-256 (hex, 16 digits) of the canonical study (plus ``extra``: the engine identity).

        Neither the description nor ``max_cases`` is part of the hash (they change no result).
        """
        d = self.to_dict()
        d["study"].pop("description", None)
        d["study"].pop("max_cases", None)
        text = json.dumps(d, sort_keys=True, separators=(",", ":")) + extra
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    @classmethod
    def from_dict(
        cls, data: Mapping[str, Any], *, source: str = "study", max_cases: int | None = None
    ) -> Study:
        """Build a study from a study-file table (see docs/sweep.md) or ``to_dict()`` output;
        ``max_cases`` overrides the table's."""
        return cls(**study_arguments(data, source, max_cases))

    @classmethod
    def from_toml(cls, path: str | Path, *, max_cases: int | None = None) -> Study:
        """Read a study file (TOML); ``max_cases`` overrides the file's."""
        data, source = read_study_file(path)
        return cls(**study_arguments(data, source, max_cases))

    def register_laws(self) -> None:
        """Register the study's own laws (``laws``) in this process, where they are not yet
        (a pool or Dask worker)."""
        ensure_laws(self.laws)


def load_study(
    source: str | Path | Mapping[str, Any] | Study, *, max_cases: int | None = None
) -> Study:
    """A ``Study`` from a study file path, a parsed table, or a ``Study`` (returned as is);
    ``max_cases`` (when given) replaces the study's limit on its number of cases."""
    if isinstance(source, Study):
        if max_cases is None or max_cases == source.max_cases:
            return source
        return dataclasses.replace(source, max_cases=max_cases)
    if isinstance(source, Mapping):
        return Study.from_dict(source, max_cases=max_cases)
    return Study.from_toml(source, max_cases=max_cases)
