"""Which contact models were built with law parameters other than the defaults that the
finite-element comparison used (``impactlab.fe.accuracy`` measures every law with its default
parameters): their verified range does not cover them.

``ContactLaw.build`` records such a model's parameter vector (:func:`note_custom`); the range
of a result (``ranges.range_status``, ``range_note.range_note``) then reads "unverified" and
names the parameters. The record lives in this process, as a tabulated law's source does.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab.contact import kernels as k

__all__ = ["custom_parameters", "note_custom"]

#: The most parameter vectors remembered (the oldest is forgotten first).
_MAX_REMEMBERED = 4096
#: The non-default parameters ("limit_pressure_ratio = 0.5") by the bytes of the model's
#: first NPARAM parameters.
_CUSTOM: dict[bytes, str] = {}


def _key(params: Any) -> bytes:
    return np.ascontiguousarray(np.asarray(params, dtype=np.float64)[: k.NPARAM]).tobytes()


def note_custom(law: Any, model: Any, pair: Any, radius: float, given: dict[str, float]) -> None:
    """Remember ``model`` (built by ``law.build(pair, radius, **given)``) as built with the
    parameters of ``given`` that differ from the law's defaults (a default of nan is taken from
    the materials: any value given differs), unless the defaults give the same parameter vector
    (a value given as the default computes it, Brake's hardness from the materials)."""
    defaults = {q.name: float(q.default) for q in law.parameters}
    custom = [f"{n} = {v:g}" for n, v in given.items() if v != defaults.get(n)]
    if not custom:
        return
    try:
        default = law.build(pair, radius).params
    except ValueError:  # no default for this pair: the values given are its own
        default = None
    if default is not None and _key(default) == _key(model.params):
        return
    if len(_CUSTOM) >= _MAX_REMEMBERED:
        del _CUSTOM[next(iter(_CUSTOM))]
    _CUSTOM[_key(model.params)] = ", ".join(custom)


def custom_parameters(params: Any) -> str | None:
    """The non-default law parameters the model of ``params`` (a 1-D parameter vector) was
    built with, as text, or None (defaults, a 2-D batch of vectors, or not built here)."""
    if params is None or np.ndim(params) != 1:
        return None
    return _CUSTOM.get(_key(params))
