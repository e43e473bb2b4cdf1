"""``impactlab calibrate``: which model and which parameters explain measured drops.

impactlab calibrate DROPS.csv|DROPS.toml --param "mu=uniform(0, 0.6)" [--param ...]
                    [--model ghaednia/coulomb ...] [--config CAL.toml] [--walkers N]
                    [--steps N] [--burn N] [--seed N] [--out DIR] [--restart] [--json] [--quiet]
                    [--scheduler tcp://host:port]

With ``--out DIR`` the chains are kept in DIR/state (an interrupted run continues where it
stopped when run again with the same inputs; a saved chain of other inputs, or one that cannot
be read, stops the run, naming the file: ``--restart`` discards it; one run at a time uses DIR)
and results.json and report.html are written there (each whole or not at all). Ctrl-C stops
with one line naming the step reached.
"""

from __future__ import annotations

import contextlib
import json
import sys
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer

from impactlab._compile_notice import gives_way
from impactlab._json import jsonable
from impactlab.cli._common import UserError, console
from impactlab.cli.output_paths import check_replaceable, output_dir
from impactlab.cli.printing import print_wrapped

_PARAM_HELP = (
    'A free parameter and its prior, "name=uniform(low, high)", "name=loguniform(low, high)" or '
    '"name=normal(mean, sd)" ("normal(mean, sd, low, high)": truncated); values with units '
    '("flat_yield_strength=uniform(100 MPa, 1 GPa)"); repeatable, one parameter each.'
)
_MODEL_HELP = (
    'A candidate model "law/friction[/flexible_rod[/rate]]" (default ghaednia/coulomb; rate: '
    "cowper-symonds or johnson-cook, the flexible rod's flat); repeatable, one model each; "
    "they are ranked by PSIS-LOO."
)


def _parameters(specs: list[str]) -> dict[str, str]:
    out: dict[str, str] = {}
    for s in specs:
        name, sep, prior = s.partition("=")
        if not sep or not name.strip():
            raise UserError(f"--param {s!r}: expected name=prior, e.g. 'mu=uniform(0, 0.6)'")
        if name.strip() in out:
            raise UserError(
                f"--param {name.strip()} is given twice ({out[name.strip()]!r} and "
                f"{prior.strip()!r}); give each parameter once"
            )
        out[name.strip()] = prior.strip()
    return out


def _progress(quiet: bool) -> tuple[Any, Any]:
    """(progress callback, the rich Progress to stop) on stderr, or (None, None). The bar
    starts with the first report: an input error before it is one line, without a blank one."""
    if quiet:
        return None, None
    from rich.console import Console
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

    bar = Progress(
        "[progress.description]{task.description}",
        BarColumn(),
        MofNCompleteColumn(),
        TimeRemainingColumn(),
        console=Console(stderr=True),
        transient=True,
        redirect_stderr=False,  # a compile notice: the bar gives way to it (gives_way)
    )
    tasks: dict[str, Any] = {}

    def report(model: str, done: int, total: int) -> None:
        if not bar.live.is_started:  # first report, or after a compile notice
            bar.start()
        if model not in tasks:
            tasks[model] = bar.add_task(model, total=total)
        bar.update(tasks[model], completed=done)

    return report, bar


def _line(text: str) -> None:
    """One line on stdout: into a pipe or a file whole, on a terminal wrapped between words
    (``printing.print_wrapped``)."""
    print_wrapped(text, sys.stdout)


def _print(cal: Any) -> None:
    """The ranking and each model's posterior on stdout (``calibrate.display``'s rows through
    ``cli.tables.show_table``: whole into a pipe or a file; on a terminal too narrow for a
    table, turned: its fields down)."""
    from impactlab.calibrate.display import (
        POSTERIOR_HEAD,
        RANKING_HEAD,
        posterior_footer,
        posterior_rows,
        ranking_rows,
    )
    from impactlab.cli.tables import show_table

    right = [c for c in RANKING_HEAD if c not in ("model", "note")]
    show_table("models ranked by PSIS-LOO (leave one drop out)", RANKING_HEAD,
               ranking_rows(cal.ranking), right=right, label=1)  # fmt: skip
    shown = set(cal.warnings)  # printed as warnings already
    right = [c for c in POSTERIOR_HEAD if c not in ("parameter", "unit")]
    for name, post in cal.posteriors.items():
        show_table(name, POSTERIOR_HEAD, posterior_rows(post), right=right)
        _line(posterior_footer(post))
        for w in post.warnings:
            if f"{name}: {w}" not in shown and w not in shown:
                _line(f"  note: {w}")


