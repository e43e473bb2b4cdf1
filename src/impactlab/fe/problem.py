"""The indentation problem: inputs, their checks, and the mesh and deck derived from them.

A sphere of radius R presses a flat to the interference delta_max and is withdrawn until the
force is zero (SI units: m, Pa, N). The critical interference delta_c is the pair's
Jackson-Green first-yield interference as the contact laws compute it
(``impactlab.contact``: ``ContactModel.critical_interference``; Jackson & Green 2005,
doi:10.1115/1.1866166); with a rigid sphere, the flat's against a rigid sphere, the sphere
material then not used; with an elastic sphere, the flat's S_y and nu, only the flat yielding
in the FE (``Problem.pair``, ``fe.problem_pair``).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from impactlab._validation import (
    check_finite,
    check_nonnegative,
    check_positive,
    value_text,
)
from impactlab.fe.deck import DeckSpec, MaterialCard, StepControl
from impactlab.fe.mesh import MeshSpec
from impactlab.fe.problem_pair import problem_pair
from impactlab.materials import ContactPair, Material
from impactlab.units import is_quantity

SphereKind = Literal["rigid", "elastic", "elastic-plastic"]
SPHERE_KINDS: tuple[str, ...] = ("rigid", "elastic", "elastic-plastic")

#: Mesh levels: the element-size growth g (element size per distance from the contact point).
#: Each level refines by sqrt(2) (twice the elements).
MESH_GROWTH: dict[int, float] = {1: 0.1, 2: 0.1 / math.sqrt(2.0), 3: 0.05, 4: 0.05 / math.sqrt(2.0)}

#: Penalty slope of the contact: K = PENALTY_FACTOR * E* / h, h the local element size of the
#: flat's surface (face-to-face penalty contact, one contact pair per band of the surface).
PENALTY_FACTOR = 100.0
#: The flat's block: depth and radius = max(FLAT_SIZE_CRITICAL a_c, FLAT_SIZE_MAX a_max).
FLAT_SIZE_CRITICAL = 500.0
FLAT_SIZE_MAX = 40.0
#: Loading increments per decade of interference, and unloading increments.
INCREMENTS_PER_DECADE = 10
UNLOADING_INCREMENTS = 30
#: The loading curve starts at LOW_FRACTION delta_c (or delta_max / 20 if smaller).
LOW_FRACTION = 0.05
#: The fewest elements of the flat's surface across the contact radius sqrt(R delta_max) that
#: ``indent`` accepts. The graded mesh puts ln(1 + g a / h0) / g elements across a radius a:
#: ln(1 + sqrt(20)) / 0.1 = 17 or more at level 1 for every delta_max (h0 = g sqrt(R
#: delta_low), delta_low <= delta_max / 20), where the Hertz check is within 1.04 % and the
#: 1000 delta_c run within 1.4 % of level 2 (docs/fe.md); 8 is half that resolution, below
#: which the loading curve's error is no longer known.
MIN_CONTACT_ELEMENTS = 8


def check_hardening(name: str, table: Any) -> tuple[tuple[float, float], ...]:
    """A hardening table as ((true stress [Pa], true plastic strain), ...) rows, checked:
    the first plastic strain 0, stresses > 0 and non-decreasing, strains increasing."""
    try:
        arr = np.asarray(table, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be rows of (true stress [Pa], plastic strain)") from None
    if arr.size == 0:
        raise ValueError(
            f"{name} must hold at least one row of (true stress [Pa], plastic strain), got none"
        )
    if arr.ndim != 2 or arr.shape[1] != 2 or len(arr) < 1:
        raise ValueError(
            f"{name} must be rows of (true stress [Pa], plastic strain), got shape {arr.shape}"
        )
    bad = np.flatnonzero(~np.all(np.isfinite(arr), axis=1))
    if bad.size:
        row = arr[int(bad[0])]
        raise ValueError(
            f"{name} must be finite, got row {int(bad[0]) + 1} ({float(row[0])!r}, "
            f"{float(row[1])!r})"
        )
    s, e = arr[:, 0], arr[:, 1]
    if e[0] != 0.0 or np.any(s <= 0.0):
        k = 0 if e[0] != 0.0 or s[0] <= 0.0 else int(np.argmax(s <= 0.0))
        swapped = np.all(s < 10.0) and np.any(e > 1.0e3)  # strains first, stresses in Pa next
        raise ValueError(
            f"{name} must start at plastic strain 0 with positive stresses: each row is (true "
            f"stress [Pa], true plastic strain), so row {k + 1} reads as stress "
            f"{float(s[k])!r} Pa and plastic strain {float(e[k])!r}"
            + ("; the columns look swapped: give the stress first" if swapped else "")
        )
    if np.any(np.diff(e) <= 0.0) or np.any(np.diff(s) < 0.0):
        raise ValueError(
            f"{name} must be monotonic: plastic strain increasing and stress non-decreasing, "
            f"got strains {e.tolist()} and stresses {s.tolist()}"
        )
    return tuple((float(a), float(b)) for a, b in arr)


#: How far a hardening table's first stress may lie from the material's S_y (relative).
HARDENING_START_TOL = 0.05
#: Largest true plastic strain of a hardening table: an indentation strains the flat by tens of
#: percent at most, so a larger number is a percentage or an engineering strain mistyped.
HARDENING_MAX_STRAIN = 5.0


def check_hardening_start(name: str, rows: tuple[tuple[float, float], ...], m: Material) -> None:
    """ValueError unless the table's first stress is the material's yield strength (within
    ``HARDENING_START_TOL``): delta_c and E*/S_y, which every result is read against, come
    from S_y, so the FE's first yield must be there."""
    s0, sy = rows[0][0], m.yield_strength
    top, strain = max(r[0] for r in rows), max(r[1] for r in rows)
    if top >= m.E:
        raise ValueError(
            f"{name}: a true stress of {value_text(top, 'Pa')} is not below E = "
            f"{value_text(m.E, 'Pa')}: no metal hardens that far; check the columns (stress "
            "[Pa], then plastic strain) and the units"
        )
    if strain > HARDENING_MAX_STRAIN:
        raise ValueError(
            f"{name}: a true plastic strain of {strain:g} (allowed: up to "
            f"{HARDENING_MAX_STRAIN:g}); strains are fractions, 0.1 for 10 %; check the columns "
            "(stress [Pa], then plastic strain)"
        )
    if abs(s0 / sy - 1.0) <= HARDENING_START_TOL:
        return
    hint = " (stresses are in Pa: 305 MPa is 305e6)" if s0 < 1e-3 * sy else ""
    raise ValueError(
        f"{name} must start at the material's yield strength S_y = {value_text(sy, 'Pa')} "
        f"(within {HARDENING_START_TOL:.0%}; delta_c and E*/S_y are computed from S_y), got "
        f"a first stress of {value_text(s0, 'Pa')}{hint}; give the material the table's "
        "first stress as its yield strength, or a table that starts at S_y"
    )


