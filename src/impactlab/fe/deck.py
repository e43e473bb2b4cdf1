"""The CalculiX input deck (text, Abaqus-like keywords) of one indentation run.

Keywords follow the CalculiX 2.20 manual (G. Dhondt, *CalculiX CrunchiX User's Manual*,
http://www.dhondt.de): CAX4 axisymmetric elements (expanded by ccx to a 2-degree sector of
C3D8 bricks), *PLASTIC isotropic hardening, face-to-face penalty contact
(*CONTACT PAIR, TYPE=SURFACE TO SURFACE) with a linear pressure-overclosure law, *FRICTION,
*STATIC with automatic incrementation and NLGEOM, results printed to the ``.dat`` file.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from impactlab.fe.mesh import Mesh

#: The deck's units: mm, N, MPa (CalculiX has no units of its own; lengths in metres make the
#: 3-D Jacobians of micron-sized sector elements fall below ccx's positivity threshold).
LENGTH_UNIT = 1.0e-3
STRESS_UNIT = 1.0e6
FORCE_UNIT = STRESS_UNIT * LENGTH_UNIT**2


@dataclass(frozen=True)
class MaterialCard:
    """A body's material for the deck: E [Pa], nu, and the hardening table as
    (true stress [Pa], true plastic strain) rows, empty for an elastic body."""

    name: str
    E: float
    nu: float
    plastic: tuple[tuple[float, float], ...] = ()


@dataclass(frozen=True)
class StepControl:
    """Automatic incrementation of one step (step time runs 0..1): first, smallest and largest
    increment, and the load path as (step time, fraction of delta_max) points."""

    first: float
    smallest: float
    largest: float
    path: tuple[tuple[float, float], ...]


@dataclass(frozen=True)
class DeckSpec:
    """Everything the deck holds besides the mesh."""

    flat: MaterialCard
    sphere: MaterialCard | None  # None: rigid sphere (every sphere node prescribed)
    delta_max: float
    mu: float
    band_edges: tuple[float, ...]  # distances [m] splitting the flat's surface into bands
    band_stiffness: tuple[float, ...]  # penalty slope of each band [Pa/m]
    loading: StepControl
    unloading: StepControl | None  # None: the run stops at delta_max (no unloading step)


def _f(x: float) -> str:
    """A float as text, 13 significant digits (ccx reads at most 20 characters a field)."""
    return f"{float(x):.12e}"


def _lines(rows: Iterable[Sequence[object]]) -> str:
    return "".join(", ".join(str(v) for v in row) + "\n" for row in rows)


def _ids(values: np.ndarray, per_line: int = 16) -> str:
    v = [str(int(i) + 1) for i in values]
    return "".join(", ".join(v[i : i + per_line]) + "\n" for i in range(0, len(v), per_line))


def _material(card: MaterialCard) -> str:
    out = f"*MATERIAL, NAME={card.name}\n*ELASTIC\n{_f(card.E / STRESS_UNIT)}, {_f(card.nu)}\n"
    if card.plastic:
        out += "*PLASTIC\n" + _lines((_f(s / STRESS_UNIT), _f(e)) for s, e in card.plastic)
    return out


def _amplitude(name: str, path: Sequence[tuple[float, float]]) -> str:
    flat = [f"{_f(t)}, {_f(a)}" for t, a in path]
    rows = [", ".join(flat[i : i + 4]) for i in range(0, len(flat), 4)]
    return f"*AMPLITUDE, NAME={name}\n" + "".join(r + "\n" for r in rows)


def band_faces(mesh: Mesh, edges: Sequence[float]) -> list[np.ndarray]:
    """The flat's contact faces split by the distance of their midpoints at ``edges`` [m]."""
    d = mesh.face_distance(mesh.flat_surface_faces)
    bounds = [0.0, *edges, np.inf]
    return [mesh.flat_surface_faces[(d >= lo) & (d < hi)] for lo, hi in itertools.pairwise(bounds)]