def calibrate_cmd(
    measurements: Annotated[
        Path | None, typer.Argument(help="Measurements file (CSV or TOML, docs/calibrate.md).")
    ] = None,
    param: Annotated[
        list[str] | None, typer.Option("--param", "-p", metavar="PARAM", help=_PARAM_HELP)
    ] = None,
    model: Annotated[
        list[str] | None, typer.Option("--model", "-m", metavar="MODEL", help=_MODEL_HELP)
    ] = None,
    config: Annotated[
        Path | None, typer.Option(help="Calibration file (TOML): measurements, parameters, ...")
    ] = None,
    walkers: Annotated[int | None, typer.Option(help="Ensemble size (default 16 or 4 P).")] = None,
    steps: Annotated[int | None, typer.Option(help="Steps per walker (default 1000).")] = None,
    burn: Annotated[int | None, typer.Option(help="Steps discarded (default steps/2).")] = None,
    seed: Annotated[int | None, typer.Option(help="Random seed (default 0).")] = None,
    out: Annotated[
        Path | None, typer.Option(help="Folder for the saved chains, results.json, report.html.")
    ] = None,
    restart: Annotated[
        bool,
        typer.Option(
            help="Discard the saved chains in --out (a chain saved with other inputs stops a run)."
        ),
    ] = False,
    scheduler: Annotated[
        str | None, typer.Option(help="Dask scheduler address: one task per model there.")
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print the result as JSON.")] = False,
    quiet: Annotated[
        bool, typer.Option("--quiet/--no-quiet", "-q", help="No progress display.")
    ] = False,
) -> None:
    """Calibrate free parameters of candidate models on measured drops (emcee on the compiled
    batch engine) and rank the models (PSIS-LOO).

    The measurements file has one row per drop (docs/calibrate.md); impactlab analyze
    --measurements FILE.csv --label NAME appends an analysed drop to it.

    Examples:

    \b
      impactlab calibrate examples/data/drops.csv -p "mu=uniform(0, 0.6)" \\
        -p "flat_yield_strength=uniform(100 MPa, 1 GPa)"

    \b
      impactlab calibrate drops.csv -p "mu=uniform(0, 0.6)" \\
        -p "flat_yield_strength=loguniform(100 MPa, 1 GPa)" \\
        -m ghaednia/coulomb -m jackson-green/coulomb --steps 2000 --out cal

    \b
      impactlab analyze drop20.c3d dent20.x3p --geometry markers.toml \\
        --measurements drops.csv --label d20
      impactlab calibrate drops.csv \\
        -p "flat_yield_strength=uniform(100 MPa, 1 GPa)" --json

    \b
      impactlab calibrate --config cal.toml --out cal
    """
    from impactlab.calibrate import calibrate
    from impactlab.calibrate.config import load_config
    from impactlab.calibrate.report import save
    from impactlab.calibrate.statelock import SavedChainError, StateInUseError

    kw: dict[str, Any] = load_config(config) if config is not None else {}
    if measurements is not None:
        kw["measurements"] = measurements
    if "measurements" not in kw:
        raise UserError("no measurements: give the file as argument or in --config")
    if param:
        given = [_as_param(k, v) for k, v in _parameters(param).items()]
        kw["parameters"] = [*kw.get("parameters", []), *given]
    if not kw.get("parameters"):
        raise UserError('no free parameter: give --param "name=prior" or [parameters] in --config')
    if model:
        kw["models"] = model
    sampler = {"walkers": walkers, "steps": steps, "burn": burn, "seed": seed}
    kw.update({k: v for k, v in sampler.items() if v is not None})
    kw.update(_run_options(seed, out, restart))
    if scheduler is not None:
        kw["scheduler"] = scheduler
        quiet = True  # the workers cannot report progress here
    report, bar = _progress(quiet)
    try:
        with gives_way(bar) if bar is not None else contextlib.nullcontext():
            cal = calibrate(progress=report, **kw)
    except StateInUseError as exc:
        if out is None or exc.folder != out / "state":
            raise
        raise UserError(
            f"another calibration is using {out}: wait for it to end or choose another --out"
            if "another calibration" in str(exc)
            else str(exc)
        ) from None
    except SavedChainError as exc:
        raise UserError(
            f"the saved chain {exc.state} {exc.reason}; it is kept: --restart discards it and "
            "starts again (or choose another --out)"
        ) from None
    except KeyboardInterrupt as exc:
        _interrupted(exc, bar, out)
    except ValueError as exc:  # the sampler's settings: named as the user gave them
        raise _sampler_error(exc, sampler, config, kw.get("steps", 1000)) from None
    finally:
        if bar is not None and bar.live.is_started:  # stop() prints a line on its own
            bar.stop()
    files = save(cal, out) if out is not None else {}
    if as_json:
        from impactlab.calibrate.jsonout import calibration_json

        doc = calibration_json(cal)
        doc["files"] = {k: str(v) for k, v in files.items()}
        print(json.dumps(jsonable(doc), indent=2))
        return
    _print(cal)
    for k, v in files.items():
        console.print(f"{k}: {v}")


def _run_options(seed: int | None, out: Path | None, restart: bool) -> dict[str, Any]:
    """``state_dir`` and ``restart`` of ``--out``/``--restart``; UserError naming the option
    for a seed outside [0, 2^32), ``--restart`` without ``--out``, an ``--out`` that is a file
    or holds a user's results.json or report.html (``output_paths.check_replaceable``)."""
    from impactlab.calibrate.input_checks import MAX_SEED
    from impactlab.calibrate.report import FILES, RESULT_KEYS

    if seed is not None and not 0 <= seed <= MAX_SEED:
        raise UserError(f"--seed must be an integer in [0, {MAX_SEED}], got {seed}")
    if restart and out is None:
        raise UserError("--restart discards the chains saved in --out: give --out DIR too")
    if out is None:
        return {}
    if out.exists() and not out.is_dir():
        raise UserError(f"--out {str(out)!r} is a file; give a folder")
    output_dir(out, "--out")  # a file above it, or a folder no file can be made in
    check_replaceable(out, FILES.values(), "calibrate", "--out", {FILES["results"]: RESULT_KEYS})
    return {"state_dir": out / "state", "restart": restart}


def _sampler_error(
    exc: ValueError, given: dict[str, int | None], config: Path | None, steps: int
) -> ValueError:
    """``exc`` (``calibrate``'s ValueError) with a sampler setting at its head ("steps must be
    >= 10, got 5") named as the user gave it: ``--steps`` on the command line, ``[sampler]
    steps`` in the --config file; "[0, steps)" with the number of steps. Any other error as
    it is."""
    head, _, rest = str(exc).partition(" ")
    if head not in given or not rest:
        return exc
    rest = rest.replace("[0, steps)", f"[0, {steps})")
    if given[head] is not None or config is None:
        return UserError(f"--{head} {rest}")
    return UserError(f"{config}: [sampler] {head} {rest}")


def _interrupted(exc: KeyboardInterrupt, bar: Any, out: Path | None) -> NoReturn:
    """Ctrl-C: one line on stderr (the step reached; how to resume), exit status 130."""
    from impactlab.calibrate.statelock import CalibrationInterrupted

    if bar is not None and bar.live.is_started:
        bar.stop()
    if isinstance(exc, CalibrationInterrupted):
        text = str(exc)
    elif out is not None:
        text = "interrupted; run the same command again to resume (the chains are in --out)"
    else:
        text = "interrupted (nothing was saved: give --out DIR to resume later)"
    print(text, file=sys.stderr)
    raise typer.Exit(130)


def _as_param(name: str, prior: str) -> Any:
    from impactlab.calibrate import parse_parameter

    return parse_parameter(name, prior)


def register(app: typer.Typer) -> None:
    """Add ``impactlab calibrate`` to ``app``."""
    app.command("calibrate")(calibrate_cmd)
