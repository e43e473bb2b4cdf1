"""``indent``: run the indentation problem for any number of maxima, in parallel, cached."""

from __future__ import annotations

import math
import os
import tempfile
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.fe import cache
from impactlab.fe.ccx import (
    DamagedOutputError,
    DatFile,
    RunOutput,
    ccx_version,
    find_ccx,
    parse_dat,
    parse_sta,
    run_ccx,
)
from impactlab.fe.deck import DeckSpec, write_deck
from impactlab.fe.interrupt import run_parallel
from impactlab.fe.mesh import Mesh, build_mesh
from impactlab.fe.problem import Problem, check_maxima, make_problem
from impactlab.fe.result import (
    IndentationResult,
    contact_radius_from_gap,
    delta_at,
    gap_tolerance,
    reactions,
    sta_summary,
    surface_gap,
)
from impactlab.materials import Material

#: The largest delta_max / delta_c the shipped FE cases reach and the mesh was checked at
#: (level 1 within 1.4 % of level 2 there, docs/fe.md).
CHECKED_RATIO = 1000.0
#: The smallest delta_max / delta_c of the shipped FE cases (their first maximum).
SMALLEST_CHECKED_RATIO = 0.3


class BeyondCheckedWarning(UserWarning):
    """An indentation asked beyond :data:`CHECKED_RATIO` delta_c, or below
    :data:`SMALLEST_CHECKED_RATIO` delta_c, where the mesh's accuracy is not known (the run
    goes on)."""


class DamagedRunsError(DamagedOutputError):
    """Runs of :func:`indent` whose ccx output is damaged (``ccx.DamagedOutputError``), in one
    line naming each file, line and fault; ``results``: every run's result in the order asked
    (None for a damaged one), the finished runs being cached as usual."""

    def __init__(
        self,
        damaged: dict[int, DamagedOutputError],
        results: Sequence[IndentationResult | None],
        cached: bool = True,
    ) -> None:
        self.damaged = dict(sorted(damaged.items()))
        self.results = list(results)
        text = "; ".join(str(e) for e in self.damaged.values())
        done = [r for r in self.results if r is not None]
        if done:
            kept = ": they are cached (run again to read them)" if cached else ""
            text += (
                f"; the other {len(done)} run(s) (delta_max = "
                + ", ".join(f"{r.delta_max * 1e6:.4g} um" for r in done)
                + f") ended{kept}"
            )
        super().__init__(text)


class NotConvergedWarning(RuntimeWarning):
    """An indentation run that ccx could not finish: its result is marked ``converged=False``
    and holds the curve up to the last converged point."""


