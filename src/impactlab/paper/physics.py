""" "Can physics explain the experiment?": the paper's three drops with the rigid rod,
the flexible rod, the flexible rod on a rate-dependent flat and the flexible rod with the
FE-tabulated law of a strain-hardening flat, side by side with the measurements. Nothing is
tuned: the paper's rod, drop velocities and measured mu (as the Coulomb coefficient), the
Ghaednia law with impactlab's defaults, the AISI 1010 flat, gravity on, no damping (the
FE-tabulated row: the law tabulated from the FE indentation of the paper's pair with AISI
1010's own strain hardening, ``impactlab.materials.hardening.AISI_1010_HARDENING``, derived
from SAE J1397's cold-drawn tensile properties; ``impactlab.fe.tabulated.hardened_law``). The model:
docs/flexible.md. Which configuration explains the drops best, with the posterior of the rod's
modal damping ratio, is the calibration of :mod:`impactlab.paper.calibration_report` (the
report's next section).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from functools import cache
from typing import Any

import pandas as pd

from impactlab.bodies import PAPER_ROD, FlexibleRod
from impactlab.contact import ContactModel
from impactlab.dynamics import simulate
from impactlab.dynamics.derived import e_gravity_removed
from impactlab.dynamics.drop import simulate_drop
from impactlab.fe.tabulated import hardened_law
from impactlab.materials import G0, ContactPair
from impactlab.paper import data as D
from impactlab.paper.quantities import flag_columns
from impactlab.paper.simulations import paper_angles

__all__ = [
    "CONFIGURATIONS",
    "E_COLUMN",
    "E_DEFINITION",
    "FE_TABULATED",
    "HARDENED_LAW",
    "LAW",
    "MEASURED",
    "ROWS",
    "SCAR_COLUMN",
    "PhysicsConfig",
    "physics_inputs",
    "physics_table",
    "rigid_e_gravity_removed",
    "run_physics",
]

#: The contact law of every configuration (the paper's own law).
LAW = "ghaednia"
#: The law of the FE-tabulated row: tabulated from the FE curves of the paper's pair with a
#: strain-hardening flat (``impactlab.fe.tabulated.hardened_law``).
HARDENED_LAW = "tabulated (FE, hardening flat)"
#: The friction model of every configuration (mu: the measured one of each drop).
FRICTION = "coulomb"
#: The configuration name of the measured rows: e, delta_p and the scar as measured (Sec.
#: 5.1.3), T not measured but inverted from the measured dent (Eq. 12, as the experimental rows).
MEASURED = "measured (paper); T: Eq. 12 inversion of the measured dent"
#: The column of e with the gravity impulse of the contact (sequence) removed, as a ballistic
#: fit of a measured rebound removes it (:data:`E_DEFINITION`; a drop's ``e``, a rigid impact's
#: ``dynamics.derived.e_gravity_removed``); not the impact's ``e`` of simulations.csv.
E_COLUMN = "e_gravity_removed"
#: The column of the extent of the mark the tip left, as a scan measures it: the rigid rod's
#: |``contact_travel``|, the flexible rod's ``scar_length``, the measured L_s; not the signed
#: slip (``sliding_length``) of simulations.csv's ``L_s [um]``.
SCAR_COLUMN = "scar_length [um]"


@dataclass(frozen=True)
class PhysicsConfig:
    """One physical model of the drop: its ``name``, whether the rod is ``flexible``, the flat's
    ``rate`` law (None: rate-independent), the sentence that states it and the contact ``law``
    (a registered name or :data:`HARDENED_LAW`)."""

    name: str
    flexible: bool
    rate: str | None
    description: str
    damping: float = 0.0
    law: str = LAW


CONFIGURATIONS: tuple[PhysicsConfig, ...] = (
    PhysicsConfig(
        "rigid rod",
        False,
        None,
        "impactlab.simulate: the paper's rigid rod (I_C = m L^2/12), one contact",
    ),
    PhysicsConfig(
        "flexible rod",
        True,
        None,
        "simulate_drop with FlexibleRod.paper() (Timoshenko, 8 axial + 2 residual + 12 bending "
        "modes, zeta = 0): the whole contact sequence",
    ),
    PhysicsConfig(
        "flexible rod + rate-dependent flat",
        True,
        "cowper-symonds",
        "as 'flexible rod', the flat's yield strength raised by the self-consistent "
        "Cowper-Symonds factor (mild steel, D = 40.4 1/s, q = 5)",
    ),
)


#: The FE-tabulated row (not calibrated: ``CONFIGURATIONS`` are). Rate-independent: a
#: rate-dependent flat raises S_y, which moves the pair off the one E*/S_y the FE curves hold
#: for (the tabulated law refuses a ContactModel with ``rate``), and no cited way scales an FE
#: curve of a hardening flat with the strain rate.
FE_TABULATED = PhysicsConfig(
    "flexible rod + FE-tabulated law (hardening flat)",
    True,
    None,
    "as 'flexible rod', the contact law tabulated from CalculiX indentations of the paper's "
    "pair to 1000 delta_c with AISI 1010's own strain hardening (Swift law 470 MPa "
    "(0.002 + eps_p)^0.070, derived from SAE J1397's cold-drawn S_y 305 and S_u 365 MPa by "
    "Considere's criterion; fe/data/hardening); rate-independent "
    "(a rate-raised S_y would leave the curves' E*/S_y; no cited way scales them with rate)",
    law=HARDENED_LAW,
)
#: Every row of the table: the configurations (also calibrated) and the FE-tabulated one.
ROWS: tuple[PhysicsConfig, ...] = (*CONFIGURATIONS, FE_TABULATED)


@cache
def _hardened_model(radius: float) -> ContactModel:
    """The FE-tabulated law of the paper's pair (hardening flat) for a tip of ``radius`` [m]."""
    return hardened_law(ContactPair(D.ROD_MATERIAL, D.FLAT_MATERIAL), radius)


