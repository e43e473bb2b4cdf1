""" "Can physics explain the experiment?" by calibration: the configurations of
:mod:`impactlab.paper.physics` ranked by PSIS-LOO on the paper's three drops, with the posterior
of each one's free parameter, the modal damping ratio zeta of the flexible rod (in place of the
hand-fitted damping row). The rigid rod has no damping: its predictions are fixed, and its score
is that of the un-tuned model.

The drops, their assumed uncertainties (``PAPER_SIGMAS``), the models and the run
(``calibrate_paper``) are :mod:`impactlab.paper.calibration_run`'s; this module holds what the
report shows of a calibration, the shipped summary and the section.
"""

from __future__ import annotations

import io
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd

from impactlab._files import write_bytes_atomic, write_text_atomic
from impactlab.calibrate import Calibration
from impactlab.paper.calibration_checks import (
    band_note,
    checks_table,
    interval_text,
    ppc_rows,
    reformat_interval,
)
from impactlab.paper.calibration_run import (  # noqa: F401  (re-exported: the old home)
    HARDENED_LAW_NAME,
    PAPER_SIGMAS,
    SHIPPED_PPC,
    SHIPPED_STEPS,
    SHIPPED_WALKERS,
    ZETA_PRIOR,
    calibrate_paper,
    hardened_law,
    paper_measurements,
    paper_models,
)
from impactlab.paper.report import Block, Bullets, Heading, Para, Table

__all__ = [
    "HARDENED_LAW_NAME",
    "PAPER_SIGMAS",
    "SHIPPED",
    "ZETA_PRIOR",
    "calibrate_paper",
    "calibration_section",
    "calibration_summary",
    "hardened_law",
    "paper_measurements",
    "paper_models",
    "shipped_calibration",
    "write_calibration_report",
    "write_shipped_calibration",
]

#: The calibration of the paper's three drops shipped with the package (the reproduction
#: report reads it: a run takes minutes of flexible drops), written by
#: ``write_shipped_calibration`` (``python3 tasks.py calibrate-paper``).
SHIPPED = Path(__file__).resolve().parent / "data" / "calibration.json"

#: Steel's material damping ratio, low and high end (docs/flexible.md).
STEEL_DAMPING = (1e-4, 1e-3)


#: The ranking's column of the posterior interval of zeta.
ZETA_INTERVAL = "zeta 90 % interval"


def _ranking(cal: Calibration) -> pd.DataFrame:
    rows = []
    for r in cal.ranking:
        post = cal.posteriors[r["model"]]
        s = post.summary["damping"]
        used = f"model {r['model']!r} does not use damping" not in " ".join(cal.warnings)
        rows.append(
            {
                "rank": r["rank"] + 1,
                "configuration": r["model"],
                "elpd_loo": r["elpd_loo"],
                "se": r["se"],
                "elpd_diff": r["elpd_diff"],
                "dse": r["dse"],
                "zeta median": s["median"] if used else None,
                ZETA_INTERVAL: interval_text(s["q05"], s["q95"]) if used else "-",
                "Pareto k > 0.7": "yes" if r["warning"] else "no",
                "converged": _yes_no(r.get("converged")),
                "note": r.get("note", ""),
            }
        )
    return pd.DataFrame(rows)


def _ranking_shown(ranking: Sequence[Mapping[str, Any]]) -> pd.DataFrame:
    """The ranking as the report shows it: a stored zeta interval in the report's number
    format (``calibration_checks.reformat_interval``)."""
    table = pd.DataFrame(list(ranking))
    if ZETA_INTERVAL in table:
        table[ZETA_INTERVAL] = [reformat_interval(v) for v in table[ZETA_INTERVAL]]
    return table


def _yes_no(flag: Any) -> str:
    return "-" if flag is None else ("yes" if flag else "no")


