"""The explicit registry of contact laws, keyed by :class:`Law` (plain names work too).

No name ever stands in for another law.
"""

from __future__ import annotations

from impactlab.contact.base import ContactLaw
from impactlab.contact.brake import Brake
from impactlab.contact.ghaednia import Ghaednia
from impactlab.contact.hertz import Hertz
from impactlab.contact.jackson_green import JacksonGreen
from impactlab.contact.kogut_komvopoulos import KogutKomvopoulos
from impactlab.contact.names import Law
from impactlab.contact.tabulated import Tabulated
from impactlab.contact.thornton import Thornton

_LAWS: dict[Law, ContactLaw] = {
    law.law: law
    for law in (
        Hertz(),
        Ghaednia(),
        JacksonGreen(),
        KogutKomvopoulos(),
        Brake(),
        Thornton(),
        Tabulated(),
    )
}


def law_names() -> tuple[str, ...]:
    """Names of the registered laws, in registration order."""
    return tuple(str(law) for law in _LAWS)


def get_law(name: str | Law) -> ContactLaw:
    """The law registered under ``name`` (a :class:`Law` or its string value); ValueError
    listing the known names otherwise."""
    try:
        return _LAWS[name]  # type: ignore[index]
    except (KeyError, TypeError):
        raise ValueError(f"unknown contact law {name!r}; known laws: {', '.join(_LAWS)}") from None
