"""The one table of result fields: name, SI unit and meaning of every engine output, history
column and derived result field.

Everything that prints or stores a result field's unit or description reads it from here (the
compiled engine's output layout, ``ImpactResult``/``BatchResult``, sweep stores, the CLI).
Units are SI and spelled one way, parseable by pint: ``"m"``, ``"m/s"``, ``"rad"``,
``"rad/s"``, ``"N"``, ``"N s"``, ``"J"``, ``"s"``, and ``"1"`` for dimensionless values.

A flexible drop's history and its sequence totals use the same names where they mean the same
quantity (per end of the rod: ``end_column``, ``"normal_force_0"``), names of their own where
they do not (``SEQUENCE_FIELDS``); the names before 0.3 read the same data with a
DeprecationWarning (``RENAMED_DROP_HISTORY``, ``RENAMED_DROP_FIELDS``).

To add an engine output: append a ``Field`` to ``OUTPUT_FIELDS`` (the order is the column order
of the engine's ``out`` array, so append, never insert) and fill it in
``impactlab.dynamics.core.driver`` (a recompilation). To add a field computed from the engine's
outputs, without touching the compiled engine: ``register_output`` (a derived output; it appears
in ``ImpactResult``, ``BatchResult``, ``DropResult`` and sweep stores, see
docs/architecture.md, "An output field").
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

__all__ = [
    "DERIVED_FIELDS",
    "DROP_FIELDS",
    "DROP_HISTORY_FIELDS",
    "END_SUFFIXES",
    "FIELDS",
    "HISTORY_FIELDS",
    "OUTPUT_FIELDS",
    "RENAMED_DROP_FIELDS",
    "RENAMED_DROP_HISTORY",
    "RESULT_FIELDS",
    "SEQUENCE_FIELDS",
    "DerivedField",
    "Field",
    "derived_values",
    "description",
    "end_column",
    "register_output",
    "unit",
    "unregister_output",
    "warn_renamed",
]


@dataclass(frozen=True)
class Field:
    """One result field: ``name``, SI ``unit`` (pint-parseable, ``"1"`` dimensionless), a
    one-line ``description`` and an optional math ``symbol`` (LaTeX, for docs and plots)."""

    name: str
    unit: str
    description: str
    symbol: str = ""


#: The engine's outputs, in the column order of its ``out`` array.
OUTPUT_FIELDS: tuple[Field, ...] = (
    Field("e", "1", "normal (kinematic) COR at the contact point, -v_n,out / v_n,in", "e"),
    Field("e_energy", "1", "energetic COR (Stronge), sqrt(-W_restitution / W_compression)", "e^*"),
    Field("vx_out", "m/s", "x velocity of the centre of mass at separation", "v_{x,out}"),
    Field("vy_out", "m/s", "y velocity of the centre of mass at separation", "v_{y,out}"),
    Field(
        "spin_out",
        "rad/s",
        "angular velocity at separation (counter-clockwise positive)",
        r"\omega_{out}",
    ),
    Field("delta_max", "m", "largest interference", r"\delta_{max}"),
    Field(
        "delta_p",
        "m",
        "permanent depth: residual depth of the unloading branch at separation (positive)",
        r"\delta_p",
    ),
    Field(
        "sliding_length",
        "m",
        "slip of the body point at the contact, int v_slip dt (signed, along +x)",
        "L_s",
    ),
    Field("contact_travel", "m", "displacement of the contact point along the flat", "x_c"),
    Field("duration", "s", "contact duration, first touch to separation", "T"),
    Field("mean_force", "N", "normal impulse / duration", "F"),
    Field("max_force", "N", "largest normal force", "F_{max}"),
    Field("normal_impulse", "N s", "int F_n dt", "P_n"),
    Field("tangential_impulse", "N s", "int F_t dt", "P_t"),
    Field("energy_dissipated", "J", "kinetic + potential energy lost", r"\Delta E"),
    Field(
        "stick_time", "s", "time in stick (Coulomb) or without gross slip (Mindlin)", "t_{stick}"
    ),
    Field("regime", "1", "friction regime code: 0 frictionless, 1 slip, 2 stick, 3 reversal"),
    Field("vn_in", "m/s", "normal velocity of the contact point at first touch", "v_{n,in}"),
    Field("vt_in", "m/s", "slip velocity of the contact point at first touch", "v_{t,in}"),
    Field("vn_out", "m/s", "normal velocity of the contact point at separation", "v_{n,out}"),
    Field("vt_out", "m/s", "slip velocity of the contact point at separation", "v_{t,out}"),
    Field("angle_out", "rad", "rod angle at separation (NaN for a sphere)", r"\theta_{out}"),
    Field("t_max", "s", "time of the largest interference", "t_{max}"),
    Field("n_steps", "1", "accepted + rejected integration steps"),
    Field(
        "energy_rise",
        "1",
        "largest rise of the total energy / initial kinetic energy (diagnostics)",
    ),
    Field(
        "friction_excess",
        "1",
        "largest (|F_t| - mu F_n) / max_force (diagnostics, coulomb/mindlin)",
    ),
    Field(
        "flags",
        "1",
        "result flags (impactlab.flags.ResultFlag bitmask): 1 energy gain, 2 gravity-dominated, "
        "4 law extrapolated, 8 other end (flexible drops: e < 0 or the other end touched); 0 none",
    ),
)

#: Columns of an impact's time history, in order.
HISTORY_FIELDS: tuple[Field, ...] = (
    Field("t", "s", "time since first touch", "t"),
    Field("penetration", "m", "interference delta", r"\delta"),
    Field("normal_force", "N", "normal force F_n", "F_n"),
    Field("tangential_force", "N", "tangential force F_t on the body (+x)", "F_t"),
    Field(
        "contact_x",
        "m",
        "contact point position along the flat, from the first contact point",
        "x_c",
    ),
    Field("slip_velocity", "m/s", "slip velocity of the body point at the contact", "v_{slip}"),
    Field("x", "m", "centre of mass x (origin: first contact point)", "x"),
    Field("y", "m", "centre of mass y", "y"),
    Field("phi", "rad", "rotation since first touch (counter-clockwise)", r"\varphi"),
    Field("vx", "m/s", "centre of mass x velocity", "v_x"),
    Field("vy", "m/s", "centre of mass y velocity", "v_y"),
    Field("spin", "rad/s", "angular velocity (counter-clockwise positive)", r"\omega"),
    Field("normal_velocity", "m/s", "normal velocity v_n of the contact point", "v_n"),
    Field("phase", "1", "0 loading curve, 1 unloading/reloading curve"),
    Field("stick", "1", "1 stick (Coulomb) / no gross slip (Mindlin), 0 slip"),
    Field("energy", "J", "kinetic + potential (from first touch) + stored elastic energy", "E"),
)

#: Fields of ``ImpactResult`` that are not engine output columns (inputs echoed and pairs).
RESULT_FIELDS: tuple[Field, ...] = (
    Field("velocity_out", "m/s", "(vx, vy) of the centre of mass at separation"),
    Field("velocity_in", "m/s", "(vx, vy) of the centre of mass at first touch"),
    Field(
        "spin_in",
        "rad/s",
        "angular velocity at first touch (counter-clockwise positive)",
        r"\omega_{in}",
    ),
    Field("angle", "rad", "angle between rod axis and flat at first touch, (0, pi/2]", r"\theta"),
    Field("mu", "1", "friction coefficient", r"\mu"),
    Field(
        "max_delta_ratio",
        "1",
        "delta_max over the law's reference (first-yield) interference, delta_max / delta_c",
        r"\delta_{max}/\delta_c",
    ),
)

#: Suffix of a per-end column of a flexible drop's history: ``<name>_0`` is the tip (end 0, the
#: end that touches first), ``<name>_1`` the other end (the ``end`` of ``ContactRecord``).
END_SUFFIXES: tuple[str, str] = ("_0", "_1")


def end_column(name: str, end: int) -> str:
    """The history column of the quantity ``name`` at the rod's ``end`` (0 the tip, 1 the other
    end): ``end_column("normal_force", 0) == "normal_force_0"``."""
    if end not in (0, 1):
        raise ValueError(f"end must be 0 (the tip) or 1 (the other end), got {end!r}")
    return name + END_SUFFIXES[end]


def _per_end(name: str, unit: str, description: str, symbol: str = "") -> tuple[Field, ...]:
    """``name`` at each end (``end_column``); the description's ``{end}`` names the end."""
    ends = ("the tip (end 0)", "the other end (end 1)")
    return tuple(
        Field(end_column(name, k), unit, description.format(end=ends[k]), symbol) for k in (0, 1)
    )


