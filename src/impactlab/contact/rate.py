"""A rate-dependent flat: the flat's yield strength raised by a strain-rate factor (SI units).

The simplest defensible variant, and only that: one multiplier k >= 1 on the flat's quasi-static
yield strength S_y for the whole impact, k = f(eps_dot), with eps_dot one characteristic strain
rate of the contact. Every contact law then runs unchanged with S_y -> k S_y (for the Jackson-Green
family this moves delta_c, F_c, the loading curve and the residual depth). The time dependence of
the rate within a contact (it falls to zero at the largest compression) and the strain dependence
of the rate sensitivity are ignored.

Rate laws and their parameters for low-carbon steel:

* Cowper-Symonds: sigma_d / sigma_0 = 1 + (eps_dot / D)^(1/q), mild steel D = 40.4 1/s, q = 5
  (law: Cowper & Symonds, Brown University Technical Report No. 28, 1957; constants for mild
  steel as quoted by Jones, Structural Impact, 1989: ``RATE_REFERENCES``, with what was
  confirmed). Jones stresses that these constants describe the initial (lower) yield stress
  and overestimate the enhancement of the flow stress at larger strains: this is an upper
  estimate for an indentation (representative strain about 0.1).
* Johnson-Cook rate term: sigma_d / sigma_0 = 1 + C ln(eps_dot / eps_dot_0), C = 0.022,
  eps_dot_0 = 1 1/s, for 1006 steel (a low-carbon steel close to the flat's AISI 1010):
  Johnson & Cook, Proc. 7th Int. Symp. on Ballistics, The Hague (1983), pp. 541-547 (pages as
  commonly cited, not confirmed); their 1006-steel constants (A = 350 MPa, B = 275 MPa,
  n = 0.36, C = 0.022, m = 1.00) confirmed against a secondary source that reproduces their
  table (its number not confirmed). A lower estimate: fitted to large-strain flow stress.

The strain-rate estimate of the contact: Tabor's representative strain of a spherical
indentation, eps_r = 0.2 a / R (D. Tabor, The Hardness of Metals, Oxford 1951; K. L. Johnson,
Contact Mechanics, 1985, doi:10.1017/CBO9781139171731, its chapter on elastic-plastic
indentation, chapter and section numbers not confirmed here), differentiated in time with the
plastic (truncation) geometry a^2 = 2 R delta (a da/dt = R d delta/dt):
eps_dot = 0.2 (da/dt) / R = 0.2 (d delta/dt) / a ~ 0.2 |v_n0| / a_m, with v_n0 the tip's normal
approach speed at first touch and a_m the contact radius at the largest interference of the
first contact (the law's own radius). Since a_m depends on k, k is found by a fixed-point
iteration (:func:`self_consistent_factor`, in :mod:`impactlab.contact.rate_factor`: it warns
where it does not converge and refuses a factor that would raise a yield strength above E).
"""

from __future__ import annotations

import dataclasses
import math
import numbers
import re
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from itertools import accumulate

from impactlab._validation import ImplausibleInputWarning, check_nonnegative, check_positive
from impactlab.contact.rate_factor import (
    RateFactor,
    RateFactorWarning,
    RateLimit,
    body_margin,
    self_consistent_factor,
    tabor_strain_rate,
)
from impactlab.materials import Material, body_yields_first
from impactlab.references import REFERENCES, Reference
from impactlab.units import magnitude, to_si

__all__ = [
    "COWPER_SYMONDS_MILD_STEEL", "JOHNSON_COOK_1006_STEEL", "LOW_CARBON_STEEL", "RATE_CONSTANTS",
    "RATE_EXAMPLES", "RATE_LAWS", "RATE_REFERENCES", "FittedFor", "RateFactor",
    "RateFactorWarning", "RateLaw", "RateLimit", "check_rate_flat", "constants_text",
    "cowper_symonds", "get_rate_law", "johnson_cook", "rate_constant", "rate_materials",
    "self_consistent_factor", "shortest", "tabor_strain_rate",
]  # fmt: skip

