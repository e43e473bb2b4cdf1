"""What :func:`impactlab.experiment.analyze` writes into its output folder: the figures and
``results.json``.

A folder holds one analysis: a figure that an earlier run left there and this run does not
draw (no dent measured this time, or ``figures=False``) is removed, with a warning, so that it
is never taken for this run's. Only files that an analysis wrote are removed or overwritten: its
figures carry a mark (the PNG text chunk ``Software: impactlab analyze ...``) and its
``results.json`` its own keys; a file of the same name without them (a photo saved as
``dent.png``) is left as it is, with a warning, or, where this run would write over it, that
file is not written (the stage's error). A file left damaged by an earlier run (an empty file,
or a ``results.json`` cut short that starts as an analysis writes it) is replaced, with a
warning. ``results.json`` is the folder's record of the analysis: when it cannot be written (a
user's file of that name, a folder in the way), which is checked before anything is written,
nothing is written or removed there. Every file is written whole or not at all
(``impactlab._files``). A file that cannot be written (no permission) is the ``figures`` or
``results`` stage's error naming the file; what was measured is kept and still reported.
"""

from __future__ import annotations

import io
import json
import os
import re
import struct
from pathlib import Path
from typing import TYPE_CHECKING

from impactlab._files import write_bytes_atomic
from impactlab._mpl import pyplot
from impactlab._version import __version__
from impactlab.experiment.plots import plot_dent, plot_kinematics
from impactlab.experiment.result import ExperimentResult

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from matplotlib.figure import Figure

__all__ = [
    "FIGURES",
    "MARK",
    "check_folder",
    "remove_stale_figures",
    "save_results",
    "write_figures",
    "written_by_analyze",
]

#: The figures of an analysis: name -> file name in the output folder.
FIGURES = {"kinematics": "kinematics.png", "dent": "dent.png"}
#: Their resolution [dots per inch].
FIGURE_DPI = 130
#: The mark of a figure written by an analysis: the start of its PNG "Software" text.
MARK = "impactlab analyze"
#: The keys that every results.json of an analysis holds.
_RESULT_KEYS = {"markers", "scan", "summary", "errors", "warnings"}
_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: How a results.json of an analysis starts (its first key): a file that starts so but is not
#: valid JSON is one cut short.
_RESULTS_HEAD = re.compile(r'\A\s*\{\s*"markers"\s*:')


def _marked_png(path: Path) -> bool:
    """Whether ``path`` is a PNG whose text chunks, before its image data, hold ``MARK`` as
    its "Software"."""
    with path.open("rb") as fh:
        if fh.read(8) != _PNG_SIGNATURE:
            return False
        while True:
            head = fh.read(8)
            if len(head) < 8:
                return False
            size, kind = struct.unpack(">I4s", head)
            if kind in (b"IDAT", b"IEND") or size > 1 << 20:
                return False
            data = fh.read(size)
            fh.read(4)  # the chunk's CRC
            if kind == b"tEXt":
                key, _, value = data.partition(b"\0")
                if key == b"Software" and value.startswith(MARK.encode()):
                    return True


