"""The result of one impact run and how it is read from ccx's printed output.

Names, units and signs are those of docs/glossary.md (SI): the contact force F >= 0 pushes the
bodies apart; the interference delta (``penetration``) is the approach of the sphere's centre
of mass past the position where it first touches the undeformed flat (the indentation model's
delta: the flat is fixed at its bottom); ``vy`` is the sphere's centre-of-mass velocity along
the flat's outward normal (up), negative towards the flat. The names before 0.3 read the new
fields with a DeprecationWarning (:data:`RENAMED_IMPACT_FIELDS`; ``velocity`` is -vy).
"""

from __future__ import annotations

import math
import re
import warnings
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from impactlab.fe.ccx import FORTRAN_FLOAT, DatFile, fortran_value
from impactlab.fe.deck import FORCE_UNIT, LENGTH_UNIT
from impactlab.fe.mesh import Mesh
from impactlab.fe.result import SECTOR_FACTOR
from impactlab.schema import warn_renamed

_CF = re.compile(
    r"statistics for slave set \S+, master set \S+ and time\s+(" + FORTRAN_FLOAT + r")\s*\n"
    r"\s*\n[^\n]*\n\s*\n\s*(" + FORTRAN_FLOAT + r")\s+(" + FORTRAN_FLOAT + r")"
)

#: The contact counts as closed while F > CONTACT_THRESHOLD * F_max.
CONTACT_THRESHOLD = 1.0e-3

#: A run ccx stopped after the force had fallen past its peak below this fraction of F_max
#: is "stopped at separation": v_out and delta_p are read at its last increment.
SEPARATION_FRACTION = 5.0e-3

#: The array fields (stored as arrays in the cache; the rest is the header).
IMPACT_ARRAYS = ("time", "force", "penetration", "vy", "dent_r", "dent_z")

#: The names before 0.3 of the impact's fields (attributes, cache files, the impact tables'
#: keys) -> their glossary names, the same values. ``velocity`` (positive towards the flat)
#: is ``vy`` with the glossary's sign: velocity = -vy.
RENAMED_IMPACT_FIELDS: dict[str, str] = {
    "restitution": "e",
    "max_interference": "delta_max",
    "contact_duration": "duration",
    "residual_depth": "delta_p",
    "interference": "penetration",
}


def renamed_field(old: str, new: str, owner: str = "fe.ImpactResult") -> Any:
    """A read-only property ``old`` of ``owner`` that reads ``new`` with a DeprecationWarning."""

    def get(self: Any) -> Any:
        warn_renamed(old, new, f"{owner} field")
        return getattr(self, new)

    return property(get, doc=f"``{new}``, its name before 0.3 (a DeprecationWarning).")