def assemble(
    problem: Problem, mesh: Mesh, deck: DeckSpec, out: RunOutput, name: str = "job.dat"
) -> IndentationResult:
    """The result of one run from ccx's printed output (``name``: the ``.dat`` file's name in
    messages). DamagedOutputError when the ``.dat`` text is damaged (``ccx.parse_dat``: a
    block with fewer rows than its set has nodes among them), lacks a surface's block at a
    time whose forces it prints, or ends before the time at which the ``.sta`` file records
    the run finishing, ccx having ended normally (a file cut at a line's end: not a run that
    stopped)."""
    sets = {"NFSURF": mesh.flat_surface_nodes}
    if deck.sphere is not None:
        sets["NSSURF"] = mesh.sphere_surface_nodes
    dat = parse_dat(out.dat, name, {k: len(v) for k, v in sets.items()})
    sta = parse_sta(out.sta)
    t, f_sphere, f_flat = reactions(dat)
    unloads = deck.unloading is not None
    end = 2.0 if unloads else 1.0
    finished = out.returncode == 0 and t.size > 0 and math.isclose(t[-1], end, rel_tol=1e-9)
    _check_complete(out, sta, end, float(t[-1]) if t.size else None, finished, name)
    _check_surfaces(dat, t, tuple(sets), out, name)
    dmax = problem.delta_max
    delta = delta_at(deck.loading, deck.unloading, t, dmax)
    peak = float(np.max(np.abs(f_sphere))) if t.size else 0.0
    balance = float(np.max(np.abs(f_sphere - f_flat)) / peak) if peak > 0.0 else math.nan
    load = t <= 1.0 + 1e-12
    unload = ~load
    sph_xy = None if deck.sphere is None else mesh.nodes
    radii = []
    for ti, di in zip(t[load], delta[load], strict=True):
        r, _, gap = surface_gap(dat, float(ti), mesh.nodes, sph_xy, problem.radius, float(di))
        radii.append(contact_radius_from_gap(r, gap - gap_tolerance(mesh, r)))
    dent_r = dent_z = final_gap = np.empty(0)
    if t.size and unloads:
        r, z, final_gap = surface_gap(dat, float(t[-1]), mesh.nodes, sph_xy, problem.radius, 0.0)
        dent_r, dent_z = r, z
    ud = (
        np.concatenate([[dmax], delta[unload]])
        if unloads and load.any() and t[load][-1] == 1.0
        else delta[unload]
    )
    uf = (
        np.concatenate([[f_sphere[load][-1]], f_sphere[unload]])
        if ud.size > delta[unload].size
        else f_sphere[unload]
    )
    # delta_r: the interference at which the withdrawn sphere touches the dent again, the
    # smallest gap between the two surfaces once both steps are done (exact to the mesh; the
    # force's zero crossing on the unloading increments only brackets it)
    delta_r = residual_depth(final_gap, dent_z, dmax) if finished and final_gap.size else math.nan
    incs, cuts, its = sta_summary(sta)
    return IndentationResult(
        delta_max=dmax,
        loading_delta=np.asarray(delta[load]),
        loading_force=np.asarray(f_sphere[load]),
        contact_radius=np.asarray(radii, dtype=np.float64),
        unloading_delta=np.asarray(ud),
        unloading_force=np.asarray(uf),
        residual_depth=delta_r,
        dent_r=np.asarray(dent_r),
        dent_z=np.asarray(dent_z) if finished else np.empty(0),
        delta_c=problem.delta_c,
        converged=bool(finished),
        last_converged_delta=float(delta[-1]) if t.size else 0.0,
        message="" if finished else out.log_tail,
        increments=incs,
        cutbacks=cuts,
        iterations=its,
        run_time=out.seconds,
        n_elements=mesh.n_elements,
        force_balance=balance,
        inputs=problem.key_data(),
    )


def _check_complete(
    out: RunOutput, sta: list[Any], end: float, last: float | None, finished: bool, name: str
) -> None:
    """DamagedOutputError when ccx ended normally and its ``.sta`` file lists a converged
    increment at the run's end time ``end``, but the ``.dat`` text stops before it (at time
    ``last``; None: no block at all)."""
    if finished or out.returncode != 0:
        return
    done = [r.total_time for r in sta if r.converged]
    if not done or not math.isclose(done[-1], end, rel_tol=1e-5):
        return
    where = "has no printed block" if last is None else f"stops at time {last:.7g}"
    raise DamagedOutputError(
        f"{name}, line {out.dat.count(chr(10))}: the file {where}, but ccx ended normally and "
        f"job.sta records the run finishing at time {end:g}; the file is damaged (cut short?)"
    )


def _check_surfaces(
    dat: DatFile, times: np.ndarray, sets: tuple[str, ...], out: RunOutput, name: str
) -> None:
    """DamagedOutputError when the ``.dat`` file prints the forces at a time but not the
    displacements of each surface node set of ``sets`` (a file cut between two blocks)."""
    for nset in sets:
        printed = {b[0] for b in dat.nodal.get(("displacements", nset), [])}
        missing = [float(t) for t in times if float(t) not in printed]
        if missing:
            raise DamagedOutputError(
                f"{name}, line {out.dat.count(chr(10))}: no displacements of set {nset} at "
                f"time {missing[0]:.7g}, whose forces the file prints; the file is damaged "
                "(cut short?)"
            )


#: Depth of the dent at the axis, relative to delta_max, from which a final state whose
#: surfaces still touch leaves delta_r unresolved (``residual_depth``).
UNRESOLVED_DENT = 1e-3


def residual_depth(final_gap: np.ndarray, dent_z: np.ndarray, delta_max: float) -> float:
    """delta_r [m]: the smallest gap between the withdrawn sphere and the dent. Where the two
    surfaces still touch at the end (a gap <= 0) although the dent at the axis lies more than
    ``UNRESOLVED_DENT`` delta_max below the undeformed surface, delta_r is below what the
    contact resolves (the paper's pair at 1.5 delta_c: a 6.3 nm dent, the sphere held at the
    surface by a tensile contact force of 0.3 N one increment before the end): nan, which the
    accuracy tables and the tabulated law leave out. Else 0 (no dent)."""
    gap = float(np.min(final_gap))
    if gap > 0.0:
        return gap
    if dent_z.size and -float(dent_z[0]) > UNRESOLVED_DENT * delta_max:
        return math.nan
    return 0.0


