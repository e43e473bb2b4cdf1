"""The dimensions of a study's case array: grid axes, the Monte Carlo sample, and the regular
chunk layout over them.

A study has named dimensions: one per grid axis (in the order given), then ``sample`` when a
Monte Carlo sample is drawn. The cases are cut into chunks: regular blocks of the N-d case array
(:class:`Layout`), of about ``chunk_size`` cases, one value of every category input per block.

Invalid inputs are refused when a study is made, naming the dimension, the offending values
and what is allowed (the rules of a single impact: ``impactlab.materials.Material``,
``impactlab.bodies``, the bounds of ``impactlab.dynamics.kernels.inputs``): a value outside
:data:`ALLOWED` on a grid axis or in ``fixed`` (:func:`check_value`, :class:`Axis`; the rules of
a value on its own are in :mod:`~impactlab.sweep.value_rules`), and, for the study as a whole,
an angle outside (0, 90] deg for a rod and a centre-of-mass velocity vy >= 0 that no spin can
turn into an approach (:func:`check_kinematics`). What only a combination of inputs makes
invalid (S_y >= E, a tip wider than half the rod, a spin too fast for the body's reach, ...)
and sampled values are checked case by case and stored as a status code, like cases that fail
physically (no separation, ...).
"""

from __future__ import annotations

from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab.dynamics.input_checks import warn_fast
from impactlab.sweep.distributions import Distribution
from impactlab.sweep.inputs import get_input
from impactlab.sweep.magnitudes import check_magnitudes

# the rules of a value on its own, imported from here too (``sweep.dimensions.ALLOWED``)
from impactlab.sweep.value_rules import ALLOWED as ALLOWED
from impactlab.sweep.value_rules import ANGLE as ANGLE
from impactlab.sweep.value_rules import Interval as Interval
from impactlab.sweep.value_rules import (
    Value,
    check_allowed,
    check_rod_angles,
    input_value,
    is_number,
    looks_like_degrees,
    refuse,
)
from impactlab.sweep.value_rules import check_value as check_value
from impactlab.sweep.value_rules import inside as inside
from impactlab.sweep.value_rules import rule_text as rule_text
from impactlab.sweep.value_rules import shown_values as shown_values
from impactlab.units import is_quantity, magnitude

#: Name of the Monte Carlo dimension (reserved: no input has this name).
SAMPLE_DIM = "sample"


def is_category(name: str) -> bool:
    """True when input ``name`` takes names (one value per engine call)."""
    return get_input(name).kind == "category"


#: Inputs of a rod that a sphere does not have (refused in a study of spheres only).
_ROD_ONLY = ("angle", "length", "tip_radius", "inertia")
#: Bodies that have an angle to the flat (a sphere's is ignored).
_ANGLED_BODIES = ("rod", "flexible_rod")


def check_kinematics(
    fixed: Mapping[str, Value], axes: Sequence[Axis], sampled: Collection[str] = ()
) -> None:
    """The study-level input rules: the angle of a rod in (0, 90] deg (unless every body is a
    sphere), and vy < 0 when the spin is zero and not varied (the contact point must approach
    the flat, as ``impactlab.simulate`` requires). ``sampled``: the inputs of the study's
    sample (their values are checked case by case). ValueError naming the dimension and the
    offending values."""
    grid = {a.name: a.values for a in axes}

    def values(name: str) -> tuple[Any, ...]:
        if name in grid:
            return grid[name]
        return (fixed[name],) if name in fixed else (get_input(name).default,)

    def where(name: str) -> str:
        return f"grid dimension {name!r}" if name in grid else f"input {name!r}"

    bodies = {str(b) for b in values("body")}
    if bodies == {"sphere"}:  # what does not apply to a sphere is refused, as everywhere
        given = [n for n in _ROD_ONLY if n in grid or n in fixed or n in sampled]
        if given:
            raise ValueError(
                f"{', '.join(given)}: a sphere has no angle, length, tip radius or inertia "
                "(radius and mass or density); leave them out, or study a rod"
            )
    if "sphere" not in bodies and any("radius" in g for g in (grid, fixed, sampled)):
        raise ValueError(
            "radius: the radius of a sphere, and no body of this study is one; a rod's tip "
            "radius is tip_radius"
        )
    angles = [float(v) for v in values("angle") if isinstance(v, float)]
    if bodies & set(_ANGLED_BODIES):
        check_rod_angles(angles, where("angle"), " for a rod" if "sphere" in bodies else "")
    spin_zero = "spin" not in (*grid, *sampled) and float(fixed.get("spin", 0.0)) == 0.0
    if spin_zero and "vy" in (*grid, *fixed):
        vy = [float(v) for v in values("vy")]
        rule = "the contact point must approach the flat (vy < 0 m/s with spin = 0)"
        refuse(where("vy"), "vy", vy, [v for v in vy if not v < 0.0], rule)
    speeds = [abs(float(v)) for n in ("vx", "vy", "speed") for v in values(n) if is_number(v)]
    if speeds:  # the warning a single impact gives (sampled values: case by case)
        warn_fast("the largest grid or fixed speed of the study", max(speeds))


@dataclass(frozen=True)
class Axis:
    """One grid dimension: an input and its values (SI floats, or names for a category)."""

    name: str
    values: tuple[Value, ...]

    def __post_init__(self) -> None:
        get_input(self.name)
        if self.name == SAMPLE_DIM:
            raise ValueError(f"{SAMPLE_DIM!r} is reserved")
        values: Any = self.values
        pint = is_quantity(values)
        if pint and not self.is_category:  # a pint array: to SI, then numbers
            unit = get_input(self.name).unit
            values = np.atleast_1d(magnitude(f"grid axis {self.name!r}", values, unit))
        if isinstance(values, set | frozenset | Mapping):
            raise ValueError(
                f"grid axis {self.name!r} must be a list of values, in order, got a "
                f"{type(values).__name__}: {values!r}"
            )
        if not isinstance(values, str) and _nested(values):
            raise ValueError(
                f"grid axis {self.name!r} must be a list of values (one dimension), got {values!r}"
            )
        raw = np.asarray(values, dtype=object).tolist() if not isinstance(values, str) else [values]
        vals = tuple(input_value(self.name, v) for v in raw)
        if not vals:
            raise ValueError(f"grid axis {self.name!r} has no values")
        numbers = [v for v in vals if isinstance(v, float)]
        if self.name == "angle" and not pint and any(map(looks_like_degrees, raw)):
            check_rod_angles(numbers, f"grid dimension {self.name!r}", bare=raw)
        check_allowed(self.name, numbers, f"grid dimension {self.name!r}")
        check_magnitudes(self.name, numbers, f"grid dimension {self.name!r}")
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
        for what, n, least in (("size", self.size, 1), ("seed", self.seed, 0)):
            if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < least:
                raise ValueError(f"sample {what} must be an integer >= {least}, got {n!r}")
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


def _nested(values: Any) -> bool:
    """Whether ``values`` holds lists or arrays (a 2-D array, a list of lists): not one axis."""
    if isinstance(values, np.ndarray):
        return values.ndim > 1
    return isinstance(values, list | tuple) and any(
        isinstance(v, list | tuple | np.ndarray) for v in values
    )
