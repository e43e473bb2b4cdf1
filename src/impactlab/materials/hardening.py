"""Strain hardening of the flat: a cited flow curve as a true stress - plastic strain table.

The finite-element reference (``impactlab.fe``) takes the flat's isotropic hardening as rows of
(true stress [Pa], true plastic strain); the contact laws other than Brake's carry none. This
module holds the hardening laws and turns them into such tables.

:data:`AISI_1010_HARDENING`: the paper's flat, AISI 1010, with its own strain hardening derived
from the grade's cited tensile properties (the cold-drawn 1010 row of SAE J1397: yield 44 ksi,
which the paper gives as S_y = 305 MPa, and tensile strength 53 ksi, S_u = 365 MPa) through
Swift's law ``sigma = K (eps0 + eps_p)^n`` (Swift 1952) with eps0 = 0.002 (sigma(0) is the
0.2 % offset yield) and Considere's necking criterion at the tensile strength: n = 0.0696,
K = 470 MPa. Nothing is fitted to an impact. Validity: one power law from yield through the
uniform strain (eps_u = n - eps0 = 0.068), extrapolated beyond; isotropic, quasi-static, room
temperature; the SAE values are estimated minima of bars of a size range. Beyond the table's
last strain (2) the FE program keeps the stress constant. docs/materials.md has the derivation,
its checks and its sensitivity.

:data:`AISI_1010_WITH_1006_HARDENING`: the earlier stand-in, kept for comparison: the paper's
S_y with the strain-hardening term of **1006 steel** (Johnson & Cook 1983, Table 1:
B = 275 MPa, n = 0.36), no law for AISI 1010 itself having been found.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from impactlab.materials.library import AISI_1010
from impactlab.references import cite

__all__ = [
    "AISI_1010_HARDENING",
    "AISI_1010_TENSILE_STRENGTH",
    "AISI_1010_WITH_1006_HARDENING",
    "PowerLawHardening",
    "SwiftHardening",
]


def _table(
    stress: Callable[[np.ndarray], np.ndarray], max_strain: float, points: int
) -> tuple[tuple[float, float], ...]:
    """Rows (true stress [Pa], true plastic strain): strain 0, then ``points - 1`` strains
    geometric from 1e-5 to ``max_strain``; 7 significant digits."""
    if points < 3:
        raise ValueError(f"points must be >= 3, got {points!r}")
    e = np.concatenate(([0.0], np.geomspace(1e-5, max_strain, points - 1)))
    s = stress(e)
    return tuple((float(f"{a:.7g}"), float(f"{b:.7g}")) for a, b in zip(s, e, strict=True))


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
        return _table(self.stress, self.max_strain, points)


@dataclass(frozen=True)
class SwiftHardening:
    """Swift's flow curve ``sigma = K (eps0 + eps_p)^n`` (Swift 1952). K [Pa]; eps0, n [1];
    ``max_strain``: the largest plastic strain tabulated; ``source``: reference keys (the law's
    and the data's). The initial yield is ``K eps0^n`` (:attr:`yield_strength`).

    :meth:`from_tensile` builds it from a grade's yield and tensile strength: eps0 is the
    yield's plastic offset (0.002 for the 0.2 % offset yield), and Considere's criterion
    (necking where ``d sigma / d eps_p = sigma``) puts the tensile strength at the uniform
    true strain ``eps_u = n - eps0``.
    """

    name: str
    K: float
    eps0: float
    n: float
    source: tuple[str, ...]
    max_strain: float = 2.0

    def __post_init__(self) -> None:
        if not (np.isfinite(self.K) and self.K > 0.0):
            raise ValueError(f"K must be a positive stress [Pa], got {self.K!r}")
        if not (np.isfinite(self.eps0) and 0.0 < self.eps0 < 1.0):
            raise ValueError(f"eps0 must lie in (0, 1), got {self.eps0!r}")
        if not 0.0 < self.n <= 1.0:
            raise ValueError(f"n must lie in (0, 1], got {self.n!r}")
        if not self.max_strain > 0.0:
            raise ValueError(f"max_strain must be > 0, got {self.max_strain!r}")
        cite(*self.source)

    @classmethod
    def from_tensile(
        cls,
        name: str,
        yield_strength: float,
        tensile_strength: float,
        source: tuple[str, ...],
        *,
        eps0: float = 0.002,
        max_strain: float = 2.0,
    ) -> SwiftHardening:
        """The Swift law through the 0.2 % offset yield ``yield_strength`` [Pa] at zero plastic
        strain and the engineering tensile strength ``tensile_strength`` [Pa] at Considere's
        necking point. Solves ``n ln(n / eps0) - (n - eps0) = ln(S_u / S_y)`` for n (one root
        above eps0), then ``K = S_y / eps0^n``. The elastic strain at the tensile strength
        (S_u / E, about 0.002 for steel) is left out of the engineering-to-true conversion."""
        for label, v in (
            ("yield_strength", yield_strength),
            ("tensile_strength", tensile_strength),
        ):
            if not (np.isfinite(v) and v > 0.0):
                raise ValueError(f"{label} must be a positive stress [Pa], got {v!r}")
        if not tensile_strength > yield_strength:
            raise ValueError(
                f"tensile_strength must exceed yield_strength ({yield_strength!r} Pa) for a "
                f"hardening law, got {tensile_strength!r} Pa"
            )
        if not (np.isfinite(eps0) and 0.0 < eps0 < 1.0):
            raise ValueError(f"eps0 must lie in (0, 1), got {eps0!r}")
        target = math.log(tensile_strength / yield_strength)

        def mismatch(n: float) -> float:
            return n * math.log(n / eps0) - (n - eps0) - target

        upper = 1.0
        if mismatch(upper) < 0.0:
            raise ValueError(
                f"tensile_strength / yield_strength = {tensile_strength / yield_strength:.4g} "
                f"needs a Swift exponent n > 1 with eps0 = {eps0!r}; allowed: n <= 1"
            )
        n = float(brentq(mismatch, eps0, upper, xtol=1e-15, rtol=1e-14))
        return cls(name, yield_strength / eps0**n, eps0, n, source, max_strain)

    @property
    def yield_strength(self) -> float:
        """Initial yield ``K eps0^n`` [Pa]."""
        return float(self.K * self.eps0**self.n)

    @property
    def uniform_strain(self) -> float:
        """Considere's uniform true plastic strain ``n - eps0`` [1] (necking in tension)."""
        return self.n - self.eps0

    @property
    def tensile_strength(self) -> float:
        """The engineering tensile strength [Pa] the law implies: the true stress at
        :attr:`uniform_strain` over ``exp(uniform_strain)`` (elastic strain left out)."""
        eu = self.uniform_strain
        return float(self.K * self.n**self.n * math.exp(-eu))

    def stress(self, plastic_strain: object) -> np.ndarray:
        """True flow stress [Pa] at true plastic strain ``plastic_strain`` [1] (>= 0)."""
        e = np.asarray(plastic_strain, dtype=np.float64)
        if np.any(e < 0.0) or not np.all(np.isfinite(e)):
            raise ValueError("plastic_strain must be finite and >= 0")
        return self.K * (self.eps0 + e) ** self.n

    def slope(self, plastic_strain: object) -> np.ndarray:
        """Hardening rate ``d sigma / d eps_p`` [Pa] at ``plastic_strain`` [1] (>= 0)."""
        e = np.asarray(plastic_strain, dtype=np.float64)
        return self.n * self.stress(e) / (self.eps0 + e)

    def table(self, points: int = 40) -> tuple[tuple[float, float], ...]:
        """Rows (true stress [Pa], true plastic strain) for the FE program, as
        :meth:`PowerLawHardening.table`: strain 0, then ``points - 1`` strains geometric from
        1e-5 to ``max_strain``; 7 significant digits."""
        return _table(self.stress, self.max_strain, points)


#: AISI 1010 cold drawn, SAE J1397's estimated minimum tensile strength: 53 ksi = 365.4 MPa,
#: rounded to 365 MPa as the paper rounds the same row's 44 ksi yield (303.4 MPa) to 305 MPa.
AISI_1010_TENSILE_STRENGTH = 365e6

#: AISI 1010's own hardening: Swift's law through the paper's S_y (305 MPa) and SAE J1397's
#: cold-drawn tensile strength (365 MPa) by Considere's criterion, eps0 = 0.002.
AISI_1010_HARDENING = SwiftHardening.from_tensile(
    "AISI 1010 cold drawn, Swift law from SAE J1397 S_y and S_u (Considere)",
    AISI_1010.yield_strength,
    AISI_1010_TENSILE_STRENGTH,
    ("swift-1952", "sae-j1397", "dieter-1961"),
)

#: The earlier stand-in: AISI 1010 (the paper's S_y) with 1006 steel's strain hardening
#: (Johnson & Cook 1983); the hardened FE case's sensitivity to the hardening law.
AISI_1010_WITH_1006_HARDENING = PowerLawHardening(
    "AISI 1010 (paper's S_y) with 1006 steel's hardening, Johnson & Cook 1983",
    AISI_1010.yield_strength,
    275e6,
    0.36,
    "johnson-cook-1983",
)
