"""How a calibration shows itself: the ranking of its models, each model's posterior, the
measurements and a model's predictions as rows of text in display units (MPa, um, ms), for
``impactlab calibrate``'s tables, ``repr`` and a notebook's ``_repr_html_``: one display path.
The objects are those of ``calibrate.api``, ``calibrate.result``, ``calibrate.measurements``
and ``calibrate.drop_predictions`` (typed ``Any`` here: those modules import this one)."""

from __future__ import annotations

import html
import math
from collections.abc import Sequence
from typing import Any

from impactlab._display import display_unit, format_number
from impactlab._html import grid_html

__all__ = [
    "POSTERIOR_HEAD", "PREDICTION_HEAD", "RANKING_HEAD", "calibration_html", "calibration_text",
    "diagnostic", "grid_text", "measurements_text", "posterior_footer",
    "posterior_rows", "posterior_text", "prediction_rows", "predictions_html",
    "predictions_text", "ranking_rows", "share",
]  # fmt: skip

#: The ranking's columns (``Calibration.ranking``, best first).
RANKING_HEAD = ("rank", "model", "elpd_loo", "se", "elpd_diff", "dse", "weight", "Pareto k",
                "converged", "law extrapolated", "note")  # fmt: skip
#: A posterior's columns, one row per parameter (display units).
POSTERIOR_HEAD = ("parameter", "median", "90 % interval", "best", "unit", "R-hat", "ESS")
#: A prediction's columns, one row per drop and quantity (display units).
PREDICTION_HEAD = ("drop", "quantity", "median", "90 % interval", "unit", "failed",
                   "law extrapolated")  # fmt: skip


def diagnostic(x: float, spec: str) -> str:
    """A diagnostic's number, or "n/a" where it could not be assessed (NaN)."""
    return "n/a" if math.isnan(x) else format(x, spec)


def share(x: float) -> str:
    """A share in percent (``"100 %"``), or "n/a" where it is not known (NaN)."""
    return "n/a" if math.isnan(x) else f"{format_number(100 * x, 2)} %"


def ranking_rows(ranking: Sequence[dict[str, Any]]) -> list[tuple[str, ...]]:
    """The rows of ``RANKING_HEAD``, best first."""
    return [(
        str(r["rank"] + 1), r["model"], f"{r['elpd_loo']:.2f}", f"{r['se']:.2f}",
        f"{r['elpd_diff']:.2f}", f"{r['dse']:.2f}", f"{r['weight']:.2f}",
        diagnostic(r["pareto_k_max"], ".2f"), "yes" if r["converged"] else "no",
        share(r.get("law_extrapolated", math.nan)), r["note"],
    ) for r in ranking]  # fmt: skip


def posterior_rows(post: Any) -> list[tuple[str, ...]]:
    """The rows of ``POSTERIOR_HEAD``: each parameter's median, 90 % interval and best fit in
    its display unit, R-hat and the bulk ESS."""
    rows: list[tuple[str, ...]] = []
    for par in post.params:
        s, d = post.summary[par.name], display_unit(par.name, par.unit)

        def f(x: float, d: Any = d) -> str:
            return format_number(x * d.scale, 4)

        rows.append((
            par.name, f(s["median"]), f"[{f(s['q05'])}, {f(s['q95'])}]", f(post.best[par.name]),
            d.unit, diagnostic(s["rhat"], ".3f"), diagnostic(s["ess_bulk"], ".0f"),
        ))  # fmt: skip
    return rows


def posterior_footer(post: Any) -> str:
    """The line under a posterior's table: evaluations, acceptance, failed cases."""
    fails = sum(post.failures.values())
    return (
        f"{post.evaluations} evaluations in this run, acceptance {post.acceptance:.2f}, "
        f"{fails} failed cases (likelihood zero)"
    )


def prediction_rows(pred: Any) -> list[tuple[str, ...]]:
    """The rows of ``PREDICTION_HEAD`` (``DropPredictions.summary``), in display units."""
    rows: list[tuple[str, ...]] = []
    for r in pred.summary():
        d = display_unit(r["quantity"], r["unit"])

        def f(x: float, d: Any = d) -> str:
            return format_number(x * d.scale, 4)

        rows.append((
            r["drop"], r["quantity"], f(r["median"]), f"[{f(r['q05'])}, {f(r['q95'])}]", d.unit,
            share(r["failed"]), share(r["extrapolated"]),
        ))  # fmt: skip
    return rows


def grid_text(title: str, head: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """``rows`` under ``head`` as aligned plain text, indented under ``title``."""
    table = [tuple(head), *(tuple(r) for r in rows)]
    widths = [max(len(r[j]) for r in table) for j in range(len(head))]
    lines = ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths, strict=True)).rstrip()
             for r in table]  # fmt: skip
    return "\n".join([title, *lines])


def measurements_text(meas: Any) -> str:
    """One line: the drops, the quantities measured, the number of values and the source."""
    drops = ", ".join(meas.labels[:6]) + (", ..." if meas.n_drops > 6 else "")
    source = f" from {meas.source}" if meas.source else ""
    return (
        f"Measurements({meas.n_drops} drops: {drops}; {meas.n_values} values of "
        f"{', '.join(meas.quantities)}{source})"
    )


def _heading(cal: Any) -> str:
    m = cal.measurements
    return (
        f"Calibration of {len(cal.posteriors)} model(s) on {m.n_drops} drops "
        f"({m.n_values} measured values of {', '.join(m.quantities)}), ranked by PSIS-LOO"
    )


def _warned(cal: Any) -> str:
    n = len(cal.warnings)
    return f"{n} warning(s) given: see .warnings" if n else "no warnings"


def posterior_text(post: Any) -> str:
    """A posterior's parameter table and its footer (``repr(ModelPosterior)``)."""
    state = "converged" if post.converged else "not converged"
    return "\n".join([
        grid_text(f"ModelPosterior {post.model} ({state})", POSTERIOR_HEAD, posterior_rows(post)),
        "  " + posterior_footer(post),
    ])  # fmt: skip


def calibration_text(cal: Any) -> str:
    """``repr(Calibration)``: the heading, the ranking and each model's posterior."""
    parts = [_heading(cal), grid_text("ranking", RANKING_HEAD, ranking_rows(cal.ranking))]
    parts += [posterior_text(post) for post in cal.posteriors.values()]
    return "\n".join([*parts, _warned(cal)])


def calibration_html(cal: Any) -> str:
    """A notebook's view of a calibration: the same tables as HTML."""
    parts = [f"<strong>{html.escape(_heading(cal))}</strong>",
             grid_html("ranking", RANKING_HEAD, ranking_rows(cal.ranking))]  # fmt: skip
    for name, post in cal.posteriors.items():
        parts.append(grid_html(name, POSTERIOR_HEAD, posterior_rows(post)))
        parts.append(f"<p>{html.escape(posterior_footer(post))}</p>")
    parts.append(f"<p>{html.escape(_warned(cal))}</p>")
    return "<div>" + "".join(parts) + "</div>"


def predictions_text(pred: Any) -> str:
    """``repr(DropPredictions)``: each drop's and quantity's median and 90 % interval."""
    n = int(pred.draws.shape[0])
    title = f"DropPredictions of {pred.model} at {n} posterior draws"
    return grid_text(title, PREDICTION_HEAD, prediction_rows(pred))


def predictions_html(pred: Any) -> str:
    """A notebook's view of the predictions."""
    n = int(pred.draws.shape[0])
    title = f"DropPredictions of {pred.model} at {n} posterior draws"
    return grid_html(title, PREDICTION_HEAD, prediction_rows(pred))
