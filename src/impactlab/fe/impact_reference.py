"""The shipped dynamic-impact results: which impacts, how they are run, how they are stored.

``python -m impactlab.fe.impact_reference`` (``python3 tasks.py fe-impact``) runs every case
of :data:`IMPACT_CASES` at each of its speeds, dynamically (:func:`impactlab.fe.impact_run.
impact`) and as the 1-DOF impact on the quasi-static FE curves of the same bodies
(:func:`impactlab.fe.impact_quasistatic.quasi_static_impact`), and writes one small JSON table
``impactlab/fe/data/impact/<case>.v2.json`` (read by :func:`load_impact_table`), so that docs
and tests compare without running CalculiX. Runs already in the FE cache are read from it.
A table of version 1 (the names before 0.3: ``restitution``, ``max_interference``, ...) is
read in the names of version 2 (``fe.impact_result.RENAMED_IMPACT_FIELDS``).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._version import __version__
from impactlab.fe.cache import gmsh_version
from impactlab.fe.ccx import ccx_version, find_ccx
from impactlab.fe.curves import DATA_DIR, material_record
from impactlab.fe.impact_problem import make_impact_problem
from impactlab.fe.impact_quasistatic import quasi_static_impact
from impactlab.fe.impact_result import RENAMED_IMPACT_FIELDS, RenamedKeys
from impactlab.fe.impact_run import impact
from impactlab.materials import AISI_201, AISI_1010, Material

IMPACT_FORMAT = "impactlab-fe-impact"
#: The version written: 2, the glossary's names; 1 (the names before 0.3) is still read.
IMPACT_VERSION = 2
#: The versions :func:`load_impact_table` reads.
READ_VERSIONS = (1, 2)
RADIUS = 8.8e-3
#: The impact tables' folder (apart from the indentation curves, which ``fe.curves`` globs).
IMPACT_DIR = DATA_DIR / "impact"


@dataclass(frozen=True)
class ImpactCase:
    """One shipped case: the flat and sphere materials, the sphere kind, the flat's hardening
    (None: elastic-perfectly plastic, "elastic"), the speeds [m/s] and the levels."""

    description: str
    flat: Material
    sphere_material: Material
    sphere: str
    flat_hardening: Any
    speeds: tuple[float, ...]
    mesh_level: int = 1
    time_level: int = 1
    dynamic: bool = True  # False: no dynamic FE run (docs/fe-dynamic.md); 1-DOF only
    mass: float | None = None  # the sphere's mass [kg]; None: a full ball's


#: The elastic case: the paper's steels, both kept elastic (a ball of AISI 201, R = 8.8 mm,
#: its own mass, on an elastic AISI 1010 flat), where Hertz's impact is the closed form.
IMPACT_CASES: dict[str, ImpactCase] = {
    "elastic-ball-on-aisi1010": ImpactCase(
        "Elastic AISI 201 ball (R = 8.8 mm, its own mass) on an elastic AISI 1010 flat",
        AISI_1010,
        AISI_201,
        "elastic",
        "elastic",
        (0.1, 1.0),
    ),
    "paper-ball-on-aisi1010": ImpactCase(
        "AISI 201 ball (R = 8.8 mm, its own mass, elastic-plastic) on AISI 1010 "
        "(elastic-perfectly plastic)",
        AISI_1010,
        AISI_201,
        "elastic-plastic",
        None,
        (0.1, 1.0),
    ),
    "rod-mass-on-aisi1010": ImpactCase(
        "The paper's rod tip (R = 8.8 mm, AISI 201, elastic-plastic) carrying the whole rod's "
        "mass (0.4607 kg: a rod striking along its axis) on AISI 1010 (elastic-perfectly "
        "plastic) at the paper's slowest drop speed",
        AISI_1010,
        AISI_201,
        "elastic-plastic",
        None,
        (1.41,),
        mass=0.4607,
    ),
}


def impact_path(name: str, directory: Path = IMPACT_DIR, version: int = IMPACT_VERSION) -> Path:
    """The data file of a case (of table version ``version``)."""
    return directory / f"{name}.v{version}.json"


def _num(x: float) -> float | None:
    x = float(x)
    return float(f"{x:.7g}") if math.isfinite(x) else None


def _series(t: np.ndarray, y: np.ndarray, n: int = 200) -> dict[str, list[float | None]]:
    keep = np.unique(np.round(np.linspace(0, t.size - 1, min(n, t.size))).astype(int))
    return {"t": [_num(v) for v in t[keep]], "y": [_num(v) for v in y[keep]]}


def _qs(qs: Any, run: Any) -> dict[str, Any]:
    """The quasi-static 1-DOF impact's entry of a row."""
    return {
        "status": run.status(),
        "e": _num(qs.e),
        "rebound_speed": _num(qs.rebound_speed),
        "max_force": _num(qs.max_force),
        "delta_max": _num(qs.delta_max),
        "delta_p": _num(qs.delta_p),
        "duration": _num(qs.duration),
        "curve_maximum": _num(qs.curve_maximum),
        "run_time": round(run.run_time, 1),
        "force": _series(qs.time, qs.force),
    }


def _record(name: str, c: ImpactCase, delta_c: float, rows: list[dict[str, Any]]) -> dict[str, Any]:
    """A case's data file content."""
    return {
        "format": IMPACT_FORMAT,
        "version": IMPACT_VERSION,
        "case": name,
        "description": c.description,
        "units": "SI (m, N, s, kg)",
        "ccx_version": ccx_version(find_ccx()),
        "gmsh_version": gmsh_version(),
        "impactlab_version": __version__,
        "delta_c": delta_c,
        "inputs": {
            "radius": RADIUS,
            "flat": material_record(c.flat),
            "sphere_material": material_record(c.sphere_material),
            "sphere": c.sphere,
            "flat_hardening": c.flat_hardening,
            "mesh_level": c.mesh_level,
            "time_level": c.time_level,
            "dynamic": c.dynamic,
        },
        "rows": rows,
    }


