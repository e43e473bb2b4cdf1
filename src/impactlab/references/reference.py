"""``Reference``: one cited source (citation, DOI, web address, what was checked)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

__all__ = ["DOI_PATTERN", "PAPER", "Reference"]

#: A well-formed DOI: "10.", a registrant code of 4-9 digits (dot-separated parts allowed), "/",
#: a suffix without spaces (Crossref's recommended pattern, widened to upper case).
DOI_PATTERN = re.compile(r"^10\.\d{4,9}(\.\d+)*/\S+$")


@dataclass(frozen=True)
class Reference:
    """A cited source: registry ``key``, ``citation`` text, ``doi`` and ``url``
    (https://doi.org/<doi>, filled in from the DOI; for a source without a DOI, its web address
    or ""); ``confirmed``: the DOI was read in a copy
    of the publication or at its DOI address; ``note``: what was checked, and where."""

    key: str
    citation: str
    doi: str = ""
    url: str = field(default="")
    confirmed: bool = False
    note: str = ""

    def __post_init__(self) -> None:
        if self.doi and not DOI_PATTERN.match(self.doi):
            raise ValueError(f"reference {self.key!r}: malformed DOI {self.doi!r}")
        if self.confirmed and not self.doi:
            raise ValueError(f"reference {self.key!r}: confirmed without a DOI")
        if self.url and not self.url.startswith(("https://", "http://")):
            raise ValueError(f"reference {self.key!r}: url must be a web address, got {self.url!r}")
        if self.doi and not self.url:
            object.__setattr__(self, "url", f"https://doi.org/{self.doi}")

    def __str__(self) -> str:
        return f"{self.citation}, doi:{self.doi}" if self.doi else self.citation


PAPER = "ghaednia-2016-impact"
"""Key of the seed paper (Ghaednia, Marghitu & Jackson 2016, Arch. Appl. Mech.)."""