def _end_fields(k: int) -> tuple[Field, ...]:
    """The five history columns of end ``k`` of a flexible drop, in the engine's order."""
    return tuple(
        group[k]
        for group in (
            _per_end("penetration", "m", "interference delta of {end}", r"\delta"),
            _per_end("normal_force", "N", "normal force F_n on {end}", "F_n"),
            _per_end("tangential_force", "N", "tangential force F_t on {end} (+x)", "F_t"),
            _per_end(
                "end_x",
                "m",
                "x of the centre of the sphere of {end} (of its lowest point: the contact point "
                "while it touches), from the first contact point",
            ),
            _per_end(
                "end_y",
                "m",
                "height of the centre of the sphere of {end} above the undeformed flat (R - delta)",
            ),
        )
    )


#: Columns of a flexible drop's time history (``DropResult.history``), in the engine's order:
#: an impact history's name where the quantity is the same (per end: ``end_column``), names of
#: their own otherwise.
DROP_HISTORY_FIELDS: tuple[Field, ...] = (
    Field("t", "s", "time since first touch", "t"),
    *_end_fields(0),
    *_end_fields(1),
    Field("x", "m", "centre of mass x (origin: first contact point)", "x"),
    Field("y", "m", "centre of mass y", "y"),
    Field("phi", "rad", "rotation since first touch (counter-clockwise)", r"\varphi"),
    Field(
        "slip_velocity_0",
        "m/s",
        "slip velocity of the body point at the contact of the tip (end 0)",
        "v_{slip}",
    ),
    Field(
        "energy_balance_error",
        "1",
        "(rigid kinetic + vibration + potential - initial - works) / initial energy at t",
    ),
)

