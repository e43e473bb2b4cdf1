"""``impact``: the dynamic normal impact of a sphere on the flat, by CalculiX, cached.

One ccx process per impact speed (in parallel, one thread each), cached on disk like
``indent`` (``impactlab.fe.cache``: a SHA-256 of every input, the ccx and gmsh versions and
the schema version). Method and verification: docs/fe-dynamic.md.
"""

from __future__ import annotations

import json
import math
import os
import re
import tempfile
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.fe import cache
from impactlab.fe.ccx import RunOutput, StaRow, ccx_version, find_ccx, parse_dat, parse_sta, run_ccx
from impactlab.fe.deck import LENGTH_UNIT
from impactlab.fe.impact_deck import ImpactDeckSpec, write_impact_deck
from impactlab.fe.impact_problem import ImpactProblem, make_impact_problem
from impactlab.fe.impact_result import (
    IMPACT_ARRAYS,
    SEPARATION_FRACTION,
    ImpactResult,
    centre_of_mass,
    contact_forces,
    contact_window,
    node_masses,
    trapezoid,
    upgrade_record,
)
from impactlab.fe.interrupt import run_parallel
from impactlab.fe.mesh import Mesh, build_mesh
from impactlab.fe.problem import check_maxima
from impactlab.fe.run import NotConvergedWarning, check_workers
from impactlab.materials import Material

#: delta_p and the rebound speed are means over the last FINAL_POINTS increments.
FINAL_POINTS = 5
#: The newest CalculiX release known to stop before the first increment whenever plasticity,
#: contact and inertia meet (``impact_deck``): an impact with a body that can yield needs a
#: newer one.
LAST_FAILING_CCX = (2, 20)
#: Where the docs say which CalculiX runs it and how to build one.
CCX_DOCS = "docs/fe-dynamic.md#the-elastic-plastic-flat-procedure-and-calculix-versions"
#: How the user sets each body plastic (for the message that refuses it).
_PLASTIC_INPUT = {"flat": "flat_hardening not 'elastic'", "sphere": "sphere='elastic-plastic'"}


def check_ccx_release(version: str, exe: str, problems: list[ImpactProblem]) -> None:
    """RuntimeError (one line) when a body can yield in ``problems`` and ccx's ``version``
    (``ccx_version``) is LAST_FAILING_CCX or older; an unreadable version passes."""
    m = re.match(r"(\d+)\.(\d+)", version)
    plastic = next((p.plastic_bodies for p in problems if p.plastic_bodies), ())
    if not plastic or m is None or (int(m.group(1)), int(m.group(2))) > LAST_FAILING_CCX:
        return
    which = " and ".join(f"the {b} ({_PLASTIC_INPUT[b]})" for b in plastic)
    raise RuntimeError(
        f"CalculiX {version} ({exe}) cannot run an impact in which {which} can yield (it "
        f"stops before the first increment): a CalculiX newer than 2.20 is needed, set through "
        f"IMPACTLAB_CCX=/path/to/ccx ({CCX_DOCS}); or keep both bodies elastic "
        f"(sphere='elastic', flat_hardening='elastic')"
    )


def deck_spec(problem: ImpactProblem, mesh: Mesh) -> ImpactDeckSpec:
    """The deck's inputs for ``problem`` on ``mesh``."""
    flat = problem.indentation.flat
    return ImpactDeckSpec(
        base=problem.deck_spec(mesh.spec),
        flat_density=flat.require_density("the FE impact deck's flat (its inertia)"),
        sphere_density=problem.sphere_density,
        speed=problem.speed,
        gap=problem.gap,
        increment=problem.increment,
        end_time=problem.end_time,
        procedure=problem.procedure,
        fixed_increment=problem.fixed_increment,
    )


def _final_surfaces(dat: Any, mesh: Mesh, n: int) -> tuple[np.ndarray, np.ndarray, float, float]:
    """(dent r, dent z of the last point [m], mean dent depth at the axis [m], mean upward
    displacement of the sphere's apex relative to its centre of mass [m]) over the last n
    printed points."""
    flat_rows = dat.nodal.get(("displacements", "NFSURF"), [])[-n:]
    sph_rows = dat.nodal.get(("displacements", "NSPH"), [])[-n:]
    x, y = mesh.nodes[:, 0], mesh.nodes[:, 1]
    tol = 1e-9 * mesh.spec.radius
    apex = int(np.flatnonzero((np.abs(x) < tol) & (np.abs(y) < tol) & _is_sphere(mesh))[0])
    weights = node_masses(mesh, mesh.sphere_elements, 1.0)
    depth, flattening = [], []
    for _, ids, u in flat_rows:
        on_axis = np.abs(x[ids - 1]) < tol
        depth.append(-float(u[on_axis, 1][0]) * LENGTH_UNIT)
    for _, ids, u in sph_rows:
        w = weights[ids - 1]
        cm = float(np.sum(w * u[:, 1]) / np.sum(w))
        k = int(np.flatnonzero(ids - 1 == apex)[0])
        flattening.append((float(u[k, 1]) - cm) * LENGTH_UNIT)
    _, ids, u = flat_rows[-1]
    r = x[ids - 1] + u[:, 0] * LENGTH_UNIT
    z = y[ids - 1] + u[:, 1] * LENGTH_UNIT
    order = np.argsort(r)
    return r[order], z[order], float(np.mean(depth)), float(np.mean(flattening))


