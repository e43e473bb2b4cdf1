"""Whether a flexible row is converged in the rod's modes: every ok run of a flexible
configuration runs again with twice its mode counts (n_axial, n_bending; at most
``impactlab.bodies.flexible_rod.MAX_MODES`` = 128 per family), and the change of each value it
predicts is set against the measurement's sigma. A change above :data:`MODE_SHIFT_MAX` sigma
marks the row "not converged in modes" (``summary``'s ``modes_converged`` False and its
``caveat``); its numbers stay those of the counts it ran with.

Why half a sigma: the verdict of a row is its z and whether |z| <= 2; a truncation of the
modes that moves a prediction by half a sigma or more moves z by as much, and can move a
value across the 2-sigma line. Twice the counts shows that the counts are off, not how far
(docs/flexible.md, "Convergence and the default": twice the counts can itself be 6-25 % from
four times), so the bound is set well below the 2-sigma band. The second run costs about 1.7
times the first (measured on the paper's three drops: docs/explain.md).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from impactlab._display import display_unit, format_number
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.explain.configurations import Configuration
from impactlab.explain.runs import Outcome, run_on_drop, scaled_modes

__all__ = ["MODES_CAVEAT", "MODE_SHIFT_MAX", "REFINE", "ModeCheck", "check_modes"]

#: A flexible row is not converged in modes when twice its mode counts move a predicted value
#: by more than this many of the measurement's sigma [1].
MODE_SHIFT_MAX = 0.5
#: The factor of the mode counts of the check's second run.
REFINE = 2
#: The words that begin the caveat of a row not converged in modes.
MODES_CAVEAT = "not converged in modes"


@dataclass(frozen=True)
class ModeCheck:
    """A flexible run checked in its modes: ``modes`` and ``refined`` ((n_axial, n_bending)
    of the run and of its second run with twice them), the second run's ``status`` ("ok" or
    why not), each predicted quantity's value with the run's counts (``values``) and with the
    refined ones (``refined_values``), SI, and its ``shifts`` = |refined - value| / sigma
    [1]."""

    modes: tuple[int, int]
    refined: tuple[int, int]
    status: str
    values: Mapping[str, float]
    refined_values: Mapping[str, float]
    shifts: Mapping[str, float]

    @property
    def converged(self) -> bool:
        """The second run is ok and moves no predicted value by more than
        :data:`MODE_SHIFT_MAX` sigma."""
        return self.status == "ok" and all(s <= MODE_SHIFT_MAX for s in self.shifts.values())

    def caveat(self) -> str:
        """The row's caveat ("" when converged): what twice the modes change."""
        if self.converged:
            return ""
        head = f"{MODES_CAVEAT}: with twice the modes, {self.refined} for {self.modes},"
        tail = f"the row's numbers are those of {self.modes} modes"
        if self.status != "ok":
            return f"{head} the run is {self.status}; {tail}"
        moved = [
            f"{q} moves from {_shown(q, self.values[q])} to {_shown(q, self.refined_values[q])} "
            f"({format_number(s, 3)} sigma)"
            for q, s in self.shifts.items()
            if s > MODE_SHIFT_MAX
        ]
        return f"{head} {', '.join(moved)}, more than {MODE_SHIFT_MAX} sigma; {tail}"


def _shown(quantity: str, value: float) -> str:
    """``value`` (SI) of a measured ``quantity`` in its display unit, with the unit."""
    unit = display_unit(quantity, MEASURABLE[quantity].unit)
    text = format_number(value * unit.scale, 4)
    return text if unit.unit in ("-", "1", "") else f"{text} {unit.unit}"


def check_modes(
    config: Configuration, drop: Measurements, law: str, friction: str, outcome: Outcome
) -> ModeCheck | None:
    """The check of ``outcome``, ``config`` on the one-drop ``drop``: the run again with its
    mode counts times :data:`REFINE`, each predicted value's change over the drop's sigma.
    None for a rigid configuration, a run that is not ok, or counts already at the limit."""
    counts = outcome.mode_counts
    if not (config.flexible and outcome.ok and counts is not None):
        return None
    if scaled_modes(counts, REFINE) == counts:
        return None  # the counts cannot grow
    again = run_on_drop(config, drop, law, friction, refine=REFINE)
    refined = again.mode_counts or counts
    values = {
        q: v
        for q, v in outcome.values.items()
        if q in drop.quantities and q not in outcome.unsupported
    }
    if not again.ok:
        return ModeCheck(counts, refined, again.status, values, {}, {})
    moved = {q: again.values[q] for q in values}
    shifts = {q: abs(moved[q] - v) / float(drop.sigma[q][0]) for q, v in values.items()}
    return ModeCheck(counts, refined, "ok", values, moved, shifts)
