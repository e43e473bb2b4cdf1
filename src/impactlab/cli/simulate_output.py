"""What ``impactlab simulate`` prints and saves (``--from``: ``impactlab.cli.simulate_from``)."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

from rich.text import Text

from impactlab._json import to_json
from impactlab.cli._common import SI_UNITS, console, emit
from impactlab.cli.drop import report_drop
from impactlab.dynamics import ImpactResult
from impactlab.dynamics.drop_result import DropResult


def report_result(result: ImpactResult | DropResult, *, out: Path | None, as_json: bool) -> None:
    """Print ``result`` (warnings on stderr; a table, or ``--json``) and, with ``out``, save its
    figures and ``impact_result.json`` there."""
    for text in result.warnings:
        print(f"warning: {text}", file=sys.stderr)
    if isinstance(result, DropResult):
        report_drop(result, as_json=as_json)
        return
    sphere = not math.isfinite(result.angle)
    hidden = ("angle", "angle_out") if sphere else ()
    data = {k: v for k, v in result.to_dict().items() if k not in hidden}
    files: list[str] = []
    if out is not None:
        from impactlab.dynamics.plotting import save_figures  # lazy: a fast CLI start

        files = [str(p) for p in save_figures(result, out)]
        saved = out / "impact_result.json"
        saved.write_text(json.dumps(to_json(data, SI_UNITS), indent=2))
        files.append(str(saved))
    if as_json:
        emit({**data, "files": files}, as_json=True)
        return
    emit(result.summary(), as_json=False, title="impact", units=result.display_units())
    for f in files:
        console.print(Text(f"saved {f}"))


__all__ = ["report_result"]
