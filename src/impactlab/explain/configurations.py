"""The physical models ("configurations") a measured drop is compared with, nothing tuned:
the rigid body (a rod's or a sphere's), the flexible rod and the flexible rod on a
rate-dependent flat.

The rate-dependent rows use the library's rate laws only where their constants hold: both
(Cowper-Symonds, an upper estimate of the rate effect; Johnson-Cook, a lower one) are fitted
for low-carbon (mild) steel (``impactlab.contact.rate``, ``RateLaw.fitted_for``), so a drop on
another flat does not run them, and the result says why. A library law is the library's
however it is given: by its name, by its form with its own constants
(``"cowper-symonds(D=40.4 1/s, q=5)"``) or as a ``RateLaw`` with them; it keeps its estimate
label and its material check. Rate laws of one's own, a form with other constants
(``rate_laws=["cowper-symonds(D=6500 1/s, q=4)"]``, ``RateLaw.custom``), replace them: the user's
constants are the flat's, and no material check applies.
"""

from __future__ import annotations

import math
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
    "library_law",
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


def _same_law(a: RateLaw, b: RateLaw) -> bool:
    """Whether ``a`` and ``b`` are one law: the same form and the same constants (to 1e-12,
    relative, as a unit conversion leaves them)."""
    if a.name != b.name or [k for k, _ in a.parameters] != [k for k, _ in b.parameters]:
        return False
    return all(math.isclose(x, y, rel_tol=1e-12)
               for (_, x), (_, y) in zip(a.parameters, b.parameters, strict=True))  # fmt: skip


def library_law(law: RateLaw) -> RateLaw:
    """The library's law (:data:`ESTIMATES`) that ``law`` is, by its form and constants, with
    its estimate label and the material its constants are fitted for; else ``law`` itself
    (one's own constants)."""
    return next((known for known in ESTIMATES if _same_law(known, law)), law)


def _rate_configuration(law: RateLaw) -> Configuration:
    """The flexible rod on a flat whose yield strength ``law`` raises; a library law (however
    it was asked for: :func:`library_law`) with its estimate label."""
    law = library_law(law)
    estimate = ESTIMATES.get(law, "")
    what = f"{law.label}{', ' + estimate if estimate else ''}"
    return Configuration(
        f"flexible rod + rate-dependent flat ({what})",
        True,
        law,
        f"as 'flexible rod', the flat's yield strength raised by the self-consistent factor of "
        f"{law.text} (impactlab.contact.rate), and the rod's, where the raised flat would "
        "overtake it, to 1.5 times the raised flat's (more where their Poisson's ratios "
        "differ), so that a flat that yields first still does, as the measured dents say (a "
        "rod that yields first is left as it is)",
    )


#: The library's rate laws, both fitted for low-carbon steel (:data:`ESTIMATES`).
LIBRARY_RATES: tuple[Configuration, ...] = tuple(_rate_configuration(law) for law in ESTIMATES)


def configurations(
    rate_laws: Iterable[object] | None = None, option: str = "rate_laws"
) -> tuple[Configuration, ...]:
    """The rigid body, the flexible rod and one rate-dependent row per rate law: ``rate_laws``
    None gives the library's (:data:`LIBRARY_RATES`), else each item is a rate law as
    ``simulate``'s ``rate`` takes it (a library name, ``"cowper-symonds(D=6500 1/s, q=4)"``, a
    ``RateLaw``); ``[]``, ``["none"]`` or ``[None]``: no rate rows. A law with the constants of
    a library law is that law (:func:`library_law`: its label, its material check). ValueError
    naming ``option`` (the rate laws as the caller took them: ``--rate``) for ``rate_laws``
    that are no rate law nor a list of them, a law not understood, "none" beside a law, or a
    law given twice (by name and by the same constants, too)."""
    if rate_laws is None:
        return (RIGID, FLEXIBLE, *LIBRARY_RATES)
    if isinstance(rate_laws, str | RateLaw):
        items: list[object] = [rate_laws]
    elif isinstance(rate_laws, Iterable) and not isinstance(rate_laws, bytes | dict):
        items = list(rate_laws)
    else:
        raise ValueError(
            f"{option} must be None (the library's rate laws), a rate law or a list of rate laws "
            "(each a library name, cowper-symonds or johnson-cook, a law with its constants such "
            "as 'cowper-symonds(D=6500 1/s, q=4)', or a RateLaw), or [] for no rate row; got "
            f"{rate_laws!r} ({type(rate_laws).__name__})"
        )
    if len(items) == 1 and get_rate_law(items[0], option) is None:
        items = []  # "none" (or None) alone: no rate row, as --rate none
    laws: list[tuple[object, RateLaw]] = []
    for item in items:
        given = get_rate_law(item, option)
        if given is None:
            raise ValueError(
                f"{option}: {item!r} is no rate law; give 'none' alone for no rate row, or "
                "leave it out beside the rate laws"
            )
        law = library_law(given)
        same = next((it for it, w in laws if _same_law(w, law)), None)
        if same is not None:
            first, again = _shown(same), _shown(item)
            twice = first if first == again else f"{first} and {again}"
            raise ValueError(
                f"{option}: {twice} {'is' if first == again else 'are'} the same law "
                "(the same form and constants) given twice; give each rate law once"
            )
        laws.append((item, law))
    return (RIGID, FLEXIBLE, *(_rate_configuration(law) for _, law in laws))


def _shown(item: object) -> str:
    """A rate law as it was given (its text; a RateLaw: its name and constants)."""
    return item.text if isinstance(item, RateLaw) else str(item)


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
