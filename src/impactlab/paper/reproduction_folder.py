"""The folder of a reproduction: the marker that identifies it (:data:`MARKER`, with the run's
status and its files), the files a reproduction can write (:data:`FILES`), the checks before a
run writes there (:func:`prepare_output`) and, after it, the removal of an earlier run's files
that this one did not write (each with a :class:`ReproductionWarning`), so that the folder holds
one run. Used by :func:`impactlab.paper.reproduction.reproduce`.
"""

from __future__ import annotations

import json
import os
import re
import warnings
from pathlib import Path
from typing import Any

from impactlab._files import folder_refusal, write_text_atomic
from impactlab._version import __version__
from impactlab.experiment.checks import check_path, output_folder
from impactlab.paper import data as D

__all__ = ["FILES", "MARKER", "TABLE_NAMES", "ReproductionWarning", "prepare_output"]

#: Marker file that identifies a folder written by ``reproduce``; it lists the files of the
#: reproduction in the folder (``"files"``), which the next run reads to remove the stale ones.
MARKER = ".impactlab-reproduction.json"

#: The file name of each angle's side-by-side table [deg].
TABLE_NAMES = {20: "table2", 45: "table3", 70: "table4"}

#: Every file a reproduction can write (besides :data:`MARKER`): one of these that a run does
#: not write is an earlier run's, whatever the marker says, and is removed.
FILES = frozenset(
    {
        "report.md",
        "report.html",
        *(f"{name}.csv" for name in TABLE_NAMES.values()),
        "comparison.csv",
        "experimental_rows.csv",
        "published_consistency.csv",
        "simulations.csv",
        "simulation_inputs.json",
        "eq12_check.csv",
        "fe_reference.csv",
        "inertia_sensitivity.csv",
        "inertia_sensitivity.png",
        "fig5_alpha.png",
        "fig4_dent.png",
        *(f"forces_{ang}deg.png" for ang in D.ANGLES_DEG),
        "physics_comparison.csv",
        "physics_drop_20deg.png",
    }
)

# the temporary file of a write cut short (impactlab._files: ".<name>.<pid>.partial")
_PARTIAL = re.compile(r"\.(?P<name>.+)\.\d+\.partial")


class ReproductionWarning(UserWarning):
    """A file an earlier reproduction left in the folder was removed (or could not be)."""


def prepare_output(out_dir: str | os.PathLike[str], name: str = "out_dir") -> Path:
    """Create ``out_dir`` or accept it if it is empty or holds a previous reproduction (marker
        file). Refuses (ValueError naming ``name``, the folder as the user gave it: the command
        line's ``--out``) a non-empty folder without the marker, a path that is a file and a folder
    no file can be made in (no permission, a read-only file system). Nothing
        outside ``out_dir`` is touched; inside it only the reproduction's own files are (re)written,
        and the marker keeps the earlier run's list of files until this run completes."""
    out = check_path(out_dir, name).expanduser()
    refusal = folder_refusal(out, name)  # nothing can be written there: refused before any work
    if refusal is not None:
        raise ValueError(refusal)
    if out.is_dir():
        entries = list(out.iterdir())
        if entries and not (out / MARKER).is_file():
            raise ValueError(
                f"{name} {str(out)!r} is not empty and was not written by 'impactlab "
                f"reproduce' (no {MARKER}); refusing to write there: choose a new or empty folder"
            )
    out = output_folder(out, name)  # refuses a file, or a file among its parents
    _write_marker(out, "running", _marker_files(out))
    return out


def _marker_status(out: Path) -> str | None:
    """The status the marker in ``out`` records (None without a readable one): after a
    ``complete`` run only the files its marker lists are the reproduction's; after one killed
    (``running``), failed or with no readable marker, every name of :data:`FILES` is."""
    try:
        status = json.loads((out / MARKER).read_text()).get("status")
    except (OSError, ValueError, AttributeError):
        return None
    return status if isinstance(status, str) else None


def _unlink_links(out: Path) -> None:
    """Remove the symbolic links in ``out`` named as a file of the reproduction, so that its
    files are written in ``out`` and never through a link to a file elsewhere (the file a link
    names is left as it is)."""
    for name in sorted(FILES):
        path = out / name
        if path.is_symlink():
            path.unlink()
            warnings.warn(
                f"{str(path)!r} was a link; this run writes its own file there (the file it "
                "named is left as it was)",
                ReproductionWarning,
                stacklevel=3,
            )


def _marker_files(out: Path) -> set[str]:
    """The files the marker in ``out`` lists (none without a readable one) that a reproduction
    can write: names of :data:`FILES` (or the temporary file of a write of one cut short). Any
    other name the marker lists (a file of the user's, a path elsewhere) is ignored, so it is
    never removed whatever the marker says."""
    try:
        listed = json.loads((out / MARKER).read_text()).get("files", [])
    except (OSError, ValueError, AttributeError):
        return set()
    if not isinstance(listed, list):
        return set()
    return {f for f in listed if isinstance(f, str) and _is_ours(f)}


def _is_ours(name: str) -> bool:
    """Whether ``name`` is a file a reproduction can write: one of :data:`FILES`, or the
    temporary file of a write of one of them (or of :data:`MARKER`) cut short."""
    if name in FILES:
        return True
    m = _PARTIAL.fullmatch(name)
    return m is not None and m.group("name") in FILES | {MARKER}


def _write_marker(out: Path, status: str, files: set[str], elapsed: float | None = None) -> None:
    """The marker: the tool, the run's ``status``, the version and the reproduction's files."""
    record: dict[str, Any] = {
        "tool": "impactlab reproduce",
        "status": status,
        "version": __version__,
        "files": sorted(files),
    }
    if elapsed is not None:
        record["elapsed_s"] = elapsed
    write_text_atomic(out / MARKER, json.dumps(record, indent=2))


def _partials(out: Path) -> set[str]:
    """The temporary files in ``out`` of a write of one of :data:`FILES` cut short."""
    return {p.name for p in out.iterdir() if p.name not in FILES and _is_ours(p.name)}


def _remove_stale(out: Path, stale: set[str]) -> tuple[list[str], set[str]]:
    """Remove the files ``stale`` (an earlier run's, not written by this one) from ``out``, one
    ReproductionWarning each; returns the names removed and those that could not be."""
    removed: list[str] = []
    kept: set[str] = set()
    for name in sorted(n for n in stale if _is_ours(n)):  # never a file the user made
        path = out / name
        if not path.is_file() or path.is_symlink():
            continue  # gone already, or not a file of ours
        try:
            path.unlink()
        except OSError as exc:
            kept.add(name)
            warnings.warn(
                f"{str(path)!r} is left from an earlier run and could not be removed "
                f"({exc.strerror or exc}): it does not show this run",
                ReproductionWarning,
                stacklevel=3,
            )
        else:
            removed.append(name)
            warnings.warn(
                f"removed {str(path)!r}, left by an earlier run (this run does not write it)",
                ReproductionWarning,
                stacklevel=3,
            )
    return removed, kept
