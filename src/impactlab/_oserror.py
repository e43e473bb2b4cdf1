"""What an error of the operating system on a file means, in the words that the command line,
a sweep's store writer and its lock all use: a full disk, a quota, a read-only file system, no
permission (``oserror_words``), and the command line's one line for such an error
(``system_error_line``)."""

from __future__ import annotations

import errno
import os
import re

#: errno -> (what happened to the file, what to do; ``{elsewhere}``: how to write elsewhere).
_WORDS: dict[int, tuple[str, str]] = {
    errno.ENOSPC: ("no space left on the device", "free space"),
    errno.EDQUOT: ("disk quota exceeded", "free space (or raise the quota)"),
    errno.EROFS: ("read-only file system", "make it writable (or {elsewhere})"),
    errno.EACCES: ("no permission for this user", "change its permissions (or {elsewhere})"),
    errno.EPERM: ("no permission for this user", "change its permissions (or {elsewhere})"),
}

#: The errnos that no writing in the same place can get past: the place must change.
UNWRITABLE = frozenset({errno.EROFS, errno.EACCES, errno.EPERM})


def oserror_words(exc: OSError, elsewhere: str = "write elsewhere") -> tuple[str, str] | None:
    """(what happened, what to do) for the errno of ``exc``: ``("no space left on the device",
    "free space")``; ``elsewhere`` is how the caller's user writes in another place (``"choose
    another --out"``). None for an errno of no other meaning than its own text."""
    words = _WORDS.get(exc.errno or 0)
    if words is None:
        return None
    what, todo = words
    return what, todo.format(elsewhere=elsewhere)


#: The temporary file of a write under way: ``.<name>.<pid>.partial`` beside the target.
PARTIAL = re.compile(r"\.(?P<name>.+)\.\d+\.partial")


def target_of(filename: str) -> str:
    """The file a write was making, for the name of its temporary file (``d/.x.csv.42.partial``
    -> ``d/x.csv``); any other name as it is."""
    folder, _, name = filename.rpartition(os.sep)
    found = PARTIAL.fullmatch(name)
    if found is None:
        return filename
    return f"{folder}{os.sep}{found['name']}" if folder else found["name"]


def system_error_line(exc: OSError) -> str:
    """An OSError of the system in one line: its own message where it has no errno text (a
    sweep's ``StoreWriteError`` says what is stored), else what its errno means for its file
    (a full disk, a quota, a read-only file system, no permission), else its text and file. The
    file is the one the user named, never the temporary file of a write under way
    (``impactlab._files``)."""
    if exc.strerror is None:
        return str(exc) or type(exc).__name__
    where = repr(target_of(str(exc.filename))) if exc.filename is not None else "a file"
    words = oserror_words(exc)
    if words is not None:
        return f"{words[0]} writing {where}: {words[1]} and run the command again"
    return f"{exc.strerror}: {where}" if exc.filename is not None else exc.strerror
