"""The shipped FE reference curves: the versioned data files in ``impactlab/fe/data/``.

Each file ``<case>.v<DATA_VERSION>.json`` holds one material pair (sphere of radius R on a
flat), loaded to several maxima and unloaded, computed by :mod:`impactlab.fe` (CalculiX):
every input, the ccx and gmsh versions, and per maximum the loading curve F(delta), the
contact radius, the unloading curve, delta_r and the run's convergence record. They are
written by ``python3 tasks.py fe-reference`` (:mod:`impactlab.fe.reference`) and read here
without ccx or gmsh.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab._html import grid_html
from impactlab.fe.problem import make_problem
from impactlab.fe.result import balanced_run
from impactlab.materials import ContactPair, Material

DATA_DIR = Path(__file__).resolve().parent / "data"
#: Where the cases with a strain-hardening flat are (kept out of ``load_cases``, whose
#: elastic-perfectly plastic cases the laws are measured against).
HARDENED_DIR = DATA_DIR / "hardening"
#: Version of the data files' layout (their names end in ``.v<DATA_VERSION>.json``).
DATA_VERSION = 1
#: The ``format`` field of every data file.
FORMAT = "impactlab.fe reference curves"


def _shown(name: str, metres: float) -> str:
    """A length [m] in its display unit (``12.34 um``); ``n/a`` when it is nan."""
    if not math.isfinite(metres):
        return "n/a"
    d = display_unit(name, "m")
    return f"{format_number(metres * d.scale, 4)} {d.unit}"


@dataclass(frozen=True, repr=False)
class ReferenceRun:
    """One maximum of a reference case (SI: m, N, s); see :class:`impactlab.fe.IndentationResult`
    for the meaning of each field. ``residual_depth`` is nan when the run did not converge."""

    delta_max: float
    loading_delta: np.ndarray
    loading_force: np.ndarray
    contact_radius: np.ndarray
    unloading_delta: np.ndarray
    unloading_force: np.ndarray
    residual_depth: float
    max_force: float
    pile_up: float
    converged: bool
    last_converged_delta: float
    message: str
    increments: int
    cutbacks: int
    iterations: int
    run_time: float
    n_elements: int
    force_balance: float

    @property
    def residual_ratio(self) -> float:
        """delta_r / delta_max (nan when the run did not converge)."""
        return self.residual_depth / self.delta_max

    @property
    def usable(self) -> bool:
        """Converged and balanced: a run to use as a reference (``fe.result.balanced_run``)."""
        return balanced_run(self.converged, self.force_balance)

    def __repr__(self) -> str:
        """One line: delta_max, F_max, delta_r, convergence and the sizes of the curves."""
        if self.converged:
            state = f"delta_r {_shown('delta_r', self.residual_depth)}, converged"
        else:
            state = f"not converged (last {_shown('delta_r', self.last_converged_delta)})"
        return (
            f"ReferenceRun(delta_max {_shown('delta_max', self.delta_max)}, F_max "
            f"{format_number(self.max_force)} N, {state}, {self.loading_delta.size} loading / "
            f"{self.unloading_delta.size} unloading points, {self.n_elements} elements)"
        )


@dataclass(frozen=True, repr=False)
class ReferenceCase:
    """One material pair of the shipped reference: its inputs and its runs (by delta_max)."""

    name: str
    description: str
    flat: Material
    sphere_material: Material
    sphere: str
    radius: float
    mu: float
    mesh_level: int
    delta_c: float
    ccx_version: str
    gmsh_version: str
    runs: tuple[ReferenceRun, ...]

    def __repr__(self) -> str:
        """One line: the case, the radius, delta_c and its runs' span (in delta_c)."""
        ratios = [r.delta_max / self.delta_c for r in self.runs]
        span = f" to {format_number(min(ratios), 3)} .. {format_number(max(ratios), 3)}"
        usable = sum(r.usable for r in self.runs)
        return (
            f"ReferenceCase({self.name!r}: R = {_shown('radius', self.radius)}, delta_c = "
            f"{_shown('delta_c', self.delta_c)}, {len(self.runs)} runs"
            f"{span if ratios else ''} delta_c ({usable} usable), mu = {format_number(self.mu)})"
        )

    def _repr_html_(self) -> str:
        """The case and one row per run (delta_max, F_max, delta_r; display units)."""
        rows = [
            (
                format_number(r.delta_max / self.delta_c, 4),
                _shown("delta_max", r.delta_max),
                f"{format_number(r.max_force)} N",
                _shown("delta_r", r.residual_depth),
                "yes" if r.usable else "no",
            )
            for r in self.runs
        ]
        title = (
            f"{self.name}: {self.description}; R = {_shown('radius', self.radius)}, "
            f"delta_c = {_shown('delta_c', self.delta_c)}"
        )
        head = ("delta_max/delta_c", "delta_max", "F_max", "delta_r", "usable")
        return grid_html(title, head, rows)

    @property
    def pair(self) -> ContactPair:
        """The contact pair the FE problem stands for (a rigid sphere as an infinitely stiff
        body that never yields): what the contact laws are built with."""
        return make_problem(
            self.flat,
            self.sphere_material,
            radius=self.radius,
            delta_max=self.radius * 1e-6,
            sphere=self.sphere,
        ).pair

    @property
    def e_star_over_sy(self) -> float:
        """E* / S_y of the pair (S_y of the material that yields first)."""
        p = self.pair
        return p.E_star / p.yield_strength

    def loading_curve(self) -> tuple[np.ndarray, np.ndarray]:
        """(delta [m], F [N]) of the loading curve that reaches farthest: the one the accuracy
        tables and the tabulated law use. The runs to smaller maxima follow the same problem
        but not the same points: their increments differ, and at the same interference their
        force differs from this curve's by up to 1.3 % below 10 delta_c and 2.7 % beyond
        (:meth:`loading_spread`; docs/fe.md, "Run-to-run spread")."""
        run = max(self.runs, key=lambda r: r.loading_delta[-1] if r.loading_delta.size else 0.0)
        return run.loading_delta, run.loading_force

    def loading_spread(self, low: float = 0.0, high: float = math.inf) -> Spread:
        """The largest relative difference between the loading force of any other converged
        run and :meth:`loading_curve` (PCHIP of log F over log delta) at the other run's
        points with ``low < delta/delta_c <= high`` within that curve's span."""
        from scipy.interpolate import PchipInterpolator

        ref_d, ref_f = self.loading_curve()
        curve = PchipInterpolator(np.log(ref_d), np.log(ref_f))
        worst = Spread(0.0, math.nan, math.nan)
        for r in self.runs:
            d, f = r.loading_delta, r.loading_force
            if d is ref_d or not r.converged:
                continue
            x = d / self.delta_c
            keep = (x > low) & (x <= high) & (d >= ref_d[0]) & (d <= ref_d[-1]) & (f > 0.0)
            if not keep.any():
                continue
            rel = f[keep] / np.exp(curve(np.log(d[keep]))) - 1.0
            j = int(np.argmax(np.abs(rel)))
            if abs(rel[j]) > abs(worst.relative):
                worst = Spread(float(rel[j]), float(x[keep][j]), r.delta_max / self.delta_c)
        return worst


