"""Result flags: what makes a computed impact untrustworthy although the integration succeeded.

A status code (``impactlab.dynamics.kernels.status``) says whether the engine could compute an
impact at all; a flag says that a computed impact must not be read as plain success. The
compiled core writes the flags as the output field ``flags`` (an integer bitmask stored as a
float, like ``regime``); ``ImpactResult.flags``, ``BatchResult.flags`` and sweep stores carry
it, ``messages(flags)`` explains it. The criteria are derived in ``docs/engine/index.md``
("Result flags"); their constants live here so that the core and the docs read one value.

This module imports nothing from impactlab (layer L0): the compiled core reads its integers.
"""

from __future__ import annotations

import enum

__all__ = [
    "ADVISORY_FLAGS",
    "ENERGY_GAIN_RTOL_FACTOR",
    "ENERGY_ROUNDOFF",
    "FLAG_BEYOND_TIP",
    "FLAG_BRITTLE",
    "FLAG_ENERGY_GAIN",
    "FLAG_GRAVITY_DOMINATED",
    "FLAG_LAW_EXTRAPOLATED",
    "FLAG_OTHER_END",
    "GRAVITY_IMPULSE_RATIO",
    "ResultFlag",
    "invalidating_names",
    "messages",
]

FLAG_ENERGY_GAIN = 1  #: bit of ``ResultFlag.ENERGY_GAIN`` (read by the compiled core)
FLAG_GRAVITY_DOMINATED = 2  #: bit of ``ResultFlag.GRAVITY_DOMINATED``
FLAG_LAW_EXTRAPOLATED = 4  #: bit of ``ResultFlag.LAW_EXTRAPOLATED`` (the law's verified range)
FLAG_OTHER_END = 8  #: bit of ``ResultFlag.OTHER_END`` (a drop; a rigid rod's other end)
FLAG_BEYOND_TIP = 16  #: bit of ``ResultFlag.BEYOND_TIP`` (a rod's impact or drop)
FLAG_BRITTLE = 32  #: bit of ``ResultFlag.BRITTLE`` (a brittle material past first yield)
#: Flags that caution rather than invalidate: the impact measures stay readable (``ok`` stays
#: True). LAW_EXTRAPOLATED: the law is used beyond its (fitted, provisional or theoretical)
#: range; its outputs stay finite but are not validated there.
ADVISORY_FLAGS = FLAG_LAW_EXTRAPOLATED

#: Energy gain tolerance, in units of ``rtol`` times the energy scale of the balance (E_0 + the
#: kinetic and |potential| energy at separation). The integrator keeps each step's error below
#: rtol; over the 15-430 steps of an impact the energy balance of the models that cannot create
#: energy (Coulomb, Mindlin; every law, rod and sphere) closed within 6.8 rtol of that scale
#: (160,000 impacts, rtol 1e-13 ... 1e-3, gravity not dominating); 100 leaves a factor of 15.
ENERGY_GAIN_RTOL_FACTOR = 100.0
#: Round-off floor of the energy balance, relative to the same scale: 2e5 steps (the step
#: limit) x 2.2e-16 = 4.4e-11, rounded up.
ENERGY_ROUNDOFF = 1e-10
#: Gravity dominates when its impulse m g T exceeds this fraction of the contact's normal
#: impulse P_n: gravity then accounts for up to that fraction of the change of the contact
#: point's normal velocity; at the threshold it changes e by about 1 % (at most 1.3 %) with
#: Coulomb friction or none, and by up to 3.5 % with Mindlin's tangential stiffness
#: (docs/engine/index.md, "Result flags").
GRAVITY_IMPULSE_RATIO = 0.1