def _solve(problem: Problem, mesh: Mesh, exe: str, keep: Path | None) -> IndentationResult:
    deck = problem.deck_spec(problem.mesh_spec())
    text = write_deck(mesh, deck)
    run = f"ccx's job.dat for delta_max = {problem.delta_max * 1e6:.4g} um"
    if keep is not None:
        out = run_ccx(text, keep, exe)
        return assemble(problem, mesh, deck, out, f"{run} ({keep / 'job.dat'})")
    with tempfile.TemporaryDirectory(prefix="impactlab-fe-") as tmp:
        out = run_ccx(text, Path(tmp), exe)
    return assemble(problem, mesh, deck, out, run)


def _run_pending(
    todo: list[int],
    workers: int,
    job: Callable[[int], tuple[int, IndentationResult | DamagedOutputError]],
    done: Callable[[int, IndentationResult], None],
) -> dict[int, DamagedOutputError]:
    """Run ``job`` for each index of ``todo`` on ``workers`` threads, handing each result to
    ``done`` as it ends; the runs whose output was damaged, by index. Ctrl-C or SIGTERM ends
    every ccx and removes its folder first (``fe.interrupt.run_parallel``)."""
    damaged: dict[int, DamagedOutputError] = {}

    def handle(out: tuple[int, IndentationResult | DamagedOutputError]) -> None:
        i, res = out
        if isinstance(res, DamagedOutputError):
            damaged[i] = res
        else:
            done(i, res)

    run_parallel(todo, workers, job, handle)
    return damaged


def check_workers(workers: Any) -> None:
    """ValueError unless ``workers`` (parallel ccx processes, of ``indent`` and ``impact``)
    is None or a positive integer: 1.5 or "2" is no count of processes (int() made them 1
    and 2), and True is no number."""
    if workers is not None and (
        isinstance(workers, bool) or not isinstance(workers, int | np.integer) or workers < 1
    ):
        raise ValueError(
            f"workers must be a positive integer (a count of ccx processes) or None, got "
            f"{workers!r}"
        )


