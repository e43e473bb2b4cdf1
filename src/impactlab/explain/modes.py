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

How far a row not converged could still move (:meth:`ModeCheck.least_z`, which the verdict
asks before it is called provisional for such a row: :func:`provisional_text`): its
converged value is taken to lie within :data:`MODE_REACH` = 4 times the measured shift of its
finer run's value. If each doubling of the modes shrinks the truncation error by at least a
fifth (a ratio r <= 0.8 of successive shifts), the error left after the finer run is at most
r / (1 - r) <= 4 shifts. The slender rod of docs/explain.md, the slowest measured, shrinks it
by 23 % (e 0.3518, 0.3254, 0.3052 at 1, 2 and 4 times its counts: shifts 0.0264 and
0.0202, r = 0.77, 3.3 shifts left).

When a verdict is provisional (:func:`provisional_text`): a ranked flexible row not converged in
its modes, or at the mode limit with a last step that moved a value, makes it so only where
more modes could change it, and a named row with another caveat (a rigid rod whose rod the
flexible rows refuse) always does. A row not converged changes the verdict only through its own
values. The rows that decide the verdict (the first of the ranking, the rows it is undecided
between, those that agree with more values than the first) count whenever they are not
converged. Another such row counts only where it is within reach (:class:`Standing`): with each
of its values moved as far towards the measured one as :meth:`ModeCheck.least_z` allows (where
the check gives no bound, all the way), it would have more values within 2 sigma than the first
over the quantities ranked, or a chi2 over them no higher than the first's (for correlated
values a lower bound of it, ``explain.correlated.chi2_floor``), or agree with more of the
drop's measured values than the first. A row out of reach in all three can neither rank above
the first nor make the verdict undecided or withheld, however its modes settle: its caveat
stays in the notes, and the verdict stays plain.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import pandas as pd

from impactlab._display import display_unit, format_number
from impactlab.bodies.flexible_rod import MAX_MODES
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.quantities import MEASURABLE
from impactlab.explain.configurations import Configuration
from impactlab.explain.correlated import Pairs, chi2_floor
from impactlab.explain.runs import Outcome, run_on_drop, scaled_modes
from impactlab.explain.tables import WITHIN

__all__ = [
    "MODES_CAVEAT",
    "MODES_UNCHECKED",
    "MODES_UNSETTLED",
    "MODE_REACH",
    "MODE_SHIFT_MAX",
    "REFINE",
    "ModeCheck",
    "Standing",
    "check_modes",
    "provisional_text",
]

#: A flexible row is not converged in modes when twice its mode counts move a predicted value
#: by more than this many of the measurement's sigma [1].
MODE_SHIFT_MAX = 0.5
#: A row's converged value lies within this many of its measured shifts of its finer run's
#: value [1] (module docstring: a doubling of the modes shrinks the error by a fifth or more).
MODE_REACH = 4.0
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

    def least_z(self, quantity: str, z: float) -> float | None:
        """The least |z| that ``quantity``, at ``z`` with the run's counts, can reach once
        converged: |z| of the finer run's value (the refined one; a row at the limit: its own)
        less :data:`MODE_REACH` times the shift, at least 0. None where the check gives no
        bound (its second run is not ok, or it did not check the quantity)."""
        if self.status != "ok" or quantity not in self.shifts:
            return None
        shift = self.shifts[quantity]
        fine = z
        if not self.capped:
            fine = z + math.copysign(shift, self.refined_values[quantity] - self.values[quantity])
        return max(0.0, abs(fine) - MODE_REACH * shift)

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


@dataclass(frozen=True)
class Standing:
    """What a row out of reach must not attain: the first's count ``within`` over the ranked
    ``common`` quantities, its ``chi2`` over them, its ``agreements`` over all the drop's
    measured values; ``got`` the ok predictions (the comparison's rows), ``modes`` each row's
    mode check (None: no bound known) and ``pairs`` the drop's correlation coefficients."""

    common: tuple[str, ...]
    within: int
    chi2: float
    agreements: int
    got: pd.DataFrame
    modes: Mapping[str, ModeCheck | None] | None
    pairs: Pairs

    def in_reach(self, name: str) -> bool:
        """Whether the row ``name``, its values moved as its mode check allows, could change
        the verdict (module docstring)."""
        check = None if self.modes is None else self.modes.get(name)
        if check is None:
            return True
        own = self.got[self.got["configuration"] == name]
        least = {}
        for q, z in zip(own["quantity"], own["z"], strict=True):
            bound = check.least_z(str(q), float(z))
            least[str(q)] = 0.0 if bound is None or math.isnan(bound) else bound
        ranked = {q: least[q] for q in self.common if q in least}
        count = sum(v <= WITHIN for v in ranked.values())
        agreements = sum(v <= WITHIN for v in least.values())
        return (
            count > self.within
            or chi2_floor(ranked, self.pairs) <= self.chi2
            or agreements > self.agreements
        )


def _names(items: Sequence[str]) -> str:
    return ", ".join(items)


def _is(rows: Sequence[str]) -> str:
    return "is" if len(rows) == 1 else "are"


def provisional_text(
    ok: pd.DataFrame,
    ranked: Sequence[str],
    deciding: Sequence[str],
    named: Sequence[str],
    standing: Standing,
) -> str:
    """What the reason adds ("" for nothing): the ``ranked`` rows not converged in modes (or at
    the limit and unsettled) that are ``deciding`` or within reach of ``standing``, and the
    other caveat of a ``named`` row."""
    caveats = {str(n): str(c) for n, c in zip(ok["configuration"], ok["caveat"], strict=True)}
    flagged = {str(n) for n, v in zip(ok["configuration"], ok["modes_converged"], strict=True)
               if not pd.isna(v) and not v}  # fmt: skip

    def counts(n: str) -> bool:
        return n in deciding or standing.in_reach(n)

    parts = []
    rows = [n for n in ranked if n in flagged and counts(n)]
    if rows:
        parts.append(
            f"{_names(rows)} {_is(rows)} {MODES_CAVEAT} (its mode check moves a value by more "
            f"than {MODE_SHIFT_MAX} sigma: see the caveat), and more modes (the drop's n_axial, "
            "n_bending) can change this verdict"
        )
    rows = [n for n in ranked if caveats.get(n, "").startswith(MODES_UNSETTLED) and counts(n)]
    if rows:
        parts.append(
            f"{_names(rows)} {_is(rows)} {MODES_UNCHECKED} (at the mode limit), and the last "
            f"doubling of the modes moved a value by more than {MODE_SHIFT_MAX} sigma (see the "
            "caveat)"
        )
    for n in named:
        c = caveats.get(n, "")
        if c and n not in flagged and not c.startswith(MODES_UNCHECKED):
            parts.append(f"{n} carries a caveat: {c}")
    return f"; provisional: {'; '.join(parts)}" if parts else ""
