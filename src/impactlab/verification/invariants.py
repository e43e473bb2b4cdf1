"""Invariants of every law and friction model on random drops of the paper's rod: the total
energy never rises, 0 <= e <= 1, 0 <= e* <= 1, 0 <= delta_p <= delta_max."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD
from impactlab.contact import builtin_law_names
from impactlab.dynamics import simulate
from impactlab.friction import friction_names
from impactlab.verification.table import TOLERANCES, VerificationTable, columns, worst_of

__all__ = ["energy_rise", "random_drops", "verify_invariants"]

_COLUMNS = columns(
    """
    law           | law
    friction      | friction
    n             | cases checked
    excluded      | reversal (excluded)
    rise          | max energy rise / E0             | .1e
    rise_excluded | energy rise / E0 of the excluded | .1e
    neg_diss      | max (-dissipated) / E0           | .1e
    e_min         | min(e, e*)                       | .4f
    e_max         | max e                            | .4f
    ee_max        | max e*                           | .4f
    dp_bad        | delta_p outside [0, delta_max]
    ok            | pass
    """
)


def random_drops(n: int, seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``n`` seeded random drops of the paper's rod: angle [rad] uniform in [0.1, pi/2], vertical
    velocity [m/s] uniform in [-2.5, -0.1], friction coefficient uniform in [0, 1]."""
    rng = np.random.default_rng(seed)
    th = rng.uniform(0.1, 0.5 * math.pi, n)
    vy = -rng.uniform(0.1, 2.5, n)
    mu = rng.uniform(0.0, 1.0, n)
    return th, vy, mu


def energy_rise(energy: Sequence[float] | np.ndarray) -> float:
    """The largest rise of a recorded total energy [J] above its running minimum, over the
    first row's energy (dimensionless, in E0)."""
    e = np.asarray(energy, dtype=float)
    return float(np.max(e - np.minimum.accumulate(e))) / e[0]


def _row(law: str, fr: str, th: np.ndarray, vy: np.ndarray, mu: np.ndarray) -> dict[str, Any]:
    """The checks of one law and friction model over the drops (angle ``th`` [rad], vertical
    velocity ``vy`` [m/s], friction ``mu``)."""
    tol = TOLERANCES["invariants"]
    tol_e = TOLERANCES["energy_history"]
    rise: list[float] = []
    rise_excl: list[float] = []
    diss: list[float] = []
    e_min, e_max, ee_max, dp_bad = math.inf, 0.0, 0.0, 0
    for i in range(len(th)):
        r = simulate(
            PAPER_ROD,
            law=law,
            friction=fr,
            mu=float(mu[i]),
            angle=float(th[i]),
            velocity=(0.0, float(vy[i])),
        )
        h = r.history
        if h is None:  # pragma: no cover - history=True is the default
            raise RuntimeError("simulate returned no history")
        energy = np.asarray(h.energy, dtype=float)
        r_rise = energy_rise(energy)
        if not 0.0 <= r.delta_p <= r.delta_max:
            dp_bad += 1
        if fr == "impulse_ratio" and r.regime == "reversal":
            rise_excl.append(r_rise)
            continue
        rise.append(r_rise)
        diss.append(-r.energy_dissipated / energy[0])
        e_min = min(e_min, r.e, r.e_energy)
        e_max = max(e_max, r.e)
        ee_max = max(ee_max, r.e_energy)
    e_checked = law != "hertz"
    ok = (
        worst_of(rise) <= tol_e
        and worst_of(diss) <= tol
        and e_min >= 0.0
        and ee_max <= 1.0 + tol
        and (e_max <= 1.0 + tol or not e_checked)
        and dp_bad == 0
    )
    return {
        "law": law,
        "friction": fr,
        "n": len(rise),
        "excluded": len(rise_excl),
        "rise": worst_of(rise),
        "rise_excluded": worst_of(rise_excl) if rise_excl else None,
        "neg_diss": max(0.0, worst_of(diss)),
        "e_min": e_min if rise else math.nan,
        "e_max": e_max if e_checked else f"{e_max:.4f} (not checked)",
        "ee_max": ee_max,
        "dp_bad": dp_bad,
        "ok": ok,
    }


