"""The fields of an impact: the engine's outputs (the column order of its ``out`` array), the
history columns and the result fields computed from them."""

from __future__ import annotations

from impactlab.schema.field import Field

__all__ = ["HISTORY_FIELDS", "OUTPUT_FIELDS", "RESULT_FIELDS"]

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
        "4 law extrapolated (advisory), 8 other end (the other end touched or may have), 16 "
        "beyond the tip (the flat reached the rim of the tip), 32 brittle (a brittle member "
        "past first yield); 0 none",
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
        "delta_max / delta_ref, the law's own reference interference (LawRange.reference: "
        "Jackson-Green's delta_c, or delta_y for Kogut-Komvopoulos, Brake, Thornton)",
        r"\delta_{max}/\delta_{ref}",
    ),
)