class ResultFlag(enum.IntFlag):
    """Bits of the ``flags`` output of an impact (0: nothing to report)."""

    NONE = 0
    #: the total energy (kinetic + gravity potential) at separation exceeds the initial kinetic
    #: energy beyond the integration tolerance: the friction model created energy
    ENERGY_GAIN = FLAG_ENERGY_GAIN
    #: gravity's impulse m g T is not small against the contact's normal impulse P_n: the body
    #: rests, rocks or tips over rather than bounces, and e and the other impact measures are
    #: not meaningful
    GRAVITY_DOMINATED = FLAG_GRAVITY_DOMINATED
    #: the largest interference passed the upper end of the contact law's range (verified
    #: against FE, else a stand-in; ``impactlab.contact.ranges``): the law is extrapolated
    #: (advisory: ``ADVISORY_FLAGS``)
    LAW_EXTRAPOLATED = FLAG_LAW_EXTRAPOLATED
    #: a drop (``simulate_drop``) whose sequence is not one bounce of the tip: the other end
    #: touched the flat within it (``stop="flight"``), or the tip still approaches the flat
    #: after its last contact (e < 0: the other end lands first); e, the duration, the mean
    #: force and the scar then mix or cut the impacts. An impact of a rigid rod (``simulate``,
    #: the tip's contact alone): the other end may have reached the flat during the contact
    #: (L sin theta <= delta_max at the smaller of the angles at first touch and at separation)
    OTHER_END = FLAG_OTHER_END
    #: a rod's impact (or a contact of a drop) whose largest interference exceeds
    #: R (1 - |cos theta|), the depth at which the flat reaches the rim of the hemispherical
    #: end (theta: the rod's angle to the flat, the one of touch or separation farther from
    #: 90 deg; a flexible rod's drop: the angle of the end's section, the rod's plus its elastic
    #: rotation): the contact is no longer a sphere's on a flat, which every contact law assumes
    BEYOND_TIP = FLAG_BEYOND_TIP
    #: a brittle member of the pair (``Material.brittle``: its yield strength holds its
    #: compressive strength) carried a mean contact pressure past its first yield, (2/3) C(nu)
    #: S_y (``impactlab.contact.brittle``): such a material cracks rather than yields, and
    #: impactlab has no fracture model
    BRITTLE = FLAG_BRITTLE


_MESSAGES: dict[ResultFlag, str] = {
    ResultFlag.ENERGY_GAIN: (
        "energy gain: the total energy at separation exceeds the initial kinetic energy, or "
        "friction did positive work in one of a drop's contacts, beyond the integration "
        "tolerance, or the impulse_ratio contact point slid along its fixed friction force "
        "(friction's power positive), so the friction model created energy (the paper's "
        "impulse_ratio does so once the slip stops; coulomb is its energy-consistent completion)"
    ),
    ResultFlag.GRAVITY_DOMINATED: (
        "gravity-dominated: gravity's impulse m g T exceeds "
        f"{GRAVITY_IMPULSE_RATIO:g} of the contact's normal impulse, so the body rests, rocks "
        "or tips over rather than bounces and e and the other impact measures are not "
        "meaningful (raise the impact velocity, or pass gravity=False)"
    ),
    ResultFlag.OTHER_END: (
        "other end: the other end of the rod touched the flat within the drop (stop='flight', "
        "or a rod landing nearly flat), or the tip still approaches the flat after its last "
        "contact (e < 0: the other end lands before the tip leaves), so e, the duration and "
        "the mean force do not describe one bounce of the tip; read the contacts one by one "
        "(dent_depth and scar_length stay the tip's: its deepest dent, and the x-extent of all "
        "its marks, the flat between separate dents included; the other end's dents are in "
        "dents). An impact of a rigid rod follows the tip alone: its other end came within the "
        "interference of the flat, L sin(angle) <= delta_max, so it may have struck; "
        "simulate_drop follows both ends"
    ),
    ResultFlag.BEYOND_TIP: (
        "beyond the tip: the largest interference exceeds R (1 - |cos(angle)|), the depth at "
        "which the flat reaches the rim of the rod's hemispherical end at its angle to the "
        "flat (in a drop: in one of its contacts; a flexible rod's: its end section's), so the "
        "contact is no longer that of a sphere on a flat, which the contact laws describe; the "
        "outputs do not hold {beyond_advice}"
    ),
    ResultFlag.BRITTLE: (
        "brittle: the largest mean contact pressure passed the first yield of a brittle "
        "member of the pair (body or flat), whose yield strength is its compressive strength; "
        "such a material cracks rather than yields, and impactlab has no fracture model, so "
        "the dent, e and the forces past first yield do not hold (treat them as a bound only; "
        "lower the impact velocity to stay below it)"
    ),
    ResultFlag.LAW_EXTRAPOLATED: (
        "law extrapolated: the largest interference passed {what}{how_far}: {so} (advisory; "
        "`impactlab laws --accuracy` measures each law)"
    ),
}