def write_deck(mesh: Mesh, spec: DeckSpec) -> str:
    """The input deck as text (nodes and elements numbered from 1)."""
    parts: list[str] = ["*HEADING\nimpactlab.fe axisymmetric sphere-on-flat indentation\n"]
    xy = mesh.nodes / LENGTH_UNIT
    parts.append("*NODE\n")
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
        "NTOP": mesh.sphere_nodes if spec.sphere is None else mesh.sphere_top_nodes,
        "NFSURF": mesh.flat_surface_nodes,
        "NSSURF": mesh.sphere_surface_nodes,
    }
    for name, ids in sets.items():
        parts.append(f"*NSET, NSET={name}\n{_ids(ids)}")
    bands = band_faces(mesh, spec.band_edges)
    for k, faces in enumerate(bands):
        if len(faces):
            parts.append(f"*SURFACE, NAME=SF{k}, TYPE=ELEMENT\n")
            parts.append("".join(f"{e + 1}, S{f}\n" for e, f in faces))
    parts.append("*SURFACE, NAME=SSPH, TYPE=ELEMENT\n")
    parts.append("".join(f"{e + 1}, S{f}\n" for e, f in mesh.sphere_surface_faces))
    parts.append(_material(spec.flat))
    parts.append(f"*SOLID SECTION, ELSET=EFLAT, MATERIAL={spec.flat.name}\n")
    sphere = spec.sphere or MaterialCard("RIGID", spec.flat.E, spec.flat.nu)
    parts.append(_material(sphere))
    parts.append(f"*SOLID SECTION, ELSET=ESPH, MATERIAL={sphere.name}\n")
    for k, faces in enumerate(bands):
        if not len(faces):
            continue
        slope = spec.band_stiffness[k] * LENGTH_UNIT / STRESS_UNIT
        parts.append(f"*SURFACE INTERACTION, NAME=I{k}\n")
        parts.append(f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n{_f(slope)}\n")
        if spec.mu > 0.0:
            parts.append(f"*FRICTION\n{_f(spec.mu)}, {_f(slope)}\n")
        parts.append(f"*CONTACT PAIR, INTERACTION=I{k}, TYPE=SURFACE TO SURFACE\nSF{k}, SSPH\n")
    parts.append(_amplitude("LOAD", spec.loading.path))
    steps = [(spec.loading, "LOAD")]
    if spec.unloading is not None:
        parts.append(_amplitude("UNLOAD", spec.unloading.path))
        steps.append((spec.unloading, "UNLOAD"))
    parts.append("*BOUNDARY\nNAXIS, 1, 1, 0.0\nNBOT, 1, 2, 0.0\n")
    if spec.sphere is None:
        parts.append("*BOUNDARY\nNTOP, 1, 1, 0.0\n")
    for k, (step, amp) in enumerate(steps):
        parts.append("*STEP, NLGEOM, INC=100000\n*STATIC\n")
        parts.append(f"{_f(step.first)}, 1.0, {_f(step.smallest)}, {_f(step.largest)}\n")
        op = "" if k == 0 else ", OP=MOD"
        parts.append(
            f"*BOUNDARY, AMPLITUDE={amp}{op}\nNTOP, 2, 2, {_f(-spec.delta_max / LENGTH_UNIT)}\n"
        )
        parts.append("*NODE PRINT, NSET=NTOP, TOTALS=ONLY\nRF\n")
        parts.append("*NODE PRINT, NSET=NBOT, TOTALS=ONLY\nRF\n")
        parts.append("*NODE PRINT, NSET=NFSURF\nU\n")
        if spec.sphere is not None:
            parts.append("*NODE PRINT, NSET=NSSURF\nU\n")
        parts.append("*CONTACT PRINT\nCSTR\n")
        parts.append("*END STEP\n")
    return "".join(parts)