def calibration_summary(cal: Calibration, n_ppc: int | None = None) -> dict[str, Any]:
    """What the report shows of ``cal``, as plain JSON values: the sampler settings (with
    ``n_ppc``, the posterior draws of the predictive check, when given), the ranking and the
    posterior predictive check (rows, with each measurement's sigma), every warning and every
    failure."""
    import json

    from impactlab._version import __version__

    return {
        "impactlab_version": __version__,
        "settings": {k: cal.settings[k] for k in ("walkers", "steps", "burn", "seed")}
        | ({} if n_ppc is None else {"n_ppc": n_ppc}),
        "ranking": json.loads(_ranking(cal).to_json(orient="records")),
        "checks": json.loads(pd.DataFrame(ppc_rows(cal.posteriors)).to_json(orient="records")),
        "warnings": list(
            dict.fromkeys(  # each once: a model's problems are also the calibration's
                [*cal.warnings]
                + [f"{name}: {w}" for name, p in cal.posteriors.items() for w in p.warnings]
            )
        ),
        "failures": [
            f"{name}: {k} ({v} cases, likelihood zero)"
            for name, p in cal.posteriors.items()
            for k, v in p.failures.items()
        ],
    }


def write_shipped_calibration(path: str | Path = SHIPPED, **settings: Any) -> Path:
    """Run ``calibrate_paper(**settings)`` and write its ``calibration_summary`` as JSON."""
    import json

    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    cal = calibrate_paper(**settings)
    summary = calibration_summary(cal, settings.get("n_ppc", SHIPPED_PPC))
    write_text_atomic(out, json.dumps(summary, indent=1) + "\n")
    return out


def shipped_calibration() -> dict[str, Any]:
    """The shipped ``calibration_summary`` of the paper's three drops (``SHIPPED``)."""
    import json

    return dict(json.loads(SHIPPED.read_text()))


def _unconverged(notes: Sequence[str]) -> list[str]:
    """The R-hat warnings of the models that sample zeta (a model that does not use it samples
    its prior: its R-hat says nothing about the calibration)."""
    import re

    unused = {m for w in notes for m in re.findall(r"model '(.+?)' does not use damping", w)}
    return [w for w in notes if "R-hat" in w and not any(w.startswith(f"{m}:") for m in unused)]


def calibration_section(cal: Calibration | Mapping[str, Any], number: int) -> list[Block]:
    """The report's blocks: what was calibrated, the ranking with each configuration's
    posterior of zeta, the posterior predictive check of every measured value, and every
    warning (nothing hidden); ``cal``: a calibration or its ``calibration_summary``."""
    shipped = isinstance(cal, Mapping)
    summary = cal if isinstance(cal, Mapping) else calibration_summary(cal)
    st = summary["settings"]
    notes = tuple(summary["warnings"])
    ranked = list(summary["ranking"])
    if ranked and "converged" in ranked[0]:  # the calibration's own verdict, per model
        unconverged = [str(r["configuration"]) for r in ranked if r["converged"] == "no"]
    else:
        unconverged = _unconverged(notes)
    origin = (
        f" These numbers are shipped with the package (paper/data/calibration.json, computed by "
        f"`python3 tasks.py calibrate-paper` with impactlab {summary['impactlab_version']}); "
        "`impactlab reproduce` reads them and does not rerun the calibration."
        if shipped
        else ""
    )
    verdict = (
        f" The chains did not converge ({len(unconverged)} of them; the warnings below say "
        "which): the ranking and the intervals are provisional."
        if unconverged
        else " Every chain that samples zeta converged (R-hat <= 1.05 over the walkers, and "
        "50 autocorrelation times after the burn-in)."
    )
    fixed = {str(r["configuration"]) for r in ranked if r.get("zeta median") is None}
    checks = checks_table(summary["checks"], fixed, PAPER_SIGMAS)
    fails = tuple(summary["failures"])
    warned: list[Block] = [Para("Warnings of the calibration:"), Bullets(notes)] if notes else []
    failed: list[Block] = [Para("Failed cases:"), Bullets(fails)] if fails else []
    return [
        Heading(f"{number}. Which physics explains the experiment? (calibrated)"),
        Para(
            "The configurations of the previous section ranked by PSIS-LOO (the expected log "
            "predictive density of each drop left out in turn; higher is better, a difference "
            "means something beyond about 2 dse), each with the posterior of its free "
            f"parameter, the flexible rod's modal damping ratio zeta (prior {ZETA_PRIOR}, one "
            "zeta for every mode). This replaces the hand-fitted damping row. Likelihood: "
            "independent Gaussian errors with assumed standard uncertainties (the paper gives "
            "none): e +- 0.03, delta_p and L_s +- 10 %; L_s is compared with the extent of "
            "the mark the tip left (the scar length), as in the previous section. Sampler: "
            f"emcee, {st['walkers']} walkers x {st['steps']} steps ({st['burn']} discarded), "
            f"seed {st['seed']}. With three drops the PSIS-LOO standard errors are wide."
            + verdict
            + origin
        ),
        Table(
            _ranking_shown(summary["ranking"]),
            "Configurations ranked by PSIS-LOO, with the posterior of zeta",
        ),
        *_damping_note(ranked),
        Table(checks, "Posterior predictive check of every measured value"),
        Para(band_note(checks, st.get("n_ppc", SHIPPED_PPC if shipped else None))),
        *warned,
        *failed,
    ]


