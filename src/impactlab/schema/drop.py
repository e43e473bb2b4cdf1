"""The fields of a flexible drop: its history columns (per end of the rod: ``end_column``), its
sequence totals (``SEQUENCE_FIELDS``) and its other fields, with the names before 0.3."""

from __future__ import annotations

from impactlab.schema.field import Field

__all__ = [
    "DROP_FIELDS",
    "DROP_HISTORY_FIELDS",
    "END_SUFFIXES",
    "RENAMED_DROP_FIELDS",
    "RENAMED_DROP_HISTORY",
    "SEQUENCE_FIELDS",
    "end_column",
]

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
        "permanent depth of the deepest dent the tip leaves on the flat in a drop (positive)",
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

#: What a drop's field of an impact's name means where it differs from the impact's (a
#: drop's ``e`` leaves out the gravity impulse of its sequence): the ``long_name`` of a
#: batch of drops' column.
DROP_MEANINGS: dict[str, str] = {
    "e": "a drop's COR, -v_n,out / v_n,in over its sequence with the gravity impulse of the "
    "sequence removed (as a fit of measured flights; e_raw keeps it)",
}

#: The other fields of ``DropResult`` that an impact has not (its sequence, energies, options),
#: and the columns of ``simulate_drops`` that one drop has not (``n_jumps``, ``t_final``).
DROP_FIELDS: tuple[Field, ...] = (
    *SEQUENCE_FIELDS,
    Field("e_raw", "1", "a drop's e with the gravity impulse of its sequence kept"),
    Field("n_contacts", "1", "number of contacts of a drop"),
    Field("n_dents", "1", "number of dents a drop left on the flat"),
    Field("n_jumps", "1", "closed-form free-flight jumps of a drop (simulate_drops only)"),
    Field(
        "t_final",
        "s",
        "time from first touch at which the end-of-sequence test passed (simulate_drops only)",
    ),
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
    Field(
        "next_end",
        "1",
        "the end that can land next (0 the tip, after a flight; 1 the other end; -1: none within "
        "the horizon)",
    ),
    Field("next_time", "s", "lower bound of that landing, from the last separation"),
    Field("n_modes", "1", "number of elastic modes of the flexible rod"),
    Field("gravity", "m/s^2", "gravitational acceleration"),
    Field("rate_factor", "1", "rate factor k of the flat's yield strength and hardness"),
    Field("strain_rate", "1/s", "representative strain rate of the rate law"),
    Field(
        "fitted_delta_ratio_max",
        "1",
        "upper end of the law's fitted range of delta_max / delta_ref (its own reference)",
    ),
)
