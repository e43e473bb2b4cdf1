"""One call from the raw files to e, mu, delta_p, L_s, T and F: :func:`analyze`.

Stages (each one's failure is recorded and the others go on, so partial results are never lost):

1. ``markers``: read the marker file, measure the impact (:func:`measure_impact`);
2. ``scan``: read the scan, measure the dent (:func:`measure_dent`);
3. ``inversion``: T and F from both (``impactlab.analytic.invert``: paper Eq. 12 with the
   measured e, mu, v_i, angle, delta_p, L_s; F from Eq. 29 with the measured centre-of-mass
   velocity change);
4. ``model`` (optional, with ``flat``): the impact engine run with the measured initial state, for
   comparison (the paper's Tables 2-3);
5. ``figures`` and ``results.json`` in ``out_dir``.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from impactlab._json import jsonable
from impactlab.experiment.errors import ExperimentError
from impactlab.experiment.kinematics import ImpactKinematics, measure_impact
from impactlab.experiment.markers import read_markers
from impactlab.experiment.profilometry import DentMetrics, measure_dent, read_scan
from impactlab.experiment.rigid import MarkerGeometry
from impactlab.experiment.uncertainty import Estimate

__all__ = ["ExperimentResult", "analyze", "default_rod", "rod_properties"]


def default_rod() -> Any:
    """The paper's rod: ``impactlab.bodies.PAPER_ROD`` (L = 0.3048 m, R = 8.8 mm, m = 0.4607 kg,
    I_C = m L^2 / 12)."""
    from impactlab.bodies import PAPER_ROD

    return PAPER_ROD


def rod_properties(rod: Any) -> Any:
    """``impactlab.analytic.RodProperties`` (mass, length, tip_radius, inertia) of a rod-like
    object (``bodies.Rod`` has ``L``; ``RodProperties`` has ``length``)."""
    from impactlab.analytic import RodProperties

    if isinstance(rod, RodProperties):
        return rod
    if hasattr(rod, "length"):
        length = float(rod.length)
    elif hasattr(rod, "L"):
        length = float(rod.L)
    elif hasattr(rod, "half_length"):
        length = 2.0 * float(rod.half_length)
    else:
        raise ValueError(f"rod must have a length (L or length), got {rod!r}")
    return RodProperties(mass=float(rod.mass), length=length, tip_radius=float(rod.tip_radius),
                         inertia=getattr(rod, "inertia", None))





@dataclass
class ExperimentResult:
    """Everything :func:`analyze` measured (SI units).

    ``kinematics`` (:class:`ImpactKinematics` or None), ``dent`` (:class:`DentMetrics` or None),
    ``inversion`` (``impactlab.analytic.InversionResult`` or None), ``model`` (engine comparison
    or None), ``errors`` (stage -> message, for each stage that failed), ``warnings``,
    ``figures`` (name -> path), ``files`` (what was saved), ``rod`` (the rod's properties used).
    """

    markers_path: str | None
    scan_path: str | None
    kinematics: ImpactKinematics | None = None
    dent: DentMetrics | None = None
    inversion: Any = None
    model: dict[str, Any] | None = None
    errors: dict[str, str] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    figures: dict[str, str] = field(default_factory=dict)
    files: dict[str, str] = field(default_factory=dict)
    rod: dict[str, float] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        """True when every stage succeeded."""
        return not self.errors

    def summary(self) -> dict[str, Estimate]:
        """The headline results as estimates (SI): e, mu, angle, v_i, dv_cy, delta_p, L_s, T, F
        (those available)."""
        out: dict[str, Estimate] = {}
        k = self.kinematics
        if k is not None:
            out["e"] = k.e
            out["mu"] = k.mu
            out["angle"] = k.theta_in
            out["v_i"] = k.v_i
            out["v_c_in_x"], out["v_c_in_y"] = k.v_c_in
            out["v_c_out_x"], out["v_c_out_y"] = k.v_c_out
            out["omega_out"] = k.omega_out
            out["dv_cy"] = k.dv_cy
        d = self.dent
        if d is not None:
            out["delta_p"] = d.delta_p
            out["L_s"] = d.L_s
            out["pileup"] = Estimate(d.pileup, 0.0, "m")
        inv = self.inversion
        if inv is not None:
            out["T"] = Estimate(inv.T, inv.sigma_T_mc, "s")
            out["F"] = Estimate(inv.F, inv.sigma_F_mc, "N")
        return out

    def raise_for_errors(self) -> None:
        """Raise :class:`ExperimentError` with all stage errors (no-op when there are none)."""
        if self.errors:
            raise ExperimentError("; ".join(f"{k}: {v}" for k, v in self.errors.items()))

    def _repr_html_(self) -> str:
        from impactlab._display import html_table

        rows = [(k, f"{v.value:.6g} +/- {v.sigma:.2g}", v.unit) for k, v in self.summary().items()]
        rows += [(f"error ({k})", v, "") for k, v in self.errors.items()]
        return html_table("ExperimentResult", rows)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (SI units; ``summary`` holds value/sigma/unit per quantity)."""
        d: dict[str, Any] = {
            "markers": self.markers_path,
            "scan": self.scan_path,
            "summary": {k: v.to_dict() for k, v in self.summary().items()},
            "errors": dict(self.errors),
            "warnings": list(self.warnings),
            "rod": dict(self.rod),
            "figures": dict(self.figures),
        }
        if self.kinematics is not None:
            d["kinematics"] = self.kinematics.to_dict()
        if self.dent is not None:
            d["dent"] = self.dent.to_dict()
        if self.inversion is not None:
            d["inversion"] = self.inversion.to_dict()
        if self.model is not None:
            d["model"] = self.model
        return jsonable(d)

    def save(self, out_dir: str | Path) -> Path:
        """Write ``results.json`` into ``out_dir`` (created); returns its path."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        p = out / "results.json"
        self.files["results"] = str(p)
        p.write_text(json.dumps(self.to_dict(), indent=2), encoding="utf-8")
        return p


def _message(exc: BaseException) -> str:
    if isinstance(exc, ExperimentError | ValueError | FileNotFoundError | OSError):
        return str(exc)
    return f"{type(exc).__name__}: {exc} (unexpected; please report)"


def analyze(
    markers_path: str | Path | None,
    scan_path: str | Path | None,
    rod: Any = None,
    *,
    flat: Any = None,
    geometry: MarkerGeometry | None = None,
    up: Any = "+z",
    marker_units: str | None = None,
    pixel_size: Any = None,
    height_unit: str | None = None,
    out_dir: str | Path | None = None,
    figures: bool = True,
    gravity: bool = False,
    n_samples: int = 20_000,
    strict: bool = False,
    kinematics_options: dict[str, Any] | None = None,
    dent_options: dict[str, Any] | None = None,
    law: str = "ghaednia",
) -> ExperimentResult:
    """Analyse one drop: marker tracks + dent scan -> e, mu, delta_p, L_s, T, F.

    Parameters
    ----------
    markers_path : C3D or CSV marker file (None skips the stage).
    scan_path : profilometer scan (None skips the stage).
    rod : rod-like (``impactlab.bodies.Rod``); default the paper's rod.
    flat : optional flat material (``impactlab.materials.Material`` or preset name) to run the
        impact engine with the measured initial state for comparison (needs the engine).
    geometry : the markers on the rod (:class:`MarkerGeometry`); None estimates it.
    up : the lab's upward axis ("+z" default). marker_units : override/supply the marker units.
    pixel_size, height_unit : for plain .npy/.csv height maps.
    out_dir : save results.json and the figures (dent.png, kinematics.png) there.
    gravity : passed to ``invert`` (gravity during the contact in Eq. 12; the measured velocity
        change already excludes the gravity impulse, see docs/experiment.md).
    n_samples : Monte Carlo samples of the inversion. strict : raise :class:`ExperimentError`
        after saving if a stage failed (default: record it in ``result.errors``).
    kinematics_options, dent_options : extra keywords for :func:`measure_impact` and
        :func:`measure_dent`. law : contact law of the engine comparison.
    """
    rod = default_rod() if rod is None else rod
    res = ExperimentResult(str(markers_path) if markers_path is not None else None,
                           str(scan_path) if scan_path is not None else None)
    try:
        props = rod_properties(rod)
        res.rod = {"mass": props.mass, "length": props.length, "tip_radius": props.tip_radius,
                   "inertia": float(props.inertia)}
    except Exception as exc:
        res.errors["rod"] = _message(exc)
        props = None

    if markers_path is not None and props is not None:
        try:
            tracks = read_markers(markers_path, units=marker_units)
            res.kinematics = measure_impact(tracks, rod, geometry=geometry, up=up,
                                            **(kinematics_options or {}))
            res.warnings += [f"markers: {w}" for w in res.kinematics.warnings]
        except Exception as exc:
            res.errors["markers"] = _message(exc)
    if scan_path is not None:
        try:
            hm = read_scan(scan_path, pixel_size=pixel_size, height_unit=height_unit)
            res.dent = measure_dent(hm, **(dent_options or {}))
            res.warnings += [f"scan: {w}" for w in res.dent.warnings]
            if res.dent.direction_ambiguous:
                res.warnings.append("scan: the sliding direction is ambiguous (both ends of the "
                                    "dent equally sharp)")
        except Exception as exc:
            res.errors["scan"] = _message(exc)
    k, d = res.kinematics, res.dent
    if k is not None and d is not None and props is not None:
        try:
            from impactlab.analytic import invert

            res.inversion = invert(
                angle=k.theta_in.pair(), v_i=k.v_i.pair(), mu=k.mu.pair(), e=k.e.pair(),
                dv_cy=k.dv_cy.pair(), delta_p=d.delta_p.pair(), L_s=d.L_s.pair(), rod=props,
                gravity=gravity, n_samples=n_samples)
        except ImportError as exc:
            res.errors["inversion"] = f"impactlab.analytic.invert is not available ({exc})"
        except Exception as exc:
            res.errors["inversion"] = _message(exc)
    if flat is not None and k is not None:
        try:
            res.model = _engine_comparison(rod, flat, k, law)
        except ImportError as exc:
            res.errors["model"] = f"the impact engine is not available ({exc})"
        except Exception as exc:
            res.errors["model"] = _message(exc)
    if out_dir is not None:
        out = Path(out_dir)
        try:
            out.mkdir(parents=True, exist_ok=True)
            if figures:
                from impactlab.experiment.plots import plot_dent, plot_kinematics

                if k is not None:
                    p = out / "kinematics.png"
                    plot_kinematics(k, p)
                    res.figures["kinematics"] = str(p)
                if d is not None:
                    p = out / "dent.png"
                    plot_dent(d, p)
                    res.figures["dent"] = str(p)
        except Exception as exc:
            res.errors["figures"] = _message(exc)
        res.save(out)
    if strict:
        res.raise_for_errors()
    return res


def _engine_comparison(rod: Any, flat: Any, k: ImpactKinematics, law: str) -> dict[str, Any]:
    """Run the engine with the measured angle, velocity, spin and friction coefficient."""
    from impactlab.dynamics import simulate  # type: ignore[attr-defined,unused-ignore]
    from impactlab.materials import Material, get_material

    mat = flat if isinstance(flat, Material) else get_material(str(flat))
    body = rod
    if not hasattr(body, "to_params"):
        from impactlab.bodies import Rod

        p = rod_properties(rod)
        body = Rod(length=p.length, tip_radius=p.tip_radius, mass=p.mass, inertia=p.inertia)
    r = simulate(body, mat, law=law, mu=k.mu.value, angle=k.theta_in.value,
                 velocity=(k.v_c_in[0].value, k.v_c_in[1].value), spin=k.omega_in.value)
    out: dict[str, Any] = {"law": law, "flat": getattr(mat, "name", str(flat))}
    for name in ("e", "delta_p", "sliding_length", "duration"):
        v = getattr(r, name, None)
        if v is not None:
            out[name] = float(v)
    vo = getattr(r, "velocity_out", None)
    if vo is not None:
        out["velocity_out"] = [float(v) for v in vo]
    so = getattr(r, "spin_out", None)
    if so is not None:
        out["spin_out"] = float(so)
    return out
