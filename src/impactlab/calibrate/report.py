"""The self-contained HTML report of a calibration (figures embedded as PNG), and ``save``:
results.json, the figures and report.html in one folder."""

from __future__ import annotations

import base64
import html
import io
import json
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from impactlab._display import display_unit, format_number
from impactlab._files import write_text_atomic
from impactlab._version import __version__
from impactlab.calibrate.api import Calibration
from impactlab.calibrate.jsonout import calibration_json
from impactlab.calibrate.plots import corner_figure, ppc_figure
from impactlab.calibrate.result import ModelPosterior

__all__ = ["FILES", "RESULT_KEYS", "html_report", "save"]

#: The files ``save`` writes into its folder, by name.
FILES = {"results": "results.json", "report": "report.html"}
#: Keys that every results.json of a calibration holds (how the command line knows its own).
RESULT_KEYS = ("measurements", "settings", "criterion", "ranking", "models")
#: The mark of report.html: its ``<meta name="generator">``, as the command line's output
#: folders mark their files (``impactlab.cli.output_paths.mark``).
GENERATOR = f"impactlab calibrate {__version__}"

_STYLE = (
    "body{font-family:sans-serif;max-width:60em;margin:2em auto;line-height:1.4}"
    "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #ccc;"
    "padding:0.2em 0.6em;text-align:right}th{background:#f3f3f3}td:first-child{text-align:left}"
    ".warn{color:#a40}"
)


def _png(fig: Any) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    from impactlab._mpl import pyplot

    pyplot().close(fig)
    return base64.b64encode(buf.getvalue()).decode()


def _table(header: list[str], rows: list[list[Any]]) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    body = "".join(
        "<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in r) + "</tr>" for r in rows
    )
    return f"<table><tr>{head}</tr>{body}</table>"


def _number(x: float, spec: str) -> str:
    """A diagnostic's number, or "n/a" where it could not be assessed (NaN)."""
    return "n/a" if math.isnan(x) else format(x, spec)


def _value(name: str, unit: str, x: float) -> str:
    d = display_unit(name, unit)
    return format_number(x * d.scale, 4)


def _model_section(post: ModelPosterior) -> str:
    rows = []
    for p in post.params:
        s, d = post.summary[p.name], display_unit(p.name, p.unit)
        rows.append(
            [
                p.name,
                d.unit,
                _value(p.name, p.unit, s["median"]),
                f"[{_value(p.name, p.unit, s['q05'])}, {_value(p.name, p.unit, s['q95'])}]",
                _value(p.name, p.unit, post.best[p.name]),
                _number(s["rhat"], ".3f"),
                _number(s["ess_bulk"], ".0f"),
                _number(s["tau"], ".1f"),
                p.describe(),
            ]
        )
    params = _table(
        [
            "parameter",
            "unit",
            "median",
            "90 % interval",
            "best fit",
            "R-hat",
            "ESS",
            "tau [steps]",
            "prior",
        ],
        rows,
    )
    fails = ", ".join(f"{k}: {v}" for k, v in post.failures.items()) or "none"
    notes = "".join(f"<li class='warn'>{html.escape(w)}</li>" for w in post.warnings)
    return (
        f"<h3>{html.escape(post.model)}</h3>{params}"
        f"<p>{'converged' if post.converged else 'not converged'}; "
        f"{post.evaluations} model evaluations; acceptance {post.acceptance:.2f}; "
        f"{post.steps} steps ({post.burn} discarded); failed cases (likelihood zero): "
        f"{html.escape(fails)}; {html.escape(_extrapolated_text(post.law_extrapolated))}</p>"
        + (f"<ul>{notes}</ul>" if notes else "")
        + f"<img alt='corner plot' src='data:image/png;base64,{_png(corner_figure(post))}'>"
    )


def _share(x: float) -> str:
    """A share in percent, or "n/a" (not known)."""
    return "n/a" if math.isnan(x) else f"{format_number(100 * x, 2)} %"


def _extrapolated_text(found: Mapping[str, Any]) -> str:
    """The law-extrapolated share of a model's predicted impacts, with what it counts."""
    if not found:
        return "law extrapolated: n/a"
    return (
        f"law extrapolated (beyond its verified range) in {_share(float(found['share']))} of "
        f"the {found['impacts']} predicted impacts at {found['basis']}"
    )


