"""Measurements of Kharaz, Gorham & Salman (2001): moved into the package (issue 12) as
``impactlab.verification.data.kharaz2001``, which states their sources; re-exported here for
the prototype scripts."""

from impactlab.verification.data.kharaz2001 import (  # noqa: F401
    KGS_ET,
    KGS_OMEGA,
    KGS_REBOUND_COM,
    KGS_REBOUND_CONTACT,
)
