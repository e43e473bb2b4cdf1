"""The SI unit of every field that impactlab prints or writes as JSON: the result fields of
``impactlab.schema`` and the others (an inversion's, a body's and a material's, a drop's
contact records, a sweep's timings), by name."""

from __future__ import annotations

from impactlab.schema import FIELDS

__all__ = ["EXTRA_UNITS", "SI_UNITS"]

#: SI units of the printed fields that are not in ``impactlab.schema``.
EXTRA_UNITS: dict[str, str] = {
    # inversion (impactlab invert, analyze)
    "T": "s",
    "F": "N",
    "T_mc": "s",
    "F_mc": "N",
    "T_interval_mc": "s",
    "F_interval_mc": "N",
    "F_momentum": "N",
    "F_rigid": "N",
    "K_x": "1/kg",
    "K_y": "1/kg",
    "alpha": "1",
    "mu_c": "1",
    "mc_rejected": "1",
    "v_i": "m/s",
    "dv_cy": "m/s",
    "L_s": "m",
    "pileup": "m",
    "v_c_in_x": "m/s",
    "v_c_in_y": "m/s",
    "v_c_out_x": "m/s",
    "v_c_out_y": "m/s",
    # bodies and materials
    "mass": "kg",
    "length": "m",
    "radius": "m",
    "tip_radius": "m",
    "inertia": "kg*m^2",
    "E": "Pa",
    "nu": "1",
    "yield_strength": "Pa",
    "brinell_hardness": "kgf/mm^2",
    "meyer_index": "1",
    "density": "kg/m^3",
    # drop (impactlab drop / simulate rod --flexible)
    "slip": "m",
    "start": "s",
    "x_start": "m",
    "x_end": "m",
    "x_min": "m",
    "x_max": "m",
    "contact_radius": "m",
    "unloading_radius": "m",
    "delta_r": "m",
    # sweep
    "wall_time": "s",
    "first_task": "s",
    "throughput": "1/s",
}

#: SI unit of every field a command prints, by name: ``impactlab.schema`` and the above.
SI_UNITS: dict[str, str] = {name: f.unit for name, f in FIELDS.items()} | EXTRA_UNITS
