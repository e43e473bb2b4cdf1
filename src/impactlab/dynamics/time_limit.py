"""A drop's time limit, ``time_limit`` [s]: the longest simulated time after the first touch
(``simulate_drop``, ``simulate_drops``, ``impactlab.simulate`` of a FlexibleRod); a sequence
still going then is an error (ST_TMAX).

Before 0.3 its keyword was ``t_max``, the name of the result field of the time of the largest
interference (``ImpactResult.t_max``). The old keyword still reads as ``time_limit`` for one
release, with a DeprecationWarning at the caller's line (``renamed_keywords``,
``takes_renamed``); both given is a TypeError naming both.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from typing import Any, ParamSpec, TypeVar

from impactlab import schema
from impactlab._validation import _caller_level

__all__ = ["DEFAULT_TIME_LIMIT", "RENAMED_KEYWORDS", "renamed_keywords", "takes_renamed"]

#: Longest simulated time after the first touch [s] (a sequence still going is an error).
DEFAULT_TIME_LIMIT = 0.5
#: A drop's keywords renamed in 0.3, read under their old name until 0.4: old -> new.
RENAMED_KEYWORDS = {"t_max": "time_limit"}

_P = ParamSpec("_P")
_R = TypeVar("_R")


def renamed_keywords(function: str, kwargs: Mapping[str, Any]) -> dict[str, Any]:
    """``kwargs`` of ``function`` with each keyword given under its name before 0.3
    (``RENAMED_KEYWORDS``: ``t_max``) under its new name (``time_limit``), with a
    DeprecationWarning at the first line outside impactlab; TypeError naming both when both
    are given."""
    out = dict(kwargs)
    for old, new in RENAMED_KEYWORDS.items():
        if old not in out:
            continue
        if new in out:
            raise TypeError(
                f"{function}() got {new}= and {old}=, its name before 0.3: they are one; give "
                f"{new} only"
            )
        schema.warn_renamed(old, new, f"{function} keyword", stacklevel=_caller_level() + 1)
        out[new] = out.pop(old)
    return out


def takes_renamed(function: Callable[_P, _R]) -> Callable[_P, _R]:
    """Decorate a drop function so that it takes its keywords' names before 0.3
    (``renamed_keywords``); its signature and docstring stay its own (the new names)."""
    name = getattr(function, "__name__", "function")

    @functools.wraps(function)
    def renamed(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        if not RENAMED_KEYWORDS.keys() & kwargs.keys():
            return function(*args, **kwargs)
        return function(*args, **renamed_keywords(name, kwargs))

    return renamed
