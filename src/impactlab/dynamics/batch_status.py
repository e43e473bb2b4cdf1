"""What every batch of results says about each case: computed or not, ok, flagged, and why.

One meaning for ``ok`` across the result family: a case is ok when it was computed (status 0)
and carries no flag but the advisory ones (``impactlab.flags.ADVISORY_FLAGS``), as
``ImpactResult.ok`` and ``DropResult.ok`` say for one result. ``computed`` is the status mask
alone. ``BatchResult`` (impacts) and ``DropBatchResult`` (flexible-rod drops) share it, with
the words of a case refused for its inputs (``case_refusals``: the input, its value and its
rule) and the notebook summary (``batch_summary_html``, ``BatchResult``'s for a drop batch).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from impactlab.bodies import Rod, Sphere
from impactlab.dynamics.batch_fields import flagged_messages
from impactlab.dynamics.export import batch_html
from impactlab.dynamics.input_checks import contact_reach, degrees_hint, mu_problem, past_normal
from impactlab.dynamics.kernels.inputs import (
    IN_MU,
    IN_OK,
    INPUT_RULES,
    RTOL_MIN,
    input_problem,
    problem_text,
)
from impactlab.dynamics.kernels.layout import OUTPUT_FIELDS
from impactlab.dynamics.kernels.status import (
    ST_BAD_ANGLE,
    ST_BAD_INPUT,
    ST_NOT_APPROACHING,
    STATUS_MESSAGES,
)
from impactlab.flags import ADVISORY_FLAGS


def flag_column(values: np.ndarray) -> np.ndarray:
    """A float ``flags`` column as the ``ResultFlag`` bitmask of each case (int64; 0 where the
    column is NaN, a failed case, whose status says why)."""
    f = np.asarray(values, dtype=np.float64)
    return np.where(np.isfinite(f), f, 0.0).astype(np.int64)


#: The outputs that hold integer codes or counts (held as floats in a batch's ``out``).
INTEGER_FIELDS = ("regime", "flags", "n_steps", "n_contacts", "next_end", "n_jumps", "n_dents")


def integer_series(values: np.ndarray, computed: np.ndarray) -> Any:
    """An integer-coded column (flags, regime, counts) as a pandas nullable ``Int64`` Series:
    integers where the case was computed, ``<NA>`` where it failed (its status says why), as
    pandas marks a missing integer; never floats."""
    import pandas as pd  # heavy, needed only here

    f = np.asarray(values, dtype=np.float64)
    keep = np.asarray(computed, dtype=bool) & np.isfinite(f)
    ints = np.where(keep, f, 0.0).astype(np.int64)
    return pd.Series(pd.arrays.IntegerArray(ints, ~keep))


def batch_summary_html(batch: Any, renamed: Mapping[str, str]) -> str:
    """The notebook summary of a batch whose outputs are not ``BatchResult``'s columns (a
    ``DropBatchResult``) through ``BatchResult``'s own (``export.batch_html``: the counts of
    its ``repr``, statistics over its ok cases): each output that ``batch_html`` reads by an
    impact's name (``OUTPUT_FIELDS``) taken from the batch's field of that meaning,
    ``renamed[name]`` (a drop's sequence totals) or the same name (NaN where it has none),
    shown under the batch's names and class."""
    n = len(batch.status)
    columns = []
    for name in OUTPUT_FIELDS:
        try:
            columns.append(np.asarray(batch[renamed.get(name, name)], dtype=np.float64))
        except KeyError:  # an output the batch has not: no row of the summary reads it
            columns.append(np.full(n, np.nan))
    out = np.stack(columns, axis=1) if n else np.empty((0, len(OUTPUT_FIELDS)))
    return batch_html(batch, title=type(batch).__name__, names=renamed, out=out)


#: The inputs of each case of a batch, in the order a refusal names the first non-finite one.
CASE_NAMES = ("angle", "vx", "vy", "spin", "mu")


def case_refusals(
    body: Rod | Sphere, cases: Mapping[str, np.ndarray], refused: np.ndarray
) -> dict[int, str]:
    """Why each case ``refused`` (indices) of a batch (``cases``: the columns of
    :data:`CASE_NAMES`) is refused for its inputs, by index, as a batch of drops words it
    (``drop_checks.case_problem``): the first non-finite input, else the first outside its
    rule (``kernels.inputs.input_problem``, the rule the compiled core applies; mu worded as
    ``simulate`` words it, ``input_checks.mu_problem``); a case whose inputs break none is left
    out. The batch's gravity and rtol are checked before it runs (ValueError), so allowed
    values stand in for them."""
    why: dict[int, str] = {}
    rod, reach = isinstance(body, Rod), contact_reach(body)
    for i in np.asarray(refused, dtype=np.int64).tolist():
        case = {name: float(cases[name][i]) for name in CASE_NAMES}
        bad = next((n for n, v in case.items() if not math.isfinite(v)), None)
        if bad is not None:
            why[i] = f"{bad} = {case[bad]!r} is not finite"
            continue
        th, vx, vy, w, mu = case.values()
        problem = input_problem(rod, th, vx, vy, w, reach, mu, 0.0, RTOL_MIN)
        if problem == IN_MU:  # in the words of simulate's ValueError
            why[i] = mu_problem(mu)
        elif problem != IN_OK:
            why[i] = problem_text(problem, case[INPUT_RULES[problem][0]])
    return why


class BatchStatus:
    """``computed``, ``ok``, ``flagged`` and ``messages`` from the ``status`` (int, 0: computed)
    and ``flags`` (``ResultFlag`` bits) of each case, which the class provides."""

    status: np.ndarray
    #: why each case refused for its inputs (ST_BAD_INPUT) is refused, by case index: the input
    #: and its rule (``case_refusals``, ``drop_checks.case_problem``); for another status the
    #: case's whole message (an engine failure in the words of ``simulate``'s or
    #: ``simulate_drop``'s ValueError)
    refusals: Mapping[int, str]
    if TYPE_CHECKING:  # each batch class has its own (a property, or a dataclass field)

        @property
        def flags(self) -> np.ndarray: ...

    @property
    def computed(self) -> np.ndarray:
        """Boolean mask of the cases that ran to a result (status 0; ``messages`` says why
        not)."""
        return np.asarray(self.status) == 0

    @property
    def ok(self) -> np.ndarray:
        """Boolean mask of the cases whose result may be read as plain success: computed, and
        no flag but the advisory ones (``ImpactResult.ok``: an energy gain or a gravity-dominated
        contact is not ok; a law beyond its verified range is ok and flagged)."""
        return self.computed & ((self.flags & ~ADVISORY_FLAGS) == 0)

    @property
    def flagged(self) -> np.ndarray:
        """Boolean mask of the computed cases that carry a flag (``impactlab.flags``)."""
        return self.computed & (self.flags != 0)

    @property
    def messages(self) -> list[str]:
        """The status message of each case (``kernels.status.STATUS_MESSAGES``); a case the
        engine stopped (status 1, 3, 5, 6, 9; a drop's 11-15) as ``simulate``'s or
        ``simulate_drop``'s error words it, with the case's own values (the law's limit, the
        approach speed, the gravity; a drop's steps and time) and what to change
        (``refusals``); a case refused for its inputs names the input, its value and its rule:
        ST_BAD_INPUT (``refusals``), ST_BAD_ANGLE (the angle, in rad and deg) and
        ST_NOT_APPROACHING (the contact point's normal velocity ``vn_in``, else vy and the
        spin); a computed case that is not ``ok`` names its flags instead of ``"ok"``
        (``batch_fields.flagged_messages``: ``"computed, not ok (flags 17): energy gain, beyond
        the tip"``), in ``BatchResult`` and ``DropBatchResult`` alike."""
        texts = [STATUS_MESSAGES.get(int(s), f"status {int(s)}") for s in self.status]
        for i, why in self.refusals.items():
            texts[i] = f"invalid input: {why}" if int(self.status[i]) == ST_BAD_INPUT else why
        status = np.asarray(self.status)
        for j in np.flatnonzero((status == ST_BAD_ANGLE) | (status == ST_NOT_APPROACHING)):
            if int(j) not in self.refusals:
                texts[j] = f"{texts[j]}: {self._refused_values(int(j))}"
        return flagged_messages(texts, self.flags, self.ok)

    def _refused_values(self, i: int) -> str:
        """The inputs of case ``i`` that its status (ST_BAD_ANGLE, ST_NOT_APPROACHING) reads."""
        inputs: Mapping[str, np.ndarray] = getattr(self, "inputs", {})
        th, vy, w = (
            float(inputs[k][i]) if k in inputs else math.nan for k in ("angle", "vy", "spin")
        )
        if int(self.status[i]) == ST_BAD_ANGLE:  # past the normal: what it means, as in simulate
            beyond = past_normal(th, False) if 0.5 * math.pi < th < math.pi else ""
            return f"angle = {th!r} rad = {math.degrees(th):.4g} deg{beyond}{degrees_hint(th)}"
        try:
            vn = float(self["vn_in"][i])  # type: ignore[index]
        except KeyError:  # a batch without the contact point's velocity
            vn = math.nan
        if math.isfinite(vn):
            return f"vn = {vn:+} m/s"
        return f"vy = {vy!r} m/s, spin = {w!r} rad/s, angle = {th!r} rad"
