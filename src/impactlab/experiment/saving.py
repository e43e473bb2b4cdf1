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
(``impactlab._files``), and under a temporary name first: the figures and ``results.json`` are
renamed into place together, and an earlier run's figures removed, only when all were written,
so that a full disk leaves the folder as it was; the files they replace are moved aside first
and put back when a rename fails. A figure that cannot be written (no
permission) is the ``figures`` stage's error naming the file (each such file named); what was
measured is kept and still reported.
"""

from __future__ import annotations

import errno
import io
import json
import os
import re
import stat
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
    "save_outputs",
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


def _add_error(res: ExperimentResult, stage: str, message: str) -> None:
    """Record ``message`` as ``stage``'s error, after any it has already."""
    before = res.errors.get(stage)
    res.errors[stage] = f"{before}; {message}" if before else message


def _drawn(res: ExperimentResult) -> dict[str, bytes]:
    """The figures of what ``res`` measured, as PNG files in memory (name -> bytes)."""
    plt = pyplot()
    drawn: list[tuple[str, Figure]] = []
    if res.kinematics is not None:
        drawn.append(("kinematics", plot_kinematics(res.kinematics)))
    if res.dent is not None:
        drawn.append(("dent", plot_dent(res.dent)))
    out: dict[str, bytes] = {}
    for name, fig in drawn:
        try:
            png = io.BytesIO()
            fig.savefig(png, dpi=FIGURE_DPI, metadata={"Software": f"{MARK} {__version__}"})
            out[name] = png.getvalue()
        finally:
            plt.close(fig)
    return out


def _blocked(path: Path, res: ExperimentResult) -> str | None:
    """Why the figure ``path`` may not be written (a user's file, a folder in the way, a file
    without write permission); None when it may."""
    if path.is_dir():
        return _cannot_write(path, OSError("a folder is in the way"))
    if path.is_file():
        if not _replaceable(path, res, "figures"):
            return f"not written: {_foreign(path)}"
        if not os.access(path, os.W_OK):
            return f"cannot write {str(path)!r}: {os.strerror(errno.EACCES)}"
    return None


def _stale(res: ExperimentResult, out: Path, drawn: set[str]) -> list[tuple[str, Path]]:
    """The figures in ``out`` that an earlier run left and this run did not draw (``drawn``:
    the names it drew, written or not): (name, path) to remove; a user's file of that name is
    left, with a warning (unless this run's error names it already)."""
    stale = []
    for name, file in FIGURES.items():
        path = out / file
        if name in drawn or not path.is_file():
            continue
        if not written_by_analyze(path) and damaged(path) is None:
            res.warnings.append(f"figures: {_foreign(path)}; it does not show this run")
            continue
        stale.append((name, path))
    return stale


class _WriteError(OSError):
    """A file of the output folder that could not be written (``path``, the ``cause``);
    ``mixed``: the files this run left replaced because the earlier ones could not be put back
    (empty: the folder is as it was)."""

    def __init__(self, path: Path, cause: OSError, mixed: tuple[Path, ...] = ()) -> None:
        super().__init__(str(cause))
        self.path, self.cause, self.mixed = path, cause, mixed


def _put_back(aside: list[tuple[Path, Path]], placed: list[Path]) -> tuple[Path, ...]:
    """Undo a rename phase: the files moved ``aside`` ((temporary, path)) renamed back, the
    ``placed`` files that had no earlier one removed; the paths that could not be undone."""
    mixed: list[Path] = []
    earlier = {path for _, path in aside}
    for path in placed:
        if path not in earlier:
            try:
                path.unlink()
            except OSError:
                mixed.append(path)
    for old, path in aside:
        try:
            os.replace(old, path)
        except OSError:
            mixed.append(path)
    return tuple(mixed)


