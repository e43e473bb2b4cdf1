"""What :func:`impactlab.experiment.analyze` writes into its output folder: the figures and
``results.json``.

A folder holds one analysis: a figure that an earlier run left there and this run does not
draw (no dent measured this time, or ``figures=False``) is removed, with a warning, so that it
is never taken for this run's. A file that cannot be written (a folder of its name in the way,
no permission) is the ``figures`` or ``results`` stage's error naming the file; what was
measured is kept and still reported.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from impactlab._mpl import pyplot
from impactlab.experiment.plots import plot_dent, plot_kinematics
from impactlab.experiment.result import ExperimentResult

if TYPE_CHECKING:  # pragma: no cover - annotations only
    from matplotlib.figure import Figure

__all__ = ["FIGURES", "remove_stale_figures", "save_results", "write_figures"]

#: The figures of an analysis: name -> file name in the output folder.
FIGURES = {"kinematics": "kinematics.png", "dent": "dent.png"}
#: Their resolution [dots per inch].
FIGURE_DPI = 130


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
            fig.savefig(str(path), dpi=FIGURE_DPI)
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
    try:
        res.save(out)
    except OSError as exc:
        res.files.pop("results", None)
        res.errors["results"] = _cannot_write(path, exc)