@dataclass(frozen=True)
class ImpactResult:
    """One impact (SI units: m, N, s, kg; names and signs of docs/glossary.md).

    time [s] (0 at the start, the sphere a gap above the flat); force: the contact force F(t)
    [N]; penetration: the interference delta(t) [m] (negative before first touch: the gap);
    vy: the sphere's centre-of-mass velocity [m/s], up positive (negative towards the flat);
    speed, mass: v_in [m/s] (> 0), m [kg]; rebound_speed: v_out [m/s] (> 0 away from the flat,
    the mean after separation); e: v_out / v_in; max_force, delta_max: the peaks of F and
    delta; contact_start [s] and duration [s]: first touch and how long the contact lasts;
    delta_p [m]: the permanent depth, the interference left after the impact: the flat's
    permanent dent depth at the axis (flat_dent_depth [m]) plus the sphere's permanent
    flattening at its apex (sphere_flattening [m]), both from the final deformed surfaces
    (means over the last increments): what the engine's delta_p (the law's delta_r at
    separation) models; dent_r, dent_z: the flat's final surface (z > 0: pile-up) [m];
    momentum_balance: |m (v_in + v_out) - integral F dt| / (m v_in), the consistency of the
    force history with the velocities; separated: the sphere left the flat before the end;
    converged: ccx finished the run (a run with separated True and converged False stopped at
    separation: v_out and delta_p are read at its last increment, where F < SEPARATION_FRACTION
    F_max); message, increments, cutbacks, iterations, run_time,
    n_elements as for an indentation; delta_c [m]; inputs: every input (the cache key's data).
    The names before 0.3 (``restitution``, ``max_interference``, ``contact_duration``,
    ``residual_depth``, ``interference``, ``velocity`` = -vy) read these with a
    DeprecationWarning.
    """

    time: np.ndarray
    force: np.ndarray
    penetration: np.ndarray
    vy: np.ndarray
    speed: float
    mass: float
    rebound_speed: float
    e: float
    max_force: float
    delta_max: float
    contact_start: float
    duration: float
    delta_p: float
    flat_dent_depth: float
    sphere_flattening: float
    dent_r: np.ndarray
    dent_z: np.ndarray
    momentum_balance: float
    separated: bool
    converged: bool
    message: str
    increments: int
    cutbacks: int
    iterations: int
    run_time: float
    n_elements: int
    delta_c: float
    inputs: dict[str, Any]

    restitution = renamed_field("restitution", "e")
    max_interference = renamed_field("max_interference", "delta_max")
    contact_duration = renamed_field("contact_duration", "duration")
    residual_depth = renamed_field("residual_depth", "delta_p")
    interference = renamed_field("interference", "penetration")

    @property
    def velocity(self) -> np.ndarray:
        """-vy [m/s], positive towards the flat: the name and sign before 0.3 (a
        DeprecationWarning)."""
        warnings.warn(
            "fe.ImpactResult field 'velocity' (positive towards the flat) is renamed 'vy', "
            "with the glossary's sign: up positive, negative towards the flat (velocity = -vy; "
            "impactlab 0.3); the old name goes in 0.4",
            DeprecationWarning,
            stacklevel=2,
        )
        return np.asarray(-self.vy)

    @property
    def stopped_at_separation(self) -> bool:
        """True when ccx stopped as the sphere left the flat (F below SEPARATION_FRACTION F_max
        after its peak): the rebound speed and the dent are read at the last increment."""
        return self.separated and not self.converged

    def status(self) -> str:
        """``converged``, ``stopped at separation: ...``, or what went wrong."""
        if self.stopped_at_separation:
            share = 100.0 * float(self.force[-1]) / self.max_force
            return (
                f"stopped at separation: ccx stopped at t = {self.time[-1]:.4g} s with "
                f"F = {share:.2g} % of F_max (v_out, delta_p read there); {self.message}"
            )
        if not self.converged:
            return f"NOT CONVERGED: ccx stopped at t = {self.time[-1]:.4g} s; {self.message}"
        if not self.separated:
            return "NOT SEPARATED: the sphere was still in contact at the end of the run"
        return "converged"

    def arrays(self) -> dict[str, Any]:
        """Every field as a plain value (arrays stay numpy arrays), for storage."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


def upgrade_record(record: dict[str, Any]) -> dict[str, Any]:
    """A stored impact (a cache file's header and arrays) in the names of 0.3: the names
    before (:data:`RENAMED_IMPACT_FIELDS`) renamed, ``velocity`` as ``vy`` = -velocity, and,
    where the record has no split of delta_p, flat_dent_depth read from the flat's final
    surface at the axis (-dent_z there, at the last increment, not a mean; nan without a dent)
    and sphere_flattening = delta_p - flat_dent_depth. A record of 0.3 is returned as is."""
    out = {RENAMED_IMPACT_FIELDS.get(k, k): v for k, v in record.items() if k != "velocity"}
    if "velocity" in record:
        out["vy"] = -np.asarray(record["velocity"], dtype=np.float64)
    if "flat_dent_depth" not in out and "delta_p" in out:
        r, z = np.asarray(out.get("dent_r", [])), np.asarray(out.get("dent_z", []))
        flat = -float(z[int(np.argmin(np.abs(r)))]) if z.size else math.nan
        out["flat_dent_depth"] = flat
        out["sphere_flattening"] = float(out["delta_p"]) - flat
    return out


class RenamedKeys(dict[str, Any]):
    """A record (an impact table's row entry, a comparison's row) whose keys before 0.3
    (:data:`RENAMED_IMPACT_FIELDS`) still read their value, with a DeprecationWarning; they
    are not among its keys (nor in its JSON)."""

    def _renamed(self, key: object) -> str | None:
        """The new name of an old key this record holds (with the DeprecationWarning), else
        None."""
        new = RENAMED_IMPACT_FIELDS.get(key) if isinstance(key, str) else None
        if new is None or not dict.__contains__(self, new):
            return None
        warn_renamed(str(key), new, "FE impact record key")
        return new

    def __missing__(self, key: str) -> Any:
        new = self._renamed(key)
        if new is None:
            raise KeyError(key)
        return dict.__getitem__(self, new)

    def get(self, key: str, default: Any = None) -> Any:  # type: ignore[override]
        if dict.__contains__(self, key):
            return dict.__getitem__(self, key)
        new = self._renamed(key)
        return default if new is None else dict.__getitem__(self, new)

    def __contains__(self, key: object) -> bool:
        return dict.__contains__(self, key) or self._renamed(key) is not None


def contact_forces(text: str) -> tuple[np.ndarray, np.ndarray]:
    """(times, axial contact force on the flat's surface [N], full circle) summed over the
    contact bands, from the ``*CONTACT PRINT ... CF`` blocks of a ``.dat`` file."""
    sums: dict[float, float] = {}
    for m in _CF.finditer(text):
        key = fortran_value(m.group(1))
        sums[key] = sums.get(key, 0.0) + fortran_value(m.group(3))
    times = sorted(sums)
    fy = np.array([sums[k] for k in times], dtype=np.float64)
    return np.array(times, dtype=np.float64), -fy * SECTOR_FACTOR * FORCE_UNIT


def node_masses(mesh: Mesh, elements: np.ndarray, density: float) -> np.ndarray:
    """Lumped node masses [kg] of the axisymmetric elements (each element's mass
    rho 2 pi r_c A shared equally by its four nodes), indexed by node id (0-based)."""
    quads = mesh.elements[elements]
    x, y = mesh.nodes[quads, 0], mesh.nodes[quads, 1]
    area = 0.5 * np.abs(np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1))
    mass = density * 2.0 * math.pi * x.mean(axis=1) * area
    out = np.zeros(len(mesh.nodes))
    np.add.at(out, quads.ravel(), np.repeat(0.25 * mass, 4))
    return out


def centre_of_mass(dat: DatFile, what: str, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(times, the weighted mean axial value [m or m/s]) of the sphere's nodes for ``what``
    ("displacements" or "velocities")."""
    rows = dat.nodal.get((what, "NSPH"), [])
    t = np.array([r[0] for r in rows], dtype=np.float64)
    vals = []
    for _, ids, v in rows:
        w = weights[ids - 1]
        vals.append(float(np.sum(w * v[:, 1]) / np.sum(w)) * LENGTH_UNIT)
    return t, np.asarray(vals, dtype=np.float64)


def contact_window(t: np.ndarray, force: np.ndarray) -> tuple[float, float, bool]:
    """(start, end, separated) of the contact: where F first rises above and last falls
    below CONTACT_THRESHOLD F_max (interpolated); separated False when F is still above at
    the last point."""
    if not force.size or float(np.max(force)) <= 0.0:
        return math.nan, math.nan, False
    on = force > CONTACT_THRESHOLD * float(np.max(force))
    i0 = int(np.argmax(on))
    i1 = len(on) - 1 - int(np.argmax(on[::-1]))
    level = CONTACT_THRESHOLD * float(np.max(force))

    def cross(a: int, b: int) -> float:
        fa, fb = force[a] - level, force[b] - level
        return float(t[a] + (t[b] - t[a]) * fa / (fa - fb)) if fa != fb else float(t[b])

    start = cross(i0 - 1, i0) if i0 > 0 else float(t[0])
    separated = i1 < len(on) - 1
    end = cross(i1, i1 + 1) if separated else float(t[-1])
    return start, end, separated


def trapezoid(y: np.ndarray, x: np.ndarray) -> float:
    """The trapezoidal integral of y over x."""
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x))) if x.size > 1 else 0.0
