"""The one table of result fields: name, SI unit and meaning of every engine output, history
column and derived result field.

Everything that prints or stores a result field's unit or description reads it from here (the
compiled engine's output layout, ``ImpactResult``/``BatchResult``, sweep stores, the CLI).
Units are SI and spelled one way, parseable by pint: ``"m"``, ``"m/s"``, ``"rad"``,
``"rad/s"``, ``"N"``, ``"N s"``, ``"J"``, ``"s"``, and ``"1"`` for dimensionless values.

To add an engine output: append a ``Field`` to ``OUTPUT_FIELDS`` (the order is the column order
of the engine's ``out`` array, so append, never insert) and fill it in
``impactlab.dynamics.core.driver`` (a recompilation). To add a field computed from the engine's
outputs, without touching the compiled engine: ``register_output`` (a derived output; it appears
in ``ImpactResult``, ``BatchResult``, ``DropResult`` and sweep stores, see
docs/architecture.md, "An output field").
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

__all__ = [
    "DERIVED_FIELDS",
    "FIELDS",
    "HISTORY_FIELDS",
    "OUTPUT_FIELDS",
    "RESULT_FIELDS",
    "DerivedField",
    "Field",
    "derived_values",
    "description",
    "register_output",
    "unit",
    "unregister_output",
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

#: Every field by name: engine outputs, history columns and derived result fields.
FIELDS: dict[str, Field] = {f.name: f for f in (*OUTPUT_FIELDS, *HISTORY_FIELDS, *RESULT_FIELDS)}


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