def _is_sphere(mesh: Mesh) -> np.ndarray:
    mask = np.zeros(len(mesh.nodes), dtype=bool)
    mask[mesh.sphere_nodes] = True
    return mask


def assemble(problem: ImpactProblem, mesh: Mesh, out: RunOutput) -> ImpactResult:
    """The result of one impact run from ccx's printed output (DamagedOutputError for a
    damaged ``.dat`` file: ``ccx.parse_dat``)."""
    sizes = {"NSPH": len(mesh.sphere_nodes), "NFSURF": len(mesh.flat_surface_nodes)}
    dat = parse_dat(out.dat, "ccx's job.dat of the impact", sizes)
    t_f, force = contact_forces(out.dat)
    weights = node_masses(mesh, mesh.sphere_elements, 1.0)
    t_u, u_cm = centre_of_mass(dat, "displacements", weights)
    t_v, v_cm = centre_of_mass(dat, "velocities", weights)
    n = min(t_f.size, t_u.size, t_v.size)
    t, force, u_cm, v_cm = t_f[:n], force[:n], u_cm[:n], v_cm[:n]
    t = np.concatenate([[0.0], t])
    force = np.concatenate([[0.0], force])
    delta = np.concatenate([[-problem.gap], -u_cm - problem.gap])
    vy = np.concatenate([[-problem.speed], v_cm])  # up positive: negative towards the flat
    start, end, separated = contact_window(t, force) if n else (math.nan, math.nan, False)
    finished = out.returncode == 0 and n > 0 and math.isclose(t[-1], problem.end_time, rel_tol=1e-6)
    stopped = not finished and n > 1 and _separating(force)
    if stopped:  # ccx stopped as the sphere left the flat: read the rebound there
        end = end if separated else float(t[-1])  # F past the threshold, or still above it
        separated = True
        rebound, points = float(vy[-1]), 1
    else:
        after = t > end if separated else np.zeros(t.size, dtype=bool)
        rebound = float(np.mean(vy[after][-FINAL_POINTS:])) if after.any() else math.nan
        points = FINAL_POINTS
    impulse = trapezoid(force, t)
    m, v = problem.mass, problem.speed
    balance = abs(m * (v + rebound) - impulse) / (m * v) if math.isfinite(rebound) else math.nan
    dent_r = dent_z = np.empty(0)
    depth = flattening = math.nan
    if (finished or stopped) and separated:
        dent_r, dent_z, depth, flattening = _final_surfaces(dat, mesh, points)
    incs, cuts, its = sta_counts(parse_sta(out.sta))
    return ImpactResult(
        time=t,
        force=force,
        penetration=delta,
        vy=vy,
        speed=v,
        mass=m,
        rebound_speed=rebound,
        e=rebound / v,
        max_force=float(np.max(force)),
        delta_max=float(np.max(delta)),
        contact_start=start,
        duration=end - start,
        delta_p=depth + flattening,
        flat_dent_depth=depth,
        sphere_flattening=flattening,
        dent_r=dent_r,
        dent_z=dent_z,
        momentum_balance=balance,
        separated=bool(separated),
        converged=bool(finished),
        message="" if finished else out.log_tail,
        increments=incs,
        cutbacks=cuts,
        iterations=its,
        run_time=out.seconds,
        n_elements=mesh.n_elements,
        delta_c=problem.delta_c,
        inputs=problem.key_data(),
    )


def _separating(force: np.ndarray) -> bool:
    """True when the force has passed its peak and fallen below SEPARATION_FRACTION F_max."""
    peak = float(np.max(force))
    return (
        peak > 0.0
        and int(np.argmax(force)) < force.size - 1
        and float(force[-1]) < SEPARATION_FRACTION * peak
    )


def sta_counts(rows: list[StaRow]) -> tuple[int, int, int]:
    """(converged increments, cut-backs, iterations) of an uncoupled temperature-displacement
    run, whose ``.sta`` file lists every attempt twice (the thermal pass, then the mechanical
    one): increments and attempts are counted once, iterations over both passes."""
    done = {(r.step, r.increment) for r in rows if r.converged}
    failed = {(r.step, r.increment, r.attempt) for r in rows if not r.converged}
    return len(done), len(failed), sum(r.iterations for r in rows)


def _solve(problem: ImpactProblem, mesh: Mesh, exe: str, keep: Path | None) -> ImpactResult:
    text = write_impact_deck(mesh, deck_spec(problem, mesh))
    if keep is not None:
        return assemble(problem, mesh, run_ccx(text, keep, exe))
    with tempfile.TemporaryDirectory(prefix="impactlab-fe-impact-") as tmp:
        out = run_ccx(text, Path(tmp), exe)
    return assemble(problem, mesh, out)


