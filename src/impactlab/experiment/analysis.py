"""One call from the raw files to e, mu, delta_p, L_s, T and F: :func:`analyze`.

Stages (a stage that fails on its data is recorded and the others go on, so partial results are
never lost; an invalid argument or a broken installation raises at once):

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

from impactlab import analytic
from impactlab._display import html_table
from impactlab._json import jsonable
from impactlab._mpl import pyplot
from impactlab.bodies import PAPER_ROD, Rod
from impactlab.dynamics import simulate
from impactlab.experiment.errors import ExperimentError
from impactlab.experiment.kinematics import ImpactKinematics, measure_impact
from impactlab.experiment.markers import read_markers
from impactlab.experiment.plots import plot_dent, plot_kinematics
from impactlab.experiment.profilometry import DentMetrics, measure_dent, read_scan
from impactlab.experiment.rigid import MarkerGeometry
from impactlab.experiment.uncertainty import Estimate
from impactlab.materials import Material, get_material

__all__ = ["ExperimentResult", "analyze", "default_rod", "rod_properties"]

#: What a stage may fail with on bad data: the package's errors (ExperimentError is a ValueError),
#: invalid values and unreadable or unwritable files. Anything else is a bug and propagates.
_DATA_ERRORS = (ValueError, OSError)


def default_rod() -> Rod:
    """The paper's rod: ``impactlab.bodies.PAPER_ROD`` (L = 0.3048 m, R = 8.8 mm, m = 0.4607 kg,
    I_C = m L^2 / 12)."""
    return PAPER_ROD


def rod_properties(rod: Any) -> Rod:
    """The rod as an ``impactlab.bodies.Rod`` (mass, length, tip_radius, inertia): a Rod itself,
    or a rod-like object with ``mass``, ``tip_radius``, a length (``L``, ``length`` or
    ``half_length``) and optionally ``inertia``. ValueError naming ``rod`` otherwise."""
    if isinstance(rod, Rod):
        return rod
    if hasattr(rod, "length"):
        length = float(rod.length)
    elif hasattr(rod, "L"):
        length = float(rod.L)
    elif hasattr(rod, "half_length"):
        length = 2.0 * float(rod.half_length)
    else:
        raise ValueError(f"rod must have a length (L or length), got {rod!r}")
    try:
        return Rod(
            length=length,
            tip_radius=float(rod.tip_radius),
            mass=float(rod.mass),
            inertia=getattr(rod, "inertia", None),
        )
    except AttributeError as exc:
        raise ValueError(f"rod must have mass and tip_radius: {exc}") from None


@dataclass
class ExperimentResult:
    """Everything :func:`analyze` measured (SI units).

    ``kinematics`` (:class:`ImpactKinematics` or None), ``dent`` (:class:`DentMetrics` or None),
    ``inversion`` (``impactlab.analytic.InversionResult`` or None), ``model`` (engine comparison
    or None), ``errors`` (stage -> message, for each stage that failed on its data),
    ``warnings``, ``figures`` (name -> path), ``files`` (what was saved), ``rod`` (the rod's
    properties used).
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
        """The headline results as estimates (SI), keyed by the paper's symbols (the table the
        command line prints): e, mu, angle, v_i, v_c_in_x/y, v_c_out_x/y, spin_out, dv_cy,
        delta_p, L_s (the sliding length), pileup, T, F (those available)."""
        out: dict[str, Estimate] = {}
        k = self.kinematics
        if k is not None:
            out["e"] = k.e
            out["mu"] = k.mu
            out["angle"] = k.angle_in
            out["v_i"] = k.v_i
            out["v_c_in_x"], out["v_c_in_y"] = k.v_c_in
            out["v_c_out_x"], out["v_c_out_y"] = k.v_c_out
            out["spin_out"] = k.spin_out
            out["dv_cy"] = k.dv_cy
        d = self.dent
        if d is not None:
            out["delta_p"] = d.delta_p
            out["L_s"] = d.sliding_length
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
    return str(exc)


def _flat_material(flat: Any) -> Material:
    try:
        return flat if isinstance(flat, Material) else get_material(str(flat))
    except ValueError as exc:
        raise ValueError(f"flat: {exc}") from None


def _markers_stage(res: ExperimentResult, path: str | Path, rod: Rod, opts: dict[str, Any]) -> None:
    try:
        tracks = read_markers(path, units=opts.pop("marker_units"))
        res.kinematics = measure_impact(tracks, rod, **opts)
    except _DATA_ERRORS as exc:
        res.errors["markers"] = _message(exc)
        return
    res.warnings += [f"markers: {w}" for w in res.kinematics.warnings]