#: The sources of the rate-dependent flat (to be merged into ``impactlab.references``).
RATE_REFERENCES: dict[str, Reference] = {
    "cowper-symonds-1957": Reference(
        "cowper-symonds-1957",
        "G. R. Cowper, P. S. Symonds, Strain-hardening and strain-rate effects in the impact "
        "loading of cantilever beams, Tech. Rep. No. 28, Division of Applied Mathematics, "
        "Brown University (1957)",
        note="title, authors, report number (No. 28, contract Nonr-562(10)) and date (September "
        "1957) confirmed against a scan of the report (DTIC AD144762); a report: no DOI",
    ),
    "jones-1989": Reference(
        "jones-1989",
        "N. Jones, Structural Impact, Cambridge University Press (1989) (Cowper-Symonds "
        "constants for mild steel)",
        note="book; table and equation numbers not confirmed, none cited",
    ),
    "johnson-cook-1983": REFERENCES["johnson-cook-1983"],
    "tabor-1951": Reference(
        "tabor-1951",
        "D. Tabor, The Hardness of Metals, Clarendon Press, Oxford (1951)",
        note="book, no DOI; chapter not confirmed",
    ),
}


def cowper_symonds(rate: float, D: float = 40.4, q: float = 5.0) -> float:
    """Cowper-Symonds factor 1 + (rate / D)^(1/q) [1] (>= 1) for the strain rate ``rate``
    [1/s]; D [1/s], q [1]."""
    if rate <= 0.0:
        return 1.0
    try:
        return 1.0 + (rate / D) ** (1.0 / q)
    except OverflowError:  # beyond any float: the caller refuses an infinite factor
        return math.inf


def johnson_cook(rate: float, C: float = 0.022, rate0: float = 1.0) -> float:
    """Johnson-Cook rate factor 1 + C ln(rate / rate0) [1], floored at 1 (no softening below
    the reference rate ``rate0`` [1/s])."""
    if rate <= rate0:
        return 1.0
    return 1.0 + C * math.log(rate / rate0)


@dataclass(frozen=True)
class FittedFor:
    """The materials a rate law's constants were fitted for: a ``name`` and the ranges of
    Young's modulus [Pa], density [kg/m^3] and quasi-static yield strength [Pa] that identify
    them (a flat outside any range is another material)."""

    name: str
    E: tuple[float, float]
    density: tuple[float, float]
    yield_strength: tuple[float, float]

    def mismatch(self, flat: Material) -> str | None:
        """None when ``flat`` lies in every range, else the first property outside, as text."""
        checks = (
            ("E", flat.E, self.E, 1e-9, "GPa"),
            ("density", flat.density, self.density, 1.0, "kg/m^3"),
            ("yield strength", flat.yield_strength, self.yield_strength, 1e-6, "MPa"),
        )
        for what, value, (lo, hi), scale, unit in checks:
            if value is None:  # a density not given: E and S_y identify the material
                continue
            if not lo <= value <= hi:
                return (
                    f"{what} = {value * scale:.4g} {unit} outside {lo * scale:.4g} to "
                    f"{hi * scale:.4g} {unit}"
                )
        return None


#: Low-carbon (mild) steel, the material of both built-in rate laws' constants: E, density and
#: S_y of plain carbon steels with up to about 0.25 % C (AISI 1006 to 1025, the paper's AISI 1010
#: flat: 200 GPa, 7870 kg/m^3, 305 MPa).
LOW_CARBON_STEEL = FittedFor("low-carbon (mild) steel", (190e9, 215e9), (7750.0, 7950.0),
                             (150e6, 450e6))  # fmt: skip

#: Each form of rate law and the SI unit of its constants ("1": a plain number).
RATE_CONSTANTS: dict[str, tuple[str, dict[str, str]]] = {
    "cowper-symonds": ("1 + (eps_dot/D)^(1/q)", {"D": "1/s", "q": "1"}),
    "johnson-cook": ("1 + C ln(eps_dot/rate0)", {"C": "1", "rate0": "1/s"}),
}
_FORMS = {name: tuple(units) for name, (_, units) in RATE_CONSTANTS.items()}
#: An example number of each constant in its unit (D, q: aluminium alloys as quoted by Jones).
RATE_EXAMPLES = {"D": "6500", "q": "4", "C": "0.03", "rate0": "1"}
_PLAIN = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def shortest(x: float) -> str:
    """The shortest text of ``x`` that reads back to the same float (``repr``, less a
    trailing ``.0``: ``6500``, ``40.43217``, ``1e-20``)."""
    return repr(float(x)).removesuffix(".0")


