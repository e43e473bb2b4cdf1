"""Views of the laws' measured accuracy (``impactlab.fe.accuracy``): the CLI's table rows, the
docs page's markdown tables, the figures, and a command line.

``python -m impactlab.fe.accuracy_views [--json] [--markdown] [--figures DIR]`` prints the tables
or writes the figures (docs/laws/accuracy.md).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from impactlab.fe.accuracy import (
    FORCE_TOLERANCE,
    RESIDUAL_TOLERANCE,
    UNITS,
    CaseAccuracy,
    VerifiedRange,
    accuracy,
    report,
)
from impactlab.fe.accuracy_display import table_rows


def _range_cell(v: VerifiedRange) -> str:
    def one(u: float, failure: float) -> str:
        return f">= {u:.3g}" if math.isnan(failure) else f"{u:.3g}"

    return (
        f"{one(v.upper, v.first_failure)} (F: {one(v.force_upper, v.force_failure)}, "
        f"dr: {one(v.residual_upper, v.residual_failure)})"
    )


def markdown(results: Sequence[CaseAccuracy]) -> str:
    """The tables of the docs page (one per case), the verified ranges and recommendations."""
    out = []
    for res in results:
        c = res.case
        out.append(
            f"### {c.description}\n\nE*/S_y = {c.e_star_over_sy:.0f}, delta_c = "
            f"{c.delta_c * 1e6:.4g} um, R = {c.radius * 1e3:g} mm. Each cell: force error / "
            f"error of delta_r/delta_max, at delta_max/delta_c:\n"
        )
        header, rows = table_rows(res)
        out.append("| " + " | ".join(header) + " |")
        out.append("|" + " --- |" * len(header))
        out.extend("| " + " | ".join(r) + " |" for r in rows)
        out.append(f"\n**Recommendation.** {res.recommendation()}\n")
    laws = [a.law for a in results[0].laws] if results else []
    out.append(
        "### Verified ranges (delta/delta_c)\n\nEach cell: the verified range (both checks), "
        "then the range the force check alone and the delta_r/delta_max check alone verify "
        "(>=: to the end of the data).\n"
    )
    out.append(
        "| law | " + " | ".join(f"E*/S_y = {r.case.e_star_over_sy:.0f}" for r in results) + " |"
    )
    out.append("|" + " --- |" * (len(results) + 1))
    for i, name in enumerate(laws):
        cells = [
            _range_cell(r.laws[i].verified) if r.laws[i].built else "not built" for r in results
        ]
        out.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def plot_errors(results: Sequence[CaseAccuracy]) -> Any:
    """Figure: per case (rows) the force error and the delta_r / delta_max error of every law
    against delta / delta_c, with the tolerance bands."""
    from impactlab._mpl import pyplot

    plt = pyplot()
    n = len(results)
    fig, axes = plt.subplots(n, 2, figsize=(10, 3.0 * n), squeeze=False, sharex=True)
    for (ax_f, ax_r), res in zip(axes, results, strict=True):
        for a in res.laws:
            (line,) = ax_f.plot(a.force_ratio, 100 * a.force_error, lw=1.3, label=a.law)
            ax_r.plot(a.maxima_ratio, a.residual_error, "o-", ms=3, lw=1.3, color=line.get_color())
        ax_f.axhspan(-100 * FORCE_TOLERANCE, 100 * FORCE_TOLERANCE, color="0.9", zorder=0)
        ax_r.axhspan(-RESIDUAL_TOLERANCE, RESIDUAL_TOLERANCE, color="0.9", zorder=0)
        ax_f.set_ylim(-100, 200)
        ax_r.set_ylim(-0.6, 0.6)
        title = f"{res.case.description} (E*/S_y = {res.case.e_star_over_sy:.0f})"
        ax_f.set_title(title, fontsize=8, loc="left")
        ax_f.set_ylabel("force error F_law/F_FE - 1 [%]", fontsize=8)
        ax_r.set_ylabel("delta_r/delta_max: law - FE", fontsize=8)
        for ax in (ax_f, ax_r):
            ax.set_xscale("log")
            ax.axhline(0.0, color="k", lw=0.6)
            ax.grid(True, which="both", lw=0.3)
            ax.tick_params(labelsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("delta / delta_c", fontsize=8)
    axes[0][0].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    return fig


def plot_curves(results: Sequence[CaseAccuracy]) -> Any:
    """Figure: per case the FE loading curve and delta_r / delta_max against every law's."""
    from impactlab._mpl import pyplot

    plt = pyplot()
    n = len(results)
    fig, axes = plt.subplots(n, 2, figsize=(10, 3.0 * n), squeeze=False)
    for (ax_f, ax_r), res in zip(axes, results, strict=True):
        c = res.case
        first = res.laws[0]
        ax_f.plot(first.force_ratio, first.force_fe, "k", lw=2.5, alpha=0.5, label="FE")
        for a in res.laws:
            ax_f.plot(a.force_ratio, (1.0 + a.force_error) * a.force_fe, lw=1.1, label=a.law)
        ax_r.plot(
            res.laws[0].maxima_ratio, res.laws[0].residual_fe, "ks", ms=6, alpha=0.5, label="FE"
        )
        for a in res.laws:
            ax_r.plot(a.maxima_ratio, a.residual_law, "o-", ms=3, lw=1.1, label=a.law)
        ax_f.set_xscale("log")
        ax_f.set_yscale("log")
        ax_r.set_xscale("log")
        ax_f.set_title(f"{c.description} (E*/S_y = {c.e_star_over_sy:.0f})", fontsize=8, loc="left")
        ax_f.set_ylabel("loading force F [N]", fontsize=8)
        ax_r.set_ylabel("delta_r / delta_max", fontsize=8)
        for ax in (ax_f, ax_r):
            ax.grid(True, which="both", lw=0.3)
            ax.tick_params(labelsize=8)
            ax.set_xlabel("delta / delta_c", fontsize=8)
    axes[0][1].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    return fig


def main(argv: list[str] | None = None) -> int:
    """``python -m impactlab.fe.accuracy_views [--json] [--markdown] [--figures DIR]``."""
    import argparse
    import json

    from impactlab._json import to_json

    parser = argparse.ArgumentParser(description="Accuracy of every contact law against FE.")
    parser.add_argument("--json", action="store_true", help="machine-readable output")
    parser.add_argument("--markdown", action="store_true", help="the docs page's tables")
    parser.add_argument("--figures", type=Path, default=None, help="write the PNGs there")
    args = parser.parse_args(argv)
    results = accuracy()
    if args.figures is not None:
        args.figures.mkdir(parents=True, exist_ok=True)
        for name, fig in (
            ("accuracy_errors.png", plot_errors(results)),
            ("accuracy_curves.png", plot_curves(results)),
        ):
            fig.savefig(args.figures / name, dpi=100)
            print(args.figures / name)
    if args.json:
        print(json.dumps(to_json(report(results), UNITS), indent=1))
    elif args.markdown:
        print(markdown(results))
    elif args.figures is None:
        for res in results:
            print(res.recommendation())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
