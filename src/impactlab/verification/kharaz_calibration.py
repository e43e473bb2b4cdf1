"""Calibrating mu on real data: Kharaz, Gorham & Salman (2001), tangential restitution and
rebound spin of 5 mm alumina spheres on glass at 3.9 m/s (``verification.data.kharaz2001``),
against the coefficient of friction the authors measured independently, mu = 0.092.

The drops: one per digitised point (8 of e_t, 7 of |omega|), incidence angle theta from the
normal, v = 3.9 m/s (vx = v sin theta, vy = -v cos theta), no gravity, the Hertz law with the
elastic constants of ``verification.partial_slip`` (Di Renzo & Di Maio's table for this
experiment). The measured spin is a magnitude; the engine's spin of a sphere moving towards +x
is clockwise (negative), so spin_out = -|omega|. The sources give no scatter: the standard
uncertainties (``KGS_SIGMAS``: 0.03 in e_t, 30 rad/s in spin) are this module's assumption
(digitising and impact-to-impact scatter), and the width of the posterior of mu scales with
them; the ranking and the posterior median barely do.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from impactlab.calibrate import Calibration, Measurements, calibrate, parse_parameter
from impactlab.calibrate.sampler import ProgressFn
from impactlab.verification.data.kharaz2001 import KGS_ET, KGS_OMEGA
from impactlab.verification.partial_slip import ALUMINA, GLASS, KGS_MU, KGS_SPEED

__all__ = [
    "KGS_MODELS",
    "KGS_MU",
    "KGS_SIGMAS",
    "kharaz_calibration",
    "kharaz_measurements",
]

#: Assumed standard uncertainties of the digitised means: e_t [-], spin_out [rad/s].
KGS_SIGMAS = {"e_t": 0.03, "spin_out": 30.0}
#: The candidate models: partial slip (Mindlin-Deresiewicz, one ``simulate`` per case),
#: Coulomb and Mindlin's tangential stiffness (both in the compiled batch).
KGS_MODELS = ("hertz/partial_slip", "hertz/mindlin", "hertz/coulomb")


def _materials() -> dict[str, Any]:
    """The sphere and the anvil as overrides of a preset (every property the Hertz law and the
    sphere use)."""
    out: dict[str, Any] = {"body": "sphere", "radius": 2.5e-3}
    for side, m in (("body", ALUMINA), ("flat", GLASS)):
        out[f"{side}_E"] = m.E
        out[f"{side}_nu"] = m.nu
        out[f"{side}_yield_strength"] = m.yield_strength
    out["body_density"] = ALUMINA.density
    return out


def kharaz_measurements(sigmas: dict[str, float] | None = None) -> Measurements:
    """The digitised means as a measurements set (one drop per point)."""
    s = {**KGS_SIGMAS, **(sigmas or {})}
    base = _materials()
    records = []
    for quantity, table, sign in (("e_t", KGS_ET, 1.0), ("spin_out", KGS_OMEGA, -1.0)):
        for theta_deg, value in table:
            th = math.radians(float(theta_deg))
            records.append(
                {
                    **base,
                    "label": f"{quantity} {theta_deg:g} deg",
                    "vx": KGS_SPEED * math.sin(th),
                    "vy": -KGS_SPEED * math.cos(th),
                    quantity: sign * float(value),
                    f"{quantity}_sigma": s[quantity],
                }
            )
    return Measurements.from_records(records)


def kharaz_calibration(
    models: Sequence[str] = KGS_MODELS,
    *,
    walkers: int = 8,
    steps: int = 300,
    seed: int = 0,
    progress: ProgressFn | None = None,
    state_dir: Any = None,
) -> Calibration:
    """mu ~ uniform(0, 0.5) calibrated on the Kharaz data for each model, ranked by PSIS-LOO;
    compare the posterior of mu with the measured ``KGS_MU`` = 0.092."""
    return calibrate(
        kharaz_measurements(),
        [parse_parameter("mu", "uniform(0, 0.5)")],
        list(models),
        walkers=walkers,
        steps=steps,
        seed=seed,
        engine={"gravity": False},
        progress=progress,
        state_dir=state_dir,
    )


def summary_rows(cal: Calibration) -> list[dict[str, Any]]:
    """Per model: median and 90 % interval of mu, whether it holds the measured 0.092, the
    PSIS-LOO rank and elpd."""
    ranks = {r["model"]: r for r in cal.ranking}
    rows = []
    for name, post in cal.posteriors.items():
        s = post.summary["mu"]
        r = ranks.get(name, {})
        rows.append(
            {
                "model": name,
                "mu_median": s["median"],
                "mu_q05": s["q05"],
                "mu_q95": s["q95"],
                "holds_measured": bool(s["q05"] <= KGS_MU <= s["q95"]),
                "rank": r.get("rank", np.nan),
                "elpd_loo": r.get("elpd_loo", np.nan),
            }
        )
    return rows