def critical_interference(pair: ContactPair, radius: float) -> float:
    """delta_c [m] of the pair at radius R [m], as the contact laws compute it."""
    from impactlab.contact import get_law

    return float(get_law("hertz").build(pair, radius=radius).critical_interference)


@dataclass(frozen=True)
class Problem:
    """One indentation run (SI). Build it with :func:`make_problem`, which checks the inputs."""

    flat: Material
    sphere_material: Material
    sphere: str
    radius: float
    delta_max: float
    flat_hardening: tuple[tuple[float, float], ...]
    sphere_hardening: tuple[tuple[float, float], ...]
    mu: float
    mesh_level: int
    unload: bool = True

    @property
    def pair(self) -> ContactPair:
        """The contact pair the problem stands for (the sphere's material first;
        ``fe.problem_pair``): a rigid sphere as a body 10^9 times stiffer than the flat, and a
        rigid or elastic sphere never the body that yields (the flat's S_y and nu, which only
        the flat can yield in the FE)."""
        return problem_pair(self.flat, self.sphere_material, self.sphere)

    @property
    def E_star(self) -> float:
        """Reduced modulus of the pair [Pa]; a rigid sphere counts only the flat's."""
        return self.pair.E_star

    @property
    def delta_c(self) -> float:
        """Critical interference [m] (``critical_interference`` of the pair)."""
        return critical_interference(self.pair, self.radius)

    @property
    def delta_low(self) -> float:
        """Where the loading curve starts being resolved [m]."""
        return min(LOW_FRACTION * self.delta_c, self.delta_max / 20.0)

    def key_data(self) -> dict[str, Any]:
        """Every input as plain JSON-able values (the cache key is a hash of this); a
        loading-only run (``unload=False``) adds ``"unload": False``, so that the keys of
        complete runs stay what they were."""

        def mat(m: Material) -> list[float]:
            return [m.E, m.nu, m.yield_strength]

        data: dict[str, Any] = {
            "flat": mat(self.flat),
            "sphere_material": mat(self.sphere_material),
            "sphere": self.sphere,
            "radius": self.radius,
            "delta_max": self.delta_max,
            "flat_hardening": [list(r) for r in self.flat_hardening],
            "sphere_hardening": [list(r) for r in self.sphere_hardening],
            "mu": self.mu,
            "mesh_level": self.mesh_level,
            "penalty": PENALTY_FACTOR,
            "flat_size": [FLAT_SIZE_CRITICAL, FLAT_SIZE_MAX],
            "increments": [INCREMENTS_PER_DECADE, UNLOADING_INCREMENTS, LOW_FRACTION],
        }
        if not self.unload:
            data["unload"] = False
        return data

    def mesh_spec(self) -> MeshSpec:
        """The self-similar mesh for this run."""
        R, g = self.radius, MESH_GROWTH[self.mesh_level]
        a_lo = math.sqrt(R * self.delta_low)
        a_max = estimated_contact_radius(R, self.delta_max)
        a_c = math.sqrt(R * self.delta_c)
        return MeshSpec(
            radius=R,
            h0=g * a_lo,
            growth=g,
            flat_size=max(FLAT_SIZE_CRITICAL * a_c, FLAT_SIZE_MAX * a_max),
            contact_extent=min(1.5 * a_max, 0.95 * R),
            sphere_height=R,
        )

    def deck_spec(self, spec: MeshSpec) -> DeckSpec:
        """Materials, contact bands with their penalty slopes, and the load path (no
        unloading step when ``unload`` is False)."""
        flat = MaterialCard("FLAT", self.flat.E, self.flat.nu, self.flat_hardening)
        sphere: MaterialCard | None = None
        if self.sphere != "rigid":
            m = self.sphere_material
            plastic = self.sphere_hardening if self.sphere == "elastic-plastic" else ()
            sphere = MaterialCard("SPHERE", m.E, m.nu, plastic)
        edges: list[float] = []
        e = 4.0 * spec.h0
        while e < 2.0 * spec.contact_extent:
            edges.append(e)
            e *= 2.0
        bounds = [0.0, *edges, 2.0 * e]
        stiffness = tuple(
            PENALTY_FACTOR * self.E_star / (spec.h0 + spec.growth * 0.5 * (lo + hi))
            for lo, hi in itertools.pairwise(bounds)
        )
        return DeckSpec(
            flat=flat,
            sphere=sphere,
            delta_max=self.delta_max,
            mu=self.mu,
            band_edges=tuple(edges),
            band_stiffness=stiffness,
            loading=loading_path(self.delta_low / self.delta_max),
            unloading=unloading_path() if self.unload else None,
        )


