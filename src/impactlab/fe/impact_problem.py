"""The dynamic impact problem: a sphere striking the flat normally, its inputs and checks.

A sphere of radius R and mass m moving at speed v (SI: m, kg, m/s) touches the flat at t = 0
and rebounds. The model is the indentation model's (``impactlab.fe.problem``: the same
axisymmetric bodies, self-similar mesh, materials and banded penalty contact) with inertia:
the sphere is free (no prescribed node) and starts with velocity -v a small gap above the flat.
The hemisphere's density is set so that its mass is m: the full ball's mass by default, or the
effective mass a rod puts behind its tip (the whole rod's mass for a rod striking along its
axis). Time integration: CalculiX's implicit integration with inertia (see
``impactlab.fe.impact_deck`` for the two procedures: the uncoupled temperature-displacement step
for an elastic flat, ``*DYNAMIC, DIRECT`` with numerical damping for an elastic-plastic one).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

from impactlab._validation import check_positive
from impactlab.fe.deck import DeckSpec
from impactlab.fe.mesh import MeshSpec
from impactlab.fe.problem import MESH_GROWTH, Problem, make_problem
from impactlab.materials import Material

#: Time levels: the number of time increments over the estimated contact duration. Each level
#: doubles them.
TIME_INCREMENTS: dict[int, int] = {1: 60, 2: 120, 3: 240}

#: Mean contact pressure of a fully plastic contact, in yield strengths (about 2.8-3 S_y; used
#: only to size the model: the mesh extent and the simulated time).
PLASTIC_PRESSURE_FACTOR = 2.8

#: An elastic-plastic flat's run takes this many fixed increments per time-level increment
#: (``*DYNAMIC, DIRECT``: Newton did not converge through the first contact increments of the
#: mesh-level-1 model at 1 and 2, converged in mostly 2-4 iterations at 4; docs/fe-dynamic.md).
PLASTIC_SUBDIVISION = 4

#: ... or more, so that the sphere approaches the flat by at most this many critical
#: interferences delta_c per fixed increment. Newton got through the contact's onset at 0.62
#: delta_c per increment at 1 m/s; at 1.41 m/s it diverged in the second contact increment at
#: 3.4 and 0.67 delta_c and got through at 1/3 (docs/fe-dynamic.md, where also the runs that
#: diverged at 1/4 and 1/3 when first touch fell exactly on an increment's end, and the ball
#: at 2 and 3 m/s, which this bound does not get through the onset).
MAX_APPROACH_PER_INCREMENT = 1.0 / 3.0

#: The sphere starts this many first increments above the flat (free flight before contact).
GAP_INCREMENTS = 3

#: Simulated time, in estimated contact durations (the rest is free flight after separation,
#: from which the rebound speed is read).
END_TIME_FACTOR = 1.4

#: The hemisphere's volume is half a ball's: its density is m / (2/3 pi R^3).
HEMISPHERE_VOLUME_FACTOR = 2.0 / 3.0 * math.pi


def hertz_estimates(mass: float, E_star: float, radius: float, speed: float) -> tuple[float, float]:
    """(peak interference [m], contact duration [s]) of Hertz's elastic impact (Johnson,
    *Contact Mechanics* 1985, Sec. 11.4): delta_m = (15 m v^2 / (16 E* sqrt(R)))^(2/5),
    T = 2.9432 delta_m / v. Used here to size the model; the check is in tests/fe."""
    dm = (15.0 * mass * speed * speed / (16.0 * E_star * math.sqrt(radius))) ** 0.4
    return dm, 2.9432 * dm / speed


def plastic_estimates(
    mass: float, yield_strength: float, radius: float, speed: float
) -> tuple[float, float]:
    """(peak interference [m], loading time [s]) of a fully plastic contact whose force is
    p A = p 2 pi R delta with p = PLASTIC_PRESSURE_FACTOR S_y (a linear spring k = 2 pi R p):
    delta_m = v sqrt(m / k), loading time pi/2 sqrt(m / k). Sizing only."""
    k = 2.0 * math.pi * radius * PLASTIC_PRESSURE_FACTOR * yield_strength
    w = math.sqrt(k / mass)
    return speed / w, 0.5 * math.pi / w


@dataclass(frozen=True)
class ImpactProblem:
    """One impact run (SI). Build it with :func:`make_impact_problem`.

    indentation: the quasi-static problem it shares bodies, materials and contact with;
    speed: impact speed v [m/s]; mass: the sphere's mass m [kg]; time_level: 1-3.
    """

    indentation: Problem
    speed: float
    mass: float
    time_level: int

    @property
    def radius(self) -> float:
        """Sphere radius R [m]."""
        return self.indentation.radius

    @property
    def delta_c(self) -> float:
        """The pair's critical interference [m]."""
        return self.indentation.delta_c

    @property
    def flat_is_elastic(self) -> bool:
        """True when the flat has no plasticity table."""
        return not self.indentation.flat_hardening

    @property
    def plastic_bodies(self) -> tuple[str, ...]:
        """The bodies that can yield: ``("flat", "sphere")``, either or none."""
        p = self.indentation
        sphere = p.sphere == "elastic-plastic" and bool(p.sphere_hardening)
        return ("flat",) * (not self.flat_is_elastic) + ("sphere",) * sphere

    def estimates(self) -> tuple[float, float]:
        """(largest expected interference [m], expected contact duration [s]): Hertz's for an
        elastic flat, else the larger of Hertz's and the fully plastic estimate."""
        p = self.indentation
        dh, th = hertz_estimates(self.mass, p.E_star, self.radius, self.speed)
        if self.flat_is_elastic:
            return dh, th
        dp, tp = plastic_estimates(self.mass, p.flat.yield_strength, self.radius, self.speed)
        return max(dh, dp), max(th, tp + 0.5 * th)

    @property
    def increment(self) -> float:
        """The time-level increment [s]: T_est / TIME_INCREMENTS[time_level] (the largest ccx
        may take for an elastic flat; it sets the gap and the end time in either case)."""
        return self.estimates()[1] / TIME_INCREMENTS[self.time_level]

    @property
    def procedure(self) -> str:
        """The procedure: "temperature-displacement" (elastic flat: automatic increments) or
        "dynamic-direct" (elastic-plastic flat: fixed increments, numerical damping)."""
        return "temperature-displacement" if self.flat_is_elastic else "dynamic-direct"

    @property
    def fixed_increment(self) -> float:
        """The fixed increment [s] of the "dynamic-direct" procedure: the time-level increment
        / PLASTIC_SUBDIVISION, or less, so that the approach per increment v dt is at most
        MAX_APPROACH_PER_INCREMENT delta_c."""
        by_time = self.increment / PLASTIC_SUBDIVISION
        by_approach = MAX_APPROACH_PER_INCREMENT * self.delta_c / self.speed
        return min(by_time, by_approach)

    @property
    def approach_limited(self) -> bool:
        """True when MAX_APPROACH_PER_INCREMENT, not the time level, sets the fixed increment
        of a "dynamic-direct" run."""
        return (
            self.procedure == "dynamic-direct"
            and self.fixed_increment < self.increment / PLASTIC_SUBDIVISION
        )

    @property
    def gap(self) -> float:
        """Initial gap between the sphere and the flat [m]."""
        return GAP_INCREMENTS * self.increment * self.speed

    @property
    def end_time(self) -> float:
        """Simulated time [s] from the start (the gap included)."""
        return END_TIME_FACTOR * self.estimates()[1] + GAP_INCREMENTS * self.increment

    @property
    def sphere_density(self) -> float:
        """Density [kg/m^3] that gives the hemisphere the mass m."""
        return self.mass / (HEMISPHERE_VOLUME_FACTOR * self.radius**3)

    def mesh_spec(self) -> MeshSpec:
        """The indentation mesh sized for the expected largest interference."""
        return self.indentation.mesh_spec()

    def deck_spec(self, spec: MeshSpec) -> DeckSpec:
        """Materials and contact bands of the indentation deck (its load steps unused)."""
        return self.indentation.deck_spec(spec)

    def key_data(self) -> dict[str, Any]:
        """Every input as plain values (the cache key hashes this)."""
        return {
            "kind": "impact",
            **self.indentation.key_data(),
            "speed": self.speed,
            "mass": self.mass,
            "time_level": self.time_level,
            "increments": TIME_INCREMENTS[self.time_level],
            "gap_increments": GAP_INCREMENTS,
            "end_time_factor": END_TIME_FACTOR,
            "procedure": self.procedure,
            "subdivision": PLASTIC_SUBDIVISION if self.procedure == "dynamic-direct" else 1,
            # only where it sets the increment (the runs it does not touch keep their keys)
            **(
                {"max_approach_per_increment": MAX_APPROACH_PER_INCREMENT}
                if self.approach_limited
                else {}
            ),
        }


