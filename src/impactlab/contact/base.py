"""Python side of the contact laws: a law builds a validated, compiled-ready ``ContactModel``."""

from __future__ import annotations

import math
import numbers
from abc import ABC, abstractmethod
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

from impactlab._html import law_html, law_repr
from impactlab._validation import check_array, check_finite, check_nonnegative, check_positive
from impactlab.contact import history_kernels as hk
from impactlab.contact import kernel_arrays as ka
from impactlab.contact import kernels as k
from impactlab.contact.curve_table import has_curves
from impactlab.contact.custom_parameters import note_custom
from impactlab.contact.names import Law
from impactlab.contact.ranges import (
    LawRange,
    critical_interference,
    law_extrapolated,
    law_range,
    range_limit,
)
from impactlab.materials import ContactPair
from impactlab.materials.core import brinell_text
from impactlab.references import Reference
from impactlab.units import is_quantity


def _scalar_like(value: Any) -> bool:
    """True for what may hold one law parameter: a number, a string or a scalar quantity."""
    if is_quantity(value):
        return np.ndim(value.magnitude) == 0
    return isinstance(value, numbers.Real | str | np.generic) or (
        isinstance(value, np.ndarray) and value.ndim == 0
    )


@dataclass(frozen=True)
class Parameter:
    """A law parameter with its default, unit and meaning (shown by ``impactlab laws``).

    A ``default`` of NaN means "taken from the contact pair"; ``default_note`` says how. The
    ``unit`` of a dimensionless parameter is ``"1"``, as everywhere in impactlab (``"-"``, an
    engineering mark, is read as it).
    """

    name: str
    default: float
    unit: str
    description: str
    default_note: str = ""

    def __post_init__(self) -> None:
        if self.unit == "-":
            object.__setattr__(self, "unit", "1")

    @property
    def default_text(self) -> str:
        """The default as shown to people (the note when it comes from the pair)."""
        if math.isnan(self.default):
            return self.default_note or "from the pair"
        return f"{self.default:g}"


@dataclass(frozen=True)
class UnloadingBranch:
    """Unloading from the maximum (delta_m [m], F_m [N]): Hertzian with radius R_r [m] about the
    residual depth delta_r [m]."""

    delta_m: float
    F_m: float
    delta_r: float
    R_r: float
    E_star: float

    def force(self, delta: Any) -> np.ndarray:
        """Unloading force [N] at interferences ``delta`` [m] (0 below delta_r)."""
        d = np.clip(np.asarray(delta, dtype=float) - self.delta_r, 0.0, None)
        return 4.0 / 3.0 * self.E_star * math.sqrt(self.R_r) * d**1.5

    def contact_radius(self, delta: Any) -> np.ndarray:
        """Contact radius [m] on the unloading branch: sqrt(R_r (delta - delta_r)), 0 below."""
        d = np.clip(np.asarray(delta, dtype=float) - self.delta_r, 0.0, None)
        return np.sqrt(self.R_r * d)

    def energy_returned(self) -> float:
        """Elastic energy recovered on unloading from delta_m to delta_r [J]."""
        d = self.delta_m - self.delta_r
        return 8.0 / 15.0 * self.E_star * math.sqrt(self.R_r) * d**2.5