def constants_text(form: str, values: Mapping[str, object] | None = None, eq: str = " = ") -> str:
    """``D = 6500 1/s, q = 4``: the constants ``values`` of the law ``form`` (a float in its
    :func:`shortest` text; None: ``RATE_EXAMPLES``), each with its unit, in the form's order."""
    values = RATE_EXAMPLES if values is None else values
    return ", ".join(
        f"{k}{eq}{shortest(v) if isinstance(v := values[k], float) else v}"
        + ("" if unit == "1" else f" {unit}")
        for k, unit in RATE_CONSTANTS[form][1].items()
    )


def rate_constant(form: str, key: str, value: object, *, bare: bool = False) -> float:
    """The constant ``key`` of the rate law ``form`` in SI (unit: ``RATE_CONSTANTS``): a number
    in that unit, or text under the package's unit rules, ``units.magnitude`` (``"6500 1/s"``)
    or, with ``bare``, the command line's ``units.to_si`` (a bare ``"6500"`` is in the unit); a
    dimensionless constant is a plain number (``4``, ``"4"``). ValueError naming ``key``."""
    unit, example = RATE_CONSTANTS[form][1][key], RATE_EXAMPLES[key]
    if unit != "1" and not isinstance(value, bool):
        value = to_si(value, unit, name=key) if bare else magnitude(key, value, unit)
    elif isinstance(value, str) and _PLAIN.fullmatch(value.strip()):
        value = float(value)
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        what = "a plain number" if unit == "1" else f"a number in {unit} or text with its unit"
        example = example if unit == "1" else f"'{example} {unit}'"
        raise ValueError(f"{key} must be {what}, e.g. {example}, got {value!r}")
    return float(value)


def _check_form(name: str, parameters: Mapping[str, object]) -> None:
    """ValueError unless ``name`` is a form of rate law and ``parameters`` its constants."""
    if name not in _FORMS:
        raise ValueError(
            f"RateLaw name must be one of {tuple(_FORMS)} (the law's form), got {name!r}"
        )
    if set(parameters) != set(_FORMS[name]):
        raise ValueError(
            f"a {name!r} RateLaw takes the parameters {_FORMS[name]}, got {tuple(parameters)}"
        )


@dataclass(frozen=True)
class RateLaw:
    """A strain-rate law for the flat's yield strength: ``name`` (its form:
    ``"cowper-symonds"`` with D > 0 [1/s] and q > 0, or ``"johnson-cook"`` with C >= 0 and
    rate0 > 0 [1/s]), its ``parameters`` (SI), the keys of its sources (``RATE_REFERENCES``),
    a description and the materials its constants were ``fitted_for`` (None: the user's own
    constants, for the flat they give them for). ``factor(rate)`` is the multiplier k >= 1 at
    a strain rate [1/s]. ``RateLaw.custom`` builds a validated law from one's own constants."""

    name: str
    parameters: tuple[tuple[str, float], ...]
    reference_keys: tuple[str, ...]
    description: str
    fitted_for: FittedFor | None = None

    def __post_init__(self) -> None:
        p = dict(self.parameters)
        _check_form(self.name, p)
        if self.name == "cowper-symonds":
            check_positive("D", p["D"], "1/s")
            check_positive("q", p["q"])
        else:
            check_nonnegative("C", p["C"])
            check_positive("rate0", p["rate0"], "1/s")
        unknown = [k for k in self.reference_keys if k not in RATE_REFERENCES]
        if unknown:
            raise ValueError(
                f"reference key {unknown[0]!r} unknown; known: {tuple(RATE_REFERENCES)}"
            )

    @classmethod
    def custom(cls, name: str, description: str = "", **parameters: object) -> RateLaw:
        """A rate law of form ``name`` with one's own constants (validated), each a number in
        its unit or text with its unit (:func:`rate_constant`), e.g.
        ``RateLaw.custom("cowper-symonds", D="6500 1/s", q=4)`` (aluminium alloys as quoted by
        Jones, Structural Impact); no material check: the constants are the flat's."""
        _check_form(name, parameters)
        values = tuple(sorted((k, rate_constant(name, k, v)) for k, v in parameters.items()))
        text = description or f"{name}, user constants {constants_text(name, dict(values))}"
        return cls(name, values, (), text, None)

    def factor(self, rate: float) -> float:
        """The yield-strength multiplier k [1] at the strain rate ``rate`` [1/s]."""
        p = dict(self.parameters)
        if self.name == "cowper-symonds":
            return cowper_symonds(rate, p["D"], p["q"])
        return johnson_cook(rate, p["C"], p["rate0"])

    @property
    def text(self) -> str:
        """The law's name with its constants: ``"cowper-symonds (D = 40.4 1/s, q = 5)"``."""
        return f"{self.name} ({constants_text(self.name, dict(self.parameters))})"

    @property
    def label(self) -> str:
        """The law's name where it is the library's law of that name, else the name with its
        constants (``"cowper-symonds (D = 6500 1/s, q = 4)"``): what a result shows."""
        return self.name if RATE_LAWS.get(self.name) == self else self.text

    @property
    def references(self) -> tuple[Reference, ...]:
        """The law's sources (law, parameters, strain-rate estimate)."""
        return tuple(RATE_REFERENCES[k] for k in (*self.reference_keys, "tabor-1951"))


