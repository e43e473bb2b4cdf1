"""The result of one indentation run and how it is read from ccx's printed output."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from impactlab.fe.ccx import DatFile, StaRow
from impactlab.fe.deck import FORCE_UNIT, LENGTH_UNIT, StepControl
from impactlab.fe.mesh import Mesh

#: ccx expands axisymmetric elements to a 2-degree sector: printed forces are 1/180 of the
#: full circumference (checked against Hertz in tests/fe).
SECTOR_FACTOR = 180.0
#: The largest difference between the forces on the sphere and on the flat, over the peak
#: force, of a run whose contact is resolved (the shipped runs: below 2e-4, docs/fe.md).
FORCE_BALANCE_MAX = 1e-3


def balanced_run(converged: bool, force_balance: float) -> bool:
    """A run to use as a reference: converged, its forces balanced to FORCE_BALANCE_MAX."""
    return converged and force_balance <= FORCE_BALANCE_MAX


@dataclass(frozen=True)
class IndentationResult:
    """One loading-unloading run (SI units: m, N, s).

    loading_delta, loading_force: the loading curve F(delta) at every converged increment;
    contact_radius: the contact radius [m] at each loading point (from the gap between the
    deformed surfaces); unloading_delta, unloading_force: the unloading curve from delta_max;
    residual_depth: delta_r, the interference where the unloading force reaches zero [m]
    (nan when the run did not get there, or where it lies below what the contact resolves:
    ``fe.run.residual_depth``); dent_r, dent_z: the flat's surface after unloading,
    radius [m] and height [m] (> 0: pile-up above the undeformed surface); a loading-only run
    (``unload=False``) has empty unloading and dent arrays and a nan residual_depth;
    delta_c: the pair's critical interference [m] (of a rigid sphere: the flat's against a
    rigid sphere); converged: True when ccx finished every
    step of the run; last_converged_delta: the interference of the last converged increment
    [m]; message: ccx's error when it stopped, else ""; increments, cutbacks, iterations: of
    all steps; run_time: ccx's wall time [s]; n_elements: of the mesh; force_balance: the largest
    relative difference between the sphere's and the flat's reaction forces (0 for a
    perfectly balanced model); inputs: every input of the run (the cache key's data).
    """

    delta_max: float
    loading_delta: np.ndarray
    loading_force: np.ndarray
    contact_radius: np.ndarray
    unloading_delta: np.ndarray
    unloading_force: np.ndarray
    residual_depth: float
    dent_r: np.ndarray
    dent_z: np.ndarray
    delta_c: float
    converged: bool
    last_converged_delta: float
    message: str
    increments: int
    cutbacks: int
    iterations: int
    run_time: float
    n_elements: int
    force_balance: float
    inputs: dict[str, Any]

    @property
    def max_force(self) -> float:
        """Force at delta_max [N] (nan when loading did not get there)."""
        done = self.loading_delta.size and math.isclose(
            float(self.loading_delta[-1]), self.delta_max, rel_tol=1e-9
        )
        return float(self.loading_force[-1]) if done else math.nan

    @property
    def contact_radius_at_max(self) -> float:
        """Contact radius at delta_max [m] (nan when loading did not get there)."""
        return float(self.contact_radius[-1]) if math.isfinite(self.max_force) else math.nan

    @property
    def balanced(self) -> bool:
        """Whether the forces on the sphere and on the flat agree to FORCE_BALANCE_MAX of the
        peak force (a run that does not resolve its contact does not)."""
        return balanced_run(True, self.force_balance)

    @property
    def usable(self) -> bool:
        """Converged and balanced: a run to use as a reference (``balanced_run``)."""
        return balanced_run(self.converged, self.force_balance)

    @property
    def residual_ratio(self) -> float:
        """delta_r / delta_max."""
        return self.residual_depth / self.delta_max

    @property
    def pile_up(self) -> float:
        """Highest point of the residual dent's rim above the undeformed surface [m]
        (negative: sink-in everywhere)."""
        return float(np.max(self.dent_z)) if self.dent_z.size else math.nan

    def status(self) -> str:
        """``converged`` or ``NOT CONVERGED at delta = ... (last converged point)``."""
        if self.converged and not self.balanced:
            return (
                f"UNBALANCED: the forces on the sphere and on the flat differ by "
                f"{self.force_balance:.3g} of the peak force (at most {FORCE_BALANCE_MAX:g}): "
                "the mesh does not resolve the contact; do not use this run"
            )
        if self.converged:
            return "converged"
        return (
            f"NOT CONVERGED: ccx stopped after delta = {self.last_converged_delta:.6g} m "
            f"({self.last_converged_delta / self.delta_c:.4g} delta_c), the last converged "
            f"point; {self.message}"
        )

    def arrays(self) -> dict[str, Any]:
        """Every field as a plain value (arrays stay numpy arrays), for storage."""
        return {f.name: getattr(self, f.name) for f in fields(self)}


def _times_values(series: list[tuple[float, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    t = np.array([s[0] for s in series], dtype=np.float64)
    v = np.array([s[1][1] for s in series], dtype=np.float64)
    return t, v


def _amplitude(step: StepControl, t: np.ndarray) -> np.ndarray:
    path = np.asarray(step.path, dtype=np.float64)
    return np.asarray(np.interp(t, path[:, 0], path[:, 1]))


def delta_at(
    loading: StepControl, unloading: StepControl | None, t: np.ndarray, dmax: float
) -> np.ndarray:
    """The prescribed interference [m] at total times t (step 1: 0..1, step 2: 1..2; a run
    without an unloading step has only step 1)."""
    if unloading is None:
        return np.asarray(_amplitude(loading, t) * dmax)
    out = np.where(t <= 1.0, _amplitude(loading, t), _amplitude(unloading, t - 1.0))
    return np.asarray(out * dmax)


def surface_gap(
    dat: DatFile,
    time: float,
    flat_xy: np.ndarray,
    sphere_xy: np.ndarray | None,
    radius: float,
    delta: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(deformed r of the flat's surface nodes, their height z, the gap to the sphere) [m] at
    ``time``; the rigid sphere's surface is analytic, a deformable one is interpolated from its
    deformed surface nodes."""
    ids, u = _nodal_at(dat, "NFSURF", time)
    r = flat_xy[ids - 1, 0] + u[:, 0] * LENGTH_UNIT
    z = flat_xy[ids - 1, 1] + u[:, 1] * LENGTH_UNIT
    order = np.argsort(r)
    r, z = r[order], z[order]
    if sphere_xy is None:
        rs = np.clip(r, 0.0, radius)
        zs = radius - np.sqrt(radius * radius - rs * rs) - delta
    else:
        sid, su = _nodal_at(dat, "NSSURF", time)
        sr = sphere_xy[sid - 1, 0] + su[:, 0] * LENGTH_UNIT
        sz = sphere_xy[sid - 1, 1] + su[:, 1] * LENGTH_UNIT
        o = np.argsort(sr)
        zs = np.interp(r, sr[o], sz[o], right=np.inf)
    return r, z, zs - z


def _nodal_at(dat: DatFile, nset: str, time: float) -> tuple[np.ndarray, np.ndarray]:
    for t, ids, vals in dat.nodal.get(("displacements", nset), []):
        if t == time:
            return ids, vals
    raise KeyError(f"no displacements of {nset} at time {time}")


def gap_tolerance(mesh: Mesh, r: np.ndarray) -> np.ndarray:
    """The gap [m] below which a flat surface node at radius r [m] counts as touching:
    h^2 / (2 R), h the local element size. Penalty contact is enforced at the faces'
    integration points, so a node inside the contact can sit up to about h^2 / (8 R) below
    the sphere's faceted surface; outside, the gap grows much faster."""
    h = mesh.spec.h0 + mesh.spec.growth * np.asarray(r)
    return np.asarray(h * h / (2.0 * mesh.spec.radius))


def contact_radius_from_gap(r: np.ndarray, gap: np.ndarray) -> float:
    """Where ``gap`` (less its tolerance) first turns positive, going out from the axis
    (linear interpolation between the last node in contact and the first one out) [m]."""
    closed = gap <= 0.0
    if not closed[0]:
        return 0.0
    k = int(np.argmin(closed)) if not closed.all() else len(r) - 1
    if closed.all():
        return float(r[-1])
    g0, g1 = gap[k - 1], gap[k]
    return float(r[k - 1] + (r[k] - r[k - 1]) * (-g0) / (g1 - g0))


def zero_crossing(delta: np.ndarray, force: np.ndarray) -> float:
    """The interference where the unloading force first reaches zero [m] (interpolated; a
    force below 1e-6 of the largest counts as zero), nan if it never does."""
    pos = force > 1e-6 * float(np.max(np.abs(force)))
    if pos.all() or not pos[0]:
        return math.nan if pos.all() else float(delta[0])
    k = int(np.argmin(pos))
    d0, d1, f0, f1 = delta[k - 1], delta[k], force[k - 1], force[k]
    return float(d0 + (d1 - d0) * f0 / (f0 - f1))


def sta_summary(rows: list[StaRow]) -> tuple[int, int, int]:
    """(converged increments, cut-backs, iterations of all attempts) of a run."""
    done = sum(r.converged for r in rows)
    return done, len(rows) - done, sum(r.iterations for r in rows)


def reactions(dat: DatFile) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(times, sphere force [N], flat force [N]) of every converged increment (full circle)."""
    t, top = _times_values(dat.totals.get(("force", "NTOP"), []))
    _, bot = _times_values(dat.totals.get(("force", "NBOT"), []))
    n = min(len(top), len(bot))
    scale = SECTOR_FACTOR * FORCE_UNIT
    return t[:n], -top[:n] * scale, bot[:n] * scale