@dataclass(frozen=True, eq=False)
class ContactModel:
    """A contact law with all its parameters fixed: what the impact engine consumes.

    ``law_id`` and ``params`` are the compiled representation (see ``contact.kernels``);
    ``details`` holds derived numbers for people (critical values, calibrated range, ...);
    ``references`` are the law's sources (``impactlab.references``); ``source`` says which
    data a tabulated law was built from ("" for the closed-form laws). The tabulated law's
    ``params`` carry its curves after slot NPARAM (``contact.curve_table``).
    """

    name: str
    law_id: int
    params: np.ndarray = field(repr=False)
    details: Mapping[str, float] = field(default_factory=dict, repr=False)
    references: tuple[Reference, ...] = field(default=(), repr=False)
    source: str = ""
    #: the contact pair a law's ``build`` made the model for (None: made by hand, or read back
    #: from a record); the engine refuses it for another pair (``dynamics.models``)
    pair: ContactPair | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        p = np.array(self.params, dtype=np.float64)
        if p.shape != (k.NPARAM,) and not (self.law_id == k.TABULATED and has_curves(p, k.NPARAM)):
            raise ValueError(f"params must have shape ({k.NPARAM},), got {p.shape}")
        p.setflags(write=False)
        object.__setattr__(self, "params", p)
        object.__setattr__(self, "details", dict(self.details))
        refs = tuple(self.references)
        if not refs:  # a model named after a registered law carries that law's sources
            refs = next((law.references for law in Law if law == self.name), ())
        object.__setattr__(self, "references", refs)

    @property
    def E_star(self) -> float:
        """Reduced modulus [Pa]."""
        return float(self.params[k.P_ESTAR])

    @property
    def radius(self) -> float:
        """Sphere (tip) radius [m]."""
        return float(self.params[k.P_R])

    @property
    def yield_onset(self) -> tuple[float, float]:
        """(delta_y [m], F_y [N]): the law's own first-yield criterion (inf, inf for Hertz).

        The loading curve may leave the elastic curve elsewhere: see ``switch_interference``.
        """
        return float(self.params[k.P_DY]), float(self.params[k.P_FY])

    @property
    def switch_interference(self) -> float:
        """Interference [m] where the loading curve leaves the elastic curve (inf for Hertz)."""
        return float(self.params[k.P_DSW])

    @property
    def max_interference(self) -> float:
        """Largest interference for which the law is valid [m] (a hard limit)."""
        return float(self.params[k.P_DLIM])

    @property
    def calibrated_max_interference(self) -> float:
        """Upper end of the law's range [m] for this pair: verified against FE where the
        pair's E*/S_y is covered, else the stand-in (advisory, inf if none;
        ``contact.ranges.range_limit``, capped at ``max_interference``).

        Beyond it the law is extrapolated; callers may warn, but it is not an error.
        """
        if "calibrated_max_interference" in self.details:
            return float(self.details["calibrated_max_interference"])
        if not 0 <= self.law_id < k.N_LAWS:
            return math.inf
        ratio = float(range_limit(self.law_id, self.params[: k.NPARAM]))
        return (
            math.inf
            if math.isinf(ratio)
            else min(ratio * self.critical_interference, self.max_interference)
        )

    @property
    def critical_interference(self) -> float:
        """Reference interference of the law's fitted range [m] (its first-yield interference;
        for Hertz the Jackson-Green delta_c of the pair): ``contact.ranges``."""
        return float(critical_interference(self.law_id, self.params))

    @property
    def fitted_range(self) -> LawRange:
        """The law's range: its stand-in with source and status, and its verified range per FE
        case (``LawRange.verified``; ``contact.ranges``)."""
        return law_range(self.name)

    def extrapolated(self, delta_max: Any) -> Any:
        """True where an impact reaching ``delta_max`` [m] leaves the law's range (verified
        against FE, else its stand-in; a bool, or a bool array for an array):
        ``contact.ranges.law_extrapolated``."""
        return law_extrapolated(self, delta_max)

    def in_calibrated_range(self, delta: Any) -> bool:
        """True when every interference in ``delta`` lies within the calibrated range."""
        return bool(np.all(np.asarray(delta, dtype=float) <= self.calibrated_max_interference))

    def check_interference(self, delta: Any) -> np.ndarray:
        """Array of ``delta`` [m] (numbers in m, a string with units or a pint Quantity);
        ValueError if any value is not a number, negative, NaN or past the validity limit."""
        d = check_array("delta", delta, "m")
        if not np.all(np.isfinite(d)):
            raise ValueError("delta must be finite")
        if np.any(d < 0.0):
            raise ValueError(f"delta must be >= 0 m, got min {float(d.min())!r}")
        if np.any(d > self.max_interference):
            raise ValueError(
                f"delta = {float(d.max())!r} m is outside the validity range of the {self.name!r} "
                f"law (delta <= {self.max_interference!r} m)"
            )
        return d

    def force(self, delta: Any) -> Any:
        """Loading force [N] at interferences ``delta`` [m]: a float (``numpy.float64``) for a
        scalar ``delta``, an array of its shape for an array."""
        d = self.check_interference(delta)
        flat = np.atleast_1d(d)
        return ka.loading_force_array(self.law_id, self.params, flat).reshape(d.shape)[()]

    def contact_radius(self, delta: Any) -> Any:
        """Contact radius [m] on the loading curve at interferences ``delta`` [m]: a float for a
        scalar ``delta``, an array of its shape for an array."""
        d = self.check_interference(delta)
        flat = np.atleast_1d(d)
        return ka.loading_contact_radius_array(self.law_id, self.params, flat).reshape(d.shape)[()]

    def unload(self, delta_m: float) -> UnloadingBranch:
        """The unloading branch after loading to ``delta_m`` [m]."""
        dm = float(self.check_interference(check_nonnegative("delta_m", delta_m, "m")))
        F_m, d_r, R_r = hk.turning_point(self.law_id, self.params, dm)
        return UnloadingBranch(dm, float(F_m), float(d_r), float(R_r), self.E_star)


