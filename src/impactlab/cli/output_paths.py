"""Paths the commands write to or read a store from, checked before any work starts: a
UserError that names the option (or argument) and the path as the user gave it, never an
``[Errno]`` text or a temporary path of the writer."""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

from impactlab.cli._common import UserError


def _nearest_existing(path: Path) -> Path:
    """``path`` itself or its nearest existing parent (the current folder at worst)."""
    for p in (path, *path.parents):
        if p.exists():
            return p
    return Path(".")


def _check_can_create_in(folder: Path, shown: str, what: str) -> None:
    """UserError ``shown: cannot create <what> in <folder>`` unless a probe (a temporary
    folder, removed at once) can be made in the existing folder ``folder``."""
    try:
        probe = tempfile.mkdtemp(prefix=".impactlab-probe-", dir=folder)
    except OSError as exc:
        raise UserError(
            f"{shown}: cannot create {what} in {str(folder)!r} ({exc.strerror or exc})"
        ) from None
    shutil.rmtree(probe, ignore_errors=True)


def output_file(path: Path, name: str) -> Path:
    """The file ``path`` that ``name`` (an option such as ``--netcdf``, or an argument) asks to
    write: UserError when it is a folder, when its folder does not exist or is a file, or when
    no file can be created there."""
    shown = f"{name} {str(path)!r}"
    if path.is_dir():
        raise UserError(f"{shown} is a folder: give the name of the file to write")
    folder = path.parent
    existing = _nearest_existing(folder)
    if not existing.is_dir():
        raise UserError(f"{shown} is inside {str(existing)!r}, a file: choose another path")
    if existing != folder:
        raise UserError(f"{shown}: the folder {str(folder)!r} does not exist")
    if not os.access(folder, os.W_OK):
        raise UserError(f"{shown}: the folder {str(folder)!r} is not writable")
    _check_can_create_in(folder, shown, "a file")
    return path


def output_store(path: Path, name: str) -> Path:
    """The sweep store (a folder, made with its parents) that ``name`` asks to write: UserError
    when it is an existing file or lies inside one, or when nothing can be created where it
    would go."""
    shown = f"{name} {str(path)!r}"
    if path.exists() and not path.is_dir():
        raise UserError(f"{shown} exists and is a file, not a sweep store (a folder): choose "
                        "another path")  # fmt: skip
    existing = _nearest_existing(path)
    if not existing.is_dir():
        raise UserError(f"{shown} is inside {str(existing)!r}, a file: choose another path")
    if existing != path:
        if not os.access(existing, os.W_OK):
            raise UserError(f"{shown}: the folder {str(existing)!r} is not writable")
        _check_can_create_in(existing, shown, "the store")
    return path


def existing_store(path: Path) -> Path:
    """The sweep store ``path`` to read: UserError when nothing is there or it is a file."""
    if not path.exists():
        raise UserError(f"sweep store {str(path)!r} does not exist")
    if not path.is_dir():
        raise UserError(
            f"{str(path)!r} is a file, not a sweep store (a folder written by impactlab sweep)"
        )
    return path
