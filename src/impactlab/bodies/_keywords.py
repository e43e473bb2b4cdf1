"""A body's keywords: a dataclass body called with a keyword it does not take raises a
TypeError naming the nearest field, or what to use instead, and the fields it takes, as
``simulate`` words it (``impactlab._validation.unexpected_keywords``)."""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from dataclasses import fields
from typing import Any, TypeVar

from impactlab._validation import unexpected_keywords

__all__ = ["FLEXIBLE_ROD_NOTES", "refuse_unknown_fields"]

#: What ``FlexibleRod`` says of the keywords users try that it does not take: the command
#: line's and the study files' names of the mode counts, and a ``DropResult``'s ``n_modes``.
FLEXIBLE_ROD_NOTES = {
    "modes_axial": "use n_axial, the command line's --modes-axial",
    "modes_bending": "use n_bending, the command line's --modes-bending",
    "n_modes": "give n_axial and n_bending; a DropResult's n_modes is their total with the "
    "axial residual pseudo-modes",
}

_T = TypeVar("_T", bound=type)


def refuse_unknown_fields(notes: Mapping[str, str]) -> Callable[[_T], _T]:
    """Decorate a dataclass (above ``@dataclass``) so that its ``__init__`` refuses a keyword
    that is not a field with the TypeError of ``unexpected_keywords`` (``notes``: keyword ->
    what to use instead) rather than Python's bare one; its signature stays the dataclass's."""

    def decorate(cls: _T) -> _T:
        init = cls.__dict__["__init__"]  # the dataclass's own
        known = frozenset(f.name for f in fields(cls) if f.init)

        @functools.wraps(init)
        def checked(self: Any, *args: Any, **kwargs: Any) -> None:
            if extra := [k for k in kwargs if k not in known]:
                raise TypeError(unexpected_keywords(cls.__name__, extra, known, notes))
            init(self, *args, **kwargs)

        setattr(cls, "__init__", checked)  # noqa: B010  # mypy refuses assigning to a method
        return cls

    return decorate