def loading_path(low: float) -> StepControl:
    """Loading in step time 0..1: delta / delta_max geometric from ``low`` to 1 (so every
    decade of interference gets the same number of increments), from 0 in the first one."""
    decades = max(math.log10(1.0 / low), 1.0)
    n = max(math.ceil(INCREMENTS_PER_DECADE * decades), 20)
    t = np.linspace(0.0, 1.0, n + 1)
    frac = np.concatenate([[0.0], np.geomspace(low, 1.0, n)])
    path = tuple(zip(t.tolist(), frac.tolist(), strict=True))
    return StepControl(1.0 / n, 1.0e-4 / n, 1.0 / n, path)


def unloading_path() -> StepControl:
    """Unloading in step time 0..1: delta / delta_max = 1 - s with s geometric from 1e-3 to 1,
    fine near delta_max where the force falls, coarse once the sphere has left the dent."""
    n = UNLOADING_INCREMENTS
    t = np.linspace(0.0, 1.0, n + 1)
    s = np.concatenate([[0.0], np.geomspace(1.0e-3, 1.0, n)])
    path = tuple(zip(t.tolist(), (1.0 - s).tolist(), strict=True))
    return StepControl(1.0 / n, 1.0e-4 / n, 1.0 / n, path)


def estimated_contact_radius(radius: float, delta: float) -> float:
    """A generous estimate of the contact radius [m] at interference delta [m]: the fully
    plastic truncation radius sqrt(2 R delta - delta^2) enlarged by 20 % for pile-up."""
    return 1.2 * math.sqrt(max(2.0 * radius * delta - delta * delta, 0.0))


def contact_elements(spec: MeshSpec, delta: float) -> float:
    """Elements of the flat's surface across the contact radius sqrt(R delta) [m] of a mesh
    whose element size grows as h0 + g d: ln(1 + g a / h0) / g."""
    a = math.sqrt(spec.radius * delta)
    return math.log1p(spec.growth * a / spec.h0) / spec.growth


def check_resolution(spec: MeshSpec, delta: float) -> None:
    """ValueError when the mesh resolves the contact radius at ``delta`` [m] by fewer than
    MIN_CONTACT_ELEMENTS elements."""
    n = contact_elements(spec, delta)
    if n < MIN_CONTACT_ELEMENTS:
        raise ValueError(
            f"the mesh is too coarse for delta_max = {value_text(delta, 'm')}: {n:.1f} elements "
            "across the "
            f"contact radius sqrt(R delta_max) = {math.sqrt(spec.radius * delta):.4g} m, at "
            f"least {MIN_CONTACT_ELEMENTS} needed; use a finer mesh_level"
        )