@dataclass(frozen=True)
class Spread:
    """The largest difference between two runs of one case: ``relative`` (F_run / F_curve - 1),
    at ``delta_ratio`` (delta/delta_c), of the run loaded to ``run_ratio`` delta_c (nan: no
    other run there)."""

    relative: float
    delta_ratio: float
    run_ratio: float


def _material(d: dict[str, Any]) -> Material:
    hb, rho = d.get("brinell_hardness"), d.get("density")
    return Material(
        d["name"],
        float(d["E"]),
        float(d["nu"]),
        float(d["yield_strength"]),
        math.nan if hb is None else float(hb),
        float(d.get("meyer_index", 2.2)),
        None if rho is None else float(rho),
    )


#: What a quasi-static indentation uses of a material (with its name): a material given by
#: these values alone holds the Material's defaults in the rest (density, Meyer index), which
#: are not inputs and which the indentation does not use (no inertia; Brake's law only).
INDENTATION_FIELDS = ("name", "E", "nu", "yield_strength")


def material_record(m: Material, *, by_values: bool = False) -> dict[str, Any]:
    """A material as JSON-ready values (the inverse of reading it from a data file); of a
    material given by its values alone (``by_values``: :data:`INDENTATION_FIELDS`), the other
    fields are None (not given)."""
    hb = m.brinell_hardness
    record = {
        "name": m.name,
        "E": m.E,
        "nu": m.nu,
        "yield_strength": m.yield_strength,
        "brinell_hardness": None if math.isnan(hb) else hb,
        "meyer_index": m.meyer_index,
        "density": m.density,
    }
    if by_values:
        record.update({k: None for k in record if k not in INDENTATION_FIELDS})
    return record


