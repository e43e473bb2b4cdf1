"""A candidate model from its text (``"law/friction[/flexible_rod[/rate]]"``, the form of its
name) or from a mapping of its fields (a ``[[model]]`` table of a calibration file), and the
record of its definition (``settings`` of a calibration: what runs it again)."""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any

from impactlab.calibrate.models import CandidateModel
from impactlab.calibrate.values import did_you_mean

__all__ = ["model_definition", "parse_model"]

_FIELDS = tuple(f.name for f in dataclasses.fields(CandidateModel))


def parse_model(spec: str | CandidateModel | Mapping[str, Any]) -> CandidateModel:
    """A CandidateModel from ``"law/friction[/flexible_rod[/rate]]"`` (the form of its
    ``name``), a mapping of its fields or itself. ValueError naming an unknown key (with the
    nearest known one) or a bad value."""
    if isinstance(spec, CandidateModel):
        return spec
    if isinstance(spec, Mapping):
        fields = dict(spec)
        label = str(fields.get("name") or fields.get("law") or "[[model]]")
        for key in fields:
            if key not in _FIELDS:
                raise ValueError(
                    f"model {label!r}: unknown key {key!r}{did_you_mean(str(key), _FIELDS)}; "
                    f"known: {', '.join(_FIELDS)}"
                )
        try:
            return CandidateModel(**fields)
        except TypeError as exc:  # a value of the wrong kind (a list for a name, ...)
            raise ValueError(f"model {label!r}: {exc}") from None
    parts = [p.strip() for p in str(spec).split("/")]
    if not 1 <= len(parts) <= 4 or not all(parts):
        raise ValueError(
            f"model {spec!r}: expected 'law', 'law/friction', 'law/friction/body' or "
            "'law/friction/flexible_rod/rate'"
        )
    friction = parts[1] if len(parts) > 1 else "coulomb"
    body = parts[2] if len(parts) > 2 else None
    rate = parts[3] if len(parts) > 3 else None
    try:
        return CandidateModel(parts[0], friction, body, rate=rate)
    except ValueError as exc:
        raise ValueError(f"model {spec!r}: {exc}") from None


def model_definition(model: CandidateModel) -> dict[str, Any]:
    """The fields of ``model`` (law, friction, body, rate, fixed, law_params): a ``[[model]]``
    table that makes it again."""
    return {
        "law": model.law,
        "friction": model.friction,
        "body": model.body,
        "rate": model.rate,
        "fixed": dict(model.fixed),
        "law_params": dict(model.law_params),
    }
