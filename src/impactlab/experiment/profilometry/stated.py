"""A pixel size or height unit given as an argument and stated in the scan file must agree.

A value the file states is the file's: ``pixel_size=`` (``--pixel-size``) and ``height_unit=``
(``--height-unit``) supply what a file lacks, and where the file states it they can only confirm
it. A disagreement is refused with one line naming the option, the file's value and the given one
(a wrong option would otherwise scale L_s or delta_p silently); an agreeing value passes.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers import length_factor
from impactlab.experiment.profilometry.heightmap import pixel_pair

__all__ = ["PIXEL_TOLERANCE", "check_height_unit", "check_pixel_size"]

#: A given pixel size agrees with the file's when both sizes differ by less than this fraction
#: (a header rounds: '8 um' for 7.9985 um).
PIXEL_TOLERANCE = 0.01


def _um(x: float) -> str:
    return f"{x * 1e6:.6g} um"


def check_pixel_size(p: Path, given: Any, stated: tuple[float, float], where: str) -> None:
    """FileFormatError when the pixel size ``given`` (as the caller gave it) differs from the
    file's (dx, dy) [m] ``stated`` (``where``: how the file states it) by ``PIXEL_TOLERANCE``
    or more; an unreadable ``given`` is named too."""
    try:
        dx, dy = pixel_pair(given)
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    pairs = zip((dx, dy), stated, strict=True)
    if all(math.isclose(a, b, rel_tol=PIXEL_TOLERANCE) for a, b in pairs):
        return
    file_text = _um(stated[0]) if stated[0] == stated[1] else f"{_um(stated[0])} x {_um(stated[1])}"
    raise FileFormatError(
        p,
        f"pixel_size {given!r} (--pixel-size) disagrees with the file's pixel size {file_text} "
        f"({where}): leave the option out (the file's own value is used) or correct it",
    )


def check_height_unit(p: Path, given: str, stated: float, stated_text: str, where: str) -> None:
    """FileFormatError when the height unit ``given`` is not the file's (``stated`` metres per
    unit, written ``stated_text``; ``where``: how the file states it)."""
    try:
        factor = length_factor(given, name="height_unit")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    if math.isclose(factor, stated, rel_tol=1e-9):
        return
    raise FileFormatError(
        p,
        f"height_unit {given!r} (--height-unit) disagrees with the file's height unit "
        f"{stated_text!r} ({where}): leave the option out (the file's own unit is used) or "
        "correct it",
    )