def _scan_stage(
    res: ExperimentResult,
    path: str | Path,
    pixel_size: Any,
    height_unit: str | None,
    opts: dict[str, Any],
) -> None:
    try:
        hm = read_scan(path, pixel_size=pixel_size, height_unit=height_unit)
        res.dent = measure_dent(hm, **opts)
    except _DATA_ERRORS as exc:
        res.errors["scan"] = _message(exc)
        return
    res.warnings += [f"scan: {w}" for w in res.dent.warnings]
    if res.dent.direction_ambiguous:
        res.warnings.append(
            "scan: the sliding direction is ambiguous (both ends of the dent equally sharp)"
        )


def _inversion_stage(
    res: ExperimentResult,
    k: ImpactKinematics,
    d: DentMetrics,
    rod: Rod,
    gravity: bool,
    n_samples: int,
) -> None:
    try:
        # through the module attribute, so that the inversion can be replaced (tests)
        res.inversion = analytic.invert(
            angle=k.angle_in.pair(),
            v_i=k.v_i.pair(),
            mu=k.mu.pair(),
            e=k.e.pair(),
            dv_cy=k.dv_cy.pair(),
            delta_p=d.delta_p.pair(),
            sliding_length=d.sliding_length.pair(),
            rod=rod,
            gravity=gravity,
            n_samples=n_samples,
        )
    except ValueError as exc:
        res.errors["inversion"] = _message(exc)


def _figures_stage(res: ExperimentResult, out: Path) -> None:
    plt = pyplot()
    try:
        out.mkdir(parents=True, exist_ok=True)
        if res.kinematics is not None:
            p = out / "kinematics.png"
            plt.close(plot_kinematics(res.kinematics, p))
            res.figures["kinematics"] = str(p)
        if res.dent is not None:
            p = out / "dent.png"
            plt.close(plot_dent(res.dent, p))
            res.figures["dent"] = str(p)
    except OSError as exc:
        res.errors["figures"] = _message(exc)


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
    rod : an ``impactlab.bodies.Rod`` (or rod-like, see :func:`rod_properties`); default the
        paper's rod.
    flat : optional flat material (``impactlab.materials.Material`` or preset name) to run the
        impact engine with the measured initial state for comparison.
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

    A stage that fails on its data (a bad file, a failed fit, an inversion outside its range) is
    recorded in ``result.errors``; an invalid ``rod`` or ``flat`` raises ValueError at once.
    """
    props = rod_properties(default_rod() if rod is None else rod)
    mat = _flat_material(flat) if flat is not None else None
    res = ExperimentResult(
        str(markers_path) if markers_path is not None else None,
        str(scan_path) if scan_path is not None else None,
    )
    assert props.inertia is not None  # a Rod sets its default inertia
    res.rod = {
        "mass": props.mass,
        "length": props.length,
        "tip_radius": props.tip_radius,
        "inertia": float(props.inertia),
    }
    if markers_path is not None:
        _markers_stage(
            res,
            markers_path,
            props,
            {
                "marker_units": marker_units,
                "geometry": geometry,
                "up": up,
                **(kinematics_options or {}),
            },
        )
    if scan_path is not None:
        _scan_stage(res, scan_path, pixel_size, height_unit, dict(dent_options or {}))
    k, d = res.kinematics, res.dent
    if k is not None and d is not None:
        _inversion_stage(res, k, d, props, gravity, n_samples)
    if mat is not None and k is not None:
        try:
            res.model = _engine_comparison(props, mat, k, law)
        except ValueError as exc:
            res.errors["model"] = _message(exc)
    if out_dir is not None:
        out = Path(out_dir)
        if figures:
            _figures_stage(res, out)
        res.save(out)
    if strict:
        res.raise_for_errors()
    return res


def _engine_comparison(rod: Rod, flat: Material, k: ImpactKinematics, law: str) -> dict[str, Any]:
    """Run the engine with the measured angle, velocity, spin and friction coefficient."""
    r = simulate(
        rod,
        flat,
        law=law,
        mu=k.mu.value,
        angle=k.angle_in.value,
        velocity=(k.v_c_in[0].value, k.v_c_in[1].value),
        spin=k.spin_in.value,
    )
    out: dict[str, Any] = {"law": law, "flat": flat.name}
    for name in ("e", "delta_p", "sliding_length", "duration"):
        out[name] = float(getattr(r, name))
    out["velocity_out"] = [float(v) for v in r.velocity_out]
    out["spin_out"] = float(r.spin_out)
    return out
