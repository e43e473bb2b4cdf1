"""The paper's closed forms for a rigid rod with a spherical tip hitting a flat, corrected, and the
inversion of a measured dent for the impact duration and mean force.

Source: H. Ghaednia, D. B. Marghitu, R. L. Jackson, "Permanent deformation during the oblique impact
with friction", Archive of Applied Mechanics 86 (2016) 121-134, doi:10.1007/s00419-015-1108-2,
Eqs. 1-13, 28, 29. The printed Eqs. 6, 10, 11, 12 and 13 contain errors; the forms here are derived
from the rigid-body impulse relations in ``docs/analytic.md`` (errata: ``docs/paper/errata.md``).

Conventions (SI throughout, angles in radians): origin at the first contact point O, x horizontal
and positive towards the centre of mass C, y up; ``angle`` is the angle between the rod axis and the
flat; the rod starts with no spin and no tangential velocity (the paper; :func:`invert` and Eq. 12's
closed forms also take the tip's incoming tangential velocity ``vt_in``) and drops with vertical
speed ``v_i``.
Lever arms from O to C: ``a = (L/2) cos(angle)``, ``b = (L/2) sin(angle) + R``
(:func:`lever_arms`, with its inputs checked; ``impactlab.bodies.lever_arms`` is the unchecked
core); ``k^2 = I_C/m``. P is the normal contact impulse. In gross sliding the tip slides
towards -x and friction gives the tangential impulse ``P_x = mu P``; then the tip velocity is
``v_O = (K_x P, v_i + K_y P)``. The dent depth
``delta_p`` and a measured sliding length are magnitudes >= 0 [m] (the paper prints them negative).

Validity: rigid rod, constant angle during contact (the rod turns by about 1.6 deg at 20 deg and
0.9 deg at 45 deg in the paper's impacts, see docs/analytic.md), the tip sliding towards -x
throughout (an incoming tangential velocity ``vt_in`` <= 0: zero in the paper), impulse-ratio
friction (paper Eq. 7), gross sliding (``mu < mu_c``). Gravity during the
contact is neglected by the paper's equations; :func:`invert` can include it (``gravity=True``).

Modules: :mod:`~impactlab.analytic.closed_forms` (K_x, K_y, alpha, mu_c, Eqs. 12, 28, 29),
:mod:`~impactlab.analytic.inversion` (:func:`invert`), :mod:`~impactlab.analytic.result`
(:class:`Measured`, :class:`InversionResult`).
"""

from __future__ import annotations

from impactlab.analytic._compliance import compliance_advice_hidden
from impactlab.analytic.closed_forms import (
    DOI,
    G0,
    alpha,
    critical_friction,
    friction_from_velocities,
    impact_duration,
    impulse_coefficients,
    lever_arms,
    mean_force_momentum,
    mean_force_rigid,
    sliding_length,
)
from impactlab.analytic.inversion import invert
from impactlab.analytic.result import InversionResult, Measured

__all__ = [
    "DOI",
    "G0",
    "InversionResult",
    "Measured",
    "alpha",
    "compliance_advice_hidden",
    "critical_friction",
    "friction_from_velocities",
    "impact_duration",
    "impulse_coefficients",
    "invert",
    "lever_arms",
    "mean_force_momentum",
    "mean_force_rigid",
    "sliding_length",
]