#: Cowper-Symonds, mild steel: D = 40.4 1/s, q = 5 (an upper estimate; module docstring).
COWPER_SYMONDS_MILD_STEEL = RateLaw(
    "cowper-symonds",
    (("D", 40.4), ("q", 5.0)),
    ("cowper-symonds-1957", "jones-1989"),
    "Cowper-Symonds, mild steel: 1 + (eps_dot / 40.4 1/s)^(1/5)",
    LOW_CARBON_STEEL,
)
#: Johnson-Cook rate term, 1006 steel: C = 0.022, eps_dot_0 = 1 1/s (a lower estimate).
JOHNSON_COOK_1006_STEEL = RateLaw(
    "johnson-cook",
    (("C", 0.022), ("rate0", 1.0)),
    ("johnson-cook-1983",),
    "Johnson-Cook rate term, 1006 steel: 1 + 0.022 ln(eps_dot / 1 1/s)",
    LOW_CARBON_STEEL,
)
#: The rate laws by name.
RATE_LAWS: dict[str, RateLaw] = {
    law.name: law for law in (COWPER_SYMONDS_MILD_STEEL, JOHNSON_COOK_1006_STEEL)
}


#: A ``rate`` text: a name, with its constants in brackets or without.
_RATE_TEXT = re.compile(r"\s*([a-z_-]+)\s*(?:\((.*)\))?\s*", re.DOTALL | re.IGNORECASE)


def get_rate_law(rate: object, name: str = "rate") -> RateLaw | None:
    """The rate law ``rate``: None for None or ``"none"``; a RateLaw itself; a library law by
    name (any case); or a form with its constants, ``RateLaw.custom`` of them, as ``--rate``
    takes it and a result prints it (``"cowper-symonds(D=6500 1/s, q=4)"``, or with spaces,
    ``"cowper-symonds (D = 6500 1/s, q = 4)"``; a bare number is in the constant's unit).
    ValueError naming ``name`` as the user gave it (the Python keyword ``rate``, ``--rate``)."""
    if rate is None or isinstance(rate, RateLaw):
        return rate
    match = _RATE_TEXT.fullmatch(rate) if isinstance(rate, str) else None
    key, inner = (match.group(1).lower(), match.group(2)) if match else ("", None)
    if key not in ("none", *RATE_LAWS) or (key == "none" and inner is not None):
        api = "; or None, or a RateLaw (RateLaw.custom: one's own constants)" * (name == "rate")
        example = f"cowper-symonds({constants_text('cowper-symonds', None, '=')})"
        raise ValueError(
            f"{name} must be one of {', '.join(('none', *RATE_LAWS))}, or a law with its "
            f'constants such as "{example}"{api}, got {rate!r}'
        )
    if inner is None:
        return None if key == "none" else RATE_LAWS[key]
    units, values, shown = RATE_CONSTANTS[key][1], {}, f"{name} {str(rate).strip()!r}"
    depth = list(accumulate((c == "(") - (c == ")") for c in inner))
    if depth and (min(depth) < 0 or depth[-1] != 0):
        raise ValueError(f"{shown}: unbalanced brackets; write the constants in one pair, e.g. "
                         f'"{key}({constants_text(key, None, "=")})"')  # fmt: skip
    takes = f"{shown}: {key} takes {', '.join(f'{k} [{u}]' for k, u in units.items())}"
    for item in inner.split(","):
        given, eq, text = (part.strip() for part in item.partition("="))
        known = {k.lower(): k for k in units}.get(given.lower())
        if not eq or not text or "=" in text or known is None or known in values:
            raise ValueError(f"{takes}, got {item.strip()!r}{' twice' * (known in values)}")
        try:  # "--rate D: '6500 m' has the wrong dimension", "--rate q must be a plain number"
            values[known] = rate_constant(key, known, text, bare=True)
        except ValueError as exc:
            raise ValueError(f"{name} {exc}") from None
    if set(values) != set(units):
        raise ValueError(f"{takes}, missing {', '.join(k for k in units if k not in values)}")
    try:
        return RateLaw.custom(key, "", **values)
    except ValueError as exc:  # "D must be > 0 1/s, got ..."
        raise ValueError(f"{name} {exc}") from None