def perfectly_plastic(m: Material) -> tuple[tuple[float, float], ...]:
    """The elastic-perfectly plastic table of a material: ((S_y, 0),)."""
    return ((m.yield_strength, 0.0),)


def make_problem(
    flat: Material,
    sphere_material: Material,
    *,
    radius: Any,
    delta_max: Any,
    sphere: str = "elastic-plastic",
    flat_hardening: Any = None,
    sphere_hardening: Any = None,
    mu: Any = 0.0,
    mesh_level: int = 1,
    unload: Any = True,
) -> Problem:
    """Check every input and build the :class:`Problem` (one-line ValueErrors naming the
    parameter, its value and what is allowed)."""
    if not isinstance(flat, Material) or not isinstance(sphere_material, Material):
        raise ValueError("flat and sphere_material must be impactlab.materials.Material objects")
    if sphere not in SPHERE_KINDS:
        raise ValueError(f"sphere must be one of {', '.join(SPHERE_KINDS)}, got {sphere!r}")
    # 15 significant digits: "5 um" converts to 4.9999999999999996e-06, and the cache key (a hash
    # of the inputs) would tell it from 5e-6, an identical run of minutes
    R = float(f"{check_positive('radius', radius, 'm'):.15g}")
    d = float(f"{check_positive('delta_max', delta_max, 'm'):.15g}")
    if d >= R:
        bare = not isinstance(delta_max, str) and not is_quantity(delta_max)
        raise ValueError(
            f"delta_max ({value_text(d, 'm')}) must be smaller than the sphere radius "
            f"({value_text(R, 'm')})"
            + (" (a bare number is in m: give a unit, e.g. '5 um')" if bare else "")
        )
    if estimated_contact_radius(R, d) >= 0.95 * R:
        raise ValueError(
            f"delta_max ({value_text(d, 'm')}) is too large for radius {value_text(R, 'm')}: "
            f"the contact radius would reach the sphere's equator; allowed delta_max < "
            f"{rounded_down(largest_delta_max(R))} m"
        )
    mu_v = check_nonnegative("mu", mu)
    if mu_v > 2.0:
        raise ValueError(f"mu must lie in [0, 2], got {mu_v!r}")
    check_finite("mu", mu_v)
    if isinstance(mesh_level, bool) or mesh_level not in MESH_GROWTH:
        raise ValueError(f"mesh_level must be one of {sorted(MESH_GROWTH)}, got {mesh_level!r}")
    if not isinstance(unload, bool | np.bool_):
        raise ValueError(f"unload must be True or False, got {unload!r}")
    if isinstance(flat_hardening, str) and flat_hardening == "elastic":
        fh: tuple[tuple[float, float], ...] = ()
    elif flat_hardening is None:
        fh = perfectly_plastic(flat)
    else:
        fh = check_hardening("flat_hardening", flat_hardening)
        check_hardening_start("flat_hardening", fh, flat)
    if sphere_hardening is None:
        sh = perfectly_plastic(sphere_material)
    else:
        sh = check_hardening("sphere_hardening", sphere_hardening)
        check_hardening_start("sphere_hardening", sh, sphere_material)
    problem = Problem(
        flat, sphere_material, sphere, R, d, fh, sh, mu_v, int(mesh_level), bool(unload)
    )
    check_resolution(problem.mesh_spec(), d)
    return problem


def rounded_down(x: float, digits: int = 4) -> str:
    """``x`` > 0 rounded down to ``digits`` significant digits, as text: a bound shown so
    that every value below it is below ``x`` too ("allowed < 0.003423 m" for 0.0034236)."""
    e = math.floor(math.log10(x)) - (digits - 1)
    return f"{math.floor(x / 10.0**e) * 10.0**e:.{digits}g}"


def largest_delta_max(R: float) -> float:
    """The largest delta_max [m] whose estimated contact radius stays below 0.95 R."""
    a = 0.95 * R / 1.2
    return R - math.sqrt(R * R - a * a)


def check_maxima(
    values: Sequence[Any] | Any, name: str = "delta_max", what: str = "interference"
) -> list[Any]:
    """``values`` (the parameter ``name``: one ``what`` or a sequence) as a list; ValueError
    naming ``name`` if empty."""
    if isinstance(values, str) or not isinstance(values, Sequence | np.ndarray):
        return [values]
    out = list(values)
    if not out:
        raise ValueError(f"{name} must hold at least one {what}, got an empty sequence")
    return out