def _swap_in(files: dict[Path, bytes]) -> None:
    """Write every file of ``files`` (path -> bytes) under a temporary name first, each whole
    (``impactlab._files``), then move each existing file aside and rename them all into place;
    a file that cannot be written or renamed is a :class:`_WriteError` naming it, and the files
    moved aside are put back, so that the folder is left as it was (or the error names the
    files that could not be put back). A file written over keeps its permission bits."""
    staged: list[tuple[Path, Path]] = []
    aside: list[tuple[Path, Path]] = []
    placed: list[Path] = []
    try:
        for path, data in files.items():
            tmp = path.with_name(f".{path.name}.{os.getpid()}.new")
            try:
                write_bytes_atomic(tmp, data)
                staged.append((tmp, path))
                if path.is_file():
                    os.chmod(tmp, stat.S_IMODE(path.stat().st_mode))
            except OSError as exc:
                raise _WriteError(path, exc) from None
        path = staged[0][1] if staged else Path()
        try:
            for _, path in staged:
                if path.is_file():
                    old = path.with_name(f".{path.name}.{os.getpid()}.old")
                    os.replace(path, old)
                    aside.append((old, path))
            for tmp, path in staged:
                os.replace(tmp, path)
                placed.append(path)
        except OSError as exc:
            raise _WriteError(path, exc, _put_back(aside, placed)) from None
        for old, _ in aside:
            old.unlink(missing_ok=True)
    finally:
        for tmp, _ in staged:
            tmp.unlink(missing_ok=True)


def save_outputs(res: ExperimentResult, out: Path, figures: bool = True) -> None:
    """Write this run's figures (with ``figures``) and ``results.json`` into ``out`` together,
    then remove the figures of an earlier run that this run did not draw (module docstring).
    Every file is written under a temporary name first and renamed into place only when all
    were written: when one cannot be (a full disk), nothing in the folder is written or
    removed, and the ``results`` (and ``figures``) stage's error says so. A figure that may not
    be written (:func:`_blocked`) is the ``figures`` stage's error, the others are written."""
    drawn = _drawn(res) if figures else {}
    files: dict[Path, bytes] = {}
    for name, png in drawn.items():
        path = out / FIGURES[name]
        problem = _blocked(path, res)
        if problem is not None:
            _add_error(res, "figures", problem)
            continue
        files[path] = png
        res.figures[name] = str(path)
    stale = _stale(res, out, set(drawn))
    removed = [
        f"figures: removed {str(path)!r}, left by an earlier run (this run drew no {name} figure)"
        for name, path in stale
    ]
    results = out / "results.json"
    if results.is_file():
        _replaceable(results, res, "results")  # (check_folder refused a user's file)
    res.files["results"] = str(results)
    res.warnings += removed
    files[results] = json.dumps(res.to_dict(), indent=2).encode("utf-8")
    try:
        _swap_in(files)
    except _WriteError as exc:
        res.warnings = [w for w in res.warnings if w not in removed]
        res.files.pop("results", None)
        for name in [n for n in res.figures if Path(res.figures[n]) in files]:
            del res.figures[name]
        done = "nothing in the folder was written or removed"
        if exc.mixed:
            done = (
                f"the earlier {', '.join(repr(str(p)) for p in exc.mixed)} could not be put "
                f"back (kept as '.NAME.{os.getpid()}.old' in the folder): replaced by this run's"
            )
        cannot = f"{_cannot_write(exc.path, exc.cause)}; {done}"
        if exc.path != results:  # a figure: the record is not written without it
            _add_error(res, "figures", cannot)
            res.errors["results"] = (
                f"not written: {str(results)!r}, the record of the analysis, is written with the "
                f"figures, one of which could not be (see figures); {done}"
            )
            return
        res.errors["results"] = cannot
        if drawn:
            _add_error(
                res,
                "figures",
                f"not written: the figures are written with {str(results)!r}, the record of "
                f"the analysis, which could not be (see results); {done}",
            )
        return
    for _name, path in stale:
        try:
            path.unlink()
        except OSError as exc:
            res.warnings.remove(next(w for w in removed if str(path) in w))
            res.warnings.append(
                f"figures: {str(path)!r} is left from an earlier run and could not be removed "
                f"({exc.strerror or exc}): it does not show this run"
            )
