""" "Can physics explain the experiment?": the paper's three drops with the rigid rod,
the flexible rod, the flexible rod on a rate-dependent flat (both of the product's rate laws for
this steel: Cowper-Symonds, an upper estimate, and Johnson-Cook, a lower one) and the flexible
rod with the FE-tabulated law of a strain-hardening flat, side by side with the measurements.
Every row's T is Eq. 12's inversion of its dent and scar, the measured rows' as the
simulated ones' (like for like), beside the simulated sequence's duration. Nothing is
tuned: the paper's rod, drop velocities and measured mu (as the Coulomb coefficient; each
row's own Eq. 28 mu, which a flexible rod does not return, beside it), the Ghaednia law with
impactlab's defaults, the AISI 1010 flat, gravity on, no damping (the FE-tabulated row: the
law tabulated from the FE indentation of the paper's pair with AISI 1010's own strain
hardening, ``impactlab.materials.hardening.AISI_1010_HARDENING``, derived from SAE J1397's
cold-drawn tensile properties; ``impactlab.fe.tabulated.hardened_law``). The model:
docs/flexible.md. Which configuration explains the drops best, with the posterior of the rod's
modal damping ratio, is the calibration of :mod:`impactlab.paper.calibration_report` (the
report's next section; it ranks :data:`ROWS`, not the Johnson-Cook row).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from functools import cache
from typing import Any

import pandas as pd

from impactlab.analytic.closed_forms import friction_from_velocities
from impactlab.bodies import PAPER_ROD, FlexibleRod
from impactlab.contact import ContactModel
from impactlab.dynamics import simulate
from impactlab.dynamics.derived import e_gravity_removed
from impactlab.dynamics.drop import simulate_drop
from impactlab.fe.tabulated import hardened_law
from impactlab.materials import G0, ContactPair
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import invert_case
from impactlab.paper.quantities import flag_columns
from impactlab.paper.simulations import paper_angles

__all__ = [
    "CONFIGURATIONS",
    "CONTACT_TIME_COLUMN",
    "DELTA_C_COLUMN",
    "E_COLUMN",
    "E_DEFINITION",
    "FE_TABULATED",
    "HARDENED_LAW",
    "LAW",
    "LIMIT_COLUMN",
    "MEASURED",
    "MU_COLUMN",
    "RATE_LOWER",
    "ROWS",
    "SCAR_COLUMN",
    "SEQUENCE_COLUMN",
    "TABLE_ROWS",
    "T_COLUMN",
    "PhysicsConfig",
    "apparent_mu",
    "eq12_duration",
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
#: The column of T: Eq. 12 solved for T from the row's own dent depth and scar (read as slip,
#: gravity neglected, the paper's rod: ``analytic_rows.invert_case``), for the measured rows and
#: the simulated ones alike, so that the two compare like for like (:func:`eq12_duration`).
T_COLUMN = "T [ms]"
#: The column of a simulation's sequence: first touch to last separation, the flights between
#: contacts included (``DropResult.sequence_duration``; the rigid rod: its one contact).
SEQUENCE_COLUMN = "sequence duration [ms]"
#: The column of a simulation's time in contact: the sum of its contacts' durations.
CONTACT_TIME_COLUMN = "time in contact [ms]"
#: The column of the paper's Eq. 28 mu = |dv_x| / (dv_y + g T) on the rod's rigid-body
#: velocities: the measured mu (the measured row) beside each simulated drop's own
#: (:func:`apparent_mu`), whose input, the local Coulomb coefficient, is the measured one.
MU_COLUMN = "mu_apparent (Eq. 28)"
#: The column of the row's own reference interference of ``max_delta_ratio``: Jackson-Green's
#: delta_c (paper Eq. 15) of its pair, the rate-dependent rows' with the rate-raised S_y [um].
DELTA_C_COLUMN = "delta_c [um]"
#: The column of the upper end of the row's law's range in ``max_delta_ratio``'s unit (the
#: row's own delta_c): verified against FE (``fitted_delta_ratio_max``), for the FE-tabulated
#: law the end of its curves, beyond which it is refused.
LIMIT_COLUMN = "range limit [delta_c]"


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
        "flexible rod + rate-dependent flat (Cowper-Symonds, upper estimate)",
        True,
        "cowper-symonds",
        "as 'flexible rod', the flat's yield strength raised by the self-consistent "
        "Cowper-Symonds factor (mild steel, D = 40.4 1/s, q = 5: constants of the initial yield "
        "stress, an upper estimate of the rate effect; docs/flexible.md)",
    ),
)
#: The flexible rod on the flat of the product's other rate law for this steel (not calibrated:
#: :data:`ROWS` are): the Johnson-Cook rate term of 1006 steel, fitted to large-strain flow
#: stress, a lower estimate; beside the Cowper-Symonds row, it bounds the rate effect.
RATE_LOWER = PhysicsConfig(
    "flexible rod + rate-dependent flat (Johnson-Cook, lower estimate)",
    True,
    "johnson-cook",
    "as 'flexible rod', the flat's yield strength raised by the self-consistent Johnson-Cook "
    "factor (1006 steel, C = 0.022, eps_dot_0 = 1 1/s: fitted to large-strain flow stress, a "
    "lower estimate of the rate effect; not in the calibration)",
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
#: The calibrated rows: the configurations and the FE-tabulated one (the shipped calibration).
ROWS: tuple[PhysicsConfig, ...] = (*CONFIGURATIONS, FE_TABULATED)
#: Every row of the table: :data:`ROWS` with the lower estimate of the rate effect.
TABLE_ROWS: tuple[PhysicsConfig, ...] = (*CONFIGURATIONS, RATE_LOWER, FE_TABULATED)


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
    configurations: Iterable[PhysicsConfig] = TABLE_ROWS,
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
        T_COLUMN: T_ms,
        MU_COLUMN: x.mu,
        SEQUENCE_COLUMN: None,
        CONTACT_TIME_COLUMN: None,
        "contacts": None,
        "F_max [N]": None,
        "rate factor": None,
        "vibration energy [J]": None,
        "flags": "",
        "max_delta_ratio": None,
        DELTA_C_COLUMN: None,
        LIMIT_COLUMN: None,
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


def eq12_duration(angle_deg: int, e: float, dent: float, scar: float) -> float:
    """Eq. 12's T [s] of a simulated drop at ``angle_deg``: the measured row's inversion
    (``analytic_rows.invert_case``: the paper's rod, the drop's v_i and mu, gravity neglected,
    the scar read as slip) of the simulation's own e, dent depth [m] and scar [m], so that it
    compares like for like with the measured row's T; NaN where Eq. 12 has no T (no dent,
    no scar)."""
    case = replace(D.EXPERIMENTS[angle_deg], e=e, delta_p=-abs(dent), L_s=-abs(scar))
    try:
        return float(invert_case(case).duration)
    except ValueError:  # a dent below 1 nm, a zero scar, e outside [0, 1]
        return float("nan")


def _simulated_row(cfg: PhysicsConfig, angle_deg: int, res: Any) -> dict[str, Any]:
    """A result in the table's units: L_s is the extent of the mark, as a scan measures it (the
    contact point's travel of a rigid impact, the scar length of a drop over all its contacts);
    T Eq. 12's from the row's own e, dent and scar (:func:`eq12_duration`); the sequence's
    duration (first touch to last separation; rigid: the contact) and time in contact."""
    flexible = cfg.flexible
    dent = res.dent_depth if flexible else res.delta_p
    scar = res.scar_length if flexible else res.contact_travel
    e = res.e if flexible else rigid_e_gravity_removed(res)
    duration = res.sequence_duration if flexible else res.duration
    touching = sum(c.duration for c in res.contacts) if flexible else res.duration
    return {
        "configuration": cfg.name,
        "angle [deg]": angle_deg,
        E_COLUMN: e,
        "delta_p [um]": abs(dent) * 1e6,
        SCAR_COLUMN: abs(scar) * 1e6,
        T_COLUMN: eq12_duration(angle_deg, e, dent, scar) * 1e3,
        MU_COLUMN: apparent_mu(res),
        SEQUENCE_COLUMN: duration * 1e3,
        CONTACT_TIME_COLUMN: touching * 1e3,
        "contacts": res.n_contacts if flexible else 1,
        "F_max [N]": res.max_force,
        "rate factor": res.rate_factor if flexible else 1.0,
        "vibration energy [J]": res.vibration_energy if flexible else 0.0,
        **flag_columns(res),
        DELTA_C_COLUMN: res.delta_max / res.max_delta_ratio * 1e6,
        LIMIT_COLUMN: _range_limit(cfg, res),
    }


def apparent_mu(res: Any) -> float:
    """The paper's Eq. 28 on a simulated drop's rigid-body velocities, gravity removed:
    |dv_x| / (dv_y + g T), the tangential over the normal impulse (``DropResult.mu_apparent``;
    a rigid impact's from its velocities and contact duration T [s])."""
    if hasattr(res, "mu_apparent"):
        return float(res.mu_apparent)
    (vx0, vy0), (vx1, vy1) = res.velocity_in, res.velocity_out
    return float(friction_from_velocities(vx1 - vx0, vy1 - vy0, duration=res.duration, g=G0))


def _range_limit(cfg: PhysicsConfig, res: Any) -> float:
    """The upper end of the row's law's range in delta_max / delta_c (the row's own delta_c):
    ``fitted_delta_ratio_max``; the FE-tabulated law, which has no fitted range, is refused
    beyond its curves' end: that end."""
    limit = float(res.fitted_delta_ratio_max)
    if cfg.law == HARDENED_LAW:
        model = _hardened_model(FlexibleRod.paper().tip_radius)
        limit = min(limit, model.max_interference / model.critical_interference)
    return limit


def physics_table(
    runs: Mapping[tuple[str, int], Any],
    experimental: pd.DataFrame,
    configurations: Iterable[PhysicsConfig] = TABLE_ROWS,
) -> pd.DataFrame:
    """The comparison: per angle the measured row (:data:`MEASURED`: T from the dent, Eq. 12,
    as in the experimental rows) and one row per configuration; display units (um, ms, N, J);
    e in :data:`E_COLUMN`, the mark's extent in :data:`SCAR_COLUMN`, Eq. 12's T of every row
    in :data:`T_COLUMN`, the simulated sequence's in :data:`SEQUENCE_COLUMN`, Eq. 28's mu in
    :data:`MU_COLUMN`; ``max_delta_ratio`` beside its row's delta_c (:data:`DELTA_C_COLUMN`) and
    its law's range in the same ratio (:data:`LIMIT_COLUMN`)."""
    T_exp = experimental.set_index("angle [deg]")["T [ms]"]  # Eq. 12 of the measured drop
    cfgs = tuple(configurations)
    rows: list[dict[str, Any]] = []
    for ang in sorted({a for _c, a in runs}):
        rows.append(_measured_row(ang, float(T_exp.loc[ang])))
        rows.extend(_simulated_row(c, ang, runs[(c.name, ang)]) for c in cfgs)
    table = pd.DataFrame(rows)
    table["contacts"] = table["contacts"].astype("Int64")  # blank for the measured rows
    return table