def ball_mass(material: Material, radius: float) -> float:
    """Mass of a full ball of the material [kg] (ValueError if the material has no density)."""
    rho = material.density
    if rho is None or not rho > 0.0:
        raise ValueError(
            f"sphere_material {material.name!r} has no density: give the sphere's mass"
        )
    return 4.0 / 3.0 * math.pi * radius**3 * float(rho)


def make_impact_problem(
    flat: Material,
    sphere_material: Material,
    *,
    radius: Any,
    speed: Any,
    mass: Any = None,
    sphere: str = "elastic-plastic",
    flat_hardening: Any = None,
    sphere_hardening: Any = None,
    mesh_level: int = 1,
    time_level: int = 1,
) -> ImpactProblem:
    """Check every input and build the :class:`ImpactProblem` (one-line ValueErrors).

    sphere: "elastic" or "elastic-plastic" (a rigid sphere has no inertia in this model);
    mass: the sphere's mass [kg] (default: a full ball of ``sphere_material``)."""
    if sphere not in ("elastic", "elastic-plastic"):
        raise ValueError(f"sphere must be 'elastic' or 'elastic-plastic', got {sphere!r}")
    R = check_positive("radius", radius, "m")
    v = check_positive("speed", speed, "m/s")
    if v > 100.0:
        raise ValueError(f"speed must be at most 100 m/s (a low-speed impact), got {v!r} m/s")
    m = ball_mass(sphere_material, R) if mass is None else check_positive("mass", mass, "kg")
    if isinstance(time_level, bool) or time_level not in TIME_INCREMENTS:
        raise ValueError(f"time_level must be one of {sorted(TIME_INCREMENTS)}, got {time_level!r}")
    if isinstance(mesh_level, bool) or mesh_level not in MESH_GROWTH:
        raise ValueError(f"mesh_level must be one of {sorted(MESH_GROWTH)}, got {mesh_level!r}")
    probe = make_problem(
        flat,
        sphere_material,
        radius=R,
        delta_max=min(1e-9, 1e-6 * R),
        sphere=sphere,
        flat_hardening=flat_hardening,
        sphere_hardening=sphere_hardening,
        mesh_level=mesh_level,
    )
    first = ImpactProblem(probe, v, m, int(time_level))
    d_est = first.estimates()[0]
    # the mesh and flat block are sized for 1.3 times the expected largest interference
    try:
        indentation = make_problem(
            flat,
            sphere_material,
            radius=R,
            delta_max=1.3 * d_est,
            sphere=sphere,
            flat_hardening=flat_hardening,
            sphere_hardening=sphere_hardening,
            mesh_level=mesh_level,
        )
    except ValueError as exc:
        raise ValueError(
            f"speed {v!r} m/s with mass {m:.4g} kg: the expected largest interference "
            f"{d_est:.3g} m (x 1.3 for the mesh) is beyond what the FE problem of a sphere of "
            f"radius {R!r} m allows ({exc}); lower the speed or the mass"
        ) from None
    return replace(first, indentation=indentation)