def load(directory: Path, key: str) -> ImpactResult | None:
    """The cached impact for ``key``, or None: none cached, or a damaged file (a
    ``cache.DamagedCacheWarning`` naming it; the impact is run again and stored over it). A
    file written before 0.3, in the names before, reads in the new ones (``upgrade_record``)."""
    path = directory / f"impact-{key}.npz"
    return cache.read_npz(path, IMPACT_ARRAYS, ImpactResult, upgrade=upgrade_record)


def store(directory: Path, key: str, result: ImpactResult) -> None:
    """Write ``result`` under ``key`` (a temporary file, then a rename)."""
    directory.mkdir(parents=True, exist_ok=True)
    values = result.arrays()
    header = {k: v for k, v in values.items() if k not in IMPACT_ARRAYS}
    fd, tmp = tempfile.mkstemp(dir=directory, suffix=".npz.tmp")
    os.close(fd)
    try:
        with open(tmp, "wb") as fh:
            np.savez(
                fh,
                header=np.array(json.dumps(header)),
                **{k: values[k] for k in IMPACT_ARRAYS},
            )
        os.replace(tmp, directory / f"impact-{key}.npz")
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def impact(
    flat: Material,
    sphere_material: Material | None = None,
    *,
    radius: Any,
    speed: Any,
    mass: Any = None,
    sphere: str = "elastic-plastic",
    flat_hardening: Any = None,
    sphere_hardening: Any = None,
    mesh_level: int = 1,
    time_level: int = 1,
    workers: int | None = None,
    cache_dir: str | Path | None = None,
    use_cache: bool = True,
    keep_files: str | Path | None = None,
    progress: Callable[[int, ImpactResult], None] | None = None,
) -> list[ImpactResult]:
    """Dynamic normal impact of a sphere on the flat at each ``speed``, by CalculiX.

    flat, sphere_material: the materials (``sphere_material`` defaults to the flat's);
    radius: R [m]; speed: one impact speed [m/s] or a sequence; mass: the sphere's mass [kg]
    (default a full ball of ``sphere_material``; a rod's effective mass for a rod's tip);
    sphere: "elastic" or "elastic-plastic"; flat_hardening, sphere_hardening: as for
    ``indent`` (``flat_hardening="elastic"`` keeps the flat elastic); mesh_level: 1-4;
    time_level: 1-3 (60, 120, 240 increments per estimated contact duration); workers,
    cache_dir, use_cache, keep_files, progress: as for ``indent``.

    RuntimeError before any run when a body can yield and ccx is CalculiX 2.20 or older
    (:func:`check_ccx_release`). Returns one :class:`ImpactResult` per speed, in the order
    given; a run ccx could not finish (its message names ccx's exit status), or in which the
    sphere did not leave the flat, comes with a ``NotConvergedWarning`` (also one that ccx
    stopped at separation, whose rebound speed and dent are read at its last increment:
    ``ImpactResult.stopped_at_separation``).
    """
    sphere_material = flat if sphere_material is None else sphere_material
    problems = [
        make_impact_problem(
            flat,
            sphere_material,
            radius=radius,
            speed=v,
            mass=mass,
            sphere=sphere,
            flat_hardening=flat_hardening,
            sphere_hardening=sphere_hardening,
            mesh_level=mesh_level,
            time_level=time_level,
        )
        for v in check_maxima(speed, "speed", "impact speed")
    ]
    check_workers(workers)
    exe = find_ccx()
    version = ccx_version(exe)
    check_ccx_release(version, exe, problems)
    directory = Path(cache_dir) if cache_dir is not None else cache.default_cache_dir()
    keys = [cache.cache_key(p.key_data(), version) for p in problems]
    results: list[ImpactResult | None] = [load(directory, k) if use_cache else None for k in keys]
    todo = [i for i, r in enumerate(results) if r is None]
    n = max(1, min(len(todo), int(workers) if workers else (os.cpu_count() or 1)))
    keep = Path(keep_files) if keep_files is not None else None
    meshes = {i: build_mesh(problems[i].mesh_spec()) for i in todo}  # gmsh: one thread

    def job(i: int) -> tuple[int, ImpactResult]:
        sub = keep / f"impact{i}" if keep is not None else None
        return i, _solve(problems[i], meshes[i], exe, sub)

    def handle(out: tuple[int, ImpactResult]) -> None:
        i, res = out
        results[i] = res
        if (res.converged or res.stopped_at_separation) and use_cache:
            store(directory, keys[i], res)
        if progress is not None:
            progress(i, res)

    if todo:  # Ctrl-C or SIGTERM ends every ccx and removes its folder (``fe.interrupt``)
        run_parallel(todo, n, job, handle)
    final = [r for r in results if r is not None]
    for r in final:
        if r.status() != "converged":
            warnings.warn(r.status(), NotConvergedWarning, stacklevel=2)
    return final
