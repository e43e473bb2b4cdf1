"""Result objects of the flexible drop (``simulate_drop``): immutable, SI units.

``DropResult``: every contact (``ContactRecord``), the dents (``DentRecord``), the totals a user
compares with an experiment, the energy balance and, if asked, the history (``DropHistory``).
Units and meanings: ``impactlab.dynamics.drop_result.UNITS``, from ``impactlab.schema`` (the
one table of impacts and drops: ``schema.unit(name)``, ``schema.description(name)``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import Any, ClassVar

from impactlab import schema
from impactlab._json import jsonable
from impactlab._version import __version__
from impactlab.contact.ranges import law_range
from impactlab.dynamics.dent import body_flattening, flattening_error, flattening_warning
from impactlab.dynamics.derived import DerivedOutputs
from impactlab.dynamics.drop_gravity import lifted_e_warning
from impactlab.dynamics.drop_history import DROP_HISTORY_COLUMNS, DropHistory
from impactlab.dynamics.drop_records import ContactDict, ContactRecord, DentRecord
from impactlab.dynamics.history import DentMap
from impactlab.dynamics.input_checks import check_dent_grid
from impactlab.dynamics.pint_fields import pint_quantities
from impactlab.dynamics.provenance import result_record
from impactlab.dynamics.result_display import BATCH_ONLY_NAMES, ResultDisplay, field_hint
from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages
from impactlab.materials import body_yields_first
from impactlab.references import Reference
from impactlab.references import dois as doi_list

__all__ = ["SUMMARY_FIELDS", "UNITS", "ContactRecord", "DentRecord", "DropHistory", "DropResult"]

#: Units of the DropResult fields (SI; "1" dimensionless), from ``impactlab.schema``.
UNITS: dict[str, str] = {
    name: schema.unit(name)
    for name in (
        "e", "e_raw", "velocity_out", "spin_out", "angle_out", "sequence_duration", "dent_depth",
        "delta_max", "scar_length", "sequence_sliding_length", "slip_path", "max_force",
        "normal_impulse", "tangential_impulse", "stick_time", "mu_apparent", "initial_energy",
        "rigid_kinetic_energy", "vibration_energy", "potential_energy", "work_normal",
        "work_friction", "work_damping", "energy_error", "next_end", "next_time", "n_steps",
        "n_contacts", "n_modes", "mu", "gravity", "angle", "velocity_in", "spin_in",
        "rate_factor", "strain_rate", "sequence_mean_force", "flags", "max_delta_ratio",
        "fitted_delta_ratio_max",
    )
} | {"n_dents": "1"}  # fmt: skip

#: The totals of a drop's summary, in order: ``print(result)``, ``_repr_html_`` and
#: ``impactlab drop`` show these (display units: ``impactlab._display``).
SUMMARY_FIELDS: tuple[str, ...] = (
    "n_contacts", "e", "e_raw", "dent_depth", "delta_max", "scar_length",
    "sequence_sliding_length", "sequence_duration", "sequence_mean_force", "max_force",
    "normal_impulse", "tangential_impulse", "spin_out", "mu_apparent", "vibration_energy",
    "energy_error", "rate_factor",
)  # fmt: skip


def _contact_text(c: ContactRecord) -> str:
    """One contact's row of ``print(result)``, its values named as ``ContactRecord``'s fields
    (the columns of ``impactlab drop`` and the keys of ``--json``), in display units."""
    return (
        f"start {c.start * 1e3:.4g} ms, duration {c.duration * 1e3:.3g} ms, delta_max "
        f"{c.delta_max * 1e6:.4g} um, normal_impulse {c.normal_impulse:.4g} N s"
    )


#: How a drop's warning begins where its rate factor did not converge (the drop is not ok).
RATE_DOUBT = "rate factor not converged: "


@dataclass(frozen=True, eq=False, repr=False)
class DropResult(DerivedOutputs, ResultDisplay):
    """The outcome of one drop (SI units: ``result.units``, each field's; ``print(result)``
    shows display units, um and ms). Immutable.

    It carries the summary attributes of ``ImpactResult`` (``impactlab.simulate`` returns it
    for a FlexibleRod) read for the whole sequence of contacts, those that mean something
    else for a sequence under names of their own (``schema.SEQUENCE_FIELDS``):

    - ``e``: minus the tip's rigid-body normal velocity after the last contact over the one
      before the first, with the gravity impulse of the sequence removed (as a ballistic fit
      of marker data would remove it; ``e_raw`` keeps it); one bounce of the tip only when
      the sequence holds the tip's contacts alone and e >= 0 (else OTHER_END, below);
    - ``dent_depth``: the tip's final dent depth, the permanent depth of its deepest dent
      (equal to ``dent().max_depth``, whatever bounds the caps' widths: ``DentMap.note``; the
      other end's dents, when it touches, are in ``dents``; an impact's ``delta_p`` is that
      of one unloading);
    - ``sequence_sliding_length``: the tip's total slip, the sum over its contacts of their
      ``sliding_length``, int v_t dt (signed, as ImpactResult's ``sliding_length`` of one
      contact; ``contacts[i].sliding_length`` is that of contact i);
      ``scar_length``: the x-extent of the mark the tip left over all its contacts (where the
      tip lands twice on separate dents, ``stop="flight"``, from the first one's near edge to
      the last one's far edge, the unmarked flat between them included; each dent's extent:
      ``dents``, x_min to x_max); ``slip_path``: the sum of int |v_t| dt;
    - ``sequence_duration``: first touch to last separation (flights between contacts
      included; an impact's ``duration`` is one contact's);
    - ``sequence_mean_force``: total normal impulse / sequence_duration (the paper's
      F_mean = P_n / T read over the sequence);
    - ``delta_max``, ``max_force``: the largest interference and normal force of any contact;
    - ``flags`` / ``warnings`` / ``ok``: as ImpactResult's (``impactlab.flags``): ENERGY_GAIN
      when the energy after the last contact (rigid kinetic + vibration + potential) exceeds
      the initial one beyond the tolerance of the rigid engine's criterion
      (``impactlab.flags.ENERGY_GAIN_RTOL_FACTOR`` rtol + ``ENERGY_ROUNDOFF``, relative to
      E0 + the final kinetic, vibration and |potential| energy), GRAVITY_DOMINATED when
      m g sequence_duration exceeds ``GRAVITY_IMPULSE_RATIO`` of the total normal impulse, or
      when the gravity impulse removed from e alone lifts it above 1 (e_raw not above 1, no
      energy gained: ``drop_gravity.e_lifted_by_gravity``; its warning says so),
      OTHER_END when the other end touched the flat in the run (gravity-dominated or not) or,
      unless gravity dominates, e < 0 (the tip still approaches the flat after its last
      contact); GRAVITY_DOMINATED is judged on the tip's sequence (its contacts until
      ``stop="sequence"`` would end: before the other end's first touch and before the tip's
      return after a clear flight);
      LAW_EXTRAPOLATED when the largest interference of the sequence left the law's fitted
      range (``impactlab.contact.ranges``; ``max_delta_ratio`` = delta_max / delta_ref, the
      law's own reference interference, ``LawRange.reference``: Jackson-Green's delta_c, or
      delta_y for Kogut-Komvopoulos, Brake, Thornton; and the upper end of the law's range in
      that ratio, ``fitted_delta_ratio_max``, verified against FE or a
      stand-in: ``fitted_range_status``, ``contact.ranges.range_status``; in one line, shown
      with the summary: ``law_range``, ``contact.range_note``);
    - ``references`` / ``dois()``: the sources used.

    ``stop="flight"`` integrates through the other end's impacts until the rod flies off
    (``next_end`` -1): "the last contact" is then the last of either end,
    ``sequence_duration`` spans
    every flight between the ends' impacts, and ``e`` (gravity removed over all of it) is a
    number of the whole flight, no coefficient of restitution (it can exceed 1); OTHER_END
    says so, and GRAVITY_DOMINATED, read on the tip's sequence, is not set by the flight.

    Velocities and spin are those of the floating frame after the last contact. Energy balance
    (``energy_balance``): rigid kinetic + vibration + potential - initial = work_normal +
    work_friction + work_damping, to ``energy_error`` of the initial energy (the largest over
    every step, through every contact and flight); a balance, that or the residual of these
    terms, worse than rtol promises is refused (``drop_checks.check_energy_balance``).

    The names before 0.3 of the renamed totals (``duration``, ``delta_p``, ``sliding_length``,
    ``mean_force``: ``schema.RENAMED_DROP_FIELDS``) read the new ones with a DeprecationWarning,
    as attributes and as ``to_dict()`` keys. ``print(result)``, ``_repr_html_`` and
    ``impactlab drop`` show ``summary()`` (``dynamics.result_display``, as an impact's).
    """

    #: Old name -> new name of the renamed totals (``schema.RENAMED_DROP_FIELDS``).
    RENAMED: ClassVar[dict[str, str]] = schema.RENAMED_DROP_FIELDS
    REPR_FIELDS: ClassVar[tuple[str, ...]] = (
        "body", "law", "friction", "n_contacts", "e", "dent_depth", "sequence_duration",
    )  # fmt: skip
    BATCH_ONLY: ClassVar[Mapping[str, str]] = BATCH_ONLY_NAMES

    contacts: tuple[ContactRecord, ...]
    dents: tuple[DentRecord, ...]
    n_contacts: int
    e: float
    e_raw: float
    velocity_out: tuple[float, float]
    spin_out: float
    angle_out: float
    sequence_duration: float
    dent_depth: float
    delta_max: float
    scar_length: float
    sequence_sliding_length: float
    slip_path: float
    max_force: float
    normal_impulse: float
    tangential_impulse: float
    stick_time: float
    mu_apparent: float
    initial_energy: float
    rigid_kinetic_energy: float
    vibration_energy: float
    potential_energy: float
    work_normal: float
    work_friction: float
    work_damping: float
    energy_error: float
    next_end: int
    next_time: float
    n_steps: int
    body: str
    n_modes: int
    law: str
    friction: str
    mu: float
    gravity: float
    angle: float
    velocity_in: tuple[float, float]
    spin_in: float
    rate: str | None = None
    rate_factor: float = 1.0
    strain_rate: float = math.nan
    flags: ResultFlag = ResultFlag.NONE
    max_delta_ratio: float = math.nan
    fitted_delta_ratio_max: float = math.inf
    fitted_range_status: str | None = None
    #: the law's range for the pair in one line (``contact.range_note``; None: unknown law)
    law_range: str | None = None
    history: DropHistory | None = field(default=None, repr=False)
    references: tuple[Reference, ...] = field(default=(), repr=False)
    #: what ``simulate`` was given: the source of ``input`` (``dynamics.provenance``)
    _call: tuple[Any, ...] | None = field(default=None, repr=False, compare=False)
    #: the contact law the drop ran (law id, SI parameters, its rate factor included)
    _law: tuple[int, Any] | None = field(default=None, repr=False, compare=False)
    #: GRAVITY_DOMINATED set by e > 1 through the removed gravity impulse alone
    #: (``drop_gravity.e_lifted_by_gravity``; m g T within 0.1 of the normal impulse)
    _e_lifted: bool = field(default=False, repr=False, compare=False)
    #: the rate factor's doubt: why its self-consistent iteration did not converge ("": it did)
    _rate_doubt: str = field(default="", repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "flags", ResultFlag(int(self.flags)))

    @property
    def n_dents(self) -> int:
        """The number of dents the drop left on the flat, ``len(dents)`` (a contact on a dent
        already made adds none; ``simulate_drops``' column of the same name)."""
        return len(self.dents)

    @property
    def sequence_mean_force(self) -> float:
        """Total normal impulse over the sequence_duration (first touch to last separation)
        [N]."""
        return self.normal_impulse / self.sequence_duration

    def __getattr__(self, name: str) -> Any:
        new = self.RENAMED.get(name)
        if new is not None:
            schema.warn_renamed(name, new, "DropResult field")
            return getattr(self, new)
        try:  # a derived output (schema.register_output), else no attribute
            return super().__getattr__(name)
        except AttributeError as error:  # a batch's column name: where this result holds it
            raise field_hint(self, name, error) from None

    def dent(self, *, nx: int = 241, ny: int = 121, margin: float = 0.15) -> DentMap:
        """The tip's predicted dent over all its contacts as a height map (SI;
        ``dynamics.drop_dent``, the model of ``ImpactResult.dent``); needs the history. nx, ny:
        grid points (integers >= 3); margin: relative padding (>= 0)."""
        from impactlab.dynamics.drop_dent import drop_dent

        nx, ny, margin = check_dent_grid(nx, ny, margin)
        clause = self._flattening()
        if clause and self.history is not None:
            raise flattening_error(clause)
        return drop_dent(self, nx=nx, ny=ny, margin=margin)

    @property
    def body_yields_first(self) -> bool | None:
        """True when the rod's material yields before the flat's
        (``materials.body_yields_first``; with a rate law as without: the raised flat keeps
        the static pair's order, ``contact.rate.rate_materials``): ``dent_depth`` and the
        ``dents`` are then the rod's permanent flattening and the flat stays elastic
        (``warnings`` says so; ``dent()`` refuses); None for a drop that ``simulate`` did not
        return."""
        if self._call is None:
            return None
        return body_yields_first(self._call[0].material, self._call[1])

    def _flattening(self) -> str:
        """``dynamics.dent.body_flattening`` of this drop (``""``: the flat yields first)."""
        if self._call is None or not self.body_yields_first:
            return ""
        depth = max([self.dent_depth, *(d.delta_p for d in self.dents)])
        what = "dent_depth (and each of dents' delta_p)" if self.dents else "dent_depth"
        return body_flattening(self._call[0].material, self._call[1], depth, what)

    @property
    def extrapolated(self) -> bool:
        """True when a contact of the drop left the law's range (verified against
        FE, else its stand-in)."""
        return ResultFlag.LAW_EXTRAPOLATED in self.flags

    @property
    def warnings(self) -> tuple[str, ...]:
        """One explanatory sentence per flag (``impactlab.flags.messages``; GRAVITY_DOMINATED
        set by e > 1 alone: ``drop_gravity.lifted_e_warning``), then, when the rod yields first
        and left a permanent interference, the advisory one that it is the rod's flattening
        (``dynamics.dent.body_flattening``); ``()`` if none."""
        how_far = (self.max_delta_ratio, self.fitted_delta_ratio_max)
        status, reference = self.fitted_range_status, "delta_c"
        try:
            record = law_range(self.law)
            status, reference = status or record.status, record.reference
        except ValueError:  # a custom law
            pass
        flags = self.flags & ~ResultFlag.GRAVITY_DOMINATED if self._e_lifted else self.flags
        said = messages(flags, extrapolation=how_far, status=status, reference=reference)
        if self._e_lifted:  # in bit order: ENERGY_GAIN (1) is never set with it
            said = (lifted_e_warning(self.e, self.e_raw), *said)
        if self._rate_doubt:
            said = (*said, RATE_DOUBT + self._rate_doubt)
        clause = self._flattening()
        return (*said, flattening_warning(clause)) if clause else said

    @property
    def ok(self) -> bool:
        """True unless a flag says the totals are not meaningful (as ImpactResult's:
        LAW_EXTRAPOLATED, an advisory flag, leaves it True) or the rate factor's
        self-consistent iteration did not converge (``warnings`` says how far)."""
        return int(self.flags) & ~ADVISORY_FLAGS == 0 and not self._rate_doubt

    @property
    def energy_balance(self) -> dict[str, float]:
        """The terms of the energy balance after the last contact [J] and its ``residual``
        (rigid kinetic + vibration + potential - initial - works)."""
        terms = {
            "initial": self.initial_energy,
            "rigid_kinetic": self.rigid_kinetic_energy,
            "vibration": self.vibration_energy,
            "potential": self.potential_energy,
            "work_normal": self.work_normal,
            "work_friction": self.work_friction,
            "work_damping": self.work_damping,
        }
        lhs = self.rigid_kinetic_energy + self.vibration_energy + self.potential_energy
        works = self.work_normal + self.work_friction + self.work_damping
        terms["residual"] = lhs - self.initial_energy - works
        return terms

    def dois(self) -> tuple[str, ...]:
        """DOIs of the sources this result used, in order, without repeats."""
        return doi_list(self.references)

    def to_pint(self, registry: Any = None) -> dict[str, Any]:
        """The totals (``UNITS``) as pint Quantities in SI (``registry``: yours)."""
        return pint_quantities(self, UNITS, registry)

    @property
    def input(self) -> dict[str, Any] | None:
        """What was simulated, JSON-ready, as ``ImpactResult.input`` (with the drop's options);
        None for a drop that ``impactlab.simulate`` did not return."""
        return result_record(self)

    def to_dict(self, *, include_history: bool = False) -> dict[str, Any]:
        """JSON-ready values: scalars (``body_yields_first`` too), ``contacts`` and ``dents`` as
        lists of dicts, the energy balance, the references' citations; the history as lists of
        columns if asked. A key before 0.3 (``"duration"``, ...; a contact's ``"slip"``) reads
        its new one with a DeprecationWarning."""
        d: dict[str, Any] = {}
        for f in fields(self):
            if f.name in ("history", "references", "contacts", "dents") or f.name[0] == "_":
                continue
            d[f.name] = getattr(self, f.name)
        d["body_yields_first"] = self.body_yields_first
        d["contacts"] = [c.__dict__ for c in self.contacts]
        d["dents"] = [x.__dict__ for x in self.dents]
        d["n_dents"] = self.n_dents
        d["extrapolated"] = self.extrapolated
        d["flags"] = int(self.flags)
        d["ok"] = bool(self.ok)
        d["warnings"] = list(self.warnings)
        d["sequence_mean_force"] = self.sequence_mean_force
        d["energy_balance"] = self.energy_balance
        d |= self.derived()  # schema.register_output
        d["references"] = [str(r) for r in self.references]
        d["impactlab_version"] = __version__
        d["input"] = self.input
        if include_history and self.history is not None:
            d["history"] = {k: self.history[k].tolist() for k in DROP_HISTORY_COLUMNS}
        out = schema.RenamedDropKeys(jsonable(d))
        out["contacts"] = [ContactDict(c) for c in out["contacts"]]  # "slip": sliding_length
        return out

    def summary(self) -> dict[str, Any]:
        """The set-up, as an impact's summary begins (``body``: the body with its sizes and
        material, and ``flat``, when ``simulate`` or ``simulate_drop`` made the result, else
        the body's model; law, friction, mu, ``angle``, ``velocity_in``, ``spin_in``, rate),
        the totals (``SUMMARY_FIELDS``, SI) and the names of the flags."""
        call = self._call  # what the drop was given (provenance)
        data: dict[str, Any] = {"body": self.body if call is None else str(call[0])}
        if call is not None:
            data["flat"] = call[1].name
        data |= {"law": self.law, "friction": self.friction, "mu": self.mu}
        data |= {"angle": self.angle, "velocity_in": self.velocity_in, "spin_in": self.spin_in}
        data["rate"] = self.rate or "none"
        data |= {k: getattr(self, k) for k in SUMMARY_FIELDS}
        if self.law_range is not None:
            data["law_range"] = self.law_range
        data |= self.flag_rows(self.flags)
        return data

    def display_units(self) -> dict[str, str]:
        """The SI unit of each numeric field of ``summary()`` (``UNITS``), from which
        ``print(result)`` chooses its display units (um, ms); the units: ``units``."""
        return UNITS

    def detail_rows(self) -> list[tuple[str, str, str]]:
        """One row per contact (``print`` and ``_repr_html_``)."""
        return [
            (f"contact {i + 1} (end {c.end})", _contact_text(c), "")
            for i, c in enumerate(self.contacts)
        ]