def verify_invariants(
    n: int = 10,
    *,
    seed: int = 0,
    laws: Sequence[str] | None = None,
    frictions: Sequence[str] | None = None,
) -> VerificationTable:
    """Every law and friction model on ``n`` random drops of the paper's rod (angle in
    [0.1, pi/2], v in [0.1, 2.5] m/s, mu in [0, 1], no spin, no tangential velocity, gravity on,
    the rod free to turn), checked along the recorded history and at the end:

    * the total energy (kinetic + potential + stored elastic) never rises above its running
      minimum by more than ``TOLERANCES["energy_history"]`` E0, and the energy dissipated is
      >= -``TOLERANCES["invariants"]`` E0;
    * 0 <= e* <= 1 (energetic COR, Stronge) and 0 <= delta_p <= delta_max;
    * 0 <= e <= 1 for the dissipative laws. For the elastic ``hertz`` law e* = 1 and the
      kinematic e may exceed 1 by O(the rod's rotation during the contact), so only e >= 0 is
      checked there (with frozen lever arms e = 1, see the rigid-body limit).

    With the paper's impulse-ratio friction a slip reversal makes F_t = mu F_n push after the
    tip has stopped, which creates energy (a documented limitation of its Eq. 7); such cases are
    counted, their energy rise is shown, and they are left out of the energy and e checks.
    """
    th, vy, mu = random_drops(n, seed)
    tol = TOLERANCES["invariants"]
    tol_e = TOLERANCES["energy_history"]
    records = [
        _row(law, fr, th, vy, mu)
        for law in (builtin_law_names() if laws is None else laws)
        for fr in (friction_names() if frictions is None else frictions)
    ]
    worst = worst_of([r["rise"] for r in records])
    passed = all(r["ok"] for r in records)
    text = f"""
{n} random drops of the paper's rod (seed {seed}; angle uniform in [0.1, pi/2] rad, v_y uniform in
[-2.5, -0.1] m/s, mu uniform in [0, 1], no spin, no tangential velocity, gravity on, the rod free
to turn) for every law and friction model. Checked:

- along each recorded history, the total energy (kinetic + potential + elastic energy stored in
  the contact) never rises above its running minimum by more than {tol_e:g} E0 (100 times the
  default rtol). The largest rises sit in the last rows before separation, in rows sampled
  from the dense output inside the step that ends the contact: a power-law unloading curve
  ends with an unbounded second derivative at delta_r, which the step's interpolant does not
  follow to rtol. They are numerical: over 600 random drops per law and friction model (drawn
  as here, seeds 1 and 2; every law, `impulse_ratio` without its reversals, `coulomb`, `mindlin`
  and `partial_slip`; `tools/energy_history_study.py`, last run) the largest was 1.4e-5 E0 at
  the default rtol of 2e-7 (`kogut-komvopoulos`, `mindlin`, a reversal; 6e-7 at most with
  `partial_slip` at its 3e-8), and on that drop 1.1e-7, 7.3e-8, 2.5e-8 and 3.8e-9 E0 at rtol
  1e-7, 1e-8, 1e-9 and 1e-10. A real energy source is orders of magnitude larger (see the
  excluded cases). The energy dissipated is >= -{tol:g} E0;
- 0 <= e* <= 1 + {tol:g} (energetic COR, Stronge) and 0 <= delta_p <= delta_max;
- 0 <= e <= 1 + {tol:g} for the dissipative laws. For the elastic `hertz` law e* = 1 and the
  kinematic e exceeds 1 slightly because the rod turns during the contact and changes its lever
  arms (with the lever arms frozen e = 1 within 1e-6, the rigid-body limit's tolerance above),
  so only e >= 0 is checked there.

With the paper's `impulse_ratio` friction (Eq. 7) a slip reversal (mu above mu_c) keeps
F_t = mu F_n pushing after the tip has stopped and creates energy, a documented limitation of
the paper's model (every such result is flagged ENERGY_GAIN): those cases are counted, their
energy rise is shown, and they are excluded from the other checks.
"""
    return VerificationTable(
        "invariants",
        "Invariants of every law and friction model",
        text,
        _COLUMNS,
        tuple(records),
        "energy rise / E0 along the histories (and dissipation, e, e*, delta_p per row)",
        worst,
        tol_e,
        passed,
    )
