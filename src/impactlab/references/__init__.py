"""The literature impactlab cites: one registry of references with their DOIs.

Models carry the references they implement (``ContactLaw.references``,
``FrictionModel.references``, the engine's integrator), and results record the references a
computation used. ``confirmed`` is True only where the DOI was checked against the publisher's
record or in a copy of the publication in this project; ``note`` says what was checked (see
docs/laws/index.md, "References and their status"). The other DOIs are carried over from the
sources' own citations and are not verified here. Every DOI must match ``DOI_PATTERN``; a
reference without a DOI (a handbook, a data sheet) has ``doi == ""`` and, where it is on the
web, the address it was read at in ``url`` (``""`` otherwise).
"""

from __future__ import annotations

from types import MappingProxyType

from impactlab.references.literature import LITERATURE
from impactlab.references.material_data import MATERIAL_DATA
from impactlab.references.reference import DOI_PATTERN, PAPER, Reference

REFERENCES: MappingProxyType[str, Reference] = MappingProxyType(
    {r.key: r for r in (*LITERATURE, *MATERIAL_DATA)}
)
"""key -> Reference: every source the package cites (read-only)."""


def cite(*keys: str) -> tuple[Reference, ...]:
    """The references registered under ``keys``, in order; ValueError for an unknown key."""
    unknown = [key for key in keys if key not in REFERENCES]
    if unknown:
        raise ValueError(f"unknown reference key(s) {unknown}; known: {', '.join(REFERENCES)}")
    return tuple(REFERENCES[key] for key in keys)


def dois(references: tuple[Reference, ...]) -> tuple[str, ...]:
    """The DOIs of ``references`` (those that have one), in order, without repeats."""
    return tuple(dict.fromkeys(r.doi for r in references if r.doi))


__all__ = ["DOI_PATTERN", "PAPER", "REFERENCES", "Reference", "cite", "dois"]
