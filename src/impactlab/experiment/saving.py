"""What :func:`impactlab.experiment.analyze` writes into its output folder: the figures and
``results.json``.

A folder holds one analysis: a figure that an earlier run left there and this run does not
draw (no dent measured this time, or ``figures=False``) is removed, with a warning, so that it
is never taken for this run's. Only files that an analysis wrote are removed or overwritten: its
figures carry a mark (the PNG text chunk ``Software: impactlab analyze ...``) and its
``results.json`` its own keys; a file of the same name without them (a photo saved as
``dent.png``) is left as it is, with a warning, or, where this run would write over it, that
file is not written (the stage's error). A file that cannot be written (a folder of its name in
the way, no permission) is the ``figures`` or ``results`` stage's error naming the file; what
was measured is kept and still reported.
"""

from __future__ import annotations

import json
import struct
from pathlib import Path
from typing import TYPE_CHECKING

from impactlab._mpl import pyplot
from impactlab._version import __version__
from impactlab.experiment.plots import plot_dent, plot_kinematics
from impactlab.experiment.result import ExperimentResult

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from matplotlib.figure import Figure

__all__ = [
    "FIGURES",
    "MARK",
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


def write_figures(res: ExperimentResult, out: Path) -> None:
    """Draw the figures of what ``res`` measured into ``out`` (``res.figures``)."""
    plt = pyplot()
    drawn: list[tuple[str, Figure]] = []
    if res.kinematics is not None:
        drawn.append(("kinematics", plot_kinematics(res.kinematics)))
    if res.dent is not None:
        drawn.append(("dent", plot_dent(res.dent)))
    for name, fig in drawn:
        path = out / FIGURES[name]
        try:
            if path.is_file() and not written_by_analyze(path):
                res.errors["figures"] = f"not written: {_foreign(path)}"
                continue
            fig.savefig(str(path), dpi=FIGURE_DPI, metadata={"Software": f"{MARK} {__version__}"})
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
        if not written_by_analyze(path):
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
    """Write ``results.json`` into ``out``; a failure is the ``results`` stage's error."""
    path = out / "results.json"
    if path.is_file() and not written_by_analyze(path):
        res.errors["results"] = f"not written: {_foreign(path)}"
        return
    try:
        res.save(out)
    except OSError as exc:
        res.files.pop("results", None)
        res.errors["results"] = _cannot_write(path, exc)
