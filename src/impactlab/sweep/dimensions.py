"""The dimensions of a study's case array: grid axes, the Monte Carlo sample, and the regular
chunk layout over them.

A study has named dimensions: one per grid axis (in the order given), then ``sample`` when a
Monte Carlo sample is drawn. The cases are cut into chunks: regular blocks of the N-d case array
(:class:`Layout`), of about ``chunk_size`` cases, one value of every category input per block.

Invalid inputs are refused when a study is made, naming the dimension, the offending values
and what is allowed (the rules of a single impact: ``impactlab.materials.Material``,
``impactlab.bodies``, the bounds of ``impactlab.dynamics.kernels.inputs``): a value outside
:data:`ALLOWED` on a grid axis or in ``fixed`` (:func:`check_value`, :class:`Axis`), and, for
the study as a whole, an angle outside (0, 90] deg for a rod and a centre-of-mass velocity
vy >= 0 that no spin can turn into an approach (:func:`check_kinematics`). What only a
combination of inputs makes invalid (S_y >= E, a tip wider than half the rod, a spin too fast
for the body's reach, ...) and sampled values are checked case by case and stored as a status
code, like cases that fail physically (no separation, ...).
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.dynamics.input_checks import PAST_NORMAL, degrees_hint, warn_fast
from impactlab.dynamics.kernels.inputs import MAX_ANGLE, MAX_MU, MAX_SPEED
from impactlab.sweep.distributions import Distribution
from impactlab.sweep.inputs import MATERIAL_OVERRIDES, get_input
from impactlab.sweep.magnitudes import check_magnitudes
from impactlab.units import angle_to_rad, is_quantity, magnitude

#: Name of the Monte Carlo dimension (reserved: no input has this name).
SAMPLE_DIM = "sample"

#: A fixed or axis value: SI float or a category name.
Value = float | str


def is_category(name: str) -> bool:
    """True when input ``name`` takes names (one value per engine call)."""
    return get_input(name).kind == "category"


#: An allowed interval: (low, high, low inclusive, high inclusive, integers only).
Interval = tuple[float, float, bool, bool, bool]
_POSITIVE: Interval = (0.0, math.inf, False, True, False)
_COUNT: Interval = (0.0, math.inf, True, True, True)

#: The values a numeric input may take on its own (SI), as the single impact requires them;
#: inputs not named here take any finite number.
ALLOWED: dict[str, Interval] = {
    "mu": (0.0, MAX_MU, True, True, False),
    "speed": (0.0, MAX_SPEED, False, True, False),
    "vx": (-MAX_SPEED, MAX_SPEED, True, True, False),
    "vy": (-MAX_SPEED, MAX_SPEED, True, True, False),
    "incidence": (-0.5 * math.pi, 0.5 * math.pi, False, False, False),
    **{n: _POSITIVE for n in ("length", "tip_radius", "radius", "mass", "inertia")},
    "n_axial": _COUNT,
    "n_bending": _COUNT,
    "damping": (0.0, 1.0, True, False, False),
    **{
        name: {
            "nu": (-1.0, 0.5, False, False, False),
            "meyer_index": (2.0, 3.0, False, True, False),
        }.get(field, _POSITIVE)
        for side in MATERIAL_OVERRIDES.values()
        for name, field in side.items()
    },
}
#: The angle of a rod (rigid or flexible) to the flat [rad]: (0, pi/2] (``MAX_ANGLE``: +1e-12
#: for 90 deg converted from degrees).
ANGLE: Interval = (0.0, MAX_ANGLE, False, True, False)
#: Inputs of a rod that a sphere does not have (refused in a study of spheres only).
_ROD_ONLY = ("angle", "length", "tip_radius", "inertia")
#: Bodies that have an angle to the flat (a sphere's is ignored).
_ANGLED_BODIES = ("rod", "flexible_rod")


def inside(x: float, rule: Interval) -> bool:
    """True when ``x`` lies in the interval ``rule`` (and is an integer where it must be)."""
    lo, hi, lo_in, hi_in, integer = rule
    return (
        (x >= lo if lo_in else x > lo)
        and (x <= hi if hi_in else x < hi)
        and (not integer or x == math.floor(x))
    )


def shown_values(name: str, values: Sequence[float]) -> tuple[list[str], str]:
    """``values`` of input ``name`` as text in its display unit, and the unit ("" for none)."""
    spec = get_input(name)
    field = next((s[name] for s in MATERIAL_OVERRIDES.values() if name in s), name)
    d = display_unit(field, spec.unit)
    return [format_number(v * d.scale) for v in values], "" if d.unit == "-" else d.unit


def rule_text(name: str, rule: Interval) -> str:
    """``"mu must be >= 0"``, ``"angle must lie in (0, 90] deg"`` (bounds in display units)."""
    lo, hi, lo_in, hi_in, integer = rule
    (lo_t, hi_t), unit = shown_values(name, [lo, hi])
    u = f" {unit}" if unit else ""
    if integer:
        return f"{name} must be an integer >= {lo_t}"
    if math.isinf(hi):
        return f"{name} must be {'>=' if lo_in else '>'} {lo_t}{u}"
    return f"{name} must lie in {'[' if lo_in else '('}{lo_t}, {hi_t}{']' if hi_in else ')'}{u}"


def _refuse(
    where: str, name: str, values: Sequence[float], bad: Sequence[float], rule: str, note: str = ""
) -> None:
    """ValueError ``"<where>: <rule>, got <bad values> (k of n values)<note>"`` when ``bad`` is
    not empty (values in display units, at most four named)."""
    if not bad:
        return
    texts, unit = shown_values(name, list(bad[:4]))
    got = ", ".join(texts) + (", ..." if len(bad) > 4 else "")
    got += f" {unit}" if unit else ""
    count = f" ({len(bad)} of {len(values)} values)" if len(values) > 1 else ""
    raise ValueError(f"{where}: {rule}, got {got}{count}{note}")


def check_allowed(name: str, values: Sequence[float], where: str) -> None:
    """ValueError naming ``where``, the input, the offending values and the allowed interval
    unless every value of input ``name`` (SI) lies in :data:`ALLOWED`."""
    rule = ALLOWED.get(name)
    if rule is not None:
        _refuse(
            where, name, values, [v for v in values if not inside(v, rule)], rule_text(name, rule)
        )


def check_rod_angles(
    angles: Sequence[float], where: str, rule_suffix: str = "", bare: Sequence[Any] = ()
) -> None:
    """ValueError naming ``where``, the offending values and the interval unless every angle
    [rad] of a rod lies in :data:`ANGLE`, (0, 90] deg (``rule_suffix`` ends the rule's text);
    with ``simulate``'s degrees hint for the first of the ``bare`` angles that reads so."""
    rule = rule_text("angle", ANGLE) + rule_suffix
    bad = [a for a in angles if not inside(a, ANGLE)]
    past = any(0.5 * math.pi < a < math.pi for a in bad)  # as simulate says it of one angle
    note = (
        ": an angle past 90 deg leans the rod past the flat's normal, the mirror of a drop at "
        "180 deg - angle with vx (or incidence) and spin negated"
    ) * past
    th = next((float(a) for a in bare if _degrees(a)), None)
    if th is not None:  # as impactlab.dynamics.input_checks.check_angle says it
        note += degrees_hint(th)
    _refuse(where, "angle", angles, bad, rule, note)


def _degrees(angle: Any) -> bool:
    """A bare number (radians) in (pi/2 + 10 deg, 90]: degrees meant? (refused where given)"""
    return _is_number(angle) and 0.5 * math.pi + PAST_NORMAL < angle <= 90.0


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
        _refuse(where("vy"), "vy", vy, [v for v in vy if not v < 0.0], rule)
    speeds = [abs(float(v)) for n in ("vx", "vy", "speed") for v in values(n) if _is_number(v)]
    if speeds:  # the warning a single impact gives (sampled values: case by case)
        warn_fast("the largest grid or fixed speed of the study", max(speeds))


def _is_number(value: Any) -> bool:
    return isinstance(value, float | int) and not isinstance(value, bool) and math.isfinite(value)


def _number(name: str, value: Any) -> Value:
    """``value`` as a fixed or axis value of input ``name`` (SI float or a category string),
    without the :data:`ALLOWED` interval; a quantity (text with its unit, a pint Quantity of
    any registry) is converted to the input's SI unit, as everywhere in the Python API."""
    spec = get_input(name)
    if spec.kind == "category":
        if not isinstance(value, str) or not value:
            raise ValueError(f"input {name!r} takes a name (string), got {value!r}")
        return value
    if isinstance(value, str) and spec.unit == "rad":  # the angle rule's own message
        value = angle_to_rad(value, name=f"input {name!r}")
    elif isinstance(value, str) or is_quantity(value):
        value = magnitude(f"input {name!r}", value, spec.unit)
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise ValueError(f"input {name!r} must be a number in {spec.unit}, got {value!r}")
    x = float(value)
    if not math.isfinite(x):
        raise ValueError(f"input {name!r} must be finite, got {x!r}")
    return x


def check_value(name: str, value: Any) -> Value:
    """A fixed value for input ``name`` (SI float or a category string), inside
    :data:`ALLOWED`."""
    x = _number(name, value)
    if name == "angle" and isinstance(x, float) and _degrees(value):
        check_rod_angles([x], f"input {name!r}", bare=[value])
    if isinstance(x, float):
        check_allowed(name, [x], f"input {name!r}")
        check_magnitudes(name, [x], f"input {name!r}")
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
        values: Any = self.values
        pint = is_quantity(values)
        if pint and not self.is_category:  # a pint array: to SI, then numbers
            unit = get_input(self.name).unit
            values = np.atleast_1d(magnitude(f"grid axis {self.name!r}", values, unit))
        raw = np.asarray(values, dtype=object).tolist() if not isinstance(values, str) else [values]
        vals = tuple(_number(self.name, v) for v in raw)
        if not vals:
            raise ValueError(f"grid axis {self.name!r} has no values")
        numbers = [v for v in vals if isinstance(v, float)]
        if self.name == "angle" and not pint and any(map(_degrees, raw)):
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
