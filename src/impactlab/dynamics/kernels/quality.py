"""The result flags of a finished impact (``impactlab.flags``): energy gain and gravity
dominance, from the energy balance and the impulses at separation, and the rim of a rod's
hemispherical end (docs/engine/index.md, "Result flags")."""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.flags import (
    ENERGY_GAIN_RTOL_FACTOR,
    ENERGY_ROUNDOFF,
    FLAG_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED,
    GRAVITY_IMPULSE_RATIO,
)

#: Slip-velocity tolerance of the regime and of ``slid_along_friction``, relative to the
#: contact point's normal velocity at first touch |v_n,in|.
SLIP_VTOL = 1e-6


@njit_internal
def energy_gained(e0, e_kin, e_pot, rtol):
    """True when the total energy at separation, kinetic ``e_kin`` + gravity potential
    ``e_pot`` [J], exceeds the initial kinetic energy ``e0`` [J] by more than the integration
    tolerance: (ENERGY_GAIN_RTOL_FACTOR rtol + ENERGY_ROUNDOFF) times the energy scale of the
    balance, e0 + e_kin + |e_pot|."""
    scale = e0 + e_kin + abs(e_pot)
    return e_kin + e_pot - e0 > (ENERGY_GAIN_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF) * scale


@njit(cache=True, inline="always", error_model="numpy")
def beyond_rim(radius, angle, angle_out, delta_max):
    """True when the largest interference ``delta_max`` [m] of a contact of a rod's
    hemispherical end (radius [m]) exceeds R (1 - |cos theta|), the depth at which the flat
    reaches the hemisphere's rim, theta the rod's angle to the flat [rad]: of those at touch and
    at separation, the one farther from pi/2 (``ResultFlag.BEYOND_TIP``). False for NaN."""
    cos_far = max(abs(math.cos(angle)), abs(math.cos(angle_out)))
    return delta_max > radius * (1.0 - cos_far)


@njit(cache=True, error_model="numpy")
def gravity_dominated(gravity_impulse, normal_impulse):
    """True when gravity's impulse m g T [N s] exceeds GRAVITY_IMPULSE_RATIO of the contact's
    normal impulse P_n [N s] (never without gravity)."""
    return gravity_impulse > 0.0 and gravity_impulse > GRAVITY_IMPULSE_RATIO * normal_impulse


@njit(cache=True, error_model="numpy")
def friction_work_gained(work, scale, rtol):
    """True when friction's work ``work`` [J] over a contact is positive beyond the energy
    criterion's tolerance, (ENERGY_GAIN_RTOL_FACTOR rtol + ENERGY_ROUNDOFF) ``scale`` [J]:
    friction created energy (which the normal contact's losses may hide from the total)."""
    return work > (ENERGY_GAIN_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF) * scale


@njit(cache=True, error_model="numpy")
def slid_along_friction(sir, vs_pos, vs_neg, vtol):
    """True when the contact point slid along a friction force of fixed sign ``sir`` (the
    ``impulse_ratio`` model's F_t = sir mu F_n): the largest slip velocity along it, ``vs_pos``
    (sir > 0) or -``vs_neg`` (sir < 0) [m/s], exceeds ``vtol`` [m/s]. Such a force does
    positive work on the sliding body, so it created energy, whatever the net work that the
    normal contact's losses leave (regime ``reversal``, flag ENERGY_GAIN)."""
    return (sir > 0.0 and vs_pos > vtol) or (sir < 0.0 and vs_neg < -vtol)


@njit_internal
def result_flags(e0, e_kin, e_pot, w_normal, rtol, gravity_impulse, normal_impulse):
    """The ``flags`` output (a ``ResultFlag`` bitmask, as a float) of an impact that separated;
    ``w_normal``: the normal force's work [J], so that friction's is the rest of the energy's
    change."""
    flags = 0
    w_friction = e_kin + e_pot - e0 - w_normal
    scale = e0 + e_kin + abs(e_pot) + abs(w_normal)
    if energy_gained(e0, e_kin, e_pot, rtol) or friction_work_gained(w_friction, scale, rtol):
        flags |= FLAG_ENERGY_GAIN
    if gravity_dominated(gravity_impulse, normal_impulse):
        flags |= FLAG_GRAVITY_DOMINATED
    return float(flags)
