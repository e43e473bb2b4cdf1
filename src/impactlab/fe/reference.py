"""The shipped FE reference curves: which cases, how they are run and how they are stored.

``python3 tasks.py fe-reference`` calls :func:`write_references`, which runs every case of
:data:`CASES` (sphere radius 8.8 mm, elastic-perfectly plastic, frictionless, the maxima of
:data:`MAXIMA_OVER_DELTA_C` times delta_c) and writes one versioned JSON file per case into
``impactlab/fe/data/`` (``<case>.v<SCHEMA_VERSION>.json``).
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from impactlab._json import jsonable
from impactlab.fe.cache import SCHEMA_VERSION
from impactlab.fe.problem import make_problem
from impactlab.fe.result import IndentationResult
from impactlab.fe.run import indent
from impactlab.materials import AISI_201, AISI_1010, Material

DATA_DIR = Path(__file__).resolve().parent / "data"
RADIUS = 8.8e-3

#: 6061-T6-like aluminium (E 68.9 GPa, nu 0.33, S_y 276 MPa; ASM Aerospace Specification Metals
#: data sheet values) and a hard bearing steel (E 210 GPa, nu 0.3, S_y 1.5 GPa).
AL_6061_T6 = Material("6061-T6-like aluminium", 68.9e9, 0.33, 276e6, density=2700.0)
HARD_STEEL = Material("hard steel (S_y 1.5 GPa)", 210e9, 0.3, 1.5e9, density=7850.0)

#: name -> (flat, sphere material, sphere kind)
CASES: dict[str, tuple[Material, Material, str]] = {
    "paper-aisi201-on-aisi1010": (AISI_1010, AISI_201, "elastic-plastic"),
    "rigid-on-al6061t6": (AL_6061_T6, AISI_201, "rigid"),
    "rigid-on-hard-steel": (HARD_STEEL, AISI_201, "rigid"),
}

MAXIMA_OVER_DELTA_C: tuple[float, ...] = (1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0)


def case_maxima(name: str) -> list[float]:
    """The interferences [m] of a case (multiples of its delta_c)."""
    flat, body, kind = CASES[name]
    dc = make_problem(flat, body, radius=RADIUS, delta_max=1e-9, sphere=kind).delta_c
    return [k * dc for k in MAXIMA_OVER_DELTA_C]


def to_record(res: IndentationResult) -> dict[str, Any]:
    """A result as JSON-ready values (SI units; the keys are the result's field names)."""
    return jsonable(res.arrays())


def _reporter(name: str, log: Callable[[str], None]) -> Callable[[int, IndentationResult], None]:
    def report(_: int, r: IndentationResult) -> None:
        log(f"  {name}: {r.delta_max / r.delta_c:.4g} delta_c, {r.status()}, {r.run_time:.0f} s")

    return report


def write_references(
    names: list[str] | None = None,
    *,
    mesh_level: int = 1,
    workers: int | None = None,
    directory: Path = DATA_DIR,
    log: Callable[[str], None] = print,
) -> list[Path]:
    """Run the cases (all by default) and write their data files; returns the paths."""
    paths = []
    for name in names or list(CASES):
        flat, body, kind = CASES[name]
        t0 = time.perf_counter()
        runs = indent(
            flat,
            body,
            radius=RADIUS,
            delta_max=case_maxima(name),
            sphere=kind,
            mesh_level=mesh_level,
            workers=workers,
            progress=_reporter(name, log),
        )
        record = {
            "case": name,
            "schema_version": SCHEMA_VERSION,
            "units": "SI (m, N, s)",
            "radius": RADIUS,
            "flat": [flat.name, flat.E, flat.nu, flat.yield_strength],
            "sphere": [body.name, body.E, body.nu, body.yield_strength, kind],
            "mesh_level": mesh_level,
            "runs": [to_record(r) for r in runs],
        }
        directory.mkdir(parents=True, exist_ok=True)
        path = directory / f"{name}.v{SCHEMA_VERSION}.json"
        path.write_text(json.dumps(record, indent=1) + "\n")
        log(f"{name}: {len(runs)} runs in {time.perf_counter() - t0:.0f} s -> {path}")
        paths.append(path)
    return paths


def main(argv: list[str] | None = None) -> int:
    """``python -m impactlab.fe.reference [CASE ...] [--mesh N] [--workers N]``."""
    import argparse

    parser = argparse.ArgumentParser(description="Run the FE reference cases, write data files.")
    parser.add_argument("cases", nargs="*", choices=[*CASES, []], help="default: all")
    parser.add_argument("--mesh", type=int, default=1, help="mesh level (default 1)")
    parser.add_argument("--workers", type=int, default=None, help="parallel ccx processes")
    args = parser.parse_args(argv)
    write_references(args.cases or None, mesh_level=args.mesh, workers=args.workers)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
