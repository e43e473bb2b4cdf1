"""What ``impactlab simulate`` prints and saves, and ``--from``: a recorded impact run again."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

from rich.text import Text

from impactlab._json import to_json
from impactlab.cli._common import SI_UNITS, UserError, console, emit
from impactlab.cli.drop import report_drop
from impactlab.dynamics import ImpactResult
from impactlab.dynamics.drop_result import DropResult


def run_from(path: Path) -> ImpactResult | DropResult:
    """The impact recorded in ``path`` (``impactlab simulate --json`` output, an
    ``impact_result.json`` or a result's ``to_dict()``), simulated again."""
    from impactlab.dynamics import rerun  # lazy: a fast CLI start

    try:
        record = json.loads(path.read_text())
    except OSError as exc:
        raise UserError(f"--from: cannot read {str(path)!r}: {exc.strerror}") from None
    except json.JSONDecodeError as exc:
        why = f"{exc.msg}, line {exc.lineno}"
        raise UserError(f"--from: {str(path)!r} is not JSON ({why})") from None
    if not isinstance(record, dict):
        raise UserError(f"--from: {str(path)!r} holds no result (a JSON object is needed)")
    try:
        if record.get("input", record).get("body", {}).get("type") == "FlexibleRod":
            return rerun(record, history=False)
        return rerun(record)
    except (ValueError, TypeError) as exc:
        raise UserError(f"--from {str(path)!r}: {exc}") from None


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
    emit(result.summary(), as_json=False, title="impact")
    for f in files:
        console.print(Text(f"saved {f}"))


__all__ = ["report_result", "run_from"]
