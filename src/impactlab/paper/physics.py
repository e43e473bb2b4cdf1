""" "Can physics explain the experiment?" (issue 11): the paper's three drops with the rigid rod,
the flexible rod and the flexible rod on a rate-dependent flat, side by side with the
measurements. Nothing is tuned: the paper's rod, drop velocities and measured mu (as the Coulomb
coefficient), the Ghaednia law with impactlab's defaults, the AISI 1010 flat, gravity on, no
damping. The model: docs/flexible.md.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import pandas as pd

from impactlab.bodies import PAPER_ROD, FlexibleRod
from impactlab.dynamics import simulate
from impactlab.dynamics.drop import simulate_drop
from impactlab.paper import data as D

__all__ = [
    "CONFIGURATIONS",
    "LAW",
    "MEASURED",
    "PhysicsConfig",
    "physics_inputs",
    "physics_table",
    "run_physics",
]

#: The contact law of every configuration (the paper's own law).
LAW = "ghaednia"
#: The friction model of every configuration (mu: the measured one of each drop).
FRICTION = "coulomb"
#: The configuration name of the measured rows.
MEASURED = "measured (paper)"


@dataclass(frozen=True)
class PhysicsConfig:
    """One physical model of the drop: its ``name``, whether the rod is ``flexible``, the flat's
    ``rate`` law (None: rate-independent) and the sentence that states it."""

    name: str
    flexible: bool
    rate: str | None
    description: str


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
    return simulate_drop(
        FlexibleRod.paper(), flat, gravity=True, rate=cfg.rate, history=history, **args
    )


def run_physics(
    angles: Iterable[int] = D.ANGLES_DEG,
    configurations: Iterable[PhysicsConfig] = CONFIGURATIONS,
    *,
    history_angle: int | None = 20,
) -> dict[tuple[str, int], Any]:
    """Every (configuration name, angle [deg]) drop: an ImpactResult (rigid) or a DropResult
    (flexible; with its history at ``history_angle``)."""
    out: dict[tuple[str, int], Any] = {}
    for cfg in configurations:
        for ang in angles:
            out[(cfg.name, ang)] = _run_one(cfg, ang, history=ang == history_angle)
    return out


def _measured_row(angle_deg: int, T_ms: float) -> dict[str, Any]:
    x = D.EXPERIMENTS[angle_deg]
    return {
        "configuration": MEASURED,
        "angle [deg]": angle_deg,
        "e": x.e,
        "delta_p [um]": abs(x.delta_p) * 1e6,
        "L_s [um]": abs(x.L_s) * 1e6,
        "T [ms]": T_ms,
        "contacts": None,
        "F_max [N]": None,
        "rate factor": None,
        "vibration energy [J]": None,
    }


def _simulated_row(cfg: PhysicsConfig, angle_deg: int, res: Any) -> dict[str, Any]:
    """A result in the table's units: L_s is the tip's sliding length (rigid) or the scar
    length (flexible); T the contact duration (rigid) or first touch to last separation."""
    flexible = cfg.flexible
    return {
        "configuration": cfg.name,
        "angle [deg]": angle_deg,
        "e": res.e,
        "delta_p [um]": abs(res.delta_p) * 1e6,
        "L_s [um]": abs(res.scar_length if flexible else res.sliding_length) * 1e6,
        "T [ms]": res.duration * 1e3,
        "contacts": res.n_contacts if flexible else 1,
        "F_max [N]": res.max_force,
        "rate factor": res.rate_factor if flexible else 1.0,
        "vibration energy [J]": res.vibration_energy if flexible else 0.0,
    }


def physics_table(
    runs: Mapping[tuple[str, int], Any],
    experimental: pd.DataFrame,
    configurations: Iterable[PhysicsConfig] = CONFIGURATIONS,
) -> pd.DataFrame:
    """The comparison: per angle the measured row (T from the dent, Eq. 12, as in the
    experimental rows) and one row per configuration; display units (um, ms, N, J)."""
    T_exp = experimental.set_index("angle [deg]")["T [ms]"]
    cfgs = tuple(configurations)
    rows: list[dict[str, Any]] = []
    for ang in sorted({a for _c, a in runs}):
        rows.append(_measured_row(ang, float(T_exp.loc[ang])))
        rows.extend(_simulated_row(c, ang, runs[(c.name, ang)]) for c in cfgs)
    table = pd.DataFrame(rows)
    table["contacts"] = table["contacts"].astype("Int64")  # blank for the measured rows
    return table
