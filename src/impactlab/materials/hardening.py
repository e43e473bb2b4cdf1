"""Strain hardening of the flat: a cited flow curve as a true stress - plastic strain table.

The finite-element reference (``impactlab.fe``) takes the flat's isotropic hardening as rows of
(true stress [Pa], true plastic strain); the contact laws other than Brake's carry none. This
module holds the cited hardening laws and turns them into such tables.

:data:`AISI_1010_HARDENING`: the paper's flat, AISI 1010, with the strain hardening of the
closest low-carbon steel for which a hardening law was found, **1006 steel** (Johnson & Cook
1983, Table 1: flow stress A + B eps_p^n, B = 275 MPa, n = 0.36, quasi-static, room
temperature). The initial yield is the paper's S_y of AISI 1010 (305 MPa, Table 1), not 1006's
A = 350 MPa: the hardening term is borrowed, the material is the paper's. Nothing is fitted.
Validity: Johnson & Cook's torsion and tension tests reach plastic strains of about 1 to 2;
beyond the table's last strain the FE program keeps the stress constant.
No cited law for AISI 1010 itself was found under any of its designations (UNS G10100,
C10/Ck10/C10E, S10C, GB 10); docs/materials.md records the search and each near miss.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from impactlab.materials.library import AISI_1010
from impactlab.references import cite

__all__ = ["AISI_1010_HARDENING", "PowerLawHardening"]


@dataclass(frozen=True)
class PowerLawHardening:
    """Flow stress ``sigma = yield_strength + B eps_p^n`` (Johnson-Cook's strain term at the
    reference rate and temperature; Ludwik's law). yield_strength, B [Pa]; n [1];
    ``max_strain``: the largest plastic strain tabulated; ``source``: a reference key."""

    name: str
    yield_strength: float
    B: float
    n: float
    source: str
    max_strain: float = 2.0

    def __post_init__(self) -> None:
        for label, v in (("yield_strength", self.yield_strength), ("B", self.B)):
            if not (np.isfinite(v) and v > 0.0):
                raise ValueError(f"{label} must be a positive stress [Pa], got {v!r}")
        if not 0.0 < self.n <= 1.0:
            raise ValueError(f"n must lie in (0, 1], got {self.n!r}")
        if not self.max_strain > 0.0:
            raise ValueError(f"max_strain must be > 0, got {self.max_strain!r}")
        cite(self.source)

    def stress(self, plastic_strain: object) -> np.ndarray:
        """True flow stress [Pa] at true plastic strain ``plastic_strain`` [1] (>= 0)."""
        e = np.asarray(plastic_strain, dtype=np.float64)
        if np.any(e < 0.0) or not np.all(np.isfinite(e)):
            raise ValueError("plastic_strain must be finite and >= 0")
        return self.yield_strength + self.B * e**self.n

    def table(self, points: int = 40) -> tuple[tuple[float, float], ...]:
        """Rows (true stress [Pa], true plastic strain) for the FE program: strain 0, then
        ``points - 1`` strains geometric from 1e-5 to ``max_strain`` (the power law's steep
        start resolved); 7 significant digits."""
        if points < 3:
            raise ValueError(f"points must be >= 3, got {points!r}")
        e = np.concatenate(([0.0], np.geomspace(1e-5, self.max_strain, points - 1)))
        s = self.stress(e)
        return tuple((float(f"{a:.7g}"), float(f"{b:.7g}")) for a, b in zip(s, e, strict=True))


#: AISI 1010 (the paper's S_y) with 1006 steel's strain hardening (Johnson & Cook 1983).
AISI_1010_HARDENING = PowerLawHardening(
    "AISI 1010 (paper's S_y) with 1006 steel's hardening, Johnson & Cook 1983",
    AISI_1010.yield_strength,
    275e6,
    0.36,
    "johnson-cook-1983",
)
