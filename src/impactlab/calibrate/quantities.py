"""What a measurements file may hold: the drop's inputs (the sweep's input catalogue) and the
measured quantities (the engine's outputs, plus the tangential restitution ``e_t``), with their
SI units and plausible ranges.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from impactlab.schema import FIELDS
from impactlab.sweep.inputs import CATEGORY_INPUTS, INPUTS, KINEMATIC_INPUTS

__all__ = [
    "AMBIGUOUS",
    "ANGLES",
    "DROP_CATEGORIES",
    "E_GRAVITY_DURATION",
    "FRACTIONS",
    "MEASURABLE",
    "NOISE_SIGMAS",
    "NUMERIC_INPUTS",
    "OUTPUT_ALIASES",
    "PLAUSIBLE",
    "Measurable",
    "canonical_output",
]


@dataclass(frozen=True)
class Measurable:
    """A measurable quantity: ``name``, SI ``unit``, ``description``, the engine ``outputs`` it
    is computed from and its physically possible range [``low``, ``high``] (None: open)."""

    name: str
    unit: str
    description: str
    outputs: tuple[str, ...]
    low: float | None = None
    high: float | None = None


def _engine(name: str, low: float | None = None, high: float | None = None) -> Measurable:
    f = FIELDS[name]
    return Measurable(name, f.unit, f.description, (name,), low, high)


#: A measured value may lie this many of its standard uncertainties outside its quantity's
#: possible range: measurement noise, used as measured (a Gaussian error crosses a bound).
NOISE_SIGMAS = 3.0

#: The contact duration T [s] that the upper end of e's range, 1 + g T/|vy|, assumes unless
#: the drop measures a longer ``duration``: longer than the engine's contacts of a 5 cm steel
#: sphere on steel at 0.1 m/s (0.56 ms), of a 5 cm sphere on PMMA at 1 m/s (1.4 ms) and than
#: the contact sequence of the paper's flexible rod at 1.41 m/s (under 1 ms).
E_GRAVITY_DURATION = 2e-3

#: Every quantity a measurements file may give, by name.
MEASURABLE: dict[str, Measurable] = {
    m.name: m
    for m in (
        Measurable(
            "e",
            FIELDS["e"].unit,
            "the normal COR of the contact point with the gravity impulse of the contact "
            "removed, (v_n,out + g T)/|v_n,in| (a drop's: over its contact sequence), as "
            "marker tracks extrapolated to the impact measure it: an elastic impact gives "
            "about 1 + g T/|v_n,in| (1.0055 for a 5 mm steel sphere at 0.1 m/s)",
            ("e",),
            0.0,
            1.0,
        ),
        _engine("e_energy", 0.0, 1.0),
        _engine("vx_out"),
        _engine("vy_out"),
        _engine("spin_out"),
        _engine("delta_max", 0.0),
        _engine("delta_p", 0.0),
        _engine("sliding_length"),
        _engine("contact_travel"),
        _engine("duration", 0.0),
        _engine("mean_force", 0.0),
        _engine("max_force", 0.0),
        _engine("normal_impulse", 0.0),
        _engine("tangential_impulse"),
        _engine("energy_dissipated", 0.0),
        Measurable(
            "angle_out",
            "rad",
            "the rod's angle to the flat at separation, in [0, 180] deg: the rod stays above "
            "the flat (at 0 or 180 deg it lies in it); a contact turns it little (the paper's "
            "rod at 1.4-5 m/s: under 0.2 deg), so it lies near the incoming angle",
            ("angle_out",),
            0.0,
            math.pi,
        ),
        Measurable(
            "sliding_distance",
            "m",
            "|sliding_length|: the length of the slip (the slip speed's integral), a magnitude; "
            "with mindlin and partial_slip the contact's elastic deflection included",
            ("sliding_length",),
            0.0,
        ),
        Measurable(
            "scar_length",
            "m",
            "the extent of the mark along the flat, a magnitude (a scan's measured L_s): "
            "|contact_travel| of an impact, a drop's scar_length over all its contacts",
            ("contact_travel",),
            0.0,
        ),
        Measurable(
            "e_t",
            "1",
            "tangential restitution of the centre of mass, v_x,out / v_x,in (needs vx != 0)",
            ("vx_out",),
            -1.0,
            1.0,
        ),
    )
}

#: Measured quantities that are angles: refused bare, as the inputs' angles are (a bare 20 could
#: be degrees or radians; ``sweep.inputs.UNIT_REQUIRED``).
ANGLES: tuple[str, ...] = tuple(q for q, m in MEASURABLE.items() if m.unit == "rad")

#: The numbers of unit 1 that are fractions, and so may be given in percent (``"43 %"``, a
#: header ``e [%]``): the restitutions and the drop's mu and damping ratio (not a Poisson's
#: ratio, a Meyer index or a number of modes).
FRACTIONS: tuple[str, ...] = ("e", "e_energy", "e_t", "mu", "damping")

#: The largest magnitude of a measured value (SI) that an impact of a drop test can have, and
#: the unit to suggest: a larger one is a unit mistake (1400 um read as 1400 m, 50 ms as 50 s).
#: A mark or a slip of 10 cm, a contact of 0.1 s are far beyond any impact of a dropped body;
#: a dent is checked against the tip radius instead (``measurement_rows``).
PLAUSIBLE: dict[str, tuple[float, str]] = {
    **dict.fromkeys(
        ("scar_length", "sliding_length", "sliding_distance", "contact_travel"), (0.1, "um")
    ),
    "duration": (0.1, "ms"),
}

#: The paper's symbols accepted as names of measured quantities (not L_s: see ``AMBIGUOUS``).
OUTPUT_ALIASES: dict[str, str] = {
    "T": "duration",
    "F": "mean_force",
    "delta_r": "delta_p",
}

#: Names a measurements file may not use, with why: the paper's L_s is the length of the mark
#: on the scan, which an impact's signed slip ``sliding_length`` is not.
AMBIGUOUS: dict[str, str] = dict.fromkeys(
    ("L_s", "Ls"),
    "L_s names two quantities: give scar_length (the mark's extent along the flat, as a "
    "scan measures it, a magnitude) or sliding_length (the engine's slip, signed along +x)",
)

#: Category inputs a drop may set (the contact law and the friction model are the candidate
#: models' choices, never the file's).
DROP_CATEGORIES: tuple[str, ...] = tuple(c for c in CATEGORY_INPUTS if c not in ("law", "friction"))
#: Numeric inputs a drop may set (SI; unset: the preset's value or the input's default).
NUMERIC_INPUTS: tuple[str, ...] = tuple(n for n, s in INPUTS.items() if s.kind == "float")
#: Inputs that describe the drop's kinematics, the velocity as speed and incidence too (never
#: free parameters or a model's fixed inputs, except mu).
KINEMATICS: tuple[str, ...] = tuple(
    k for k in (*KINEMATIC_INPUTS, "speed", "incidence") if k != "mu"
)


def canonical_output(name: str) -> str | None:
    """The measurable called ``name`` (aliases resolved), or None when there is none."""
    name = OUTPUT_ALIASES.get(name, name)
    return name if name in MEASURABLE else None
