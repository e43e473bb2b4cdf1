"""Paths the commands write to or read a store from, checked before any work starts: a
UserError that names the option (or argument) and the path as the user gave it, never an
``[Errno]`` text or a temporary path of the writer; and the rule of the files in an output
folder (``--out``): a file that an earlier run of the same command wrote is replaced, a user's
file of the same name never (:func:`check_replaceable`)."""

from __future__ import annotations

import io
import json
import os
import re
import shutil
import struct
import tempfile
from collections.abc import Collection, Iterable, Mapping
from pathlib import Path
from typing import Any

from impactlab._files import folder_refusal, missing_link, write_bytes_atomic
from impactlab._oserror import oserror_words
from impactlab._version import __version__
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
        words = oserror_words(exc)
        why = words[0] if words is not None else (exc.strerror or str(exc))
        raise UserError(f"{shown}: cannot create {what} in {str(folder)!r} ({why})") from None
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


def output_dir(path: Path, name: str) -> Path:
    """The folder ``path`` that ``name`` (``--out``, ``--plot``) asks to write into, checked
    before any work and not yet made: UserError when it or a folder above it is a file, or when
    no file can be created in it (or, still to be made, in the nearest existing folder above)."""
    from impactlab.experiment.checks import check_output_folder

    try:
        folder = check_output_folder(path, name)
    except ValueError as exc:
        raise UserError(str(exc)) from None
    refusal = folder_refusal(path, name)
    if refusal is not None:
        raise UserError(refusal)
    return folder


def output_store(path: Path, name: str) -> Path:
    """The sweep store (a folder, made with its parents) that ``name`` asks to write: UserError
    when it is an existing file or lies inside one, a symbolic link to something missing (or
    inside one), or when nothing can be created where it would go."""
    shown = f"{name} {str(path)!r}"
    link = missing_link(path, name)
    if link is not None:
        raise UserError(link)
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


# --- Files in an output folder: one rule for every command that writes into a folder --------
# A file that a run of the same command wrote may be replaced; any other file of the same name
# (a user's) is left alone, and the command stops before any work with one line naming it.
# impactlab recognises its files by a mark in them, as ``impactlab analyze`` does
# (``experiment.saving``): a figure's PNG "Software" text or PDF "Creator", an HTML page's
# ``<meta name="generator">``, each "impactlab COMMAND VERSION"; a JSON file by its keys.

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_GENERATOR = re.compile(rb"<meta\s+name=['\"]generator['\"]\s+content=['\"]([^'\"]*)['\"]")
_PDF_CREATOR = re.compile(rb"/Creator\s*\(([^)]*)\)")


def mark(command: str) -> str:
    """The mark of a file written by ``impactlab COMMAND``: "impactlab COMMAND VERSION"."""
    return f"impactlab {command} {__version__}"


def _png_software(path: Path) -> str:
    """The "Software" text of a PNG file (its text chunks before the image data), or ""."""
    with path.open("rb") as fh:
        if fh.read(8) != _PNG_SIGNATURE:
            return ""
        while True:
            head = fh.read(8)
            if len(head) < 8:
                return ""
            size, kind = struct.unpack(">I4s", head)
            if kind in (b"IDAT", b"IEND") or size > 1 << 20:
                return ""
            data = fh.read(size + 4)[:size]  # the chunk and its CRC
            key, _, value = data.partition(b"\0")
            if kind == b"tEXt" and key == b"Software":
                return value.decode("latin-1")


def _tail_match(path: Path, pattern: re.Pattern[bytes], head: bool) -> str:
    """The first group of ``pattern`` in the first (``head``) or last 64 KiB of ``path``."""
    with path.open("rb") as fh:
        if not head:
            fh.seek(max(0, path.stat().st_size - (1 << 16)))
        found = pattern.search(fh.read(1 << 16))
    return found.group(1).decode("latin-1") if found else ""


def written_by(path: Path, command: str, keys: Collection[str] = ()) -> bool:
    """Whether the file ``path`` was written by ``impactlab COMMAND`` (see above; a JSON file:
    an object holding every one of ``keys``). An empty file counts as one (nothing to lose:
    left by an interrupted write); a file that cannot be read does not."""
    try:
        if path.stat().st_size == 0:
            return True
        suffix = path.suffix.lower()
        if suffix == ".json":
            data = json.loads(path.read_text(encoding="utf-8"))
            return bool(keys) and isinstance(data, dict) and set(keys) <= data.keys()
        if suffix == ".png":
            text = _png_software(path)
        elif suffix in (".html", ".pdf"):
            pattern = _GENERATOR if suffix == ".html" else _PDF_CREATOR
            text = _tail_match(path, pattern, head=suffix == ".html")
        else:
            return False
    except (OSError, ValueError):
        return False
    return text.rpartition(" ")[0] == f"impactlab {command}"  # "impactlab COMMAND VERSION"


def check_replaceable(
    folder: Path,
    names: Iterable[str],
    command: str,
    option: str = "--out",
    keys: Mapping[str, Collection[str]] | None = None,
) -> None:
    """UserError, before anything is written, when a file ``command`` writes into ``folder``
    (``names``) is in the way: a file of that name that it did not write (:func:`written_by`,
    the JSON files by their ``keys``), or a folder of that name. Nothing is written or
    removed; the message names each such file and ``option``, where to write instead."""
    paths = [folder / name for name in names]
    dirs = [p for p in paths if p.is_dir()]
    if dirs:
        raise UserError(
            f"cannot write {str(dirs[0])!r}: a folder of that name is in the way (remove or "
            f"rename it, or choose another {option})"
        )
    foreign = [
        p for p in paths if p.is_file() and not written_by(p, command, (keys or {}).get(p.name, ()))
    ]
    if foreign:
        one = len(foreign) == 1
        named = ", ".join(repr(str(p)) for p in foreign[:3])
        if len(foreign) > 3:
            named += f" and {len(foreign) - 3} more"
        raise UserError(
            f"{named} {'is' if one else 'are'} in the output folder but {'was' if one else 'were'}"
            f" not written by impactlab {command}: {'it is' if one else 'they are'} left as "
            f"{'it is' if one else 'they are'} (move {'it' if one else 'them'}, or choose another "
            f"{option})"
        )


def figure_bytes(fig: Any, path: Path, command: str, dpi: float) -> bytes:
    """The matplotlib figure ``fig`` as the file ``path`` holds it (PNG or PDF by its suffix),
    marked as written by ``impactlab COMMAND``."""
    fmt = path.suffix.lower().lstrip(".")
    buf = io.BytesIO()
    key = "Creator" if fmt == "pdf" else "Software"
    fig.savefig(buf, format=fmt, dpi=dpi, metadata={key: mark(command)})
    return buf.getvalue()


def save_figure(fig: Any, path: Path, command: str, dpi: float) -> Path:
    """Write the matplotlib figure ``fig`` to ``path`` (PNG or PDF by its suffix) whole
    (``impactlab._files``), marked as written by ``impactlab COMMAND``; returns ``path``."""
    write_bytes_atomic(path, figure_bytes(fig, path, command, dpi))
    return path
