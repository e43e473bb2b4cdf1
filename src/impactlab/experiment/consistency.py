"""Is an inferred impact duration or force plausible? The checks behind the warnings of
``impactlab analyze`` and ``impactlab invert``.

The paper's Eq. 12 infers the duration T from the dent and the rebound; its ± is the
measurement's uncertainty propagated through the formula, not the formula's own error. Two
independent references bound what T (and F = P_n / T) can be:

- the simulated impact with the measured initial state (the engine, any contact law): the
  contact laws and the finite-element reference agree on T within tens of percent
  (docs/laws/accuracy.md), so an inferred T or F more than ``PLAUSIBLE_RATIO`` times off the
  simulated one is not a model spread but a disagreement, reported with its factor;
- the single-impact assumption of the marker fits (docs/experiment.md, Limitations): the fits
  leave out the frames around the impact instant (``guard``), and a contact longer than that
  gap would reach into the fitted free flight.
"""

from __future__ import annotations

import math

from impactlab._display import format_number

__all__ = ["PLAUSIBLE_RATIO", "check_against_model", "check_single_impact", "times_text"]

#: An inferred T or F off the simulated one by more than this factor (either way) is reported.
PLAUSIBLE_RATIO = 3.0


def times_text(ratio: float) -> str:
    """``"34 times"`` or ``"1/34 of"``: how ``ratio`` (inferred / reference) reads."""
    if ratio >= 1.0:
        return f"{ratio:.3g} times"
    return f"1/{1.0 / ratio:.3g} of"


def _ms(seconds: float, digits: int = 5) -> str:
    return f"{format_number(seconds * 1e3, digits)} ms"


def check_against_model(
    duration: float,
    mean_force: float,
    *,
    model_duration: float | None,
    model_force: float | None,
    law: str,
    sigma_duration: float = 0.0,
    ratio: float = PLAUSIBLE_RATIO,
) -> list[str]:
    """One sentence per inferred quantity (T [s], F [N]) that is more than ``ratio`` times off
    the simulated impact's (None: not simulated), saying by how much."""
    out: list[str] = []
    note = (
        f" (the ± {_ms(sigma_duration, 2)} is the measurement's propagated uncertainty, not the "
        "error of Eq. 12)"
        if sigma_duration > 0
        else ""
    )
    pairs = (
        ("T", duration, model_duration, _ms, "duration"),
        ("F", mean_force, model_force, lambda f: f"{format_number(f)} N", "mean force"),
    )
    for name, inferred, simulated, text, what in pairs:
        if simulated is None or not (simulated > 0 and inferred > 0):
            continue
        if not (math.isfinite(inferred) and math.isfinite(simulated)):
            continue
        r = inferred / simulated
        if 1.0 / ratio <= r <= ratio:
            continue
        out.append(
            f"implausible {name}: the inferred {name} = {text(inferred)} is {times_text(r)} the "
            f"simulated impact's {what} {text(simulated)} ({law} law, the measured initial "
            f"state), beyond the factor {ratio:g} that separates the contact laws"
            + (note if name == "T" else "")
        )
    return out


def check_single_impact(duration: float, gap: float, guard: int) -> str | None:
    """The sentence when T [s] exceeds ``gap`` [s], the time between the last frame of the
    pre-impact fit and the first of the post-impact fit (``guard`` frames left out on each
    side); None when it fits."""
    if not (math.isfinite(duration) and math.isfinite(gap)) or duration <= gap:
        return None
    return (
        f"implausible T for one impact: T = {_ms(duration)} is {times_text(duration / gap)} the "
        f"{_ms(gap)} the marker fits leave out around the impact instant (guard = {guard} "
        "frames each side), so the contact would reach into the fitted free flight: the "
        "single-impact assumption does not hold for this T (raise guard, or doubt T)"
    )