def run_case(name: str, *, workers: int | None = None) -> dict[str, Any]:
    """Run one case (dynamic FE and the quasi-static 1-DOF) and return its record."""
    c = IMPACT_CASES[name]
    if not c.dynamic:
        return _quasi_static_only(name, c)
    dyn = impact(
        c.flat,
        c.sphere_material,
        radius=RADIUS,
        speed=list(c.speeds),
        mass=c.mass,
        sphere=c.sphere,
        flat_hardening=c.flat_hardening,
        mesh_level=c.mesh_level,
        time_level=c.time_level,
        workers=workers,
    )
    rows = []
    for d in dyn:
        qs, run = quasi_static_impact(
            c.flat,
            c.sphere_material,
            radius=RADIUS,
            speed=d.speed,
            mass=d.mass,
            delta_guess=d.delta_max,
            sphere=c.sphere,
            flat_hardening=c.flat_hardening,
            mesh_level=c.mesh_level,
        )
        rows.append(
            {
                "speed": d.speed,
                "mass": d.mass,
                "dynamic": {
                    "status": d.status(),
                    "procedure": d.inputs.get("procedure"),
                    "e": _num(d.e),
                    "rebound_speed": _num(d.rebound_speed),
                    "max_force": _num(d.max_force),
                    "delta_max": _num(d.delta_max),
                    "delta_p": _num(d.delta_p),
                    "flat_dent_depth": _num(d.flat_dent_depth),
                    "sphere_flattening": _num(d.sphere_flattening),
                    "duration": _num(d.duration),
                    "momentum_balance": _num(d.momentum_balance),
                    "increments": d.increments,
                    "cutbacks": d.cutbacks,
                    "run_time": round(d.run_time, 1),
                    "n_elements": d.n_elements,
                    "force": _series(d.time - d.contact_start, d.force),
                    "penetration": _series(d.time - d.contact_start, d.penetration),
                },
                "quasi_static": _qs(qs, run),
            }
        )
    return _record(name, c, dyn[0].delta_c, rows)


def _quasi_static_only(name: str, c: ImpactCase) -> dict[str, Any]:
    """The record of a case without the dynamic FE run: the 1-DOF impact on the quasi-static
    FE curves, started from the model's size estimate of the peak interference."""
    rows = []
    delta_c = math.nan
    for v in c.speeds:
        p = make_impact_problem(
            c.flat, c.sphere_material, radius=RADIUS, speed=v, mass=c.mass, sphere=c.sphere,
            flat_hardening=c.flat_hardening, mesh_level=c.mesh_level,
        )  # fmt: skip
        delta_c = p.delta_c
        qs, run = quasi_static_impact(
            c.flat, c.sphere_material, radius=RADIUS, speed=v, mass=p.mass,
            delta_guess=p.estimates()[0], sphere=c.sphere, flat_hardening=c.flat_hardening,
            mesh_level=c.mesh_level,
        )  # fmt: skip
        rows.append({"speed": v, "mass": p.mass, "dynamic": None, "quasi_static": _qs(qs, run)})
    return _record(name, c, delta_c, rows)


def write_impact_tables(
    names: list[str] | None = None, *, workers: int | None = None, directory: Path = IMPACT_DIR
) -> list[Path]:
    """Run the cases (all by default) and write their data files; returns the paths."""
    paths = []
    for name in names or list(IMPACT_CASES):
        record = run_case(name, workers=workers)
        path = impact_path(name, directory)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(record, separators=(",", ":")) + "\n")
        paths.append(path)
    return paths


def load_impact_table(name: str, directory: Path = IMPACT_DIR) -> dict[str, Any]:
    """A case's record, the newest version found (ValueError naming the known cases for an
    unknown one), in the names of version 2: a row's ``dynamic`` and ``quasi_static`` entries
    are mappings whose names before 0.3 (``restitution``, ...) still read their values, with a
    DeprecationWarning (``fe.impact_result.RenamedKeys``)."""
    found = [impact_path(name, directory, v) for v in reversed(READ_VERSIONS)]
    path = next((p for p in found if p.is_file()), None)
    if path is None:
        known = sorted(p.name for p in directory.glob("*.json"))
        raise ValueError(f"no impact table {name!r}; shipped: {', '.join(known) or 'none'}")
    data: dict[str, Any] = json.loads(path.read_text())
    if data.get("format") != IMPACT_FORMAT or data.get("version") not in READ_VERSIONS:
        raise ValueError(
            f"{path.name}: not an impactlab impact table of version "
            f"{' or '.join(map(str, READ_VERSIONS))}"
        )
    for row in data["rows"]:
        for key in ("dynamic", "quasi_static"):
            if row.get(key) is not None:
                row[key] = RenamedKeys(
                    {RENAMED_IMPACT_FIELDS.get(k, k): v for k, v in row[key].items()}
                )
    return data


def main(argv: list[str] | None = None) -> int:
    """``python -m impactlab.fe.impact_reference [CASE ...] [--workers N]``."""
    import argparse

    parser = argparse.ArgumentParser(description="Run the FE impact cases, write data files.")
    parser.add_argument("cases", nargs="*", choices=[*IMPACT_CASES, []], help="default: all")
    parser.add_argument("--workers", type=int, default=None, help="parallel ccx processes")
    args = parser.parse_args(argv)
    for p in write_impact_tables(args.cases or None, workers=args.workers):
        print(p)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
