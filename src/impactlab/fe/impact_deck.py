"""The CalculiX input deck of one impact run.

The bodies, materials and banded penalty contact are the indentation deck's
(``impactlab.fe.deck``); the sphere is shifted up by the initial gap, has no prescribed node
and starts with the velocity -v (``*INITIAL CONDITIONS, TYPE=VELOCITY``; ccx passes it to
the expanded sector's nodes only when the node set also carries a surface, hence ``SVEL``).

Procedures. Both integrate implicitly (Newton-iterated) with inertia (``*DENSITY``).

- Elastic flat: an ``*UNCOUPLED TEMPERATURE-DISPLACEMENT`` step at constant temperature (no
  thermal expansion; the thermal field plays no part) with automatic increments. ``*DYNAMIC``
  with automatic increments does not get past the first contact increment: its energy-based
  impact rules (ccx's ``checkimpacts``, applied only to ``*DYNAMIC`` steps) force the increment
  below any minimum (1e-14 s) whatever the penalty slope or the increment; ``*DYNAMIC,
  EXPLICIT`` needs increments of about 3.5e-12 s (the smallest brick of the 2-degree sector at
  the axis), some 10^7 increments per impact.
- Elastic-plastic flat: ``*DYNAMIC, DIRECT`` (fixed increments, no impact rules) with the
  Hilber-Hughes-Taylor parameter ``ALPHA`` = :data:`HHT_ALPHA`, whose numerical damping of the
  highest frequencies lets Newton converge through the contact's onset (it did not at
  alpha = 0 or -0.05; Hilber, Hughes, Taylor 1977, doi:10.1002/eqe.4290050306). The automatic
  temperature-displacement step ran, but with cut-backs to 1e-8 s at every contact increment.
  CalculiX 2.20 stops with "no convergence in incplas" before the first increment whenever
  plasticity, contact and inertia meet (``impact_run.check_ccx_release`` refuses such a run
  on 2.20 and older); a CalculiX built from the author's sources after 2.23 runs it
  (docs/fe-dynamic.md).

Printed per increment: the contact force of every band (``*CONTACT PRINT``, ``CF``), the
displacements and velocities of every sphere node and of the flat's surface.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from impactlab.fe.deck import (
    LENGTH_UNIT,
    STRESS_UNIT,
    DeckSpec,
    _f,
    _ids,
    _material,
    band_faces,
)
from impactlab.fe.mesh import Mesh

#: A density in kg/m^3 times this is the deck's (tonne/mm^3, consistent with mm, N, s).
DENSITY_TO_DECK = 1.0e-12
#: Thermal data the procedure needs (steel-like; no thermal expansion, constant temperature):
#: conductivity [W/(m K) = N/(s K)], specific heat [J/(kg K)], temperature [K].
CONDUCTIVITY = 50.0
SPECIFIC_HEAT = 460.0
TEMPERATURE = 293.0
#: The Hilber-Hughes-Taylor parameter of the "dynamic-direct" procedure (-1/3 <= alpha <= 0;
#: -1/3 the strongest damping of the highest frequencies).
HHT_ALPHA = -0.3
#: The procedures: the step card of each.
PROCEDURES = ("temperature-displacement", "dynamic-direct")


@dataclass(frozen=True)
class ImpactDeckSpec:
    """What the impact deck holds besides the mesh: the indentation deck's materials and
    contact, the densities [kg/m^3], the speed [m/s], the gap [m], the increment and end time
    [s], the procedure (one of :data:`PROCEDURES`) and the fixed increment [s] of
    "dynamic-direct"."""

    base: DeckSpec
    flat_density: float
    sphere_density: float
    speed: float
    gap: float
    increment: float
    end_time: float
    procedure: str = "temperature-displacement"
    fixed_increment: float = 0.0


def shifted(mesh: Mesh, gap: float) -> np.ndarray:
    """Node coordinates with the sphere raised by ``gap`` [m]."""
    nodes = mesh.nodes.copy()
    nodes[mesh.sphere_nodes, 1] += gap
    return nodes


def _material_card(card_text: str, density: float) -> str:
    """A material card with the thermal data and the density inserted after its name."""
    head, rest = card_text.split("\n", 1)
    spec_heat = SPECIFIC_HEAT * 1.0e6  # J/(kg K) = m^2/(s^2 K) -> mm^2/(s^2 K)
    extra = (
        f"*CONDUCTIVITY\n{_f(CONDUCTIVITY)}\n*SPECIFIC HEAT\n{_f(spec_heat)}\n"
        f"*DENSITY\n{_f(density * DENSITY_TO_DECK)}\n"
    )
    return f"{head}\n{extra}{rest}"


def procedure_card(spec: ImpactDeckSpec) -> str:
    """The procedure card and its time line (first, end, smallest, largest increment [s])."""
    dt, t_end = spec.increment, spec.end_time
    limits = f"{_f(t_end)}, {_f(1e-4 * dt)}, {_f(dt)}\n"
    if spec.procedure == "temperature-displacement":
        return f"*UNCOUPLED TEMPERATURE-DISPLACEMENT\n{_f(0.5 * dt)}, {limits}"
    if spec.procedure == "dynamic-direct":
        if not 0.0 < spec.fixed_increment <= dt:
            raise ValueError(
                f"fixed_increment must be in (0, increment = {dt!r}] s, "
                f"got {spec.fixed_increment!r} s"
            )
        return f"*DYNAMIC, DIRECT, ALPHA={HHT_ALPHA}\n{_f(spec.fixed_increment)}, {limits}"
    raise ValueError(f"procedure must be one of {PROCEDURES}, got {spec.procedure!r}")


def write_impact_deck(mesh: Mesh, spec: ImpactDeckSpec) -> str:
    """The impact deck as text (nodes and elements numbered from 1)."""
    base = spec.base
    if base.sphere is None:
        raise ValueError("an impact needs a deformable sphere (elastic or elastic-plastic)")
    xy = shifted(mesh, spec.gap) / LENGTH_UNIT
    parts: list[str] = ["*HEADING\nimpactlab.fe axisymmetric sphere-on-flat impact\n", "*NODE\n"]
    parts.append("".join(f"{i + 1}, {_f(x)}, {_f(y)}, 0.0\n" for i, (x, y) in enumerate(xy)))
    for name, els in (("EFLAT", mesh.flat_elements), ("ESPH", mesh.sphere_elements)):
        parts.append(f"*ELEMENT, TYPE=CAX4, ELSET={name}\n")
        conn = mesh.elements[els] + 1
        parts.append(
            "".join(
                f"{e + 1}, {a}, {b}, {c}, {d}\n" for e, (a, b, c, d) in zip(els, conn, strict=True)
            )
        )
    sets = {
        "NAXIS": mesh.axis_nodes,
        "NBOT": mesh.flat_bottom_nodes,
        "NSPH": mesh.sphere_nodes,
        "NFSURF": mesh.flat_surface_nodes,
        "NALL": np.arange(len(mesh.nodes)),
    }
    for name, ids in sets.items():
        parts.append(f"*NSET, NSET={name}\n{_ids(ids)}")
    bands = band_faces(mesh, base.band_edges)
    for k, faces in enumerate(bands):
        if len(faces):
            parts.append(f"*SURFACE, NAME=SF{k}, TYPE=ELEMENT\n")
            parts.append("".join(f"{e + 1}, S{f}\n" for e, f in faces))
    parts.append("*SURFACE, NAME=SSPH, TYPE=ELEMENT\n")
    parts.append("".join(f"{e + 1}, S{f}\n" for e, f in mesh.sphere_surface_faces))
    parts.append("*SURFACE, NAME=SVEL, TYPE=NODE\nNSPH\n")
    parts.append(_material_card(_material(base.flat), spec.flat_density))
    parts.append(f"*SOLID SECTION, ELSET=EFLAT, MATERIAL={base.flat.name}\n")
    parts.append(_material_card(_material(base.sphere), spec.sphere_density))
    parts.append(f"*SOLID SECTION, ELSET=ESPH, MATERIAL={base.sphere.name}\n")
    used = []
    for k, faces in enumerate(bands):
        if not len(faces):
            continue
        used.append(k)
        slope = base.band_stiffness[k] * LENGTH_UNIT / STRESS_UNIT
        parts.append(f"*SURFACE INTERACTION, NAME=I{k}\n")
        parts.append(f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{_f(slope)}\n")
        if base.mu > 0.0:
            parts.append(f"*FRICTION\n{_f(base.mu)}, {_f(slope)}\n")
        parts.append(f"*CONTACT PAIR, INTERACTION=I{k}, TYPE=SURFACE TO SURFACE\nSF{k}, SSPH\n")
    parts.append("*BOUNDARY\nNAXIS, 1, 1, 0.0\nNBOT, 1, 2, 0.0\n")
    parts.append(f"*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, {_f(TEMPERATURE)}\n")
    v = -spec.speed / LENGTH_UNIT
    parts.append(f"*INITIAL CONDITIONS, TYPE=VELOCITY\nNSPH, 2, {_f(v)}\n")
    parts.append("*STEP, NLGEOM, INC=100000\n" + procedure_card(spec))
    parts.append("*NODE PRINT, NSET=NBOT, TOTALS=ONLY\nRF\n")
    parts.append("*NODE PRINT, NSET=NSPH\nU, V\n")
    parts.append("*NODE PRINT, NSET=NFSURF\nU\n")
    parts.extend(f"*CONTACT PRINT, SLAVE=SF{k}, MASTER=SSPH, TOTALS=ONLY\nCF\n" for k in used)
    parts.append("*END STEP\n")
    return "".join(parts)
