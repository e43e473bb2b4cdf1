"""An estimated marker geometry checked by the impulse relation: the axis tilt the data imply.

Without a given geometry the rod's axis is taken as the markers' principal direction, and the
centre of mass C as the ballistic body point. Markers that are not laid out along the rod tilt
that axis, in the plane of the swing, by some delta: the angle read is off by delta, while C,
the velocity change of C and the spin change are not (none depends on the axis). The impulse
relation of :mod:`.impulse`,

    k^2 dw = b dv_Cx - a dv_Cy,   a = (L/2) cos(theta),   b = (L/2) sin(theta) + R,

then holds at the true angle theta + delta, not at the angle read: the tilt the data imply is
the root delta of ``predicted(theta + delta) = measured`` nearest to zero (a sinusoid in theta,
solved in closed form), and its standard uncertainty comes from the covariance of every
measured quantity it depends on (dw, dv_C, theta: the spin change's alone understates it many
times at shallow angles, where dv_Cx weighs as much) and from a relative uncertainty
``K2_RELATIVE`` of k^2 = I_C / m (the rod's inertia, rarely known better, as the given
geometry's check allows): a rod whose inertia is 10 % off the nominal then implies a tilt of
about 2 sigma, never a gross one.

The relative difference of the two spin changes does not measure the geometry's error: at
steep angles a lever arm (L/2) cos(theta) makes a 1 deg tilt change the predicted spin by ~17 %,
at shallow angles a 20 deg tilt by ~18 %. The tilt does, in degrees, at every angle. Simulated
drops (docs/experiment.md, "Without a marker geometry") set the bounds below.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab.experiment.kinematics.result import ImpactKinematics
from impactlab.experiment.uncertainty import propagate

__all__ = [
    "GROSS_TILT",
    "INERTIA_OFF",
    "K2_RELATIVE",
    "MAX_TILT",
    "TILT_SIGMAS",
    "UNDECIDED_SIGMAS",
    "TiltCheck",
    "implied_tilt",
    "tilt_check",
]

#: A tilt larger than this [rad] (5 deg), by ``GROSS_SIGMAS`` of its uncertainty beyond it and by
#: more than ``TILT_SIGMAS`` in all, is refused: the docs' marker layout (a 20 deg tilt) ...
GROSS_TILT = math.radians(5.0)
GROSS_SIGMAS = 2.0
#: ... a tilt of more than this many sigmas (but not gross) marks the result not ok: markers
#: glued 1-3 mm off the rod's axis tilt it 1-3 deg and bias e by up to 35 of its sigmas ...
TILT_SIGMAS = 3.0
#: ... and so does a check that cannot tell a ``GROSS_TILT`` from none (one within this many
#: sigmas: shallow angles, a slow camera, noisy markers).
UNDECIDED_SIGMAS = 2.0
#: No tilt within this [rad] (45 deg) that satisfies the relation: refused.
MAX_TILT = math.radians(45.0)
#: The relative standard uncertainty of k^2 = I_C / m propagated into the tilt's sigma ...
K2_RELATIVE = 0.05
#: ... and a relative error of it that is never refused (a gross tilt that is none with k^2
#: this much off marks the result not ok).
INERTIA_OFF = 0.1


def _root(y: np.ndarray, idx: tuple[int, ...], half: float, R: float, k2: float) -> float:
    """The tilt [rad] nearest to zero that satisfies the impulse relation for the derived values
    ``y`` (indices of angle_in, spin_in, spin_out, dv_cx, dv_cy); NaN when no angle does."""
    i_th, i_w0, i_w1, i_dx, i_dy = idx
    dvx, dvy, theta = float(y[i_dx]), float(y[i_dy]), float(y[i_th])
    size = math.hypot(dvx, dvy)
    if not size > 0:
        return math.nan
    # (L/2)(dv_Cx sin t - dv_Cy cos t) = k^2 dw - R dv_Cx, i.e. (L/2)|dv| sin(t - phi) = c
    s = (k2 * float(y[i_w1] - y[i_w0]) - R * dvx) / (half * size)
    if abs(s) > 1.0:
        return math.nan
    phi = math.atan2(dvy, dvx)
    roots = (phi + math.asin(s), phi + math.pi - math.asin(s))
    tilts = [(r - theta + math.pi) % (2.0 * math.pi) - math.pi for r in roots]
    return min(tilts, key=abs)


def implied_tilt(k: ImpactKinematics, k2: float) -> tuple[float, float]:
    """(the tilt [rad] of the rod's axis from the estimated one that the impulse relation
    implies, NaN when none does; its standard uncertainty [rad]) for the measured impact ``k``
    with ``k2`` = I_C / m [m^2], uncertain by ``K2_RELATIVE`` of it (module docstring)."""
    names = list(k.derived_names)
    idx = tuple(names.index(n) for n in ("angle_in", "spin_in", "spin_out", "dv_cx", "dv_cy"))
    y = np.asarray(k.derived_values, dtype=np.float64)
    tilt = _root(y, idx, k.half_length, k.tip_radius, k2)
    if math.isnan(tilt):
        return math.nan, math.inf

    def f(x: np.ndarray) -> np.ndarray:
        return np.array([_root(x[:-1], idx, k.half_length, k.tip_radius, float(x[-1]))])

    n = y.size
    cov_in = np.zeros((n + 1, n + 1))
    cov_in[:n, :n] = np.asarray(k.derived_cov, dtype=np.float64)
    cov_in[n, n] = (K2_RELATIVE * k2) ** 2
    _, cov = propagate(f, np.append(y, k2), cov_in)
    var = float(cov[0, 0])
    return tilt, math.sqrt(var) if math.isfinite(var) and var >= 0 else math.inf


@dataclass(frozen=True)
class TiltCheck:
    """The implied tilt ``tilt`` [rad] (NaN: none within reach) and its ``sigma`` [rad]."""

    tilt: float
    sigma: float
    inertia_explains: bool = False
    """Whether a gross tilt is none with the rod's inertia ``INERTIA_OFF`` off (the verdict is
    then "inertia": not ok, not refused)."""

    @property
    def gross(self) -> bool:
        """Whether the tilt is gross at the nominal inertia (bounds above)."""
        d, s = abs(self.tilt), self.sigma
        if math.isnan(d) or d > MAX_TILT:
            return True
        return d > GROSS_TILT + GROSS_SIGMAS * s and d > TILT_SIGMAS * s

    @property
    def verdict(self) -> str:
        """ "gross" (refused), "inertia", "tilted" or "undecided" (not ok) or "pass" (bounds
        above)."""
        d, s = abs(self.tilt), self.sigma
        if self.gross:
            return "inertia" if self.inertia_explains else "gross"
        if d > TILT_SIGMAS * s:
            return "tilted"
        if GROSS_TILT < UNDECIDED_SIGMAS * s:
            return "undecided"
        return "pass"

    def text(self) -> str:
        """The tilt in degrees with its sigma."""
        if math.isnan(self.tilt):
            return f"no tilt within {math.degrees(MAX_TILT):.0f} deg"
        return f"{math.degrees(self.tilt):+.1f} +- {math.degrees(self.sigma):.1f} deg"


def tilt_check(k: ImpactKinematics, k2: float) -> TiltCheck:
    """:class:`TiltCheck` of the measured impact ``k`` (``k2`` = I_C / m [m^2]); a gross tilt
    that is none with k^2 ``INERTIA_OFF`` lower or higher is marked ``inertia_explains`` (near
    the limits of the relation, at shallow angles, the first-order sigma understates it)."""
    check = TiltCheck(*implied_tilt(k, k2))
    if not check.gross:
        return check
    others = (TiltCheck(*implied_tilt(k, k2 * (1.0 + f))) for f in (-INERTIA_OFF, INERTIA_OFF))
    return TiltCheck(check.tilt, check.sigma, any(not c.gross for c in others))
