"""Write a file whole or not at all: a user's data and a run's results never left cut short.

The text goes to a temporary file beside the target (same folder, so same file system), which
then replaces the target in one step (``os.replace``): an interrupted write, a full disk or a
crash leaves the old file as it was, and the temporary one is removed. A target that exists is
replaced only where it could be written in place (a read-only file is refused as ``open`` would
refuse it: ``os.replace`` would not ask), the new file keeps its permission bits, and a symbolic
link is written through (the file it names is replaced, the link kept). An error of the
system names the target, never the temporary file. ``folder_refusal`` says, before any work,
why no file can be made in a folder (``missing_link`` for a symbolic link to nothing on its way).
"""

from __future__ import annotations

import errno
import os
import shutil
import stat
import tempfile
from pathlib import Path

from impactlab._oserror import oserror_words


def missing_link(path: str | os.PathLike[str], name: str) -> str | None:
    """One line naming ``name`` and ``path`` as given when ``path``, or the folder above it
    where it would be made, is a symbolic link to something missing (the folder could not be
    made through it); None otherwise."""
    given = Path(path)
    for p in (given, *given.parents):
        if p.is_symlink() and not p.exists():
            try:
                to = f" ({os.readlink(p)!r})"
            except OSError:  # pragma: no cover - a link that vanished meanwhile
                to = ""
            where = "is" if p == given else f"is inside {str(p)!r},"
            return (
                f"{name} {str(path)!r} {where} a symbolic link to a missing folder{to}: make "
                f"that folder, or choose another {name}"
            )
        if p.exists():
            break
    return None


def folder_refusal(path: str | os.PathLike[str], name: str) -> str | None:
    """Why the folder ``path`` (of the option or argument ``name``) cannot take new files, as
    one line naming ``name`` and ``path`` as given, or None when it can: it, or a folder above
    it, is a symbolic link to something missing (:func:`missing_link`), or the folder, or the
    nearest existing one above it where it is still to be made, does not let a probe (a
    temporary folder, removed at once) be created. A file in the way is left to the caller's
    check."""
    link = missing_link(path, name)
    if link is not None:
        return link
    given = Path(path)
    existing = next((p for p in (given, *given.parents) if p.exists()), Path("."))
    if not existing.is_dir():
        return None
    try:
        probe = tempfile.mkdtemp(prefix=".impactlab-probe-", dir=existing)
    except OSError as exc:
        words = oserror_words(exc)
        why = words[0] if words is not None else (exc.strerror or str(exc))
        if exc.errno == errno.ENOENT:  # the folder exists: a file system that makes no files
            why = "it takes no new files, as in /proc or /sys"
        where = "the folder" if existing == given else f"its folder {str(existing)!r}"
        return f"{name} {str(path)!r}: {where} is not writable ({why}); choose another {name}"
    shutil.rmtree(probe, ignore_errors=True)
    return None


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> None:
    """Write ``data`` to ``path`` whole, or leave ``path`` as it was (see module);
    PermissionError for an existing file that cannot be written."""
    target = Path(path)
    if target.is_symlink():  # write the file the link names: the link stays a link
        target = target.resolve()
    mode = None
    if target.exists():
        if not os.access(target, os.W_OK):
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(target))
        mode = stat.S_IMODE(target.stat().st_mode)
    tmp = target.with_name(f".{target.name}.{os.getpid()}.partial")
    try:
        with open(tmp, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        if mode is not None:
            os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException as exc:
        tmp.unlink(missing_ok=True)
        if isinstance(exc, OSError) and exc.filename is not None:
            exc.filename = os.fspath(path)  # the file the user named, not the temporary one
        raise


def write_text_atomic(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> None:
    """Write ``text`` to ``path`` whole, or leave ``path`` as it was (see module)."""
    write_bytes_atomic(path, text.encode(encoding))
