"""What ``impactlab simulate`` prints and saves (``--from``: ``impactlab.cli.simulate_from``).

With ``--plot`` the figures (``impactlab.dynamics.plotting``, each as PNG and PDF) and
``impact_result.json`` go into ``--out`` (the current folder by default; where the impacting
body yields first, ``ImpactResult.body_yields_first``, the flat has no dent: no dent figure, and
the contact path without one): files that an earlier
``impactlab simulate`` wrote there are replaced, a user's file of the same name never
(``impactlab.cli.output_paths``; checked before the impact is simulated)."""

from __future__ import annotations

import json
import math
from pathlib import Path

from rich.text import Text

from impactlab._files import write_bytes_atomic, write_text_atomic
from impactlab._interrupts import signals_held
from impactlab._json import jsonable, to_json
from impactlab.cli._common import SI_UNITS, console, emit
from impactlab.cli.drop import missing_as_nan, report_drop
from impactlab.cli.output_paths import check_replaceable, figure_bytes
from impactlab.cli.printing import print_wrapped
from impactlab.dynamics import ImpactResult
from impactlab.dynamics.drop_result import DropResult

#: The figures of ``--plot`` (the ``plot_*`` of ``impactlab.dynamics.plotting``), their formats
#: and resolution [dpi], and the result saved with them.
FIGURES = ("force_time", "force_penetration", "contact_path", "dent")
FORMATS = ("png", "pdf")
FIGURE_DPI = 150
RESULT_FILE = "impact_result.json"
#: Keys that every ``impact_result.json`` of ``impactlab simulate`` holds (how it is known).
RESULT_KEYS = ("e", "delta_p", "duration", "mean_force", "impactlab_version", "input")


def output_names() -> list[str]:
    """The files ``--plot`` writes into its folder."""
    return [f"impact_{name}.{ext}" for name in FIGURES for ext in FORMATS] + [RESULT_FILE]


def check_plot_folder(folder: Path) -> None:
    """UserError, before anything runs, when a file ``--plot`` writes into ``folder`` is a
    user's (not written by ``impactlab simulate``) or a folder of that name."""
    check_replaceable(folder, output_names(), "simulate", "--out", {RESULT_FILE: RESULT_KEYS})


def _save(result: ImpactResult, data: dict[str, object], out: Path) -> list[str]:
    """The figures and ``impact_result.json`` written into ``out`` (made with its parents),
    each whole and marked as impactlab simulate's; the paths written. Everything is drawn
    first, then written together with Ctrl-C held, so that an interrupted run leaves the
    earlier run's files, not some of each."""
    from impactlab._mpl import pyplot
    from impactlab.dynamics import plotting
    from impactlab.experiment.checks import output_folder

    output_folder(out, "--out")
    plt, drawn = pyplot(), {}
    # no dent in the flat: the body yields first, or the impact leaves none (an elastic law)
    no_dent = not (result.delta_p > 0.0) or result.body_yields_first
    for name in FIGURES:
        if no_dent and name == "dent":
            continue
        fig = getattr(plotting, f"plot_{name}")(result)  # the contact path: no dent there
        try:
            for ext in FORMATS:
                path = out / f"impact_{name}.{ext}"
                drawn[path] = figure_bytes(fig, path, "simulate", FIGURE_DPI)
        finally:
            plt.close(fig)
    saved = out / RESULT_FILE
    with signals_held():
        for path, content in drawn.items():
            write_bytes_atomic(path, content)
        if no_dent:  # an earlier run's dent (checked replaceable) would mislead
            for ext in FORMATS:
                (out / f"impact_dent.{ext}").unlink(missing_ok=True)
        write_text_atomic(saved, json.dumps(to_json(data, SI_UNITS), indent=2))
    return [*map(str, drawn), str(saved)]


def report_result(result: ImpactResult | DropResult, *, out: Path | None, as_json: bool) -> None:
    """Print ``result`` (warnings on stderr; a table, or ``--json``) and, with ``out``, save its
    figures and ``impact_result.json`` there."""
    for text in result.warnings:
        print_wrapped(f"warning: {text}")
    if isinstance(result, DropResult):
        report_drop(result, as_json=as_json)
        return
    sphere = not math.isfinite(result.angle)
    hidden = ("angle", "angle_out") if sphere else ()
    data = {k: v for k, v in result.to_dict().items() if k not in hidden}
    recorded = data.pop("input")  # the record as written: its numbers are not result fields
    data = missing_as_nan(data, SI_UNITS) | {"input": recorded}
    files = _save(result, data, out) if out is not None else []
    if as_json:  # the record as it is: a law's data holds numbers under result fields' names
        doc = to_json({k: v for k, v in data.items() if k != "input"}, SI_UNITS)
        print(json.dumps(doc | {"input": jsonable(recorded), "files": files}, indent=2))
        return
    emit(result.summary(), as_json=False, title="impact", units=result.display_units())
    for f in files:
        console.print(Text(f"saved {f}"))


__all__ = ["check_plot_folder", "output_names", "report_result"]
