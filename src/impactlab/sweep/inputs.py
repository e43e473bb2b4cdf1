"""The catalogue of sweepable inputs: names, SI units, kinds and defaults; the outputs' units and
meanings come from :mod:`impactlab.schema`.

Every input of a study is one of these names. A numeric input is stored in SI units (the column
``unit``); in a study file a bare number is read in SI (an angle is refused bare: ``"20 deg"``
or ``unit = "deg"``) and a string such as ``"8.8 mm"`` or ``"20 deg"`` is converted. A numeric input
whose default is ``None`` and that the study does not set means "take the value from the preset"
(the material preset, the paper's rod); it travels as NaN inside the sweep.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from impactlab.schema import FIELDS, OUTPUT_FIELDS, Field

Kind = Literal["float", "category"]


@dataclass(frozen=True)
class InputSpec:
    """One sweepable input.

    name : the input's name in study files, the Python API and the result Dataset.
    unit : SI unit of the stored value ("1" for dimensionless, "" for categories).
    kind : "float" (numeric, may vary case by case) or "category" (one value per engine call).
    default : value when the study does not set it; ``None``: from the preset (numeric) or
        required (``required=True``).
    required : the study must set it (in [fixed], [grid] or [sample]).
    file_unit : unit of a bare number in a study file.
    description : one line for docs and error messages.
    """

    name: str
    unit: str
    kind: Kind
    default: float | str | None
    description: str
    required: bool = False
    file_unit: str | None = None

    @property
    def parse_unit(self) -> str:
        """Unit in which a bare number of a study file is read."""
        return self.file_unit or self.unit


#: The inputs every study must set (in [fixed], [grid] or [sample]).
REQUIRED_INPUTS: tuple[str, ...] = ("angle", "vy", "mu")  # angle: not for a sphere-only study
#: Inputs whose bare numbers in a study file are not in their SI unit (none: every bare
#: number is SI, and the angles are refused bare, :data:`UNIT_REQUIRED`).
_FILE_UNITS: dict[str, str] = {}
#: Inputs a study file must give with a unit ("20 deg", or ``unit = "deg"`` in the table): a
#: bare angle could be degrees or radians (the angle rule, docs/glossary.md).
UNIT_REQUIRED: tuple[str, ...] = ("angle", "incidence")


def _f(name: str, unit: str, description: str, default: float | None = None) -> InputSpec:
    required = name in REQUIRED_INPUTS
    return InputSpec(name, unit, "float", default, description, required, _FILE_UNITS.get(name))


def _c(name: str, default: str, description: str) -> InputSpec:
    return InputSpec(name, "", "category", default, description)


_MATERIAL_FIELDS = (
    ("E", "Pa", "Young's modulus"),
    ("nu", "1", "Poisson's ratio"),
    ("yield_strength", "Pa", "yield strength S_y"),
    ("brinell_hardness", "kgf/mm^2", "Brinell hardness number HB (Brake's law)"),
    ("meyer_index", "1", "Meyer strain-hardening index n (Brake's law)"),
    ("density", "kg/m^3", "mass density"),
)

#: Names of the per-case material overrides, by side ("body", "flat"): input name -> field.
#: (The flat is massive: its density plays no part, so there is no ``flat_density``.)
MATERIAL_OVERRIDES: dict[str, dict[str, str]] = {
    side: {
        f"{side}_{field}": field
        for field, _, _ in _MATERIAL_FIELDS
        if not (side == "flat" and field == "density")
    }
    for side in ("body", "flat")
}

_INERTIA = "moment of inertia about the centre of mass I_C (rod: m L^2/12 if not set)"

_SPECS: tuple[InputSpec, ...] = (
    # kinematics (paper Sec. 2: theta, v_i; omega_i = 0, no tangential velocity)
    _f("angle", "rad", "angle of the rod axis to the flat at first contact (theta)"),
    _f("vx", "m/s", "initial horizontal velocity of the centre of mass (+x towards C)", 0.0),
    _f("vy", "m/s", "initial vertical velocity of the centre of mass (< 0: towards the flat)"),
    _f("spin", "rad/s", "initial angular velocity (counter-clockwise positive)", 0.0),
    _f("speed", "m/s", "speed of the centre of mass (with incidence, instead of vx and vy)"),
    _f(
        "incidence",
        "rad",
        "angle of the velocity to the flat's normal, in (-90, 90) deg (with speed; "
        "vx = speed sin(incidence), vy = -speed cos(incidence))",
    ),
    _f("mu", "1", "coefficient of friction"),
    # body geometry (None: the paper's rod, impactlab.bodies.PAPER_ROD)
    _c("body", "rod", "impacting body: 'rod' (hemispherical tip), 'sphere' or 'flexible_rod'"),
    _f("length", "m", "rod length L (rod)"),
    _f("tip_radius", "m", "rod tip radius R (rod)"),
    _f("radius", "m", "sphere radius (sphere)"),
    _f("mass", "kg", "body mass m (sphere: from the density if not set)"),
    _f("inertia", "kg*m^2", _INERTIA),
    # flexible rod (body = "flexible_rod"; None: FlexibleRod's defaults; impactlab.sweep.flexible)
    _f("n_axial", "1", "axial free-free modes of a flexible rod (integer; + 2 residual modes)"),
    _f("n_bending", "1", "bending free-free modes of a flexible rod (integer)"),
    _f("damping", "1", "modal damping ratio zeta of a flexible rod, in [0, 1)"),
    # materials: presets and per-property overrides
    _c("body_material", "aisi-201", "material preset of the impacting body"),
    _c("flat_material", "aisi-1010", "material preset of the flat"),
    *(
        _f(f"{side}_{field}", unit, f"{desc} of the {side} (overrides the preset)")
        for side in ("body", "flat")
        for field, unit, desc in _MATERIAL_FIELDS
        if f"{side}_{field}" in MATERIAL_OVERRIDES[side]
    ),
    # model choices
    _c("law", "ghaednia", "normal contact law (impactlab laws)"),
    _c("friction", "coulomb", "tangential (friction) model"),
)

INPUTS: dict[str, InputSpec] = {s.name: s for s in _SPECS}

#: Inputs that enter the contact model (law parameters): changing one rebuilds the ContactModel.
LAW_INPUTS: tuple[str, ...] = (
    "law",
    "body_material",
    "flat_material",
    "tip_radius",
    "radius",
    "body",
    *MATERIAL_OVERRIDES["body"],
    *MATERIAL_OVERRIDES["flat"],
)
#: Inputs that enter the body parameters.
BODY_INPUTS: tuple[str, ...] = (
    "body",
    "length",
    "tip_radius",
    "radius",
    "mass",
    "inertia",
    "body_material",
    "body_density",
)
#: Per-case kinematic inputs (the engine's ``initial`` and ``mu`` arrays).
KINEMATIC_INPUTS: tuple[str, ...] = ("angle", "vx", "vy", "spin", "mu")

#: Category inputs: constant within a chunk (the engine is called with one value each).
CATEGORY_INPUTS: tuple[str, ...] = tuple(s.name for s in _SPECS if s.kind == "category")


#: What a study calls an input that ``simulate`` and the results spell otherwise.
_STUDY_SPELLING = {
    "velocity": "a study takes the velocity as vx and vy (or speed and incidence)",
    "velocity_in": "a study takes the velocity as vx and vy (or speed and incidence)",
    "spin_in": "a study's name for it is spin",
    "material": "a study names the materials body_material and flat_material",
    "flat": "a study's name for it is flat_material",
    **{
        option: f"{option} is an engine option of the whole study, not an input: "
        f"Study(engine=EngineOptions({option}=...)) in Python, {option} under [engine] in a "
        "study file"
        for option in ("gravity", "rtol", "constant_angle", "partial_slip_cells")
    },
    "law_params": "a study takes the contact law's parameters as Study(law_params={...}) in "
    "Python, the [law_params] table in a study file",
}


#: Options of a single drop or impact that a study cannot take, and why (with what to do).
_NOT_IN_A_STUDY = {
    "rate": "a study takes no rate-dependent flat: its self-consistent rate factor is iterated "
    "drop by drop, each case to its own, while a sweep runs a chunk's cases in one compiled "
    "call (simulate_drops refuses it for the same reason); run impactlab.simulate_drop(body, "
    "flat, rate=..., ...) for each case instead (a Rod or a FlexibleRod; impactlab drop --rate "
    "on the command line), or sweep without it (a rate-independent flat)",
}


def unknown_input(name: object) -> str:
    """``"unknown input 'velocity': a study takes ...; known inputs: angle, vx, ..."``: what
    to write instead where ``simulate`` spells it otherwise, and the known names; for an
    option no study takes (``rate``), why and what to do instead."""
    if isinstance(name, str) and name in _NOT_IN_A_STUDY:
        return f"input {name!r} cannot be swept: {_NOT_IN_A_STUDY[name]}"
    hint = _STUDY_SPELLING.get(name) if isinstance(name, str) else None
    return f"unknown input {name!r}{': ' + hint if hint else ''}; known inputs: {', '.join(INPUTS)}"


def get_input(name: str) -> InputSpec:
    """The input called ``name``; ValueError listing the known names otherwise."""
    try:
        return INPUTS[name]
    except (KeyError, TypeError):
        raise ValueError(unknown_input(name)) from None


#: The engine's outputs by name: unit and meaning (``impactlab.schema``, the one table).
OUTPUTS: dict[str, Field] = {f.name: f for f in OUTPUT_FIELDS}
#: Integer-valued outputs and their stored dtype (fill value -1).
INTEGER_OUTPUTS: dict[str, str] = {"regime": "int8", "n_steps": "int32", "flags": "int16"}
#: Outputs stored whatever ``[outputs] keep`` says (when the engine has them): the result flags
#: (``impactlab.flags.ResultFlag``) that mark results not to be trusted as plain success.
ALWAYS_STORED: tuple[str, ...] = ("flags",)

#: The paper's symbols accepted as output names.
OUTPUT_ALIASES: dict[str, str] = {
    "L_s": "sliding_length",
    "Ls": "sliding_length",
    "T": "duration",
    "F": "mean_force",
    "delta_r": "delta_p",
}


def output_spec(name: str) -> Field:
    """Unit and description of an output (unit "unknown" for a field not in the schema)."""
    return FIELDS.get(name, Field(name, "unknown", name))