#: The advice that ends the BEYOND_TIP sentence: alone, and with GRAVITY_DOMINATED (the rod
#: rests on or falls onto the flat, its angle shrinking as it tips over: the impact's speed is
#: not what takes the flat past the rim).
_BEYOND_TIP_ADVICE = "(raise the angle or lower the impact velocity)"
_BEYOND_TIP_GRAVITY_ADVICE = (
    "(gravity dominates: the rod rests, rocks or falls over onto the flat rather than bounces, "
    "so the rim meets the flat as it lies down and e and the other impact measures are not "
    "meaningful; lowering the impact velocity does not help: raise it, or pass gravity=False)"
)

#: The LAW_EXTRAPOLATED sentence per range status (``impactlab.contact.ranges.STATUSES``):
#: (what was exceeded, what the limit is called, the consequence).
_EXTRAPOLATION_TEXT = {
    "confirmed": (
        "the law's fitted range",
        "fitted up to",
        "the law is used beyond the data it was fitted to",
    ),
    "provisional": (
        "the law's provisional limit (a stand-in: its own fitted range was not found)",
        "provisional limit",
        "the law is probably used beyond the data it was fitted to",
    ),
    "theory": (
        "the limit of the law's theory (first yield)",
        "limit",
        "its theory no longer holds there",
    ),
    "verified": (
        "the range where the law was verified against FE",
        "verified up to",
        "it may differ from FE there by more than 10 % in force or 0.05 in delta_r/delta_max",
    ),
    "unverified": (
        "the law's stand-in limit (no FE case covers the pair's E*/S_y)",
        "stand-in limit",
        "the law is probably used beyond its validated range",
    ),
}
_UNKNOWN_STATUS = (
    "the law's range",
    "limit",
    "the law is used beyond its validated range",
)


def _how_far(
    extrapolation: tuple[float, float] | None, limit_name: str, reference: str = "delta_c"
) -> str:
    """`` (max delta/delta_c = 312, fitted up to 110)`` (``reference``: the law's own
    reference interference, ``delta_y`` for Kogut-Komvopoulos and Brake) or ``""`` when
    unknown."""
    if extrapolation is None:
        return ""
    ratio, limit = extrapolation
    if not (ratio == ratio and limit == limit and limit < float("inf")):  # NaN or no range
        return ""
    return f" (max delta/{reference} = {ratio:.4g}, {limit_name} {limit:.4g})"


def messages(
    flags: int,
    *,
    extrapolation: tuple[float, float] | None = None,
    status: str | None = None,
    reference: str = "delta_c",
) -> tuple[str, ...]:
    """One explanatory sentence per flag set in ``flags`` (an int or a ``ResultFlag``), in bit
    order; ``()`` for none. Unknown bits raise ``ValueError``. ``extrapolation`` = (max
    delta/delta_ref, the law's upper end), when known, says how far LAW_EXTRAPOLATED went
    (``impactlab.contact.ranges.extrapolation``), in the law's own ``reference``
    (``delta_c``, or ``delta_y`` for Kogut-Komvopoulos and Brake: ``LawRange.delta_ref``);
    ``status``, the range's status (``contact.ranges.range_status``: "verified",
    "unverified", "provisional", "theory", ...), words that sentence. The BEYOND_TIP sentence's
    advice depends on GRAVITY_DOMINATED: with it, the rod falls onto the flat rather than
    bounces, and a lower impact velocity would not help."""
    try:
        value = int(flags)
    except (TypeError, ValueError):
        raise TypeError(f"flags must be an integer bitmask, got {flags!r}") from None
    known = 0
    for flag in ResultFlag:
        known |= int(flag)
    if value < 0 or value & ~known:
        raise ValueError(f"flags {value!r} holds bits outside the known flags (mask {known})")
    what, limit_name, so = _EXTRAPOLATION_TEXT.get(status or "", _UNKNOWN_STATUS)
    how_far = _how_far(extrapolation, limit_name, reference)
    gravity = value & ResultFlag.GRAVITY_DOMINATED
    advice = _BEYOND_TIP_GRAVITY_ADVICE if gravity else _BEYOND_TIP_ADVICE
    return tuple(
        text.format(how_far=how_far, what=what, so=so, beyond_advice=advice)
        for flag, text in sorted(_MESSAGES.items())
        if value & flag
    )


def invalidating_names() -> str:
    """The short names of the flags that make a result not plain success (every flag but
    ``ADVISORY_FLAGS``), in bit order: ``"energy gain, gravity-dominated, other end, beyond the
    tip, brittle"``."""
    bits = [f for f in ResultFlag if f.value and not f & ADVISORY_FLAGS]
    return ", ".join(_MESSAGES[f].split(":")[0] for f in bits)