def _our_results(path: Path) -> bool:
    """Whether ``path`` is a results.json that an analysis wrote (its keys)."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except ValueError:
        return False
    return isinstance(data, dict) and _RESULT_KEYS <= data.keys()


def written_by_analyze(path: Path) -> bool:
    """Whether the file ``path`` was written by an analysis (module docstring); False for a
    file that cannot be read."""
    try:
        return _our_results(path) if path.suffix == ".json" else _marked_png(path)
    except OSError:
        return False


def damaged(path: Path) -> str | None:
    """How the file ``path`` is damaged, when it is an analysis' own left damaged (an empty
    file: nothing to lose; a results.json cut short: not JSON, but it starts as an analysis
    writes one); None otherwise."""
    try:
        if path.stat().st_size == 0:
            return "it is empty"
        if path.suffix != ".json":
            return None
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return None
    if not _RESULTS_HEAD.match(text):
        return None
    try:
        json.loads(text)
    except ValueError:
        return "it is cut short (not valid JSON), left by an interrupted run"
    return None


def _replaceable(path: Path, res: ExperimentResult, stage: str) -> bool:
    """Whether the existing file ``path`` may be written over: written by an analysis, or such
    a file left damaged (:func:`damaged`; a warning of ``stage`` says that it is replaced)."""
    if written_by_analyze(path):
        return True
    why = damaged(path)
    if why is not None:
        res.warnings.append(f"{stage}: {str(path)!r} is replaced: {why}")
    return why is not None


def _foreign(path: Path) -> str:
    return (
        f"{str(path)!r} is in the output folder but was not written by impactlab analyze: it is "
        "left as it is (move it, or choose another output folder)"
    )


def _cannot_write(path: Path, exc: OSError) -> str:
    if path.is_dir():
        return (
            f"cannot write {str(path)!r}: a folder of that name is in the way (remove or rename "
            "it, or choose another output folder)"
        )
    return f"cannot write {str(path)!r}: {exc.strerror or exc}"


def check_folder(res: ExperimentResult, out: Path, figures: bool = True) -> bool:
    """Whether this run may write into ``out``: False, with the ``results`` (and, when it would
    draw ``figures``, the ``figures``) stage's error, when its ``results.json`` cannot be written
    (a user's file of that name, a folder in the way, a folder without write permission);
    checked before anything is written, so that the folder is then left as it was."""
    path = out / "results.json"
    if path.is_dir():
        res.errors["results"] = _cannot_write(path, OSError("a folder is in the way"))
    elif path.is_file() and not written_by_analyze(path) and damaged(path) is None:
        res.errors["results"] = f"not written: {_foreign(path)}"
    elif not os.access(out, os.W_OK | os.X_OK):
        res.errors["results"] = f"cannot write {str(path)!r}: no permission to write in the folder"
    else:
        return True
    if figures and (res.kinematics is not None or res.dent is not None):
        res.errors["figures"] = (
            f"not written: the figures are written with {str(path)!r}, the record of the "
            "analysis, which cannot be written (see results); nothing in the folder was changed"
        )
    return False


def write_figures(res: ExperimentResult, out: Path) -> None:
    """Draw the figures of what ``res`` measured into ``out`` (``res.figures``), each written
    whole or not at all."""
    plt = pyplot()
    drawn: list[tuple[str, Figure]] = []
    if res.kinematics is not None:
        drawn.append(("kinematics", plot_kinematics(res.kinematics)))
    if res.dent is not None:
        drawn.append(("dent", plot_dent(res.dent)))
    for name, fig in drawn:
        path = out / FIGURES[name]
        try:
            if path.is_file() and not _replaceable(path, res, "figures"):
                res.errors["figures"] = f"not written: {_foreign(path)}"
                continue
            png = io.BytesIO()
            fig.savefig(png, dpi=FIGURE_DPI, metadata={"Software": f"{MARK} {__version__}"})
            write_bytes_atomic(path, png.getvalue())
        except OSError as exc:
            res.errors["figures"] = _cannot_write(path, exc)
            continue
        finally:
            plt.close(fig)
        res.figures[name] = str(path)


def remove_stale_figures(res: ExperimentResult, out: Path) -> None:
    """Remove the figures in ``out`` that this run did not draw (module docstring)."""
    for name, file in FIGURES.items():
        path = out / file
        if name in res.figures or not path.is_file():
            continue
        if not written_by_analyze(path) and damaged(path) is None:
            if str(path) in res.errors.get("figures", ""):
                continue  # refused by write_figures, said there
            res.warnings.append(f"figures: {_foreign(path)}; it does not show this run")
            continue
        try:
            path.unlink()
        except OSError as exc:
            res.warnings.append(
                f"figures: {str(path)!r} is left from an earlier run and could not be removed "
                f"({exc.strerror or exc}): it does not show this run"
            )
        else:
            res.warnings.append(
                f"figures: removed {str(path)!r}, left by an earlier run (this run drew no "
                f"{name} figure)"
            )


def save_results(res: ExperimentResult, out: Path) -> None:
    """Write ``results.json`` into ``out`` (whole or not at all); a failure is the ``results``
    stage's error."""
    path = out / "results.json"
    if path.is_file() and not _replaceable(path, res, "results"):
        res.errors["results"] = f"not written: {_foreign(path)}"
        return
    try:
        res.save(out)
    except OSError as exc:
        res.files.pop("results", None)
        res.errors["results"] = _cannot_write(path, exc)
