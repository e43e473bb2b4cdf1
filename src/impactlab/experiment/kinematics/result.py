"""The measured impact: :class:`ImpactKinematics` (estimates with uncertainties, diagnostics)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab._display import display_unit, field_row, html_table, text_table
from impactlab.experiment.kinematics.fits import SegmentFit, segment_data
from impactlab.experiment.kinematics.frame import G0
from impactlab.experiment.rigid import Poses, RigidityReport
from impactlab.experiment.uncertainty import Estimate

__all__ = ["ImpactKinematics"]


def _estimate_text(name: str, x: Estimate) -> str:
    """``angle_in=20.046 ± 0.041 deg``: an estimate in its display unit."""
    _, text, _ = field_row(name, x.value, x.unit, x.sigma)
    unit = display_unit(name, x.unit).unit
    return f"{name}={text}" + ("" if unit == "-" else f" {unit}")


@dataclass(frozen=True, repr=False)
class ImpactKinematics:
    """The measured impact (SI units; frame and signs in the package docstring).

    ``correlation``: correlation matrix of the derived quantities (names in
    ``derived_names``). Diagnostics: ``pre``/``post`` fits, ``rigidity``, ``fitted_gravity``
    [m/s^2], ``tilt_out_of_plane`` [rad], ``warnings``; ``ok`` False with ``doubts``.
    """

    t_impact: Estimate
    """The impact instant [s]: where the tip heights of the two fits cross."""
    angle_in: Estimate
    """Rod angle to the flat at the impact instant, from the fit before [rad]."""
    angle_out: Estimate
    """The same from the fit after [rad]."""
    v_c_in: tuple[Estimate, Estimate]
    """(x, y) velocity of the centre of mass before [m/s]; ``v_c_out`` after."""
    v_c_out: tuple[Estimate, Estimate]
    spin_in: Estimate
    """Spin (counter-clockwise) before [rad/s]; ``spin_out`` after."""
    spin_out: Estimate
    v_tip_in: tuple[Estimate, Estimate]
    """(x, y) velocity of the contact point before [m/s]; ``v_tip_out`` after."""
    v_tip_out: tuple[Estimate, Estimate]
    e: Estimate
    """-v_tip,y,out / v_tip,y,in."""
    mu: Estimate
    """|dv_Cx / dv_Cy| (paper Eq. 28)."""
    dv_cx: Estimate
    """Change of the centre-of-mass velocity [m/s], x; ``dv_cy`` y."""
    dv_cy: Estimate
    v_c_z_in: Estimate
    """Out-of-plane centre-of-mass velocity before [m/s] (should be ~0); ``v_c_z_out`` after."""
    v_c_z_out: Estimate
    derived_names: tuple[str, ...]
    derived_values: np.ndarray = field(repr=False)
    derived_cov: np.ndarray = field(repr=False)
    pre: SegmentFit = field(repr=False)
    post: SegmentFit = field(repr=False)
    impact_frame: int = -1
    t_ref: float = 0.0
    gravity: float = G0
    half_length: float = 0.0
    tip_radius: float = 0.0
    frame_axes: np.ndarray = field(default_factory=lambda: np.eye(3), repr=False)
    origin: np.ndarray = field(default_factory=lambda: np.zeros(3), repr=False)
    com_body: np.ndarray = field(default_factory=lambda: np.zeros(3), repr=False)
    axis_body: np.ndarray = field(default_factory=lambda: np.array([1.0, 0, 0]), repr=False)
    geometry_source: str = "given"
    rigidity: RigidityReport | None = field(default=None, repr=False)
    fitted_gravity: float | None = None
    tilt_out_of_plane: float = 0.0
    poses: Poses | None = field(default=None, repr=False)
    warnings: tuple[str, ...] = ()
    doubts: tuple[str, ...] = ()
    """What makes the result not ok (each one of the ``warnings`` too): an estimated marker
    geometry that the impulse relation finds tilted, or cannot check."""

    @property
    def ok(self) -> bool:
        """False when something makes the result doubtful (``doubts``)."""
        return not self.doubts

    def __repr__(self) -> str:
        """One line: e, mu, the angle, v_i and the impact instant with their sigma in display
        units (deg, ms), ok, and the number of warnings (``str``: the whole table)."""
        shown = [("e", self.e), ("mu", self.mu), ("angle_in", self.angle_in)]
        shown += [("v_i", self.v_i), ("t_impact", self.t_impact)]
        parts = [_estimate_text(n, x) for n, x in shown]
        parts.append(f"ok={self.ok}")
        if self.warnings:
            parts.append(f"{len(self.warnings)} warning" + "s" * (len(self.warnings) > 1))
        return f"ImpactKinematics({', '.join(parts)})"

    def __str__(self) -> str:
        return text_table("ImpactKinematics", self._rows())

    def _repr_html_(self) -> str:
        return html_table("ImpactKinematics", self._rows())

    def _rows(self) -> list[tuple[str, str, str]]:
        """(name, value, unit) rows: every estimate in display units, then the diagnostics."""
        estimates: list[tuple[str, Estimate]] = [
            ("t_impact", self.t_impact),
            ("angle_in", self.angle_in),
            ("angle_out", self.angle_out),
        ]
        for name, (x, y) in (("v_c", self.v_c_in), ("v_tip", self.v_tip_in)):
            estimates += [(f"{name}_x_in", x), (f"{name}_y_in", y)]
        for name, (x, y) in (("v_c", self.v_c_out), ("v_tip", self.v_tip_out)):
            estimates += [(f"{name}_x_out", x), (f"{name}_y_out", y)]
        estimates += [("spin_in", self.spin_in), ("spin_out", self.spin_out), ("e", self.e)]
        estimates += [("mu", self.mu), ("dv_cx", self.dv_cx), ("dv_cy", self.dv_cy)]
        estimates += [("v_c_z_in", self.v_c_z_in), ("v_c_z_out", self.v_c_z_out)]
        rows = [field_row(n, x.value, x.unit, x.sigma) for n, x in estimates]
        rows += [
            ("impact_frame", str(self.impact_frame), ""),
            ("frames before / after", f"{self.pre.n} / {self.post.n}", ""),
            ("geometry", self.geometry_source, ""),
            field_row("fitted_gravity", self.fitted_gravity, "m/s^2"),
            field_row("tilt_out_of_plane", self.tilt_out_of_plane, "rad"),
            ("ok", "yes" if self.ok else "no", ""),
        ]
        rows += [("doubt", d, "") for d in self.doubts]
        return rows + [("warning", w, "") for w in self.warnings if w not in self.doubts]

    @property
    def v_i(self) -> Estimate:
        """Normal (vertical) tip velocity before the impact [m/s] (negative: downwards)."""
        return self.v_tip_in[1]

    @property
    def correlation(self) -> np.ndarray:
        s = np.sqrt(np.clip(np.diag(self.derived_cov), 0, None))
        with np.errstate(invalid="ignore", divide="ignore"):
            c = self.derived_cov / np.outer(s, s)
        return np.nan_to_num(c)

    def series(self) -> tuple[np.ndarray, np.ndarray]:
        """All frames with a pose: (time [s], (n, 4) X, Y, Z of C [m] and the rod angle [rad])
        in the impact frame (NaN where no pose)."""
        if self.poses is None:
            return np.zeros(0), np.zeros((0, 4))
        fr = np.flatnonzero(self.poses.ok)
        data = segment_data(
            self.poses, fr, self.com_body, self.axis_body, self.frame_axes, self.origin
        )
        return self.poses.time[fr], data

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready summary (SI units: angles in rad)."""

        def est(x: Estimate) -> dict[str, Any]:
            return x.to_dict()

        d: dict[str, Any] = {
            "t_impact": est(self.t_impact),
            "angle_in": est(self.angle_in),
            "angle_out": est(self.angle_out),
            "v_c_in": [est(v) for v in self.v_c_in],
            "v_c_out": [est(v) for v in self.v_c_out],
            "spin_in": est(self.spin_in),
            "spin_out": est(self.spin_out),
            "v_tip_in": [est(v) for v in self.v_tip_in],
            "v_tip_out": [est(v) for v in self.v_tip_out],
            "v_i": est(self.v_i),
            "e": est(self.e),
            "mu": est(self.mu),
            "dv_cx": est(self.dv_cx),
            "dv_cy": est(self.dv_cy),
            "v_c_z_in": est(self.v_c_z_in),
            "v_c_z_out": est(self.v_c_z_out),
            "impact_frame": self.impact_frame,
            "frames_before": self.pre.n,
            "frames_after": self.post.n,
            "fit_rms_before": {
                "X_m": self.pre.rms[0],
                "Y_m": self.pre.rms[1],
                "Z_m": self.pre.rms[2],
                "angle_rad": self.pre.rms[3],
            },
            "fit_rms_after": {
                "X_m": self.post.rms[0],
                "Y_m": self.post.rms[1],
                "Z_m": self.post.rms[2],
                "angle_rad": self.post.rms[3],
            },
            "geometry": self.geometry_source,
            "fitted_gravity": self.fitted_gravity,
            "tilt_out_of_plane": {"value": self.tilt_out_of_plane, "unit": "rad"},
            "ok": self.ok,
            "doubts": list(self.doubts),
            "warnings": list(self.warnings),
        }
        if self.rigidity is not None:
            d["rigidity"] = self.rigidity.to_dict()
        return d
