"""The shipped FE reference curves: which cases, how they are run and how they are stored.

``python3 tasks.py fe-reference`` calls :func:`write_references`, which runs every case of
:data:`CASES` (sphere radius 8.8 mm, elastic-perfectly plastic, frictionless, mesh level 1,
the maxima of :data:`MAXIMA_OVER_DELTA_C` times delta_c) and of :data:`HARDENED_CASES` (the
same with a strain-hardening flat) and writes one versioned JSON file per case into
``impactlab/fe/data/`` (``<case>.v<DATA_VERSION>.json``, read by :mod:`impactlab.fe.curves`;
the hardened ones into ``data/hardening/``), then :func:`write_derived`: the tabulated law's
curves and the laws' verified ranges. Runs already in the FE cache are read from it.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._json import jsonable
from impactlab._version import __version__
from impactlab.fe.cache import gmsh_version
from impactlab.fe.ccx import ccx_version, find_ccx
from impactlab.fe.curves import (
    DATA_DIR,
    DATA_VERSION,
    FORMAT,
    HARDENED_DIR,
    data_path,
    material_record,
)
from impactlab.fe.problem import make_problem
from impactlab.fe.result import IndentationResult
from impactlab.fe.run import indent
from impactlab.materials import AISI_201, AISI_1010, Material
from impactlab.materials.hardening import AISI_1010_HARDENING
from impactlab.materials.library import AISI_304, AISI_52100, COPPER_OFHC, PMMA

RADIUS = 8.8e-3

#: 6061-T6 aluminium (typical values of the Aluminum Association / ASM data sheet: E 68.9 GPa,
#: nu 0.33, S_y 276 MPa, Brinell 95).
AL_6061_T6 = Material("6061-T6 aluminium", 68.9e9, 0.33, 276e6, 95.0, density=2700.0)
#: A hard steel: AISI 4340 oil-quenched and tempered at 427 C (800 F): S_y 1379 MPa (200 ksi),
#: Brinell 415 (vendor data sheet, 1 in round); E 205 GPa and nu 0.29 (ASM typical for 4340).
AISI_4340_QT = Material(
    "AISI 4340 Q&T 427 C (hard steel)", 205e9, 0.29, 1379e6, 415.0, density=7850.0
)

#: name -> (flat, sphere material, sphere kind). The flat is the body that yields in every case:
#: the paper's pair (AISI 201 sphere, S_y 760 MPa, on AISI 1010, 305 MPa; both elastic-plastic),
#: the paper's sphere steel on 6061-T6 aluminium (elastic-plastic sphere), and a sphere of the
#: hard steel kept elastic (a hardened ball) on the hard steel: an AISI 201 sphere would yield
#: before a 1.4 GPa flat. The library's flats span E*/S_y = 28 (PMMA) to 1731 (OFHC copper)
#: against an AISI 52100 or AISI 201 ball; the ends of that span are cases of their own, with
#: the library's entries (``impactlab.materials.library``, cited there) and the ball that gives
#: the end's extreme E*/S_y, so that both balls' pairs lie inside the span: the AISI 201 sphere
#: on PMMA (E*/S_y 28.04; 28.05 with a 52100 ball), and an elastic AISI 52100 ball (hardened,
#: S_y 2 GPa: it does not yield) on OFHC copper (1731; 1720 with an AISI 201 ball) and on
#: AISI 304 (504), which splits the long gap between the paper's 360 and copper's 1731.
CASES: dict[str, tuple[Material, Material, str]] = {
    "paper-aisi201-on-aisi1010": (AISI_1010, AISI_201, "elastic-plastic"),
    "aisi201-on-al6061t6": (AL_6061_T6, AISI_201, "elastic-plastic"),
    "elastic-sphere-on-aisi4340": (AISI_4340_QT, AISI_4340_QT, "elastic"),
    "aisi201-on-pmma": (PMMA, AISI_201, "elastic-plastic"),
    "elastic-52100-on-aisi304": (AISI_304, AISI_52100, "elastic"),
    "elastic-52100-on-copper-ofhc": (COPPER_OFHC, AISI_52100, "elastic"),
}

#: The cases whose flat strain-hardens, as :data:`CASES`: the paper's pair with AISI 1010's
#: own hardening (``impactlab.materials.hardening.AISI_1010_HARDENING``). They are stored
#: apart, in ``data/hardening/`` (``fe.curves.HARDENED_DIR``), so that the law accuracy and
#: the verified ranges, which compare the laws (all elastic-perfectly plastic) with FE, read
#: only the elastic-perfectly plastic cases; the hardened paper's pair gives the tabulated law
#: of the experiment's report row.
HARDENED_CASES: dict[str, tuple[Material, Material, str]] = {
    "paper-aisi201-on-aisi1010-hardening": (AISI_1010, AISI_201, "elastic-plastic"),
}
#: Every case ``python3 tasks.py fe-reference`` runs.
ALL_CASES: dict[str, tuple[Material, Material, str]] = {**CASES, **HARDENED_CASES}
#: The hardened cases' flat hardening: name -> (true stress [Pa], true plastic strain) rows.
FLAT_HARDENING: dict[str, tuple[tuple[float, float], ...]] = {
    "paper-aisi201-on-aisi1010-hardening": AISI_1010_HARDENING.table(),
}

#: One line per case for people (stored in its data file).
DESCRIPTIONS: dict[str, str] = {
    "paper-aisi201-on-aisi1010": "The paper's pair: AISI 201 sphere (elastic-plastic) on AISI 1010",
    "aisi201-on-al6061t6": "Aluminium: AISI 201 sphere (elastic-plastic) on 6061-T6",
    "elastic-sphere-on-aisi4340": "Hard steel: an elastic AISI 4340 Q&T sphere on AISI 4340 Q&T",
    "aisi201-on-pmma": "PMMA: AISI 201 sphere (elastic-plastic) on PMMA (rate-independent, "
    "elastic-perfectly plastic: the data sheet's quasi-static values)",
    "elastic-52100-on-aisi304": "Stainless steel: an elastic AISI 52100 ball on annealed AISI 304",
    "elastic-52100-on-copper-ofhc": "Copper: an elastic AISI 52100 ball on annealed OFHC copper",
    "paper-aisi201-on-aisi1010-hardening": "The paper's pair with a strain-hardening flat: AISI "
    "201 sphere (elastic-plastic) on AISI 1010 with its own hardening (Swift law from SAE "
    "J1397's cold-drawn yield and tensile strength, Considere's criterion)",
}

#: The maxima, in multiples of the case's delta_c: about two per decade from 0.3 to 1000, and
#: 1.5 and 2 where the permanent depth starts (where most laws leave 0.05 of FE in it).
MAXIMA_OVER_DELTA_C: tuple[float, ...] = (
    0.3, 1.0, 1.5, 2.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0
)  # fmt: skip

#: Cases whose maxima differ. The hard steel's delta_c is 8.5 um, about R / 1000, so 1000
#: delta_c would reach the sphere's radius: it stops at 100 delta_c (0.85 mm, delta / R = 0.1).
#: The aluminium's 1000 delta_c (1.38 mm) did not converge at mesh level 1: ccx stopped on
#: loading at 775 delta_c (increment below the minimum after 65 increments and 27 cut-backs,
#: 548 s), and 700 delta_c stopped at 618 delta_c (too many cut-backs, 242 s); its largest
#: maximum is 500 delta_c.
#: PMMA's delta_c is 83 um, R / 106: it stops at 10 delta_c (0.83 mm, delta / R = 0.095), as
#: the hard steel stops at delta / R = 0.1. Copper's 100 delta_c (2.0 um) did not converge at
#: mesh level 1: ccx stopped on loading at 69.6 delta_c (too many cut-backs, 59 increments,
#: 284 s), nor did 50 delta_c, tried in its place (stopped at 30.7 delta_c, 268 s), while 150,
#: 300 and 1000 delta_c converged: 150 stands in for 100.
CASE_MAXIMA: dict[str, tuple[float, ...]] = {
    "aisi201-on-al6061t6": (0.3, 1.0, 1.5, 2.0, 3.0, 10.0, 30.0, 100.0, 300.0, 500.0),
    "elastic-sphere-on-aisi4340": (0.3, 1.0, 1.5, 2.0, 3.0, 10.0, 30.0, 100.0),
    "aisi201-on-pmma": (0.3, 1.0, 1.5, 2.0, 3.0, 10.0),
    "elastic-52100-on-copper-ofhc": (0.3, 1.0, 1.5, 2.0, 3.0, 10.0, 30.0, 150.0, 300.0, 1000.0),
}


def case_delta_c(name: str) -> float:
    """The critical interference delta_c [m] of a case (its FE problem's)."""
    flat, body, kind = ALL_CASES[name]
    return make_problem(flat, body, radius=RADIUS, delta_max=1e-9, sphere=kind).delta_c


def case_ratios(name: str) -> list[float]:
    """The maxima of a case in multiples of its delta_c."""
    return list(CASE_MAXIMA.get(name, MAXIMA_OVER_DELTA_C))


def case_maxima(name: str) -> list[float]:
    """The interferences [m] of a case (multiples of its delta_c)."""
    dc = case_delta_c(name)
    return [k * dc for k in case_ratios(name)]


#: Curves are stored with at most this many points (evenly picked, the ends kept) and floats
#: with SIGNIFICANT_DIGITS digits, which keeps each data file to some tens of kB.
MAX_POINTS = 300
SIGNIFICANT_DIGITS = 7


def _thin(n: int, limit: int = MAX_POINTS) -> np.ndarray:
    """Indices of at most ``limit`` of ``n`` points, evenly spread, first and last kept."""
    if n <= limit:
        return np.arange(n)
    return np.unique(np.round(np.linspace(0, n - 1, limit)).astype(int))


def _num(x: float) -> float | None:
    x = float(x)
    return None if not math.isfinite(x) else float(f"{x:.{SIGNIFICANT_DIGITS}g}")


def _nums(a: np.ndarray, keep: np.ndarray) -> list[float | None]:
    return [_num(v) for v in np.asarray(a, dtype=np.float64)[keep]]


def to_record(res: IndentationResult) -> dict[str, Any]:
    """One run as JSON-ready values (SI units): the curves (thinned to MAX_POINTS), delta_r,
    the convergence record and every input (``IndentationResult.inputs``)."""
    kl = _thin(res.loading_delta.size)
    ku = _thin(res.unloading_delta.size)
    n_dent = min(res.dent_r.size, res.dent_z.size)  # no dent when the run did not finish
    kd = _thin(n_dent)
    return {
        "delta_max": res.delta_max,
        "delta_max_over_delta_c": _num(res.delta_max / res.delta_c),
        "residual_depth": _num(res.residual_depth),
        "residual_ratio": _num(res.residual_ratio),
        "max_force": _num(res.max_force),
        "pile_up": _num(res.pile_up),
        "converged": res.converged,
        "last_converged_delta": res.last_converged_delta,
        "message": res.message,
        "increments": res.increments,
        "cutbacks": res.cutbacks,
        "iterations": res.iterations,
        "run_time": round(res.run_time, 1),
        "n_elements": res.n_elements,
        "force_balance": _num(res.force_balance),
        "loading": {
            "delta": _nums(res.loading_delta, kl),
            "force": _nums(res.loading_force, kl),
            "contact_radius": _nums(res.contact_radius, kl),
        },
        "unloading": {
            "delta": _nums(res.unloading_delta, ku),
            "force": _nums(res.unloading_force, ku),
        },
        "dent": {"r": _nums(res.dent_r, kd), "z": _nums(res.dent_z, kd)},
        "inputs": jsonable(res.inputs),
    }


def case_record(
    name: str, runs: list[IndentationResult], mesh_level: int, ccx: str, gmsh: str
) -> dict[str, Any]:
    """The content of a case's data file (read back by ``impactlab.fe.curves``)."""
    flat, body, kind = ALL_CASES[name]
    runs = sorted(runs, key=lambda r: r.delta_max)
    return {
        "format": FORMAT,
        "version": DATA_VERSION,
        "case": name,
        "description": DESCRIPTIONS.get(name, ""),
        "units": "SI (m, N, s, Pa)",
        "ccx_version": ccx,
        "gmsh_version": gmsh,
        "impactlab_version": __version__,
        "delta_c": runs[0].delta_c,
        "inputs": {
            "radius": RADIUS,
            "flat": material_record(flat),
            "sphere_material": material_record(body),
            "sphere": kind,
            "mu": 0.0,
            "mesh_level": mesh_level,
            "maxima_over_delta_c": case_ratios(name),
            "flat_hardening": [list(r) for r in FLAT_HARDENING[name]]
            if name in FLAT_HARDENING
            else None,
        },
        "runs": [to_record(r) for r in runs],
    }


def _reporter(name: str, log: Callable[[str], None]) -> Callable[[int, IndentationResult], None]:
    def report(_: int, r: IndentationResult) -> None:
        log(f"  {name}: {r.delta_max / r.delta_c:.4g} delta_c, {r.status()}, {r.run_time:.0f} s")

    return report


def case_directory(name: str, directory: Path = DATA_DIR) -> Path:
    """Where the data file of case ``name`` goes: ``directory``, or its ``hardening/`` folder
    for a case whose flat strain-hardens."""
    return Path(directory) / HARDENED_DIR.name if name in FLAT_HARDENING else Path(directory)


def write_references(
    names: list[str] | None = None,
    *,
    mesh_level: int = 1,
    workers: int | None = None,
    directory: Path = DATA_DIR,
    log: Callable[[str], None] = print,
) -> list[Path]:
    """Run the cases (all by default; ``workers`` ccx processes at once, default 1) and write
    their data files; returns the paths."""
    paths = []
    version = ccx_version(find_ccx())
    for name in names or list(ALL_CASES):
        flat, body, kind = ALL_CASES[name]
        t0 = time.perf_counter()
        runs = indent(
            flat,
            body,
            radius=RADIUS,
            delta_max=case_maxima(name),
            sphere=kind,
            flat_hardening=FLAT_HARDENING.get(name),
            mesh_level=mesh_level,
            workers=1 if workers is None else workers,
            progress=_reporter(name, log),
        )
        record = case_record(name, runs, mesh_level, version, gmsh_version())
        folder = case_directory(name, directory)
        folder.mkdir(parents=True, exist_ok=True)
        path = data_path(name, folder)
        path.write_text(json.dumps(record, separators=(",", ":")) + "\n")
        log(f"{name}: {len(runs)} runs in {time.perf_counter() - t0:.0f} s -> {path}")
        paths.append(path)
    return paths


def main(argv: list[str] | None = None) -> int:
    """``python -m impactlab.fe.reference [CASE ...] [--mesh N] [--workers N]``."""
    import argparse

    parser = argparse.ArgumentParser(description="Run the FE reference cases, write data files.")
    parser.add_argument("cases", nargs="*", choices=[*ALL_CASES, []], help="default: all")
    parser.add_argument("--mesh", type=int, default=1, help="mesh level (default 1)")
    parser.add_argument(
        "--workers", type=int, default=None, help="parallel ccx processes (default 1)"
    )
    args = parser.parse_args(argv)
    names = args.cases or list(ALL_CASES)
    write_references(names, mesh_level=args.mesh, workers=args.workers)
    if any(n in CASES for n in names):
        write_derived()
    return 0


def write_derived(log: Callable[[str], None] = print) -> None:
    """Rewrite what is derived from the shipped elastic-perfectly plastic curves: the tabulated
    law's curves (``contact/data/fe-curves.json``) and the laws' verified ranges
    (``contact/data/verified-ranges.json``, the engine's LAW_EXTRAPOLATED flag)."""
    from impactlab.fe.tabulated import write_shipped_curves
    from impactlab.fe.verified_ranges import write_verified_ranges

    log(f"-> {write_shipped_curves()}")
    log(f"-> {write_verified_ranges()}")


if __name__ == "__main__":
    raise SystemExit(main())