def _power(x: float) -> str:
    """``1e-4`` for 0.0001."""
    return f"{x:.0e}".replace("e-0", "e-")


def _damping_note(ranked: Sequence[Mapping[str, Any]]) -> list[Block]:
    """What the posterior zeta means beside steel's own damping (docs/flexible.md)."""
    zetas = [float(r["zeta median"]) for r in ranked if r.get("zeta median") is not None]
    if not zetas:
        return []
    lo, hi = min(zetas), max(zetas)
    return [
        Para(
            f"The zeta medians, {lo:.2g} to {hi:.2g}, are {lo / STEEL_DAMPING[1]:.0f} to "
            f"{hi / STEEL_DAMPING[1]:.0f} times the upper end of steel's material damping "
            f"({_power(STEEL_DAMPING[0])} to {_power(STEEL_DAMPING[1])}; docs/flexible.md): zeta "
            "stands for whatever takes that much energy out of the rod's vibration (the release, "
            "the support, the flat), which the experiment does not show; it is not a property "
            "of the rod, and a configuration ranked high with it is not thereby confirmed."
        )
    ]


def write_calibration_report(
    out_dir: str | Path, cal: Calibration | None = None, *, number: int = 12, **settings: Any
) -> dict[str, Path]:
    """Write the section as ``calibration.md`` and ``calibration.html`` (self-contained, with
    the predicted-vs-measured figure ``calibration_ppc.png``) into ``out_dir`` (a reproduction
    folder, next to its report); ``cal``: a finished calibration, else ``calibrate_paper(**
    settings)`` is run. Returns name -> path."""
    from impactlab._mpl import pyplot
    from impactlab.calibrate.plots import ppc_figure
    from impactlab.paper.report import Figure, to_html, to_markdown

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    cal = cal if cal is not None else calibrate_paper(**settings)
    fig = ppc_figure(cal.posteriors)
    png = out / "calibration_ppc.png"
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    pyplot().close(fig)
    write_bytes_atomic(png, buf.getvalue())
    blocks = [
        *calibration_section(cal, number),
        Figure(
            png.name,
            "Measured (+- assumed sigma) and each configuration's prediction: "
            "median, 90 % band of the model, and with the noise (wide)",
        ),
    ]
    title = "Which physics explains the experiment? (calibrated)"
    files = {"markdown": out / "calibration.md", "html": out / "calibration.html", "figure": png}
    write_text_atomic(files["markdown"], to_markdown(blocks, title))
    write_text_atomic(files["html"], to_html(blocks, title, base=out))
    return files


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m impactlab.paper.calibration_report OUT_DIR [STEPS]``: run and write the
    section into OUT_DIR; ``--shipped [STEPS]``: run and write the shipped summary
    (``SHIPPED``, what the reproduction report shows); ``-h``, ``--help``: the usage, rc 0."""
    import sys

    args = list(sys.argv[1:] if argv is None else argv)
    usage = "usage: python -m impactlab.paper.calibration_report OUT_DIR|--shipped [STEPS >= 10]"
    asked = "-h" in args or "--help" in args
    if asked or not 1 <= len(args) <= 2 or (args[0].startswith("-") and args[0] != "--shipped"):
        print(usage, file=sys.stdout if asked else sys.stderr)
        return 0 if asked else 2
    try:
        steps = int(args[1]) if len(args) == 2 else SHIPPED_STEPS
    except ValueError:
        steps = 0
    if steps < 10:
        print(f"error: STEPS must be an integer >= 10, got {args[1]!r}", file=sys.stderr)
        return 2
    if args[0] == "--shipped":
        print(f"summary: {write_shipped_calibration(steps=steps)}")
        return 0
    for name, path in write_calibration_report(args[0], steps=steps).items():
        print(f"{name}: {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
