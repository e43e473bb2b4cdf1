"""Randomised flexible drops (a seeded sample over modes, laws, friction, rate, angles down to
0.001 deg, both ends with ``stop="flight"``): no missed contact, no e < 0 or energy gain
without a flag, finite outputs, 0 <= delta_p <= delta_max, the contacts' works adding up to
the drop's; a failure is a one-line
ValueError, never another exception. The larger run: benchmarks/bench_flexible_fuzz.py."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import DropError, simulate_drop
from impactlab.dynamics.flexcore import layout as F
from impactlab.flags import ENERGY_GAIN_RTOL_FACTOR, ENERGY_ROUNDOFF

N_DROPS = 200
#: (n_axial, n_bending, axial_residual): few, so that each modal basis is built once
MODES = ((0, 0, False), (1, 1, True), (2, 4, True), (3, 0, False), (8, 12, True))
LAWS = ("ghaednia", "jackson-green", "kogut-komvopoulos", "brake", "thornton", "hertz")
FRICTION = ("coulomb", "impulse_ratio", "mindlin", "partial_slip")


def _case(rng: np.random.Generator) -> dict[str, Any]:
    n_axial, n_bending, residual = MODES[int(rng.integers(0, len(MODES)))]
    law = str(rng.choice(LAWS))
    rate_models = (None, None, "cowper-symonds", "johnson-cook")
    return {
        "body": FlexibleRod.paper(
            n_axial=n_axial,
            n_bending=n_bending,
            axial_residual=residual,
            damping=float(rng.choice([0.0, 0.02])),
        ),
        "law": law,
        "friction": str(rng.choice(FRICTION)),
        "mu": float(rng.choice([0.0, rng.uniform(0.0, 0.6)])),
        "rate": None if law == "hertz" else rate_models[int(rng.integers(0, 4))],
        "angle": math.radians(float(10.0 ** rng.uniform(-3.0, math.log10(90.0)))),
        "velocity": (float(rng.uniform(-0.5, 0.5)), -float(10.0 ** rng.uniform(-0.5, 0.6))),
        "spin": float(rng.choice([0.0, rng.uniform(-10.0, 10.0)])),
        "stop": "flight" if rng.random() < 0.3 else "sequence",
    }


def _check(r: Any) -> list[str]:
    bad = []
    values = (
        r.e,
        r.dent_depth,
        r.delta_max,
        r.sequence_duration,
        r.vibration_energy,
        r.sequence_mean_force,
    )
    if not all(math.isfinite(v) for v in values):
        bad.append(f"non-finite output {values}")
    if not 0.0 <= r.dent_depth <= r.delta_max:
        bad.append(f"delta_p {r.dent_depth} outside [0, delta_max {r.delta_max}]")
    works = r.initial_energy + abs(r.work_normal) + abs(r.work_friction)
    for name in ("work_normal", "work_friction"):  # each contact's are its end's own
        total = sum(getattr(c, name) for c in r.contacts)
        if abs(total - getattr(r, name)) > 1e-9 * works:
            bad.append(f"the contacts' {name} add up to {total}, the drop's is {getattr(r, name)}")
    if r.ok:
        if not r.e >= 0.0:
            bad.append(f"e = {r.e} < 0 without a flag")
        e_end = r.rigid_kinetic_energy + r.vibration_energy + r.potential_energy
        scale = r.initial_energy + r.rigid_kinetic_energy + r.vibration_energy
        scale += abs(r.potential_energy)
        tol = (ENERGY_GAIN_RTOL_FACTOR * F.DROP_DEFAULT_RTOL + ENERGY_ROUNDOFF) * scale
        if e_end - r.initial_energy > tol:
            bad.append(f"energy gain {e_end / r.initial_energy - 1:.3g} E0 without a flag")
    if r.history is not None:  # the tip never deeper than its deepest dent with zero force
        h = r.history
        dr = max(d.delta_p for d in r.dents if d.end == 0)
        over = float(((h["penetration_0"] - dr) * (h["normal_force_0"] == 0.0)).max(initial=0.0))
        if over > 1e-5 * r.delta_max:
            bad.append(f"tip {over:.3g} m inside its dent with zero force")
    return bad


def test_random_drops_are_trustworthy() -> None:
    rng = np.random.default_rng(20261128)
    anomalies = []
    results = refused = 0
    for i in range(N_DROPS):
        case = _case(rng)
        body = case.pop("body")
        try:
            r = simulate_drop(body, history=i % 8 == 0, **case)
        except DropError as exc:
            refused += 1
            if exc.status == F.ST_MISSED_CONTACT or "\n" in str(exc):
                anomalies.append((case, str(exc)))
            continue
        except ValueError as exc:  # a refused input: one line, naming it
            refused += 1
            if "\n" in str(exc):
                anomalies.append((case, str(exc)))
            continue
        results += 1
        anomalies.extend((case, what) for what in _check(r))
    assert not anomalies, anomalies[:5]
    assert results >= N_DROPS // 2
