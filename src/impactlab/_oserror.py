"""What an error of the operating system on a file means, in the words that the command line,
a sweep's store writer and its lock all use: a full disk, a quota, a read-only file system, no
permission (``oserror_words``)."""

from __future__ import annotations

import errno

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
