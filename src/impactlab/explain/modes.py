"""Whether a flexible row is converged in the rod's modes: every ok run of a flexible
configuration runs again with twice its mode counts (n_axial, n_bending; at most
``impactlab.bodies.flexible_rod.MAX_MODES`` = 128 per family), and the change of each value it
predicts is set against the measurement's sigma. A change above :data:`MODE_SHIFT_MAX` sigma
marks the row "not converged in modes" (``summary``'s ``modes_converged`` False and its
``caveat``); its numbers stay those of the counts it ran with. A family already at the limit
is not doubled (the caveat names the counts run, not "twice the modes").

A row whose counts are both at the limit cannot be checked: ``modes_converged`` stays empty
and its caveat says "not checked in modes". It runs once more with half its counts, the
previous refinement: where that step moves a value by more than :data:`MODE_SHIFT_MAX`
sigma, the caveat says "not checked in modes, may not be converged" and a verdict that ranks
the row is provisional (``explain.verdict``).

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
from impactlab.bodies.flexible_rod import MAX_MODES
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.explain.configurations import Configuration
from impactlab.explain.runs import Outcome, run_on_drop, scaled_modes

__all__ = [
    "MODES_CAVEAT",
    "MODES_UNCHECKED",
    "MODES_UNSETTLED",
    "MODE_SHIFT_MAX",
    "REFINE",
    "ModeCheck",
    "check_modes",
]

#: A flexible row is not converged in modes when twice its mode counts move a predicted value
#: by more than this many of the measurement's sigma [1].
MODE_SHIFT_MAX = 0.5
#: The factor of the mode counts of the check's second run.
REFINE = 2
#: The words that begin the caveat of a row not converged in modes.
MODES_CAVEAT = "not converged in modes"
#: The words that begin the caveat of a row at the mode limit (no check was run).
MODES_UNCHECKED = "not checked in modes"
#: ... of such a row whose previous refinement (half its counts) moved a value too far.
MODES_UNSETTLED = f"{MODES_UNCHECKED}, may not be converged"


@dataclass(frozen=True)
class ModeCheck:
    """A flexible run checked in its modes: ``modes`` and ``refined`` ((n_axial, n_bending)
    of the run and of its second run with twice them, each at most ``MAX_MODES``), the second
    run's ``status`` ("ok" or why not), each predicted quantity's value with the run's counts
    (``values``) and with the refined ones (``refined_values``), SI, and its ``shifts`` =
    |refined - value| / sigma [1]. ``capped``: the run's counts are at the limit, so the
    second run has half of them (the previous refinement) and the row is not checked."""

    modes: tuple[int, int]
    refined: tuple[int, int]
    status: str
    values: Mapping[str, float]
    refined_values: Mapping[str, float]
    shifts: Mapping[str, float]
    capped: bool = False

    @property
    def converged(self) -> bool | None:
        """The second run is ok and moves no predicted value by more than
        :data:`MODE_SHIFT_MAX` sigma; None for a row at the limit (not checked)."""
        if self.capped:
            return None
        return self.status == "ok" and all(s <= MODE_SHIFT_MAX for s in self.shifts.values())

    def _moved(self) -> list[str]:
        return [
            f"{q} moves from {_shown(q, self.values[q])} to {_shown(q, self.refined_values[q])} "
            f"({format_number(s, 3)} sigma)"
            for q, s in self.shifts.items()
            if s > MODE_SHIFT_MAX
        ]

    def caveat(self) -> str:
        """The row's caveat ("" when converged): what twice the modes (or the counts run, for
        a family at the limit) change; for a row at the limit, that it is not checked and what
        its previous refinement changed."""
        tail = f"the row's numbers are those of {self.modes} modes"
        if self.capped:
            return self._capped_caveat(tail)
        if self.converged:
            return ""
        doubled = self.refined == (2 * self.modes[0], 2 * self.modes[1])
        more = "twice the modes," if doubled else "more modes,"
        head = f"{MODES_CAVEAT}: with {more} {self.refined} for {self.modes},"
        if self.status != "ok":
            return f"{head} the run is {self.status}; {tail}"
        return f"{head} {', '.join(self._moved())}, more than {MODE_SHIFT_MAX} sigma; {tail}"

    def _capped_caveat(self, tail: str) -> str:
        """The caveat of a row at the limit: not checked, and what the step from half its
        counts (``refined``, its values ``refined_values``) to them changed."""
        why = (f"the mode counts {self.modes} are at the limit ({MAX_MODES} per family), so no "
               "run with more modes was made")  # fmt: skip
        if self.status != "ok":
            return f"{MODES_UNCHECKED}: {why}; the run with {self.refined} is {self.status}; {tail}"
        moved = [
            f"{q} moves from {_shown(q, self.refined_values[q])} to {_shown(q, self.values[q])} "
            f"({format_number(s, 3)} sigma)"
            for q, s in self.shifts.items()
            if s > MODE_SHIFT_MAX
        ]
        step = f"from {self.refined} modes to {self.modes},"
        if not moved:
            return (f"{MODES_UNCHECKED}: {why}; {step} no predicted value moves by more than "
                    f"{MODE_SHIFT_MAX} sigma; {tail}")  # fmt: skip
        return (f"{MODES_UNSETTLED}: {why}; {step} {', '.join(moved)}, more than "
                f"{MODE_SHIFT_MAX} sigma; {tail}")  # fmt: skip


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
    None for a rigid configuration or a run that is not ok. Counts at the limit in both
    families: the run with half of them instead (``ModeCheck.capped``); None where those are
    the same counts too."""
    counts = outcome.mode_counts
    if not (config.flexible and outcome.ok and counts is not None):
        return None
    capped = scaled_modes(counts, REFINE) == counts  # the counts cannot grow
    factor = 1 / REFINE if capped else REFINE
    if capped and scaled_modes(counts, factor) == counts:
        return None
    again = run_on_drop(config, drop, law, friction, refine=factor)
    refined = again.mode_counts or counts
    values = {
        q: v
        for q, v in outcome.values.items()
        if q in drop.quantities and q not in outcome.unsupported
    }
    if not again.ok:
        return ModeCheck(counts, refined, again.status, values, {}, {}, capped)
    moved = {q: again.values[q] for q in values}
    shifts = {q: abs(moved[q] - v) / float(drop.sigma[q][0]) for q, v in values.items()}
    return ModeCheck(counts, refined, "ok", values, moved, shifts, capped)
