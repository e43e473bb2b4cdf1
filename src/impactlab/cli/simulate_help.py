"""Help texts of ``impactlab simulate``'s options that are keys of its config file."""

from __future__ import annotations

from impactlab._display import format_number
from impactlab.cli._common import KINEMATIC_HELP, STOP_HELP, length_help, rate_help
from impactlab.cli.drop_body import MODES_HELP
from impactlab.dynamics.drop import DEFAULT_TIME_LIMIT
from impactlab.dynamics.flexcore.layout import DROP_DEFAULT_RTOL
from impactlab.dynamics.input_checks import MINDLIN_RTOL_MAX, PARTIAL_SLIP_RTOL_MAX
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, PARTIAL_SLIP_RTOL
from impactlab.friction import PARTIAL_SLIP_CELLS, PARTIAL_SLIP_CELLS_MAX, PARTIAL_SLIP_CELLS_MIN

__all__ = ["HELP"]

_n = format_number  # "2e-7", as the defaults are written elsewhere

#: Help of the options that are keys of the config file.
HELP = {
    **KINEMATIC_HELP,
    "law": "Contact law, see 'impactlab laws' (default ghaednia).",
    "friction": "Friction model: impulse_ratio, coulomb (default), mindlin or partial_slip.",
    "inertia": 'Rod I_C, e.g. "0.0036 kg*m^2" (bare number: kg*m^2; default m L^2/12; rigid rod '
    "only).",
    "radius": "Tip / sphere radius (--tip-radius too), e.g. '8.8 mm' (bare number: m; default "
    "8.8 mm, the paper's).",
    "length": length_help("0.3048 m"),
    "mass": "Mass, e.g. '0.46 kg' (bare number: kg; rod default 0.4607 kg, the paper's rod's: "
    "another --material or --length needs --mass or --diameter; sphere default from the "
    "density).",
    "diameter": "Rod diameter d, e.g. '12 mm' (bare number: m; optional): the mass follows from "
    "d, L and the material's density (with --mass too: checked to 2 %).",
    "material": "Body material: a library name (see 'impactlab materials'), properties "
    "'E=200GPa, nu=0.3, Sy=760MPa, rho=7800kg/m^3' (HB=, n=, brittle=yes optional) or a TOML file "
    "(default aisi-201).",
    "flat": "Flat material: a library name (see 'impactlab materials'), properties "
    "'E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3' (HB=, n=, brittle=yes optional) or a TOML file "
    "(default aisi-1010).",
    **{k: f"Flexible rod: {v[0].lower()}{v[1:]}" for k, v in MODES_HELP.items()},
    "damping": "Flexible rod: modal damping ratio zeta of every mode, in [0, 1) (default 0).",
    "rate": f"Flexible rod only. {rate_help()}",
    "stop": f"Flexible rod: {STOP_HELP}",
    "time_limit": "Flexible rod: longest simulated time after the first touch, e.g. '2 s' "
    f"(bare number: s; default {DEFAULT_TIME_LIMIT * 1e3:g} ms).",
    "rtol": f"Integration tolerance, in [1e-13, 1e-3] (default {_n(DEFAULT_RTOL)}, "
    f"{_n(PARTIAL_SLIP_RTOL)} with partial_slip, {_n(DROP_DEFAULT_RTOL)} for the flexible rod; "
    f"{_n(PARTIAL_SLIP_RTOL_MAX)} at most for the flexible rod and with partial_slip, "
    f"{MINDLIN_RTOL_MAX:.0e} with mindlin).".replace("e-0", "e-"),
    "partial_slip_cells": f"With --friction partial_slip: its cells over the largest contact "
    f"radius, an integer in [{PARTIAL_SLIP_CELLS_MIN}, {PARTIAL_SLIP_CELLS_MAX}] (default "
    f"{PARTIAL_SLIP_CELLS}; 64 converge e_t near normal incidence, at 4 to 5 times the cost; "
    "rigid rod and sphere).",
}