def indent(
    flat: Material,
    sphere_material: Material | None = None,
    *,
    radius: Any,
    delta_max: Any,
    sphere: str = "elastic-plastic",
    flat_hardening: Any = None,
    sphere_hardening: Any = None,
    mu: Any = 0.0,
    mesh_level: int = 1,
    unload: bool = True,
    workers: int | None = None,
    cache_dir: str | Path | None = None,
    use_cache: bool = True,
    keep_files: str | Path | None = None,
    progress: Callable[[int, IndentationResult], None] | None = None,
) -> list[IndentationResult]:
    """Quasi-static indentation of a flat by a sphere, loaded to each ``delta_max`` and
    unloaded to zero force, by CalculiX (one ``ccx`` process per maximum, in parallel).

    flat, sphere_material: the materials (``sphere_material`` defaults to the flat's; not
    used for a rigid sphere: delta_c is then the flat's against a rigid sphere). radius: R
    [m]. delta_max: one interference [m] or a sequence (numbers in m, strings with units or
    pint quantities). sphere: "rigid", "elastic" or "elastic-plastic". flat_hardening,
    sphere_hardening: rows of (true stress
    [Pa], true plastic strain), the first at strain 0 (default: elastic-perfectly plastic at
    S_y); ``flat_hardening="elastic"`` keeps the flat elastic. mu: Coulomb friction
    coefficient of the contact (0: frictionless). mesh_level: 1-4, each doubling the number
    of elements. unload: False stops each run at delta_max (the loading curve and contact
    radius only: no unloading curve, delta_r or dent), about half the iterations of a
    frictionless run and a fifth of a frictional one, whose unloading is the costly part; the
    loading curve is bit for bit the complete run's. workers: parallel ccx processes (default
    ``os.cpu_count()``).
    cache_dir: where results are cached (``impactlab.fe.cache``);
    use_cache: False to always run. keep_files: a folder to keep the ccx files in (one
    sub-folder per maximum). progress: called as ``progress(index, result)`` as each run ends.

    Returns one :class:`IndentationResult` per maximum, in the order given. A run that ccx
    cannot finish comes back with ``converged=False`` (curve up to the last converged point)
    and a :class:`NotConvergedWarning`; it is cached as well, read back as it was, its
    warning then saying where it was read (``cache.from_cache_note``). A run whose ccx output
    is damaged (a ``.dat`` file cut short, or a nan or inf printed:
    ``ccx.NonFiniteOutputError``) raises :class:`DamagedRunsError` once every run has
    ended, naming the file, the line and the fault; it is not cached, the runs that ended
    are, and are in its ``results``. Ctrl-C or SIGTERM ends every ccx and removes its
    temporary folder (``fe.interrupt``).
    RuntimeError when ccx is not installed (with how to install it), ImportError when gmsh is
    missing, ValueError for bad input.
    """
    sphere_material = flat if sphere_material is None else sphere_material
    problems = [
        make_problem(
            flat,
            sphere_material,
            radius=radius,
            delta_max=d,
            sphere=sphere,
            flat_hardening=flat_hardening,
            sphere_hardening=sphere_hardening,
            mu=mu,
            mesh_level=mesh_level,
            unload=unload,
        )
        for d in check_maxima(delta_max)
    ]
    check_workers(workers)
    for p in problems:  # before minutes of ccx: where the mesh is known to hold
        if p.delta_max > CHECKED_RATIO * p.delta_c * (1.0 + 1e-9):
            warnings.warn(
                f"delta_max = {p.delta_max / p.delta_c:.4g} delta_c is beyond {CHECKED_RATIO:g} "
                "delta_c, the largest interference the shipped FE cases reach and the mesh "
                "was checked at (docs/fe.md): its accuracy there is not known, and the run "
                "may stop before its end",
                BeyondCheckedWarning,
                stacklevel=2,
            )
        elif p.delta_max < SMALLEST_CHECKED_RATIO * p.delta_c * (1.0 - 1e-9):
            warnings.warn(
                f"delta_max = {p.delta_max / p.delta_c:.4g} delta_c is below "
                f"{SMALLEST_CHECKED_RATIO:g} delta_c, the smallest maximum of the shipped FE "
                "cases (docs/fe.md): its accuracy there is not known (below delta_c Hertz is "
                "exact: impactlab.contact's hertz law needs no FE run)",
                BeyondCheckedWarning,
                stacklevel=2,
            )
    exe = find_ccx()
    version = ccx_version(exe)
    directory = Path(cache_dir) if cache_dir is not None else cache.default_cache_dir()
    keys = [cache.cache_key(p.key_data(), version) for p in problems]
    results: list[IndentationResult | None] = [
        cache.load(directory, k) if use_cache else None for k in keys
    ]
    for i, res in enumerate(results):
        if res is not None and progress is not None:
            progress(i, res)
    todo = [i for i, r in enumerate(results) if r is None]
    read = {i for i, r in enumerate(results) if r is not None}  # from the cache
    meshes = {i: build_mesh(problems[i].mesh_spec()) for i in todo}  # gmsh: one thread
    n = max(1, min(len(todo), int(workers) if workers else (os.cpu_count() or 1)))
    keep = Path(keep_files) if keep_files is not None else None

    def job(i: int) -> tuple[int, IndentationResult | DamagedOutputError]:
        sub = keep / f"run{i}" if keep is not None else None
        try:
            return i, _solve(problems[i], meshes[i], exe, sub)
        except DamagedOutputError as exc:  # the other runs go on, and are kept
            return i, exc

    def done(i: int, res: IndentationResult) -> None:
        results[i] = res
        if use_cache:  # a run that did not converge too: ccx stops there again on its inputs
            cache.store(directory, keys[i], res)
        if progress is not None:
            progress(i, res)

    damaged = _run_pending(todo, n, job, done) if todo else {}
    final = [r for r in results if r is not None]
    for i, r in enumerate(results):  # a cached one says where it was read
        if r is not None and not r.usable:
            note = f"; {cache.from_cache_note(directory, keys[i])}" if i in read else ""
            warnings.warn(r.status() + note, NotConvergedWarning, stacklevel=2)
    if damaged:
        raise DamagedRunsError(damaged, results, cached=use_cache)
    return final


def indent_one(
    flat: Material, sphere_material: Material | None = None, **kwargs: Any
) -> IndentationResult:
    """:func:`indent` for one ``delta_max`` (a number or quantity, not a sequence)."""
    d = kwargs.get("delta_max")
    if isinstance(d, Sequence) and not isinstance(d, str):
        raise ValueError("indent_one takes one delta_max; use indent for several")
    return indent(flat, sphere_material, **kwargs)[0]
