"""The dent metrics measured on a scan (:class:`DentMetrics`, SI units)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import PurePath
from typing import Any

import numpy as np

from impactlab._display import display_unit, field_row, html_table, text_table
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.uncertainty import Estimate

__all__ = ["LS_SCALE", "DentMetrics", "sliding_length_note", "unmeasured_notes"]

#: L_s is not measured when its uncertainty exceeds this fraction of the width (as well as its
#: magnitude): L_s near 0 (a round dent, no sliding) is a measurement when its +- is small.
LS_SCALE = 0.1


def _value_text(name: str, value: float, si_unit: str, sigma: float | None = None) -> str:
    """``22.016 ± 0.027 um``: a value in its display unit."""
    _, text, _ = field_row(name, value, si_unit, sigma)
    unit = display_unit(name, si_unit).unit
    return text + ("" if unit == "-" else f" {unit}")


def unmeasured_notes(**estimates: tuple[float, float]) -> list[str]:
    """A warning for each length (name -> (value, standard uncertainty) [m]) whose uncertainty
    exceeds its magnitude: not measured, whatever the value says."""
    return [
        f"{name} = {value * 1e6:.4g} um has an uncertainty of {sigma * 1e6:.3g} um, larger "
        "than itself: it is not measured (an outline's crossing on a flat profile, a dent at "
        "the noise); check the scan and its dent plot"
        for name, (value, sigma) in estimates.items()
        if sigma > abs(value)
    ]


def sliding_length_note(value: float, sigma: float, width: float) -> list[str]:
    """The warning for L_s = ``value`` +- ``sigma`` [m] whose uncertainty exceeds both its
    magnitude and ``LS_SCALE`` x the ``width`` [m] (a round dent's L_s near 0, +- a few um, is
    measured: no sliding)."""
    if not (sigma > abs(value) and sigma > LS_SCALE * width):
        return []
    return [
        f"sliding_length = {value * 1e6:.4g} um has an uncertainty of {sigma * 1e6:.3g} um, "
        f"larger than itself and than {LS_SCALE:.0%} of the width ({width * 1e6:.4g} um): it is "
        "not measured (an outline's crossing on a flat profile, a dent at the noise); check the "
        "scan and its dent plot"
    ]


@dataclass(frozen=True, repr=False)
class DentMetrics:
    """The dent measured on a scan (SI; definitions in the package docstring). ``outline``
    (k, 2) [m]; ``edge_threshold``, ``noise`` [m]; ``plane``; ``dropout_fraction`` (whole scan)
    and ``filled_in_dent`` (fraction of the dent area interpolated); ``profile`` (s [m] along
    the axis from the deepest point, height [m]) and ``cross_profile`` (the same across it)."""

    delta_p: Estimate
    """Maximum depth below the levelled surface [m], a positive magnitude."""
    sliding_length: Estimate
    """L_s = length - width [m], a magnitude: >= 0 up to its uncertainty, not clipped."""
    length: Estimate
    """Largest Feret diameter of the deformed area [m]."""
    width: Estimate
    """Width at the deepest point [m], perpendicular to the sliding axis."""
    deepest: tuple[float, float]
    """(x, y) of the deepest point in the scan [m]."""
    axis: tuple[float, float]
    """Unit vector of the sliding axis (scan x, y; the outline's long principal axis), oriented
    along the sliding direction."""
    sliding_angle: float
    """Angle [rad] of the sliding direction from the scan's +x axis, in (-pi, pi]."""
    direction_ambiguous: bool
    """Both ends of the dent equally sharp (within 10 %): the direction is a guess."""
    end_sharpness: tuple[float, float]
    """80 %-to-20 % fall distance [m] at the start and at the end."""
    deepest_fraction: float
    """Position of the deepest point from the start, 0..1."""
    pileup: float
    """Height of the pile-up [m]; ``pileup_at`` its (x, y)."""
    pileup_at: tuple[float, float]
    outline: np.ndarray = field(repr=False)
    edge_threshold: float = 0.0
    noise: float = 0.0
    plane: tuple[float, float, float] = (0.0, 0.0, 0.0)
    dropout_fraction: float = 0.0
    filled_in_dent: float = 0.0
    profile: tuple[np.ndarray, np.ndarray] = field(default=(np.zeros(0), np.zeros(0)), repr=False)
    cross_profile: tuple[np.ndarray, np.ndarray] = field(
        default=(np.zeros(0), np.zeros(0)), repr=False
    )
    levelled: HeightMap | None = field(default=None, repr=False)
    source: str = ""
    warnings: tuple[str, ...] = ()

    def __repr__(self) -> str:
        """One line: the scan, delta_p, L_s, length and width with their sigma and the
        sliding angle in display units (um, mm, deg), and the number of warnings (``str``: the
        whole table)."""
        shown = [("delta_p", self.delta_p), ("sliding_length", self.sliding_length)]
        shown += [("length", self.length), ("width", self.width)]
        parts = [f"{n}={_value_text(n, x.value, x.unit, x.sigma)}" for n, x in shown]
        parts.append(f"sliding_angle={_value_text('sliding_angle', self.sliding_angle, 'rad')}")
        parts.append(f"pileup={_value_text('pileup', self.pileup, 'm')}")
        if self.warnings:
            parts.append(f"{len(self.warnings)} warning" + "s" * (len(self.warnings) > 1))
        where = f"{PurePath(self.source).name}: " if self.source else ""
        return f"DentMetrics({where}{', '.join(parts)})"

    def __str__(self) -> str:
        return text_table("DentMetrics", self._rows())

    def _repr_html_(self) -> str:
        return html_table("DentMetrics", self._rows())

    def _rows(self) -> list[tuple[str, str, str]]:
        """(name, value, unit) rows in display units, then the warnings."""
        rows = [
            field_row(n, x.value, x.unit, x.sigma)
            for n, x in (
                ("delta_p", self.delta_p),
                ("sliding_length", self.sliding_length),
                ("length", self.length),
                ("width", self.width),
            )
        ]
        rows += [
            field_row("sliding_angle", self.sliding_angle, "rad"),
            ("direction_ambiguous", "yes" if self.direction_ambiguous else "no", ""),
            field_row("deepest_fraction", self.deepest_fraction, "1"),
            field_row("pileup", self.pileup, "m"),
            ("noise", *field_row("pileup", self.noise, "m")[1:]),  # dent scale: um
            field_row("dropout_fraction", self.dropout_fraction, "1"),
            field_row("filled_in_dent", self.filled_in_dent, "1"),
            ("outline points", str(self.outline.shape[0]), ""),
            ("source", self.source or "-", ""),
        ]
        return rows + [("warning", w, "") for w in self.warnings]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready summary (SI)."""
        return {
            "delta_p": self.delta_p.to_dict(),
            "sliding_length": self.sliding_length.to_dict(),
            "length": self.length.to_dict(),
            "width": self.width.to_dict(),
            "deepest_xy_m": list(self.deepest),
            "sliding_axis": list(self.axis),
            "sliding_angle": {"value": self.sliding_angle, "unit": "rad"},
            "direction_ambiguous": self.direction_ambiguous,
            "end_fall_distance_m": {"start": self.end_sharpness[0], "end": self.end_sharpness[1]},
            "deepest_fraction": self.deepest_fraction,
            "pileup_height_m": self.pileup,
            "pileup_xy_m": list(self.pileup_at),
            "edge_threshold_m": self.edge_threshold,
            "noise_m": self.noise,
            "plane": list(self.plane),
            "dropout_fraction": self.dropout_fraction,
            "filled_in_dent": self.filled_in_dent,
            "outline_points": int(self.outline.shape[0]),
            "source": self.source,
            "warnings": list(self.warnings),
        }
