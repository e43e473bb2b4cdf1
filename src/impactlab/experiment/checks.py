"""Argument checks of the experiment pipeline's entry points and its output folders.

Each check raises one ``TypeError`` (wrong kind of value) or ``ValueError`` (a value outside what
is allowed) that names the parameter, the value given and what is allowed, before any work is
done: a bad argument never surfaces as an ``AttributeError`` deep inside a fit.
"""

from __future__ import annotations

import inspect
import os
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from impactlab._files import missing_link
from impactlab.experiment.errors import FileFormatError

__all__ = [
    "check_input_file",
    "check_instance",
    "check_options",
    "check_output_folder",
    "check_path",
    "output_folder",
]


def _kind(value: Any) -> str:
    text = repr(value)
    return f"{type(value).__name__} {text if len(text) <= 60 else text[:57] + '...'}"


def check_path(value: Any, name: str) -> Path:
    """``value`` as a Path; TypeError naming ``name`` unless it is a str or an os.PathLike."""
    if isinstance(value, bool) or not isinstance(value, str | os.PathLike):
        raise TypeError(f"{name} must be a path (str or os.PathLike), got {_kind(value)}")
    if isinstance(value, str) and not value.strip():
        raise ValueError(f"{name} must be a path, got an empty string")
    return Path(value)


def check_input_file(value: Any, name: str) -> Path:
    """``value`` as the Path of an existing, readable file; FileFormatError naming ``name`` and
    the path otherwise. Checked before any work, so that a misspelt path leaves an output
    folder as it was."""
    p = check_path(value, name)
    if not p.exists():
        problem = "no such file"
    elif not p.is_file():
        problem = "not a file"
    else:
        try:
            with p.open("rb"):
                return p
        except OSError as exc:
            problem = f"cannot be read ({exc.strerror or exc})"
    raise FileFormatError(p, f"{problem} ({name}); nothing was read or written")


def check_instance(value: Any, cls: type, name: str, hint: str = "") -> None:
    """TypeError naming ``name`` unless ``value`` is a ``cls`` (``hint``: where one comes from)."""
    if not isinstance(value, cls):
        more = f" ({hint})" if hint else ""
        article = "an" if cls.__name__[:1] in "AEIOU" else "a"
        raise TypeError(f"{name} must be {article} {cls.__name__}{more}, got {_kind(value)}")


def check_options(options: Any, func: Callable[..., Any], name: str) -> dict[str, Any]:
    """``options`` (None or a mapping of keyword arguments of ``func``) as a dict; TypeError for
    another type, ValueError naming an unknown key and listing the allowed ones."""
    if options is None:
        return {}
    if not isinstance(options, Mapping):
        raise TypeError(f"{name} must be a mapping of keyword arguments, got {_kind(options)}")
    allowed = [
        p.name for p in inspect.signature(func).parameters.values() if p.kind is p.KEYWORD_ONLY
    ]
    unknown = sorted(str(k) for k in options if k not in allowed)
    if unknown:
        raise ValueError(
            f"{name}: unknown option(s) {unknown} of {func.__name__}; allowed: {', '.join(allowed)}"
        )
    return dict(options)


def output_folder(path: Any, name: str = "out_dir") -> Path:
    """The folder ``path`` (created with its parents): ValueError naming ``name`` and the path when
    it, or one of its parents, is an existing file, or when it cannot be created."""
    out = check_output_folder(path, name)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(
            f"{name} {str(out)!r}: cannot create the folder ({exc.strerror or exc})"
        ) from None
    return out


def check_output_folder(path: Any, name: str = "out_dir") -> Path:
    """The folder ``path``, checked as :func:`output_folder` checks it but not created: nothing
    is touched (the inputs are checked next, before the folder is made). ValueError also for a
    symbolic link to something missing as the folder or in the way of its making."""
    out = check_path(path, name).expanduser()
    link = missing_link(out, name)
    if link is not None:
        raise ValueError(link)
    for p in (out, *out.parents):
        if p.exists():
            if not p.is_dir():
                what = "exists and is not a folder" if p == out else f"is inside {str(p)!r}, a file"
                raise ValueError(f"{name} {str(out)!r} {what}: choose a folder")
            break
    return out
