"""Result objects of the impact engine: immutable, SI units, computed once.

Nothing here changes a simulation: results are frozen dataclasses holding read-only arrays, and
derived products (the dent map, data frames) are computed from them on request.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab import schema
from impactlab._json import jsonable
from impactlab._version import __version__
from impactlab.contact.range_note import range_note
from impactlab.contact.ranges import (
    extrapolation,
    extrapolation_flags,
    range_status,
    reference_name,
)
from impactlab.dynamics.dent import (
    body_flattening,
    dent_map,
    flattening_error,
    flattening_warning,
)
from impactlab.dynamics.derived import DerivedOutputs
from impactlab.dynamics.history import HISTORY_UNITS, DentMap, History, readonly_copy
from impactlab.dynamics.input_checks import check_dent_grid
from impactlab.dynamics.kernels.layout import HISTORY_FIELDS
from impactlab.dynamics.pint_fields import pint_quantities
from impactlab.dynamics.provenance import result_record
from impactlab.dynamics.result_display import ResultDisplay, field_hint
from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages
from impactlab.materials import body_yields_first
from impactlab.references import Reference
from impactlab.references import dois as doi_list

__all__ = [
    "HISTORY_UNITS",
    "SUMMARY_FIELDS",
    "UNITS",
    "DentMap",
    "History",
    "ImpactResult",
    "assemble_result",
    "pint_quantities",
    "readonly_copy",
]

#: Units of the ImpactResult scalar fields (from ``impactlab.schema``).
UNITS: dict[str, str] = {
    name: schema.unit(name)
    for name in (
        "e",
        "e_energy",
        "velocity_out",
        "spin_out",
        "delta_max",
        "delta_p",
        "sliding_length",
        "contact_travel",
        "duration",
        "mean_force",
        "max_force",
        "normal_impulse",
        "tangential_impulse",
        "energy_dissipated",
        "stick_time",
        "vn_in",
        "vt_in",
        "vn_out",
        "vt_out",
        "angle_out",
        "t_max",
        "angle",
        "velocity_in",
        "spin_in",
        "mu",
        "max_delta_ratio",
    )
}

#: The fields of an impact's summary, in order: ``print(result)``, ``_repr_html_`` and
#: ``impactlab simulate`` show these (display units: ``impactlab._display``).
SUMMARY_FIELDS: tuple[str, ...] = (
    "law", "friction", "mu", "angle", "velocity_in", "spin_in", "regime", "e", "e_energy",
    "velocity_out", "spin_out", "angle_out", "delta_max", "delta_p", "sliding_length",
    "contact_travel", "duration", "t_max", "stick_time", "max_force", "mean_force",
    "normal_impulse", "tangential_impulse", "energy_dissipated", "vn_in", "vt_in", "vn_out",
    "vt_out", "n_steps", "max_delta_ratio",
)  # fmt: skip


@dataclass(frozen=True, eq=False, repr=False)
class ImpactResult(DerivedOutputs, ResultDisplay):
    """The outcome of one impact (SI units). Computed once; immutable.

    Every value is SI: the unit of each field is in ``result.units`` (the module's ``UNITS``
    and the derived outputs' units), its meaning in ``impactlab.schema.description(name)``;
    ``print(result)`` shows them in display units (um, ms). ``velocity_in`` and
    ``velocity_out`` are pairs (vx, vy): a batch's ``vx_out`` is ``velocity_out[0]`` here, its
    ``vx``, ``vy`` and ``spin`` are ``velocity_in`` and ``spin_in``. ``references`` are the
    sources the computation used; ``dois()`` their DOIs. ``print(result)``, ``_repr_html_``
    and ``impactlab simulate`` show ``summary()`` (``dynamics.result_display``, as a drop's).

    Sign conventions: x points from the tip towards the centre-of-mass side, y up, spin
    counter-clockwise positive. ``sliding_length`` is the integral of the slip velocity of the
    body point at the contact (negative when the tip slides towards -x, as in the paper's
    tables); ``contact_travel`` is the displacement of the contact point along the flat.
    """

    e: float
    e_energy: float
    velocity_out: tuple[float, float]
    spin_out: float
    delta_max: float
    delta_p: float
    sliding_length: float
    contact_travel: float
    duration: float
    mean_force: float
    max_force: float
    normal_impulse: float
    tangential_impulse: float
    energy_dissipated: float
    stick_time: float
    regime: str
    law: str
    friction: str
    mu: float
    angle: float
    velocity_in: tuple[float, float]
    spin_in: float
    vn_in: float
    vt_in: float
    vn_out: float
    vt_out: float
    angle_out: float
    t_max: float
    n_steps: int
    flags: ResultFlag = ResultFlag.NONE
    history: History | None = field(default=None, repr=False)
    references: tuple[Reference, ...] = field(default=(), repr=False)
    _law_id: int = field(default=-1, repr=False)
    _law_params: np.ndarray | None = field(default=None, repr=False)
    #: What ``simulate`` was given, checked (body, flat, law, law_params, gravity [m/s^2],
    #: constant_angle, rtol, drop options): the source of ``input`` (``dynamics.provenance``).
    _call: tuple[Any, ...] | None = field(default=None, repr=False, compare=False)

    def __getattr__(self, name: str) -> Any:
        try:  # a derived output (schema.register_output), else no attribute
            return super().__getattr__(name)
        except AttributeError as error:  # a batch's column name: where this result holds it
            raise field_hint(self, name, error) from None

    def __post_init__(self) -> None:
        # the engine writes the bitmask as a float; LAW_EXTRAPOLATED from contact.ranges
        extra = extrapolation_flags(self._law_id, self._law_params, self.delta_max)
        object.__setattr__(self, "flags", ResultFlag(int(self.flags) | extra))

    max_delta_ratio = property(
        lambda self: extrapolation(self._law_id, self._law_params, self.delta_max)[0],
        doc="delta_max / delta_ref of the impact's law and pair: the law's own reference "
        "interference (LawRange.reference: Jackson-Green's delta_c, or delta_y for "
        "Kogut-Komvopoulos, Brake, Thornton); NaN if unknown (contact.ranges).",
    )
    body = property(
        lambda self: None if self._call is None else str(self._call[0]),
        doc="The body simulated, described as ``print`` shows it (a drop's ``body`` too); None "
        "for a result ``simulate`` did not make. The object: ``rerun(result.input)``.",
    )
    flat = property(
        lambda self: None if self._call is None else str(self._call[1].name),
        doc="The flat's material by name, as ``print`` shows it; None as ``body``.",
    )
    extrapolated = property(lambda self: ResultFlag.LAW_EXTRAPOLATED in self.flags,
                            doc="True when the impact left the law's range.")  # fmt: skip
    law_range = property(
        lambda self: range_note(self._law_id, self._law_params),
        doc="The law's range for this pair in one line: verified against FE (up to what), or "
        "unverified (E*/S_y outside the FE cases) and the stand-in (contact.range_note).",
    )

    @property
    def warnings(self) -> tuple[str, ...]:
        """One explanatory sentence per flag (``impactlab.flags.messages``), then, when the
        impacting body yields first and delta_p > 0, the advisory one that delta_p is the
        body's flattening (``dynamics.dent.body_flattening``); ``()`` if none."""
        how_far = extrapolation(self._law_id, self._law_params, self.delta_max)
        status = self.fitted_range_status
        reference = reference_name(self._law_id)
        said = messages(self.flags, extrapolation=how_far, status=status, reference=reference)
        clause = self._flattening()
        return (*said, flattening_warning(clause)) if clause else said

    @property
    def body_yields_first(self) -> bool | None:
        """True when the impacting body's material yields before the flat's
        (``materials.body_yields_first``): delta_p is then the body's permanent flattening and
        the flat stays elastic (``warnings`` says so; ``dent()`` refuses); None for a result
        that ``simulate`` did not return."""
        call = getattr(self, "_call", None)
        return None if call is None else body_yields_first(call[0].material, call[1])

    def _flattening(self) -> str:
        """``dynamics.dent.body_flattening`` of this impact (``""``: the flat yields first)."""
        if not self.body_yields_first:
            return ""
        call = self._call
        assert call is not None  # body_yields_first is None without it
        return body_flattening(call[0].material, call[1], self.delta_p, "delta_p")

    @property
    def ok(self) -> bool:
        """True unless a flag says the impact measures are not meaningful (a result exists only
        for a successful integration); ``ADVISORY_FLAGS`` (LAW_EXTRAPOLATED) leave it True."""
        return (int(self.flags) & ~ADVISORY_FLAGS) == 0

    @property
    def fitted_delta_ratio_max(self) -> float:
        """The upper end of the law's range for the pair, in delta / delta_ref (as
        ``max_delta_ratio``; verified against FE, else its stand-in; inf: none), as
        ``DropResult.fitted_delta_ratio_max``."""
        return float(extrapolation(self._law_id, self._law_params, self.delta_max)[1])

    @property
    def fitted_range_status(self) -> str | None:
        """How the law's range for the pair is known (``contact.ranges.range_status``: verified
        against FE, or its stand-in; None: not known), as ``DropResult.fitted_range_status``."""
        return range_status(self._law_id, self._law_params)

    def to_dict(self, *, include_history: bool = False) -> dict[str, Any]:
        """Scalar fields as a plain dict (with ``max_delta_ratio``, ``fitted_delta_ratio_max``,
        ``fitted_range_status``, ``extrapolated`` and ``body_yields_first``, as a drop's;
        ``flags`` as an int, ``warnings`` as a list; history as lists of columns if asked). A
        sphere has no ``angle`` and ``angle_out`` (left out, as by ``impactlab simulate --json``
        and ``summary()``; its ``input`` records ``angle`` as None). Strict JSON, as a drop's:
        a value that is NaN or infinite (``fitted_delta_ratio_max`` of a law without a verified
        range) is None."""
        d: dict[str, Any] = {}
        for name in self.__dataclass_fields__:
            if name.startswith("_") or name in ("history", "references"):
                continue
            v = getattr(self, name)
            if name in ("angle", "angle_out") and isinstance(v, float) and math.isnan(v):
                continue  # a sphere's (strict JSON has no NaN)
            d[name] = list(v) if isinstance(v, tuple) else v
        d["max_delta_ratio"] = self.max_delta_ratio
        d["fitted_delta_ratio_max"] = self.fitted_delta_ratio_max
        d["fitted_range_status"] = self.fitted_range_status
        d["extrapolated"] = self.extrapolated
        d["law_range"] = self.law_range
        d["body_yields_first"] = self.body_yields_first
        d["flags"] = int(self.flags)
        d["ok"] = bool(self.ok)
        d["warnings"] = list(self.warnings)
        d |= self.derived()  # schema.register_output
        d["impactlab_version"] = __version__
        d["input"] = self.input
        if include_history and self.history is not None:
            d["history"] = {k: self.history[k].tolist() for k in HISTORY_FIELDS}
        return jsonable(d)

    def to_pint(self, registry: Any = None) -> dict[str, Any]:
        """The scalar fields (and ``max_delta_ratio``) as pint Quantities in SI, e.g.
        ``r.to_pint()["delta_p"].to("um")``; ``registry``: your pint registry (default
        ``impactlab.units.registry()``). A sphere has no ``angle`` and ``angle_out`` (left
        out, as by ``to_dict()``)."""
        units = {**UNITS, "max_delta_ratio": "1"}
        for name in ("angle", "angle_out"):
            if math.isnan(getattr(self, name)):  # a sphere's
                del units[name]
        return pint_quantities(self, units, registry)

    @property
    def input(self) -> dict[str, Any] | None:
        """What was simulated, JSON-ready: body, materials, flat, law and its parameters,
        friction, mu, angle, velocity, spin, gravity, tolerance and the impactlab version
        (``impactlab.dynamics.provenance``); ``impactlab.rerun(result.to_dict())`` runs it
        again. None for a result that ``simulate`` did not return."""
        return result_record(self)

    def dois(self) -> tuple[str, ...]:
        """DOIs of the sources this result used (contact law, friction model if mu > 0, the
        integrator), in order, without repeats."""
        return doi_list(self.references)

    def summary(self) -> dict[str, Any]:
        """What was simulated (``body``, ``flat``: their descriptions, when ``simulate`` made
        the result), the summary's fields (``SUMMARY_FIELDS``, SI; no angles for a sphere), the
        law's range (``law_range``, when the law is known) and the names of the flags."""
        call = getattr(self, "_call", None)  # what simulate() was given (provenance)
        data = {} if call is None else {"body": str(call[0]), "flat": call[1].name}
        data |= {k: getattr(self, k) for k in SUMMARY_FIELDS}
        for k in ("angle", "angle_out"):
            if not np.isfinite(data[k]):
                del data[k]  # a sphere
        if self.law_range is not None:
            data["law_range"] = self.law_range
        data |= self.flag_rows(self.flags)
        return data

    REPR_FIELDS = ("law", "friction", "e", "delta_p", "sliding_length", "duration")

    def display_units(self) -> dict[str, str]:
        """The SI unit of each numeric field of ``summary()`` (``UNITS``), from which
        ``print(result)`` chooses its display units (um, ms); the units: ``units``."""
        return UNITS

    def dent(self, *, nx: int = 241, ny: int = 121, margin: float = 0.15) -> DentMap:
        """The predicted permanent dent as a height map (model: docs/engine/index.md, "Dent").

        nx, ny : grid points along and across the impact plane (integers >= 3); margin :
        relative padding (>= 0). ValueError when the impacting body yields first and delta_p
        > 0 (``body_yields_first``): delta_p is the body's flattening, the flat has no dent.
        """
        nx, ny, margin = check_dent_grid(nx, ny, margin)
        if self.history is None or self._law_params is None:
            raise ValueError("dent() needs the history: run simulate(..., history=True)")
        clause = self._flattening()
        if clause:
            raise flattening_error(clause)
        h = self.history
        surface = dent_map(
            self._law_id, self._law_params, h.penetration, h.contact_x, nx=nx, ny=ny, margin=margin
        )
        return DentMap(*surface)


def assemble_result(values: dict[str, Any]) -> ImpactResult:
    """``ImpactResult(**values)`` without the generated ``__init__`` (``dynamics.outcome``):
    ``values`` holds every field in field order, ``flags`` the ``ResultFlag`` that
    ``__post_init__`` would make (the engine's bits and LAW_EXTRAPOLATED)."""
    result = object.__new__(ImpactResult)
    result.__dict__.update(values)
    return result
