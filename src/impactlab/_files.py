"""Write a file whole or not at all: a user's data and a run's results never left cut short.

The text goes to a temporary file beside the target (same folder, so same file system), which
then replaces the target in one step (``os.replace``): an interrupted write, a full disk or a
crash leaves the old file as it was, and the temporary one is removed.
"""

from __future__ import annotations

import os
from pathlib import Path


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> None:
    """Write ``data`` to ``path`` whole, or leave ``path`` as it was (see module)."""
    target = Path(path)
    tmp = target.with_name(f".{target.name}.{os.getpid()}.partial")
    try:
        with open(tmp, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_text_atomic(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> None:
    """Write ``text`` to ``path`` whole, or leave ``path`` as it was (see module)."""
    write_bytes_atomic(path, text.encode(encoding))