#: A drop's history columns before 0.3, old name -> new name (the old names read the same
#: column with a DeprecationWarning for one release).
RENAMED_DROP_HISTORY: dict[str, str] = {
    "delta0": "penetration_0",
    "fn0": "normal_force_0",
    "ft0": "tangential_force_0",
    "x0": "end_x_0",
    "y0": "end_y_0",
    "delta1": "penetration_1",
    "fn1": "normal_force_1",
    "ft1": "tangential_force_1",
    "x1": "end_x_1",
    "y1": "end_y_1",
    "xc": "x",
    "yc": "y",
    "vt0": "slip_velocity_0",
    "energy_err": "energy_balance_error",
}

#: Totals of a flexible drop's contact sequence that mean something else than the impact field
#: of the old name (``DropResult``, its ``to_dict``, the ``impactlab drop`` table, the columns
#: of a flexible sweep store).
SEQUENCE_FIELDS: tuple[Field, ...] = (
    Field(
        "sequence_duration",
        "s",
        "first touch to last separation of a drop's contact sequence (flights included)",
        "T_{seq}",
    ),
    Field(
        "dent_depth",
        "m",
        "permanent depth of the deepest dent a drop leaves on the flat (positive)",
        r"\delta_{p,seq}",
    ),
    Field(
        "sequence_sliding_length",
        "m",
        "the tip's slip summed over its contacts, sum of int v_slip dt (signed, along +x)",
        "L_{s,seq}",
    ),
    Field(
        "sequence_mean_force",
        "N",
        "total normal impulse of a drop / sequence_duration",
        "F_{seq}",
    ),
)

#: ``DropResult`` fields, ``to_dict`` keys and store columns before 0.3, old name -> new name
#: (the old attribute and ``to_dict`` key read the new field with a DeprecationWarning for one
#: release; a store column of the old name holds impact values only).
RENAMED_DROP_FIELDS: dict[str, str] = {
    "duration": "sequence_duration",
    "delta_p": "dent_depth",
    "sliding_length": "sequence_sliding_length",
    "mean_force": "sequence_mean_force",
}

#: The other fields of ``DropResult`` that an impact has not (its sequence, energies, options).
DROP_FIELDS: tuple[Field, ...] = (
    *SEQUENCE_FIELDS,
    Field("e_raw", "1", "a drop's e with the gravity impulse of its sequence kept"),
    Field("n_contacts", "1", "number of contacts of a drop"),
    Field("scar_length", "m", "x-extent of the tip's contact-point path over all its contacts"),
    Field("slip_path", "m", "sum over the tip's contacts of int |v_slip| dt"),
    Field("mu_apparent", "1", "|dvx / (dvy + g T)|: the paper's Eq. 28 on the frame velocities"),
    Field("initial_energy", "J", "kinetic energy at first touch"),
    Field("vibration_energy", "J", "elastic (modal) energy after the last contact"),
    Field("rigid_kinetic_energy", "J", "rigid-body kinetic energy after the last contact"),
    Field("potential_energy", "J", "gravity potential after the last contact (0 at first touch)"),
    Field("work_normal", "J", "work of the normal forces (negative: dissipated)"),
    Field("work_friction", "J", "work of friction (negative: dissipated)"),
    Field("work_damping", "J", "work of the modal damping (negative: dissipated)"),
    Field("energy_error", "1", "largest |T + V - E0 - W| / E0 over a drop"),
    Field("next_end", "1", "the end that can land next (-1: none within the horizon)"),
    Field("next_time", "s", "lower bound of that landing, from the last separation"),
    Field("n_modes", "1", "number of elastic modes of the flexible rod"),
    Field("gravity", "m/s^2", "gravitational acceleration"),
    Field("rate_factor", "1", "rate factor k of the flat's yield strength and hardness"),
    Field("strain_rate", "1/s", "representative strain rate of the rate law"),
    Field(
        "fitted_delta_ratio_max",
        "1",
        "upper end of the law's fitted range of delta_max / delta_c",
    ),
)

