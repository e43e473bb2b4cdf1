"""A profilometer scan as a height map in SI units, and pixel sizes from user input."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import PurePath
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.units import to_si

__all__ = ["MAX_PIXEL_SIZE", "HeightMap", "pixel_pair"]


@dataclass(frozen=True, repr=False)
class HeightMap:
    """A height map: ``z`` (ny, nx) [m] (NaN = no data; row i is y = i dy, column j is x = j dx),
    pixel sizes ``dx``, ``dy`` [m], ``source`` (file), ``meta`` (reader information)."""

    z: np.ndarray
    dx: float
    dy: float
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        z = np.array(self.z, dtype=np.float64)
        where = f" ({self.source})" if self.source else ""
        if z.ndim != 2 or min(z.shape) < 8:
            raise ValueError(
                f"a height map must be 2D with at least 8 x 8 pixels, got shape {z.shape}{where}"
            )
        z[~np.isfinite(z)] = np.nan
        for name, v in (("dx", self.dx), ("dy", self.dy)):
            if not (math.isfinite(float(v)) and float(v) > 0):
                raise ValueError(f"{name} (pixel size) must be > 0 m, got {v!r}{where}")
        if np.isnan(z).all():
            raise ValueError(f"the height map has no valid data{where}")
        z.setflags(write=False)
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "dx", float(self.dx))
        object.__setattr__(self, "dy", float(self.dy))

    def __repr__(self) -> str:
        """One line: the file, pixels, pixel size, extent, height range and valid share
        (never the array)."""
        ny, nx = self.shape
        um, mm = display_unit("pileup", "m"), display_unit("length", "m")
        pixel = format_number(self.dx * um.scale, 4)
        if self.dy != self.dx:
            pixel += f" x {format_number(self.dy * um.scale, 4)}"
        z = self.z[self.valid]
        where = f"{PurePath(self.source).name}: " if self.source else ""
        return (
            f"HeightMap({where}{nx} x {ny} pixels (x by y) of {pixel} {um.unit} = "
            f"{format_number(nx * self.dx * mm.scale, 4)} x "
            f"{format_number(ny * self.dy * mm.scale, 4)} {mm.unit}, z "
            f"{format_number(float(z.min()) * um.scale, 4)} .. "
            f"{format_number(float(z.max()) * um.scale, 4)} {um.unit}, "
            f"{format_number(100 * z.size / self.z.size, 4)} % valid)"
        )

    @property
    def shape(self) -> tuple[int, int]:
        return (int(self.z.shape[0]), int(self.z.shape[1]))

    @property
    def valid(self) -> np.ndarray:
        return np.isfinite(self.z)

    def flipped(self) -> HeightMap:
        """The same scan the other way up (heights negated): for a file that stores depths as
        positive heights (``meta["flipped"]`` is then True)."""
        return HeightMap(-self.z, self.dx, self.dy, self.source, {**self.meta, "flipped": True})

    def coords(self) -> tuple[np.ndarray, np.ndarray]:
        """Pixel-centre coordinate grids (X, Y) [m]."""
        ny, nx = self.shape
        return np.meshgrid(np.arange(nx) * self.dx, np.arange(ny) * self.dy)


#: The largest pixel size [m] taken as a profilometer's: a drop's dent is a few mm long, and a
#: scan needs many pixels across it (a bare number is metres: "12" is a pixel of 12 m). Pixels
#: up to it that are still too large for the dent are left to ``check_dent`` (the pixel size).
MAX_PIXEL_SIZE = 1e-2

#: A number without a unit ("12", "0.5", "1e-6").
_BARE_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def _check_unambiguous(parts: list[Any], given: Any, name: str) -> None:
    """ValueError when one of two texts is a bare number and the other has a unit: a decimal
    comma ("12,5 um") or a unit left off; neither reading is safe."""
    texts = [p.strip() if isinstance(p, str) else None for p in parts]
    bare = [t is not None and bool(_BARE_NUMBER.match(t)) for t in texts]
    if None in texts or bare[0] == bare[1]:
        return
    a, b = texts
    assert a is not None and b is not None
    no_unit, with_unit = (a, b) if bare[0] else (b, a)
    fix = "give each size its unit, '12.5 um, 12.5 um' (x then y), or one size once, '12.5 um'"
    m = re.match(r"^(\d+)\s*([a-zA-Zµμ].*)$", b)
    if bare[0] and a.lstrip("+-").isdigit() and m is not None:
        unit = m.group(2).strip()
        one, pair = f"{a}.{m.group(1)} {unit}", f"{a} {unit}, {m.group(1)} {unit}"
        fix = (
            f"write '{one}' (a decimal point) for one size or '{one}, {one}' for x then y; or, "
            f"a unit left off, '{pair}' for x then y"
        )
    raise ValueError(
        f"{name} {given!r} is ambiguous: {no_unit!r} has no unit while {with_unit!r} has one "
        f"(a decimal comma, or a unit left off?): {fix}"
    )


def pixel_pair(pixel_size: Any, name: str = "pixel_size") -> tuple[float, float]:
    """(dx, dy) [m] from one pixel size or a (dx, dy) pair (quantity strings such as "2 um",
    metres for bare numbers; a pair also as one text, "2 um, 3 um": the command line's form).

    ValueError naming ``name`` for a pair of texts of which one has a unit and the other not
    ("12,5 um": a decimal comma), a size that is not > 0, or one above ``MAX_PIXEL_SIZE``."""
    given = pixel_size
    if isinstance(pixel_size, str) and not pixel_size.strip():
        raise ValueError(f"{name} is empty; write one length and its unit, e.g. '12.5 um'")
    if isinstance(pixel_size, str) and "," in pixel_size:
        pixel_size = [p.strip() for p in pixel_size.strip().strip("()[]").split(",")]
    if isinstance(pixel_size, tuple | list):
        if len(pixel_size) != 2:
            raise ValueError(f"{name} must be one size or (dx, dy), got {given!r}")
        _check_unambiguous(list(pixel_size), given, name)
        dx = to_si(pixel_size[0], "m", name=name)
        dy = to_si(pixel_size[1], "m", name=name)
    else:
        dx = dy = to_si(pixel_size, "m", name=name)
    if not (dx > 0 and dy > 0):
        raise ValueError(f"{name} must be > 0 (a length such as '2 um'), got {given!r}")
    if max(dx, dy) > MAX_PIXEL_SIZE:
        raise ValueError(
            f"{name} {given!r} is a pixel of {max(dx, dy):.4g} m, larger than "
            f"{MAX_PIXEL_SIZE * 1e2:g} cm: no profilometer scan of a dent has such pixels "
            "(a bare number is read in metres): give the unit, e.g. '12.5 um'"
        )
    return dx, dy