def _setting(name: str, v: Any, nested: bool = False) -> str:
    """A setting of results.json as text: a quantity with its unit, in its display unit
    (``9.80665 m/s^2``, ``300 MPa``), a table as ``key = value; ...`` (within one, as
    ``{ key = value, ... }``), None as the default."""
    if isinstance(v, Mapping) and set(v) == {"value", "unit"}:
        if isinstance(v["value"], bool) or not isinstance(v["value"], int | float):
            return str(v["value"])
        d = display_unit(name, str(v["unit"]))
        shown = format_number(float(v["value"]) * d.scale, 6)
        return shown if d.unit in ("", "1", "-") else f"{shown} {d.unit}"
    if isinstance(v, Mapping):
        items = [f"{k} = {_setting(str(k), x, True)}" for k, x in v.items() if x not in (None, {})]
        if nested:
            return "{ " + ", ".join(items) + " }"
        return "; ".join(items) or "none"
    if isinstance(v, list | tuple):
        return ", ".join(_setting(name, x) for x in v)
    return "default" if v is None else str(v)


def _settings_rows(settings: Mapping[str, Any]) -> list[list[str]]:
    """One row per setting, per prior and engine option, per model definition, and per
    reference."""
    rows = []
    for key, v in settings.items():
        if key in ("parameters", "engine", "model_definitions") and isinstance(v, Mapping):
            rows += [[f"{key}: {k}", _setting(str(k), x)] for k, x in v.items()]
        elif key == "references" and isinstance(v, list):
            rows += [[key if i == 0 else "", str(r)] for i, r in enumerate(v)]
        else:
            rows.append([key, _setting(key, v)])
    return rows


def html_report(cal: Calibration, title: str = "impactlab calibration") -> str:
    """The report as one HTML document (figures embedded)."""
    m = cal.measurements
    rank = _table(
        [
            *("rank", "model", "elpd_loo", "se", "elpd_diff", "dse", "p_loo", "weight"),
            *("Pareto k (max)", "converged", "law extrapolated", "note"),
        ],
        [
            [
                r["rank"] + 1,
                r["model"],
                f"{r['elpd_loo']:.2f}",
                f"{r['se']:.2f}",
                f"{r['elpd_diff']:.2f}",
                f"{r['dse']:.2f}",
                f"{r['p_loo']:.2f}",
                f"{r['weight']:.2f}",
                f"{_number(r['pareto_k_max'], '.2f')}" + (" (> 0.7)" if r["warning"] else ""),
                "yes" if r["converged"] else "no",
                _share(r["law_extrapolated"]),
                r["note"],
            ]
            for r in cal.ranking
        ],
    )
    settings = _table(["setting", "value"], _settings_rows(calibration_json(cal)["settings"]))
    notes = "".join(f"<li class='warn'>{html.escape(w)}</li>" for w in cal.warnings)
    ppc = _png(ppc_figure(cal.posteriors))
    return (
        f"<!DOCTYPE html><html><head><meta charset='utf-8'><meta name='generator' "
        f"content='{GENERATOR}'><title>{html.escape(title)}</title>"
        f"<style>{_STYLE}</style></head><body><h1>{html.escape(title)}</h1>"
        f"<p>{m.n_drops} drops ({html.escape(str(m.source or 'in memory'))}), {m.n_values} "
        f"measured values: {html.escape(', '.join(m.quantities))}.</p>"
        f"<h2>Ranking</h2><p>PSIS-LOO: expected log predictive density of each drop left out "
        "(higher is better); a difference matters when it exceeds about twice its standard "
        f"error dse.</p>{rank}"
        + (f"<ul>{notes}</ul>" if notes else "")
        + f"<h2>Posterior predictive check</h2><img alt='ppc' src='data:image/png;base64,{ppc}'>"
        + "<h2>Models</h2>"
        + "".join(_model_section(p) for p in cal.posteriors.values())
        + f"<h2>Settings</h2>{settings}</body></html>"
    )


def save(cal: Calibration, out_dir: str | Path, *, report: bool = True) -> dict[str, Path]:
    """Write results.json (the command line's JSON, docs/json-schema.md) and report.html into
    ``out_dir``, each whole or not at all (a full disk leaves an earlier file as it was);
    returns name -> path."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    files = {"results": out / FILES["results"]}
    write_text_atomic(files["results"], json.dumps(calibration_json(cal), indent=2))
    if report:
        files["report"] = out / FILES["report"]
        write_text_atomic(files["report"], html_report(cal))
    return files
