"""What :func:`impactlab.experiment.analyze` measured: :class:`ExperimentResult` (SI units)."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from impactlab._display import field_row, html_table, text_table
from impactlab._files import write_text_atomic
from impactlab._json import jsonable
from impactlab._version import __version__
from impactlab.experiment.errors import ExperimentError
from impactlab.experiment.kinematics import ImpactKinematics
from impactlab.experiment.profilometry import DentMetrics
from impactlab.experiment.result_json import analysis_json
from impactlab.experiment.uncertainty import Estimate

__all__ = ["ExperimentResult", "model_rows"]

#: The engine comparison's fields (``ExperimentResult.model``) shown as ``model <field>``, and
#: their SI units.
_MODEL = {
    "e": "1",
    "delta_p": "m",
    "contact_travel": "m",
    "sliding_length": "m",
    "duration": "s",
    "mean_force": "N",
    "spin_out": "rad/s",
}


def model_rows(model: dict[str, Any] | None) -> list[tuple[str, str, str]]:
    """The table rows ``model <field> (<law>)`` of the engine comparison (display units); the
    contact travel as the scan measures L_s, a magnitude (``model L_s = |contact_travel|``)."""
    if model is None:
        return []
    law = model.get("law", "")
    rows = []
    for k, unit in _MODEL.items():
        v = model.get(k)
        if isinstance(v, float):
            label = f"model {k} ({law})"
            if k == "contact_travel":  # the mark's extent, as the scan's L_s: a magnitude
                v, label = abs(v), f"model L_s = |contact_travel| ({law})"
            _n, text, shown = field_row(k, v, unit)
            rows.append((label, text, shown))
    return rows


@dataclass
class ExperimentResult:
    """Everything :func:`analyze` measured (SI units).

    ``kinematics`` (:class:`ImpactKinematics` or None), ``dent`` (:class:`DentMetrics` or None),
    ``inversion`` (``impactlab.analytic.InversionResult`` or None), ``model`` (engine comparison
    or None), ``errors`` (stage -> message, for each stage that failed on its data),
    ``warnings``, ``figures`` (name -> path), ``files`` (what was saved), ``rod`` (the rod's
    properties used), ``options`` (the analysis's settings as given, JSON-ready: what repeats
    it), ``implausible`` (what the analysis's checks find impossible or implausible in the
    result, each one among the warnings too: part of ``doubts``).
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
    options: dict[str, Any] = field(default_factory=dict)
    implausible: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """True when every stage succeeded and nothing makes the result doubtful
        (``doubts``)."""
        return not self.errors and not self.doubts

    def add_doubt(self, text: str) -> None:
        """Record ``text`` as a warning that marks the result not ok (``implausible``)."""
        self.warnings.append(text)
        self.implausible.append(text)

    def summary(self) -> dict[str, Estimate]:
        """The headline results as estimates (SI), keyed by the glossary's names (the table the
        command line prints): e, mu, angle, v_i, v_cx_in, v_cy_in, v_cx_out, v_cy_out,
        spin_out, dv_cy, delta_p, sliding_length (the scar's, a magnitude), pileup, duration,
        mean_force (those available; duration and mean_force with the Monte Carlo sigma)."""
        out: dict[str, Estimate] = {}
        k = self.kinematics
        if k is not None:
            out["e"] = k.e
            out["mu"] = k.mu
            out["angle"] = k.angle_in
            out["v_i"] = k.v_i
            out["v_cx_in"], out["v_cy_in"] = k.v_c_in
            out["v_cx_out"], out["v_cy_out"] = k.v_c_out
            out["spin_out"] = k.spin_out
            out["dv_cy"] = k.dv_cy
        d = self.dent
        if d is not None:
            out["delta_p"] = d.delta_p
            out["sliding_length"] = d.sliding_length
            out["pileup"] = Estimate(d.pileup, 0.0, "m")
        inv = self.inversion
        if inv is not None:
            out["duration"] = Estimate(inv.duration, inv.sigma_T_mc, "s")
            out["mean_force"] = Estimate(inv.mean_force, inv.sigma_F_mc, "N")
        return out

    def raise_for_errors(self) -> None:
        """Raise :class:`ExperimentError` with all stage errors (no-op when there are none)."""
        if self.errors:
            raise ExperimentError("; ".join(f"{k}: {v}" for k, v in self.errors.items()))

    @property
    def doubts(self) -> tuple[str, ...]:
        """What makes the result doubtful though every stage succeeded: an estimated marker
        geometry in doubt (``kinematics.doubts``) and what the checks find impossible or
        implausible (``implausible``: a rod whose mass and inertia do not fit, a velocity
        change that implies e outside [0, 1], a T longer than 0.1 s, a T or F far from the
        simulated impact's or longer than the marker fits allow); empty when there is none."""
        geometry = () if self.kinematics is None else self.kinematics.doubts
        return (*geometry, *self.implausible)

    def _rows(self) -> list[tuple[str, str, str]]:
        rows = [field_row(k, v.value, v.unit, v.sigma) for k, v in self.summary().items()]
        rows += model_rows(self.model)
        rows.append(("ok", "yes" if self.ok else "no", ""))
        rows += [("doubt", d, "") for d in self.doubts]
        rows += [(f"error ({k})", v, "") for k, v in self.errors.items()]
        shown = {*self.doubts, *(f"markers: {d}" for d in self.doubts)}  # each once
        return rows + [("warning", w, "") for w in self.warnings if w not in shown]

    def __str__(self) -> str:
        return text_table("ExperimentResult", self._rows())

    def __repr__(self) -> str:
        """One line: the files, the headline estimates (SI, with their sigma), whether it is
        ok, and the numbers of errors and warnings (``str`` gives the whole table)."""
        files = [Path(p).name for p in (self.markers_path, self.scan_path) if p]
        parts = [" + ".join(files) or "no files"]
        shown = ("e", "mu", "delta_p", "sliding_length", "duration", "mean_force")
        for name, est in self.summary().items():
            if name in shown:
                sigma = f" ± {est.sigma:.2g}" if est.sigma > 0 else ""
                unit = "" if est.unit in ("", "1") else f" {est.unit}"
                parts.append(f"{name}={est.value:.6g}{sigma}{unit}")
        parts.append(f"ok={self.ok}")
        for what, items in (("error", self.errors), ("warning", self.warnings)):
            if items:
                parts.append(f"{len(items)} {what}" + "s" * (len(items) > 1))
        return f"ExperimentResult({', '.join(parts)})"

    def _repr_html_(self) -> str:
        return html_table("ExperimentResult", self._rows())

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready (SI units; ``summary`` holds value/sigma/unit per quantity), with the
        analysis's ``options`` and the ``impactlab_version`` that made it."""
        d: dict[str, Any] = {
            "markers": self.markers_path,
            "scan": self.scan_path,
            "summary": {k: v.to_dict() for k, v in self.summary().items()},
            "ok": self.ok,
            "doubts": list(self.doubts),
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
        d["options"] = dict(self.options)
        d["impactlab_version"] = __version__
        return jsonable(d)

    def save(self, out_dir: str | Path) -> Path:
        """Write ``results.json`` into ``out_dir`` (created), whole or not at all (an
        interrupted write leaves the earlier file as it was): the analysis as JSON, every
        quantity a ``{"value", "sigma", "unit"}`` object (``result_json.analysis_json``, as
        ``impactlab analyze --json`` prints it); returns its path."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        p = out / "results.json"
        self.files["results"] = str(p)
        write_text_atomic(p, json.dumps(analysis_json(self), indent=2))
        return p