#: Every field by name: engine outputs, history columns, derived result fields and a drop's.
FIELDS: dict[str, Field] = {
    f.name: f
    for f in (*OUTPUT_FIELDS, *HISTORY_FIELDS, *RESULT_FIELDS, *DROP_HISTORY_FIELDS, *DROP_FIELDS)
}


def warn_renamed(old: str, new: str, what: str, stacklevel: int = 3) -> None:
    """The DeprecationWarning of a renamed ``what`` (``"history column"``, ...): ``old`` still
    reads the data of ``new``, for one release."""
    warnings.warn(
        f"{what} {old!r} is renamed {new!r} (impactlab 0.3); the old name goes in 0.4",
        DeprecationWarning,
        stacklevel=stacklevel,
    )


def unit(name: str) -> str:
    """SI unit of the field ``name`` (``"1"`` for dimensionless); KeyError names the known."""
    return _get(name).unit


def description(name: str) -> str:
    """One-line description of the field ``name``."""
    return _get(name).description


def _get(name: str) -> Field:
    try:
        return FIELDS[name]
    except KeyError:
        raise KeyError(f"unknown result field {name!r}; known: {', '.join(FIELDS)}") from None


@dataclass(frozen=True)
class DerivedField:
    """An output computed from the engine's outputs: ``field`` (name, unit, meaning), the
    engine outputs it ``needs`` (``OUTPUT_FIELDS`` names) and ``compute``, called with them as
    keyword arguments (floats, or arrays of one shape: it must broadcast, as numpy does)."""

    field: Field
    needs: tuple[str, ...]
    compute: Callable[..., Any]


#: The derived outputs registered (``register_output``), by name, in registration order.
DERIVED_FIELDS: dict[str, DerivedField] = {}


def register_output(
    name: str,
    unit: str,
    description: str,
    needs: tuple[str, ...] | list[str],
    compute: Callable[..., Any],
    symbol: str = "",
) -> DerivedField:
    """Register a derived output ``name`` [``unit``, SI, pint-parseable; "1" dimensionless],
    computed by ``compute(**{need: value})`` from the engine outputs ``needs``. It then shows
    in every result's ``to_dict`` and as an attribute (``ImpactResult``, ``DropResult``), as a
    column of ``BatchResult`` (``batch[name]``, ``to_xarray``, ``to_dataframe``) and as a sweep
    output (a store variable). ValueError for a name already taken (any field), a need that is
    no engine output, or a ``compute`` that is not callable."""
    if not (isinstance(name, str) and name.isidentifier() and not name.startswith("_")):
        raise ValueError(f"output name must be a Python identifier, got {name!r}")
    if name in FIELDS:
        raise ValueError(f"output name {name!r} is taken: {FIELDS[name].description}")
    outputs = {f.name for f in OUTPUT_FIELDS}
    bad = [n for n in needs if n not in outputs]
    if not needs or bad:
        raise ValueError(
            f"needs must name engine outputs, got {list(needs)!r}; engine outputs: "
            f"{', '.join(f.name for f in OUTPUT_FIELDS)}"
        )
    if not callable(compute):
        raise ValueError(f"compute must be callable, got {compute!r}")
    derived = DerivedField(Field(name, unit, description, symbol), tuple(needs), compute)
    DERIVED_FIELDS[name] = derived
    FIELDS[name] = derived.field
    return derived


def unregister_output(name: str) -> None:
    """Remove the derived output ``name`` (ValueError if none is registered under it)."""
    if DERIVED_FIELDS.pop(name, None) is None:
        raise ValueError(f"no derived output {name!r}; registered: {list(DERIVED_FIELDS)}")
    del FIELDS[name]


def derived_values(value_of: Callable[[str], Any]) -> dict[str, Any]:
    """Every derived output from ``value_of(engine output name)`` (a float or an array)."""
    return {
        name: d.compute(**{n: value_of(n) for n in d.needs}) for name, d in DERIVED_FIELDS.items()
    }