class ContactLaw(ABC):
    """A registered normal contact law for a sphere (radius R) on a flat.

    Subclasses declare their :class:`Law` member (``law``), title, literature reference,
    validity and calibrated range, and turn a contact pair plus parameters into a
    ``ContactModel``. ``name``, ``law_id``, ``references`` and ``doi`` (of the defining paper)
    follow from ``law``.
    """

    law: ClassVar[Law]
    name: ClassVar[str]
    law_id: ClassVar[int]
    references: ClassVar[tuple[Reference, ...]]
    doi: ClassVar[str]
    title: ClassVar[str]
    reference: ClassVar[str]
    validity: ClassVar[str]
    parameters: ClassVar[tuple[Parameter, ...]] = ()

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        law = cls.__dict__.get("law")
        if law is not None:
            cls.name = law.value
            cls.law_id = law.law_id
            cls.references = law.references
            cls.doi = cls.references[0].doi

    def build(self, pair: ContactPair, radius: float, **params: float) -> ContactModel:
        """Validate ``params`` (unknown names are an error) and build the model for ``pair``.

        ``radius`` [m] is the radius of the sphere (rod tip) against the flat.
        """
        if not isinstance(pair, ContactPair):
            raise ValueError(f"pair must be a ContactPair, got {type(pair).__name__}")
        R = check_positive("radius", radius, "m")
        given = self.parameter_values(params)
        values = {q.name: given.get(q.name, float(q.default)) for q in self.parameters}
        p = np.full(k.NPARAM, np.nan)
        p[k.P_ESTAR] = pair.E_star
        p[k.P_R] = R
        p[k.P_SY] = pair.yield_strength
        p[k.P_NU] = pair.nu
        p[k.P_DLIM] = R
        details = self._fill(p, pair, values) or {}
        self._check_loading_curve(p, pair, published=values.get("published_switch", 0.0) == 1.0)
        model = ContactModel(self.name, self.law_id, p, details, self.references)
        note_custom(self, model, pair, R, given)
        object.__setattr__(model, "pair", pair)
        return model

    def parameter_values(self, params: Any) -> dict[str, float]:
        """The given law parameters ``params`` (a mapping of names to values) as floats in the
        parameters' units: a value is a number in its unit, or, for a parameter with a unit, a
        string with units or a pint Quantity; a 0/1 switch (``published_switch``) also True or
        False. ValueError for a non-mapping, an unknown name or a bad value (naming it)."""
        if not isinstance(params, Mapping):
            raise ValueError(
                f"law_params must be a mapping of parameter names to values, got {params!r}"
            )
        odd = {k: v for k, v in params.items() if not _scalar_like(v)}
        if odd:
            raise ValueError(
                f"law_params values must be numbers (or, for a parameter with a unit, strings "
                f"with units or pint Quantities), got {odd!r}"
            )
        known = {q.name: q for q in self.parameters}
        unknown = sorted(set(params) - set(known))
        if unknown:
            raise ValueError(
                f"unknown parameter(s) {unknown} for contact law {self.name!r}; "
                f"known: {sorted(known) or 'none'}"
            )
        values = {}
        for name, v in params.items():
            unit = known[name].unit
            if isinstance(v, bool | np.bool_) and name.endswith("_switch"):
                values[name] = float(v)  # a 0/1 switch: True and False say it best
                continue
            if unit == "kgf/mm^2":  # a Brinell number, as a material takes it: "105 HB"
                v = brinell_text(v)
            values[name] = check_finite(name, v, "" if unit in ("-", "1") else unit)
        return values

    def _check_loading_curve(self, p: np.ndarray, pair: ContactPair, *, published: bool) -> None:
        """ValueError unless the loading curve is finite and non-decreasing up to the hard limit
        (checked on a fine grid; a published force jump at the switch point is allowed)."""
        dlim = float(p[k.P_DLIM])
        refs = (float(p[k.P_DSW]), float(p[k.P_DY]))
        grids = [np.geomspace(dlim * 1e-9, dlim, 4000)]
        grids += [
            np.linspace(0.2 * ref, min(5.0 * ref, dlim), 2001)
            for ref in refs
            if math.isfinite(ref) and 0.0 < ref < dlim
        ]
        grid = np.unique(np.concatenate(grids))
        f = ka.loading_force_array(self.law_id, p, grid)
        bad = ~np.isfinite(f) | (f < 0.0)
        drop = np.diff(f) < -1e-12 * np.abs(f[1:])
        if published:
            dsw = float(p[k.P_DSW])
            drop &= ~((grid[:-1] < dsw) & (grid[1:] >= dsw))
        if bad.any() or drop.any():
            where = (
                float(grid[int(np.argmax(bad))]) if bad.any() else float(grid[int(np.argmax(drop))])
            )
            raise ValueError(
                f"the {self.name!r} law gives a {'non-finite' if bad.any() else 'decreasing'} "
                f"loading curve near delta = {where:.4g} m for this pair (E* = {pair.E_star:.4g}"
                f" Pa, S_y = {pair.yield_strength:.4g} Pa, nu = {pair.nu!r}, R = "
                f"{float(p[k.P_R])!r} m): the pair lies outside the law's range"
            )

    @abstractmethod
    def _fill(
        self, p: np.ndarray, pair: ContactPair, values: dict[str, float]
    ) -> dict[str, float] | None:
        """Fill the law-specific slots of ``p`` (and P_DY, P_FY, P_DSW, P_DLIM); validate
        ``values`` (NaN means "default from the pair"). Return derived numbers for ``details``
        (at least ``calibrated_max_interference`` where the law has one)."""

    @property
    def calibrated_range(self) -> str:
        """The verified range and the stand-in in one line (``contact.ranges.LawRange.text``)."""
        return law_range(self.law).text

    def __repr__(self) -> str:
        return law_repr(self.describe())

    def _repr_html_(self) -> str:
        return law_html(self.describe())

    def describe(self) -> dict[str, Any]:
        """The law's metadata as plain data (used by ``impactlab laws``)."""
        return {
            "name": self.name,
            "law_id": self.law_id,
            "title": self.title,
            "reference": self.reference,
            "doi": self.doi,
            "references": [
                {"key": r.key, "citation": r.citation, "doi": r.doi, "url": r.url}
                for r in self.references
            ],
            "validity": self.validity,
            "calibrated_range": self.calibrated_range,
            "fitted_range": law_range(self.law).describe(),
            "parameters": [
                {
                    "name": q.name,
                    "default": None if math.isnan(q.default) else q.default,
                    "default_text": q.default_text,
                    "unit": q.unit,
                    "description": q.description,
                }
                for q in self.parameters
            ],
        }
