"""The physical models ("configurations") a measured drop is compared with, nothing tuned:
the rigid body (a rod's or a sphere's), the flexible rod and the flexible rod on a
rate-dependent flat.

The rate-dependent rows use the library's rate laws only where their constants hold: both
(Cowper-Symonds, an upper estimate of the rate effect; Johnson-Cook, a lower one) are fitted
for low-carbon (mild) steel (``impactlab.contact.rate``, ``RateLaw.fitted_for``), so a drop on
another flat does not run them, and the result says why. Rate laws of one's own
(``rate_laws=["cowper-symonds(D=6500 1/s, q=4)"]``, ``RateLaw.custom``) replace them: the user's
constants are the flat's, and no material check applies.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from impactlab.contact.rate import (
    COWPER_SYMONDS_MILD_STEEL,
    JOHNSON_COOK_1006_STEEL,
    RateLaw,
    get_rate_law,
)
from impactlab.materials import Material

__all__ = [
    "ESTIMATES",
    "FLEXIBLE",
    "LIBRARY_RATES",
    "RIGID",
    "Configuration",
    "configurations",
    "rate_not_applicable",
]


@dataclass(frozen=True)
class Configuration:
    """One physical model of a drop: its ``name`` (the rows of an Explanation), whether the
    rod is ``flexible`` (``FlexibleRod`` of the drop's rod: default modes, the drop's damping
    or none), the flat's ``rate`` law (None: rate-independent) and a ``description``."""

    name: str
    flexible: bool
    rate: RateLaw | None
    description: str


#: The rigid body of each drop (a rod: I_C as the file gives it or m L^2 / 12; a sphere: the
#: rigid sphere), one contact. Named "rigid body": a sphere's drop runs it too.
RIGID = Configuration(
    "rigid body",
    False,
    None,
    "the drop's own rigid body, a rigid rod or a rigid sphere (simulate: one contact)",
)
#: The drop's rod as a FlexibleRod: the whole contact sequence, re-contacts included.
FLEXIBLE = Configuration(
    "flexible rod",
    True,
    None,
    "the drop's rod as a FlexibleRod (Timoshenko modes, FlexibleRod's default counts, the "
    "drop's damping ratio or none): the whole contact sequence, re-contacts included",
)


#: The library's rate laws and what their constants estimate: Cowper-Symonds (Jones's mild
#: steel constants of the initial yield stress, an upper estimate of the rate effect) and the
#: Johnson-Cook rate term (1006 steel, fitted to large-strain flow stress, a lower estimate).
ESTIMATES: dict[RateLaw, str] = {
    COWPER_SYMONDS_MILD_STEEL: "upper estimate",
    JOHNSON_COOK_1006_STEEL: "lower estimate",
}


def _rate_configuration(law: RateLaw) -> Configuration:
    """The flexible rod on a flat whose yield strength ``law`` raises; a library law (however
    it was asked for) with its estimate label."""
    estimate = ESTIMATES.get(law, "")
    what = f"{law.label}{', ' + estimate if estimate else ''}"
    return Configuration(
        f"flexible rod + rate-dependent flat ({what})",
        True,
        law,
        f"as 'flexible rod', the flat's yield strength raised by the self-consistent factor of "
        f"{law.text} (impactlab.contact.rate), and the rod's, where it is not above the raised "
        "flat's or the rod would yield first, to 1.5 times the raised flat's (more where their "
        "Poisson's ratios differ), so that only the flat yields, as the measured dents say",
    )


#: The library's rate laws, both fitted for low-carbon steel (:data:`ESTIMATES`).
LIBRARY_RATES: tuple[Configuration, ...] = tuple(_rate_configuration(law) for law in ESTIMATES)


def configurations(
    rate_laws: Iterable[object] | None = None, option: str = "rate_laws"
) -> tuple[Configuration, ...]:
    """The rigid body, the flexible rod and one rate-dependent row per rate law: ``rate_laws``
    None gives the library's (:data:`LIBRARY_RATES`), else each item is a rate law as
    ``simulate``'s ``rate`` takes it (a library name, ``"cowper-symonds(D=6500 1/s, q=4)"``, a
    ``RateLaw``); ``[]``, ``["none"]`` or ``[None]``: no rate rows. ValueError naming
    ``option`` (the rate laws as the caller took them: ``--rate``) for a law not understood,
    "none" beside a law, or a law given twice (by name and by the same constants, too)."""
    if rate_laws is None:
        return (RIGID, FLEXIBLE, *LIBRARY_RATES)
    items = [rate_laws] if isinstance(rate_laws, str | RateLaw) else list(rate_laws)
    if len(items) == 1 and get_rate_law(items[0], option) is None:
        items = []  # "none" (or None) alone: no rate row, as --rate none
    laws: list[RateLaw] = []
    for item in items:
        law = get_rate_law(item, option)
        if law is None:
            raise ValueError(
                f"{option}: {item!r} is no rate law; give 'none' alone for no rate row, or "
                "leave it out beside the rate laws"
            )
        same = next((w for w in laws if (w.name, w.parameters) == (law.name, law.parameters)),
                    None)  # fmt: skip
        if same is not None:
            twice = law.text if same.text == law.text else f"{same.label} and {law.label}"
            raise ValueError(
                f"{option}: {twice} {'is' if same.text == law.text else 'are'} the same law "
                "(the same form and constants) given twice; give each rate law once"
            )
        laws.append(law)
    return (RIGID, FLEXIBLE, *(_rate_configuration(law) for law in laws))


def rate_not_applicable(config: Configuration, flat: Material) -> str | None:
    """Why ``config`` does not run on ``flat`` (None: it does): a library rate law's constants
    are fitted for another material (``RateLaw.fitted_for``); never applied silently."""
    law = config.rate
    if law is None or law.fitted_for is None:
        return None
    why = law.fitted_for.mismatch(flat)
    if why is None:
        return None
    return (
        f"not run: the {law.name} constants are fitted for {law.fitted_for.name}, but the flat "
        f"{flat.name!r} has {why}; give the flat's own constants (rate_laws=[...], --rate)"
    )