def physics_inputs(angle_deg: int) -> dict[str, Any]:
    """The inputs shared by every configuration at ``angle_deg``: the paper's flat, law,
    friction, measured mu, angle [rad] and drop velocity (0, v_i) [m/s]."""
    x = D.EXPERIMENTS[angle_deg]
    return {
        "flat": D.FLAT_MATERIAL,
        "law": LAW,
        "friction": FRICTION,
        "mu": x.mu,
        "angle": x.angle,
        "velocity": (0.0, x.v_i),
    }


def _run_one(cfg: PhysicsConfig, angle_deg: int, history: bool) -> Any:
    args = physics_inputs(angle_deg)
    flat = args.pop("flat")
    if not cfg.flexible:
        return simulate(PAPER_ROD, flat, gravity=True, **args)
    body = FlexibleRod.paper(damping=cfg.damping)
    if cfg.law == HARDENED_LAW:
        args["law"] = _hardened_model(body.tip_radius)
    return simulate_drop(body, flat, gravity=True, rate=cfg.rate, history=history, **args)


def run_physics(
    angles: Iterable[int] = D.ANGLES_DEG,
    configurations: Iterable[PhysicsConfig] = ROWS,
    *,
    history_angle: int | None = 20,
) -> dict[tuple[str, int], Any]:
    """Every (configuration name, angle [deg]) drop: an ImpactResult (rigid) or a DropResult
    (flexible; with its history at ``history_angle``); ``angles``: of the paper's experiments
    (20, 45, 70 deg; ValueError for another)."""
    out: dict[tuple[str, int], Any] = {}
    angs = paper_angles(angles)
    for cfg in configurations:
        for ang in angs:
            out[(cfg.name, ang)] = _run_one(cfg, ang, history=ang == history_angle)
    return out


def _measured_row(angle_deg: int, T_ms: float) -> dict[str, Any]:
    x = D.EXPERIMENTS[angle_deg]
    return {
        "configuration": MEASURED,
        "angle [deg]": angle_deg,
        E_COLUMN: x.e,
        "delta_p [um]": abs(x.delta_p) * 1e6,
        SCAR_COLUMN: abs(x.L_s) * 1e6,
        "T [ms]": T_ms,
        "contacts": None,
        "F_max [N]": None,
        "rate factor": None,
        "vibration energy [J]": None,
        "flags": "",
        "max_delta_ratio": None,
    }


#: What the table's ``e`` column is, for every simulated row (the report states it).
E_DEFINITION = (
    "e is -v_n,out/v_n,in of the tip's rigid-body normal velocity with the gravity impulse of "
    "the contact (sequence) removed, for every simulated row (DropResult.e; for the rigid rod "
    "ImpactResult.e + g T/|v_i|, since ImpactResult.e keeps that impulse), as a ballistic fit "
    "of the measured rebound removes it"
)


def rigid_e_gravity_removed(res: Any) -> float:
    """The rigid engine's e (ImpactResult, gravity on: the gravity impulse m g T of the contact
    kept) with that impulse removed, as ``DropResult.e`` removes it: -(v_n,out + g T)/v_n,in.
    Gravity exerts no moment about the centre of mass, so it changes only v_y."""
    return float(e_gravity_removed(res.vn_in, res.vn_out, res.duration, G0))


def _simulated_row(cfg: PhysicsConfig, angle_deg: int, res: Any) -> dict[str, Any]:
    """A result in the table's units: L_s is the extent of the mark, as a scan measures it (the
    contact point's travel of a rigid impact, the scar length of a drop over all its contacts);
    T the contact duration (rigid) or first touch to last separation."""
    flexible = cfg.flexible
    dent = res.dent_depth if flexible else res.delta_p
    duration = res.sequence_duration if flexible else res.duration
    return {
        "configuration": cfg.name,
        "angle [deg]": angle_deg,
        E_COLUMN: res.e if flexible else rigid_e_gravity_removed(res),
        "delta_p [um]": abs(dent) * 1e6,
        SCAR_COLUMN: abs(res.scar_length if flexible else res.contact_travel) * 1e6,
        "T [ms]": duration * 1e3,
        "contacts": res.n_contacts if flexible else 1,
        "F_max [N]": res.max_force,
        "rate factor": res.rate_factor if flexible else 1.0,
        "vibration energy [J]": res.vibration_energy if flexible else 0.0,
        **flag_columns(res),
    }


def physics_table(
    runs: Mapping[tuple[str, int], Any],
    experimental: pd.DataFrame,
    configurations: Iterable[PhysicsConfig] = ROWS,
) -> pd.DataFrame:
    """The comparison: per angle the measured row (:data:`MEASURED`: T from the dent, Eq. 12,
    as in the experimental rows) and one row per configuration; display units (um, ms, N, J);
    e in :data:`E_COLUMN`, the mark's extent in :data:`SCAR_COLUMN`."""
    T_exp = experimental.set_index("angle [deg]")["T [ms]"]
    cfgs = tuple(configurations)
    rows: list[dict[str, Any]] = []
    for ang in sorted({a for _c, a in runs}):
        rows.append(_measured_row(ang, float(T_exp.loc[ang])))
        rows.extend(_simulated_row(c, ang, runs[(c.name, ang)]) for c in cfgs)
    table = pd.DataFrame(rows)
    table["contacts"] = table["contacts"].astype("Int64")  # blank for the measured rows
    return table