def _array(v: Any) -> np.ndarray:
    a = np.asarray(v if v is not None else [], dtype=np.float64)
    a.setflags(write=False)
    return a


def _float(v: Any) -> float:
    return math.nan if v is None else float(v)


def _run(d: dict[str, Any]) -> ReferenceRun:
    load, unload = d["loading"], d["unloading"]
    return ReferenceRun(
        delta_max=float(d["delta_max"]),
        loading_delta=_array(load["delta"]),
        loading_force=_array(load["force"]),
        contact_radius=_array(load["contact_radius"]),
        unloading_delta=_array(unload["delta"]),
        unloading_force=_array(unload["force"]),
        residual_depth=_float(d["residual_depth"]),
        max_force=_float(d["max_force"]),
        pile_up=_float(d["pile_up"]),
        converged=bool(d["converged"]),
        last_converged_delta=float(d["last_converged_delta"]),
        message=str(d["message"]),
        increments=int(d["increments"]),
        cutbacks=int(d["cutbacks"]),
        iterations=int(d["iterations"]),
        run_time=float(d["run_time"]),
        n_elements=int(d["n_elements"]),
        force_balance=_float(d["force_balance"]),
    )


def case_from_record(record: dict[str, Any]) -> ReferenceCase:
    """A case from the content of a data file; ValueError for another format or version."""
    if record.get("format") != FORMAT or record.get("version") != DATA_VERSION:
        raise ValueError(
            f"not an impactlab.fe reference file of version {DATA_VERSION}: format "
            f"{record.get('format')!r}, version {record.get('version')!r}"
        )
    inp = record["inputs"]
    runs = tuple(sorted((_run(r) for r in record["runs"]), key=lambda r: r.delta_max))
    return ReferenceCase(
        name=str(record["case"]),
        description=str(record.get("description", "")),
        flat=_material(inp["flat"]),
        sphere_material=_material(inp["sphere_material"]),
        sphere=str(inp["sphere"]),
        radius=float(inp["radius"]),
        mu=float(inp["mu"]),
        mesh_level=int(inp["mesh_level"]),
        delta_c=float(record["delta_c"]),
        ccx_version=str(record["ccx_version"]),
        gmsh_version=str(record["gmsh_version"]),
        runs=runs,
    )


def data_path(name: str, directory: Path = DATA_DIR) -> Path:
    """The data file of case ``name``."""
    return Path(directory) / f"{name}.v{DATA_VERSION}.json"


def case_names(directory: Path = DATA_DIR) -> tuple[str, ...]:
    """Names of the cases shipped in ``directory`` (sorted)."""
    suffix = f".v{DATA_VERSION}.json"
    return tuple(
        sorted(p.name[: -len(suffix)] for p in Path(directory).glob(f"*{suffix}") if p.is_file())
    )


def load_case(name: str, directory: Path = DATA_DIR) -> ReferenceCase:
    """The shipped case ``name``; ValueError listing the known cases otherwise."""
    path = data_path(name, directory)
    if not path.is_file():
        known = ", ".join(case_names(directory)) or "none"
        raise ValueError(f"no FE reference case {name!r}; shipped cases: {known}")
    return case_from_record(json.loads(path.read_text()))


def load_cases(directory: Path = DATA_DIR) -> list[ReferenceCase]:
    """Every shipped case, the softest pair (largest E*/S_y) first."""
    cases = [load_case(n, directory) for n in case_names(directory)]
    return sorted(cases, key=lambda c: -c.e_star_over_sy)
