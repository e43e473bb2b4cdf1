"""The dimensions of a study's case array: grid axes, the Monte Carlo sample, and the regular
chunk layout over them.

A study has named dimensions: one per grid axis (in the order given), then ``sample`` when a
Monte Carlo sample is drawn. The cases are cut into chunks: regular blocks of the N-d case array
(:class:`Layout`), of about ``chunk_size`` cases, one value of every category input per block.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab.sweep.distributions import Distribution
from impactlab.sweep.inputs import get_input

#: Name of the Monte Carlo dimension (reserved: no input has this name).
SAMPLE_DIM = "sample"

#: A fixed or axis value: SI float or a category name.
Value = float | str


def is_category(name: str) -> bool:
    """True when input ``name`` takes names (one value per engine call)."""
    return get_input(name).kind == "category"


def check_value(name: str, value: Any) -> Value:
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
        vals = (
            tuple(check_value(self.name, v) for v in np.asarray(self.values).tolist())
            if not isinstance(self.values, str)
            else (check_value(self.name, self.values),)
        )
        if not vals:
            raise ValueError(f"grid axis {self.name!r} has no values")
        if len(set(vals)) != len(vals):
            raise ValueError(f"grid axis {self.name!r} has repeated values")
        object.__setattr__(self, "values", vals)

    @property
    def is_category(self) -> bool:
        return is_category(self.name)

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
        if (
            isinstance(self.size, bool)
            or not isinstance(self.size, int | np.integer)
            or self.size < 1
        ):
            raise ValueError(f"sample size must be an integer >= 1, got {self.size!r}")
        if (
            isinstance(self.seed, bool)
            or not isinstance(self.seed, int | np.integer)
            or self.seed < 0
        ):
            raise ValueError(f"sample seed must be an integer >= 0, got {self.seed!r}")
        if not self.inputs:
            raise ValueError("a sample needs at least one input with a distribution")
        for name, dist in self.inputs.items():
            if is_category(name):
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


def layout(axes: Sequence[Axis], sample: Sample | None, chunk_size: int) -> Layout:
    """The layout of the case array of ``axes`` (then ``sample``) in chunks of ~``chunk_size``."""
    dims = tuple(a.name for a in axes)
    shape = tuple(len(a.values) for a in axes)
    category = [a.is_category for a in axes]
    if sample is not None:
        dims += (SAMPLE_DIM,)
        shape += (sample.size,)
        category.append(False)
    return Layout(dims, shape, chunk_shape(shape, category, chunk_size))


def block_values(
    axes: Sequence[Axis], sample: Sample | None, block: tuple[slice, ...]
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """The varying inputs over one block: (numeric input -> 1-D float64 array over the block's
    cases in C order, category axis -> its single value in the block)."""
    bshape = tuple(s.stop - s.start for s in block)
    numeric: dict[str, np.ndarray] = {}
    categories: dict[str, str] = {}
    for j, axis in enumerate(axes):
        vals = axis.array()[block[j]]
        if axis.is_category:
            categories[axis.name] = str(vals[0])
            continue
        shp = [1] * len(bshape)
        shp[j] = bshape[j]
        numeric[axis.name] = np.broadcast_to(vals.reshape(shp), bshape).ravel()
    if sample is not None:
        sl = block[-1]
        shp = [1] * len(bshape)
        shp[-1] = bshape[-1]
        for name in sample.inputs:
            vals = sample.draw(name, sl.start, sl.stop)
            numeric[name] = np.broadcast_to(vals.reshape(shp), bshape).ravel()
    return numeric, categories