def check_rate_flat(law: RateLaw, flat: Material) -> None:
    """ValueError when ``flat`` is not the material the rate law's constants were fitted for
    (``RateLaw.fitted_for``; a law with the user's own constants is not checked)."""
    if law.fitted_for is None:
        return
    why = law.fitted_for.mismatch(flat)
    if why is not None:
        raise ValueError(
            f"rate {law.name!r}: its constants are fitted for {law.fitted_for.name}, but the "
            f"flat {flat.name!r} has {why}; give the flat's own constants, e.g. "
            f"rate=RateLaw.custom({law.name!r}, ...)"
        )


def _order_turned(body: Material, flat: Material, flat_k: Material) -> bool:
    """Whether the rate-raised flat ``flat_k`` turns the order of the static pair: the flat
    yielded first and the body now would, or the body's S_y was above the flat's and is not
    above the raised one's."""
    if body_yields_first(body, flat):
        return False
    overtaken = flat.yield_strength < body.yield_strength <= flat_k.yield_strength
    return overtaken or body_yields_first(body, flat_k)


def rate_materials(body: Material, flat: Material, k: float) -> tuple[Material, Material]:
    """(body, flat) with the flat's yield strength multiplied by k >= 1.

    impactlab's contact pair takes the yield strength of the body that yields first
    (``materials.body_yields_first``: the smaller C(nu) S_y); a rate-raised flat can exceed the
    rod's static yield strength, but the rod is rate-sensitive too, so its static value is no
    cap: where the raised flat's S_y reaches the body's, or makes the body yield first, where
    the static pair had the flat yield first (:func:`_order_turned`), the body's yield strength
    is raised to ``rate_factor.body_margin`` (1.5 for equal Poisson's ratios) times the flat's
    (only the flat yields, as the measured dents say). A body that yields first already (a
    copper rod on steel) is left as it is, and so is every body at k = 1: a factor of 1 is the
    pair without a rate law. A yield strength
    at or above its E is refused (ValueError; ``rate_factor.RateLimit`` gives the largest k);
    the materials' plausibility warnings are not issued for these derived copies. The Brinell
    hardness (Brake's law) scales with the yield strength of the same material: hardness is a
    flow stress at Tabor's representative strain (H ~ 2.8 sigma_r; D. Tabor, The Hardness of
    Metals, 1951), so a rate factor on the flow stress is one on the hardness."""
    k = check_positive("k", k)
    with warnings.catch_warnings():  # derived, not given: "check the units" would mislead
        warnings.simplefilter("ignore", ImplausibleInputWarning)
        flat_k = dataclasses.replace(
            flat,
            name=f"{flat.name} x{k:.4g} (rate)",
            yield_strength=k * flat.yield_strength,
            brinell_hardness=k * flat.brinell_hardness,
        )
        if _order_turned(body, flat, flat_k):
            f = body_margin(body, flat) * flat_k.yield_strength / body.yield_strength
            body = dataclasses.replace(
                body,
                yield_strength=f * body.yield_strength,
                brinell_hardness=f * body.brinell_hardness,
            )
    return body, flat_k
