"""The paper's drops and rod section, shared by the flexible-rod tests (a module of its own, not
``conftest``: another folder's ``conftest`` would shadow it when several folders run at once)."""

from __future__ import annotations

from impactlab.bodies.rod_section import RodSection

#: The paper's three drops: angle [deg], vy [m/s], measured mu (used as the Coulomb mu).
CASES = [(20, -1.41, 0.20), (45, -2.18, 0.13), (70, -3.45, 0.10)]
#: The paper's rod as a section (d from m, L and rho).
SEC = RodSection.paper()
