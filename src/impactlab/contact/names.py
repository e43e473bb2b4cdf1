"""The contact laws by name: :class:`Law`, the keys of the law registry.

Each member carries its compiled id (``contact.kernels``) and the sources the law implements
(``impactlab.references``). Members are strings (``Law.GHAEDNIA == "ghaednia"``), so plain names
work wherever a law is asked for.
"""

from __future__ import annotations

import enum

from impactlab.contact import kernels as k
from impactlab.references import PAPER, Reference, cite


class Law(enum.StrEnum):
    """The registered normal contact laws (sphere or rod tip on a flat)."""

    HERTZ = ("hertz", k.HERTZ, ("hertz-1882", "johnson-1985"))
    GHAEDNIA = ("ghaednia", k.GHAEDNIA, ("ghaednia-2016-contact", PAPER))
    JACKSON_GREEN = ("jackson-green", k.JACKSON_GREEN, ("jackson-green-2005",))
    KOGUT_KOMVOPOULOS = (
        "kogut-komvopoulos",
        k.KOGUT_KOMVOPOULOS,
        ("kogut-komvopoulos-2004", PAPER),
    )
    BRAKE = ("brake", k.BRAKE, ("brake-2015", PAPER))
    THORNTON = ("thornton", k.THORNTON, ("thornton-1997",))
    TABULATED = (
        "tabulated",
        k.TABULATED,
        (
            "fritsch-carlson-1980",
            "jackson-green-2005",
            "de-boor-1978",
            "craven-wahba-1979",
        ),
    )

    law_id: int
    reference_keys: tuple[str, ...]

    def __new__(cls, value: str, law_id: int, keys: tuple[str, ...]) -> Law:
        member = str.__new__(cls, value)
        member._value_ = value
        member.law_id = law_id
        member.reference_keys = keys
        return member

    @property
    def references(self) -> tuple[Reference, ...]:
        """The law's sources, its defining paper first (``impactlab.references``)."""
        return cite(*self.reference_keys)


__all__ = ["Law"]
