"""What a calibration checks in its own chains: convergence (R-hat, the autocorrelation time,
and whether they can be assessed at all), a posterior piled against a bound of its prior, and
the texts of a measured value shown in its display unit."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.calibrate.priors import Parameter, possible_range

__all__ = [
    "EDGE_MASS",
    "EDGE_SHARE",
    "MISFIT_SIGMAS",
    "RHAT_MAX",
    "TAU_MULTIPLE",
    "convergence_notes",
    "edge_note",
    "misfit_text",
    "misfits",
    "shown",
]

#: R-hat above this: the walkers have not mixed.
RHAT_MAX = 1.05
#: A chain shorter than this many autocorrelation times is too short (emcee's advice).
TAU_MULTIPLE = 50
#: The outer share of a prior's mass at each bound, and the share of posterior draws in it
#: above which the posterior lies against that bound (2.5 times the prior's own share: a
#: posterior equal to its prior puts 2 % there, one cut off by the bound far more).
EDGE_MASS = 0.02
EDGE_SHARE = 0.05


def convergence_notes(summary: Mapping[str, Mapping[str, float]], steps: int) -> list[str]:
    """One line per parameter whose chain has not converged (R-hat > RHAT_MAX, shorter than
    TAU_MULTIPLE autocorrelation times) or cannot be assessed (too few draws per walker:
    R-hat, ESS or the autocorrelation time is not a number)."""
    notes = []
    for n, s in summary.items():
        if not (math.isfinite(s["rhat"]) and math.isfinite(s["ess_bulk"])):
            notes.append(
                f"{n}: R-hat and ESS not assessable (too few draws per walker after burn-in; "
                "ArviZ needs at least 4): convergence unknown, run more steps"
            )
        elif s["rhat"] > RHAT_MAX:
            notes.append(f"{n}: R-hat {s['rhat']:.3f} > {RHAT_MAX} (run more steps)")
        if not math.isfinite(s["tau"]):
            notes.append(
                f"{n}: autocorrelation time not assessable (chain too short): run more steps"
            )
        elif s["tau"] * TAU_MULTIPLE > steps:
            notes.append(
                f"{n}: chain shorter than {TAU_MULTIPLE} autocorrelation times ({s['tau']:.0f})"
            )
    return notes


def shown(name: str, unit: str, x: float, digits: int = 4) -> str:
    """``x`` (in ``unit``) in the display unit of ``name`` with that unit: ``"49.52 um"``."""
    d = display_unit(name, unit)
    u = "" if d.unit in ("", "1", "-") else f" {d.unit}"
    return f"{format_number(x * d.scale, digits)}{u}"


def edge_note(p: Parameter, draws: np.ndarray) -> str | None:
    """A line when the posterior draws of ``p`` pile against a finite bound of its prior
    (more than EDGE_SHARE of them in the outer EDGE_MASS of the prior's mass there), or None.
    The bound is the prior's choice (widen it) or the parameter's possible range (the data
    favour the limit)."""
    x = np.asarray(draws, dtype=np.float64)
    x = x[np.isfinite(x)]
    if x.size == 0:
        return None
    u = p.cdf(x)
    lo, hi = possible_range(p.name)
    for side, share, bound, limit in (
        ("upper", float(np.mean(u > 1.0 - EDGE_MASS)), p.high, hi),
        ("lower", float(np.mean(u < EDGE_MASS)), p.low, lo),
    ):
        if not (math.isfinite(bound) and share > EDGE_SHARE):
            continue
        at = shown(p.name, p.unit, bound)
        why = (
            f"the {'largest' if side == 'upper' else 'smallest'} possible value: the data favour "
            "the limit"
            if bound == limit
            else "the prior cuts it off: widen the prior if "
            f"{'larger' if side == 'upper' else 'smaller'} values are possible"
        )
        return (
            f"{p.name}: the posterior lies against the {side} bound of its prior ({at}; "
            f"{100 * share:.0f} % of the draws in the prior's outer {100 * EDGE_MASS:.0f} %): "
            f"{why}"
        )
    return None


def misfit_text(r: Mapping[str, Any]) -> str:
    """A posterior predictive row's best fit against the measured value, in display units."""
    q, u = r["quantity"], r["unit"]
    return (
        f"{r['drop']} {q}: best fit {shown(q, u, r['best'])} is {r['z_best']:+.1f} sigma from "
        f"the measured {shown(q, u, r['observed'])}"
    )


#: A best fit farther than this many standard uncertainties from a measured value is a misfit.
MISFIT_SIGMAS = 5.0


def misfits(posteriors: Mapping[str, Any]) -> list[str]:
    """One line per measured value that no model's best fit comes within MISFIT_SIGMAS of
    (``posteriors``: model name -> ModelPosterior), in display units."""
    worst: dict[tuple[str, str], tuple[float, str, Mapping[str, Any]]] = {}
    for name, p in posteriors.items():
        for r in p.ppc:
            key, z = (r["drop"], r["quantity"]), abs(r["z_best"])
            z = z if math.isfinite(z) else math.inf
            if key not in worst or z < worst[key][0]:
                worst[key] = (z, name, r)
    lines = []
    for (d, q), (z, name, r) in worst.items():
        if z <= MISFIT_SIGMAS:
            continue
        show = display_unit(q, r["unit"])  # dent-scale lengths in um, as the tables
        unit = "" if show.unit in ("1", "", "-") else f" {show.unit}"
        value, sigma, best = (format_number(r[k] * show.scale, n)
                              for k, n in (("observed", 4), ("sigma", 2), ("best", 4)))  # fmt: skip
        lines.append(
            f"no model reproduces {d} {q} = {value} +- {sigma}{unit}: the closest best fit "
            f"({name}: {best}{unit}) is {z:.1f} sigma away"
        )
    return lines
