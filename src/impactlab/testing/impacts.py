"""Known impacts for synthetic experiments: the rigid-body impulse solution and the engine's.

* :func:`rigid_impulse_impact`: the outgoing state of a rod after an instantaneous impact at its
  contact point (``impactlab.bodies.rigid_impulse``: Newton restitution ``e`` of the contact
  point's normal velocity, Coulomb friction ``mu``, slip or stick);
* :func:`engine_impact`: the same impact from the engine (``impactlab.dynamics.simulate``, a
  finite contact duration and the history through the contact).

Frame (the paper's, Fig. 1): x along the flat towards the centre of mass C, y up; the spin is
counter-clockwise positive (the rate of the angle of the vector tip -> C above the flat).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.bodies import Rod, rigid_impulse
from impactlab.dynamics import simulate
from impactlab.materials import Material

__all__ = ["ImpactTruth", "engine_impact", "rigid_impulse_impact"]


@dataclass(frozen=True)
class ImpactTruth:
    """The true impact (SI units; frame in the module docstring).

    ``angle`` [rad]; ``v_in``, ``v_out``: (x, y) velocity of C [m/s]; ``spin_in``, ``spin_out``
    [rad/s]; ``v_tip_in``, ``v_tip_out``: (x, y) velocity of the contact point [m/s]; ``e``
    (normal restitution of the contact point), ``mu`` (impulse ratio |P_t / P_n| = |dv_Cx /
    dv_Cy|); ``regime`` ("slip", "stick" or "reversal", the engine's names); ``duration`` [s] (0
    for the impulse model); ``source`` ("impulse" or "engine"); for the engine also ``delta_p``,
    ``sliding_length`` [m] and ``contact`` (k, 4): t [s], x, y of C [m] (origin: first contact
    point) and the rotation phi [rad] through the contact."""

    angle: float
    v_in: tuple[float, float]
    spin_in: float
    v_out: tuple[float, float]
    spin_out: float
    v_tip_in: tuple[float, float]
    v_tip_out: tuple[float, float]
    e: float
    mu: float
    regime: str
    duration: float = 0.0
    source: str = "impulse"
    delta_p: float = math.nan
    sliding_length: float = math.nan
    contact: np.ndarray | None = field(default=None, repr=False)

    def __repr__(self) -> str:
        """One line: the scalars (the contact path as its size only)."""
        path = "" if self.contact is None else f", contact=<{len(self.contact)} rows>"
        return (
            f"ImpactTruth(source={self.source!r}, regime={self.regime!r}, "
            f"angle={self.angle:.6g} rad, e={self.e:.6g}, mu={self.mu:.6g}, "
            f"duration={self.duration:.6g} s, delta_p={self.delta_p:.6g} m{path})"
        )


def _pair(v: Any) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def rigid_impulse_impact(
    rod: Rod,
    angle: float,
    velocity: tuple[float, float] = (0.0, -1.41),
    spin: float = 0.0,
    *,
    e: float = 0.5,
    mu: float = 0.2,
) -> ImpactTruth:
    """Instantaneous rigid-body impact of ``rod`` at its contact point
    (``impactlab.bodies.rigid_impulse``). ``angle`` [rad] in (0, pi/2), ``velocity`` (vx, vy) of
    C [m/s], ``spin`` [rad/s]; ``e`` the contact point's normal restitution, ``mu`` the Coulomb
    coefficient. ValueError if the contact point does not approach the flat."""
    r = rigid_impulse(rod, angle, velocity, spin, e=e, mu=mu)
    vt0, vn0 = r.contact_velocity_in
    vt1, vn1 = r.contact_velocity_out
    return ImpactTruth(
        float(angle),
        _pair(velocity),
        float(spin),
        _pair(r.velocity_out),
        float(r.spin_out),
        (float(vt0), float(vn0)),
        (float(vt1), float(vn1)),
        float(-vn1 / vn0),
        float(r.mu_effective),
        r.regime,
    )


def engine_impact(
    rod: Rod,
    flat: Material,
    angle: float,
    velocity: tuple[float, float],
    *,
    mu: float,
    **kwargs: Any,
) -> ImpactTruth:
    """The impact from the engine (``impactlab.dynamics.simulate``, finite contact duration).
    Extra keyword arguments (e.g. ``spin``) go to ``simulate``. ``mu`` of the truth is the
    contact's impulse ratio (the gravity impulse excluded), ``e`` the engine's normal restitution
    of the contact point."""
    res = simulate(rod, flat, mu=mu, angle=angle, velocity=_pair(velocity), history=True, **kwargs)
    h = res.history
    contact = np.column_stack([h.t, h.x, h.y, h.phi]) if h is not None else None
    return ImpactTruth(
        angle,
        _pair(velocity),
        float(kwargs.get("spin", 0.0)),
        _pair(res.velocity_out),
        float(res.spin_out),
        (float(res.vt_in), float(res.vn_in)),
        (float(res.vt_out), float(res.vn_out)),
        float(res.e),
        abs(float(res.tangential_impulse) / float(res.normal_impulse)),
        str(res.regime),
        float(res.duration),
        "engine",
        float(res.delta_p),
        float(res.sliding_length),
        contact,
    )
