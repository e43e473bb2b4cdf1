""" "Can physics explain the experiment?" by calibration: the configurations of
:mod:`impactlab.paper.physics` ranked by PSIS-LOO on the paper's three drops, with the posterior
of each one's free parameter, the modal damping ratio zeta of the flexible rod (in place of the
hand-fitted damping row). The rigid rod has no damping: its predictions are fixed, and its score
is that of the un-tuned model.

The measured values (e, delta_p, L_s at 20, 45 and 70 deg, Sec. 5.1.3) come without stated
uncertainties; ``PAPER_SIGMAS`` are this module's assumption (e +- 0.03; delta_p and L_s +- 10 %),
stated in the section. L_s is compared with the extent of the mark the tip left
(``scar_length``: the contact point's travel of a rigid impact, a drop's scar length over all
its contacts; not the slip integral); e with the gravity impulse of the contact removed, for
the rigid rod as for the drops (``dynamics.derived.e_gravity_removed``).
"""

from __future__ import annotations

import io
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pandas as pd

from impactlab._files import write_bytes_atomic, write_text_atomic
from impactlab.calibrate import Calibration, CandidateModel, Measurements, calibrate
from impactlab.calibrate import parse_parameter as _prior
from impactlab.calibrate.sampler import ProgressFn
from impactlab.paper import data as D
from impactlab.paper.calibration_checks import band_note, checks_table, ppc_rows
from impactlab.paper.physics import FE_TABULATED, FRICTION, HARDENED_LAW, ROWS
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

#: The sampler of the shipped run: the chains' autocorrelation time is about 25 steps, so 50
#: of them after a burn-in of half the chain need about 2500 steps (2400: 45-49 of them).
SHIPPED_WALKERS = 8
SHIPPED_STEPS = 2400
#: The posterior draws of the shipped run's predictive check (the shipped summary, written
#: before the summary recorded it, used calibrate_paper's default).
SHIPPED_PPC = 30

#: Assumed standard uncertainties: e absolute, delta_p and L_s relative.
PAPER_SIGMAS = {"e": 0.03, "delta_p": 0.10, "scar_length": 0.10}
#: Steel's material damping ratio, low and high end (docs/flexible.md).
STEEL_DAMPING = (1e-4, 1e-3)
#: The prior of the flexible rod's modal damping ratio (the hand fit's scan range).
ZETA_PRIOR = "uniform(0, 0.6)"


#: The name under which the FE-tabulated law of the hardening flat is registered for the
#: calibration (a candidate model names its law; ``contact.register_law``).
HARDENED_LAW_NAME = "paper-fe-hardened"


@contextmanager
def hardened_law() -> Iterator[str]:
    """The FE-tabulated law of the hardening flat registered under :data:`HARDENED_LAW_NAME`
    while the block runs (the same curves as the physics section's), unregistered after it
    unless it was registered before: a calibration leaves the process's laws as it found them."""
    from impactlab.contact import law_names, register_law, unregister_law
    from impactlab.fe.tabulated import hardened_curves

    ours = HARDENED_LAW_NAME not in law_names()
    if ours:
        register_law(HARDENED_LAW_NAME, hardened_curves(), title=FE_TABULATED.name)
    try:
        yield HARDENED_LAW_NAME
    finally:
        if ours:
            unregister_law(HARDENED_LAW_NAME)


def paper_models(hardened: str) -> tuple[CandidateModel, ...]:
    """Every configuration of the physics section as a candidate model (its law, friction,
    body and rate), the FE-tabulated one under the registered law ``hardened``
    (``with hardened_law() as name: paper_models(name)``)."""
    return tuple(
        CandidateModel(
            hardened if c.law == HARDENED_LAW else c.law,
            FRICTION,
            "flexible_rod" if c.flexible else None,
            name=c.name,
            rate=c.rate,
        )
        for c in ROWS
    )


def paper_measurements(sigmas: dict[str, float] | None = None) -> Measurements:
    """The three drops: the paper's rod on AISI 1010, angle, drop velocity (0, v_i) and
    measured mu of each; measured e, delta_p and |L_s| with the ``PAPER_SIGMAS``."""
    s = {**PAPER_SIGMAS, **(sigmas or {})}
    records = []
    for ang, x in D.EXPERIMENTS.items():
        dp, ls = abs(x.delta_p), abs(x.L_s)
        records.append(
            {
                "label": f"{ang} deg",
                "angle": f"{x.angle_deg} deg",
                "vy": x.v_i,
                "mu": x.mu,
                "e": x.e,
                "e_sigma": s["e"],
                "delta_p": dp,
                "delta_p_sigma": s["delta_p"] * dp,
                "scar_length": ls,
                "scar_length_sigma": s["scar_length"] * ls,
            }
        )
    return Measurements.from_records(records)


def calibrate_paper(
    models: Sequence[CandidateModel] | None = None,
    *,
    walkers: int = SHIPPED_WALKERS,
    steps: int = SHIPPED_STEPS,
    seed: int = 0,
    n_ppc: int = SHIPPED_PPC,
    progress: ProgressFn | None = None,
    state_dir: Any = None,
) -> Calibration:
    """zeta ~ ``ZETA_PRIOR`` for every configuration (``models``; None: ``paper_models``)
    on the three drops. A flexible drop costs about 0.1 s here (its modes are rebuilt for each
    zeta): the defaults (the shipped run's) take about 40 minutes on 2 cores; the rigid rod
    does not use zeta (a CalibrationWarning says so)."""
    import warnings

    from impactlab.calibrate import CalibrationWarning

    with warnings.catch_warnings(), hardened_law() as hardened:
        warnings.simplefilter("ignore", CalibrationWarning)  # reported in cal.warnings
        return calibrate(
            paper_measurements(),
            [_prior("damping", ZETA_PRIOR)],
            list(paper_models(hardened) if models is None else models),
            walkers=walkers,
            steps=steps,
            seed=seed,
            n_ppc=n_ppc,
            progress=progress,
            state_dir=state_dir,
        )


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
                "zeta 90 % interval": f"[{s['q05']:.3g}, {s['q95']:.3g}]" if used else "-",
                "Pareto k > 0.7": "yes" if r["warning"] else "no",
                "converged": _yes_no(r.get("converged")),
                "note": r.get("note", ""),
            }
        )
    return pd.DataFrame(rows)


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
            pd.DataFrame(summary["ranking"]),
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
