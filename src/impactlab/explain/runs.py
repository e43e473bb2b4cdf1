"""One configuration run on one measured drop, through the calibration's own prediction.

Each (drop, configuration) is one ``simulate`` call (a rigid impact, or a flexible rod's whole
drop), made inside ``impactlab.calibrate.models.predict`` with no free parameter: predict builds
the case (the drop's inputs, its materials as the calibration completes them, its body), reads
every measured quantity from the result as the calibration reads it (a rigid impact's e with
the gravity impulse of its contact removed, the scar as the mark's extent, a dent as the drop's
final dent, ...) and gives a case whose result is flagged invalidating its status, so that
explain and calibrate cannot disagree about what a model predicts. The evaluator handed to
predict (:class:`_OneCase`) runs the case as the calibration runs its one-by-one cases and keeps
the whole result, whose sequence (contacts, Eq. 28's mu, the law's range) the explanation shows.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab.analytic.closed_forms import friction_from_velocities
from impactlab.bodies.flexible_rod import MAX_MODES, FlexibleRod
from impactlab.calibrate.measurements import Measurements

# the calibration's own case builder and output reader: one definition of a model's prediction
from impactlab.calibrate.models import (
    STATUS_REFUSED,
    CandidateModel,
    case_body,
    output_value,
    predict,
    simulate_row,
    status_message,
    whole_materials,
)
from impactlab.contact.kernels import P_ESTAR, P_NU, P_R, P_SY
from impactlab.contact.rate import RateLaw
from impactlab.dynamics.drop_result import RATE_DOUBT, DropResult
from impactlab.dynamics.input_checks import gravity_value
from impactlab.explain.configurations import Configuration
from impactlab.flags import FLAG_LAW_EXTRAPOLATED
from impactlab.materials import Material, first_yield_factor
from impactlab.sweep.flexible import FLEXIBLE_BODY
from impactlab.sweep.models import Statics, material_for

__all__ = ["Outcome", "drop_alone", "drop_flat", "run_on_drop", "scaled_modes"]


@dataclass(frozen=True)
class Outcome:
    """A configuration on one drop: ``status`` ("ok", or why not: refused, flagged, not run),
    ``ok``, the predicted ``values`` (quantity -> SI value; NaN where not predicted),
    ``unsupported`` quantities (the model defines none of them), the ``result`` (an
    ImpactResult or DropResult; None when nothing ran), ``law_extrapolated``, the
    ``warnings`` the run emitted, ``body_refused`` (the drop's body was refused before the
    run: a rod the flexible rod does not accept), a flexible rod's ``mode_counts`` (n_axial,
    n_bending; None for a rigid body or a body not built) and ``modes``, the check of those
    counts (``explain.modes.ModeCheck``; None: not checked)."""

    status: str
    ok: bool
    values: Mapping[str, float]
    unsupported: tuple[str, ...] = ()
    result: Any = None
    law_extrapolated: bool = False
    warnings: tuple[str, ...] = ()
    body_refused: bool = False
    mode_counts: tuple[int, int] | None = None
    modes: Any = None

    @property
    def ran(self) -> bool:
        """True when the run produced a result (ok or flagged; not a refused run or one that
        did not run)."""
        return self.result is not None


def scaled_modes(counts: tuple[int, int], factor: float) -> tuple[int, int]:
    """The mode ``counts`` (n_axial, n_bending) times ``factor`` (rounded up), each at most
    ``MAX_MODES``."""
    axial, bending = counts
    return (min(MAX_MODES, math.ceil(axial * factor)),
            min(MAX_MODES, math.ceil(bending * factor)))  # fmt: skip


class _OneCase:
    """The Evaluator predict calls: each case through ``simulate``, as the calibration's
    one-by-one cases (``calibrate.models``), keeping the result, the refusal and the warnings;
    a FlexibleRod with its mode counts times ``refine`` (1: as built), the (n_axial,
    n_bending) of each run in ``modes``."""

    identity = "explain"

    def __init__(self, rate: RateLaw | None, refine: float = 1) -> None:
        self.rate = rate
        self.refine = refine
        self.results: list[Any] = []
        self.refusals: list[str] = []
        self.warnings: list[str] = []
        self.body_refused = False
        self.modes: list[tuple[int, int]] = []

    def output_fields(self) -> tuple[str, ...]:
        return ()

    def status_messages(self) -> dict[int, str]:
        return {}

    def regimes(self) -> dict[int, str]:
        return {}

    def integer_outputs(self) -> tuple[str, ...]:
        return ()

    def validate(self, categories: Mapping[str, Sequence[str]]) -> None:
        return None

    def __call__(
        self, cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
    ) -> tuple[dict[str, np.ndarray], np.ndarray]:
        n = len(cases["angle"])
        res = {o: np.full(n, np.nan) for o in outputs}
        status = np.zeros(n, dtype=np.int32)
        for i in range(n):
            row = {k: float(v[i]) for k, v in cases.items()}
            result = self._run(statics, row)
            self.results.append(result)
            if result is None:
                status[i] = STATUS_REFUSED
                continue
            for o in outputs:
                res[o][i] = output_value(result, o)
        return res, status

    def _run(self, statics: Statics, row: Mapping[str, float]) -> Any:
        cat = statics.categories
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                body = case_body(cat, row)
            except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
                self.refusals.append(str(exc))
                self.body_refused = True
                self.warnings += [str(w.message) for w in caught]
                return None
            if isinstance(body, FlexibleRod):
                built = (int(body.n_axial or 0), int(body.n_bending or 0))
                na, nb = scaled_modes(built, self.refine)
                if self.refine != 1:
                    body = dataclasses.replace(body, n_axial=na, n_bending=nb)
                self.modes.append((na, nb))
            try:
                return simulate_row(body, statics, row, self.rate)
            except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
                self.refusals.append(str(exc))
                return None
            finally:
                self.warnings += [str(w.message) for w in caught]


def drop_alone(meas: Measurements, d: int) -> Measurements:
    """Drop ``d`` of ``meas`` alone, with only the quantities it measured and its correlation
    coefficients."""
    measured = [q for q in meas.quantities if math.isfinite(meas.observed[q][d])]
    return Measurements(
        (meas.labels[d],),
        (meas.categories[d],),
        {k: v[d : d + 1].copy() for k, v in meas.inputs.items()},
        {q: meas.observed[q][d : d + 1].copy() for q in measured},
        {q: meas.sigma[q][d : d + 1].copy() for q in measured},
        meas.source,
        {
            (a, b): x[d : d + 1].copy()
            for (a, b), x in meas.correlation.items()
            if a in measured and b in measured and not math.isnan(x[d])
        },
    )


def drop_flat(meas: Measurements, d: int) -> Material:
    """The flat of drop ``d`` as its cases get it: the library material, or one whose
    properties the drop's columns set (``flat_yield_strength``, ...)."""
    cases = {k: v[d : d + 1].copy() for k, v in meas.inputs.items()}
    cat = whole_materials(dict(meas.categories[d]), cases)
    return material_for("flat", cat["flat_material"], {k: float(v[0]) for k, v in cases.items()})


def run_on_drop(
    config: Configuration,
    drop: Measurements,
    law: str,
    friction: str = "coulomb",
    refine: float = 1,
) -> Outcome:
    """``config`` with the contact ``law`` and ``friction`` on the one-drop ``drop``
    (:func:`drop_alone`): predict with no free parameter, through :class:`_OneCase`; a
    flexible rod with its mode counts times ``refine`` (1: as FlexibleRod builds them; 1/2:
    half of them, rounded up)."""
    model = CandidateModel(law, friction, FLEXIBLE_BODY if config.flexible else None)
    case = _OneCase(config.rate, refine)
    pred = predict(model, drop, (), np.empty((1, 0)), evaluator=case)
    unsupported = tuple(model.unsupported(drop.quantities))
    values = {q: float(v[0, 0]) for q, v in pred.values.items()}
    code = int(pred.status[0, 0])
    result = case.results[0] if case.results else None
    notes = tuple(dict.fromkeys(case.warnings))
    counts = case.modes[0] if case.modes else None
    doubt = [w for w in getattr(result, "warnings", ()) if w.startswith(RATE_DOUBT)]
    if code == 0 and doubt:  # a drop whose rate factor did not converge: not ok
        extrapolated = bool(pred.extrapolated is not None and pred.extrapolated[0, 0])
        return Outcome(f"not ok: {doubt[0]}", False, values, unsupported, result, extrapolated,
                       notes, case.body_refused, counts)  # fmt: skip
    if code == 0:
        extrapolated = bool(pred.extrapolated is not None and pred.extrapolated[0, 0])
        return Outcome("ok", True, values, unsupported, result, extrapolated, notes,
                       case.body_refused, counts)  # fmt: skip
    why = case.refusals[0] if code == STATUS_REFUSED and case.refusals else status_message(code)
    word = "refused" if code == STATUS_REFUSED else "not ok"
    extrapolated = result is not None and bool(int(result.flags) & FLAG_LAW_EXTRAPOLATED)
    return Outcome(f"{word}: {why}", False, values, unsupported, result, extrapolated, notes,
                   case.body_refused, counts)  # fmt: skip


def sequence_values(result: Any, gravity: float | bool = True) -> dict[str, Any]:
    """What the run's whole sequence says beside the predictions: ``n_contacts`` (the number
    of contacts, the tip's and the other end's, re-contacts of a ringing rod included; a rigid
    impact: 1), ``mu_apparent`` (the paper's Eq. 28 on the rigid-body velocities, the gravity
    impulse removed), ``max_delta_ratio`` and the law's range ``fitted_delta_ratio_max`` (in
    the law's own reference), ``law_range`` (that range in words: verified against FE or its
    stand-in), ``delta_c`` (Jackson-Green's critical interference of the pair the law ran
    with, a rate row's with its rate-raised S_y [m]), ``rate_factor``, ``strain_rate`` (a rate
    row's [1/s]; NaN for another) and the ``flags``; None values when nothing ran."""
    if result is None:
        return dict.fromkeys(
            ("n_contacts", "mu_apparent", "max_delta_ratio", "fitted_delta_ratio_max",
             "law_range", "delta_c", "rate_factor", "strain_rate", "flags"),
        )  # fmt: skip
    drop = isinstance(result, DropResult)
    return {
        "n_contacts": int(result.n_contacts) if drop else 1,
        "mu_apparent": float(result.mu_apparent) if drop else _rigid_mu(result, gravity),
        "max_delta_ratio": float(result.max_delta_ratio),
        "fitted_delta_ratio_max": float(result.fitted_delta_ratio_max),
        "law_range": result.law_range,
        "delta_c": _delta_c(result),
        "rate_factor": float(result.rate_factor) if drop else 1.0,
        "strain_rate": float(result.strain_rate) if drop and result.rate else math.nan,
        "flags": int(result.flags),
    }


def _delta_c(result: Any) -> float:
    """Jackson-Green's delta_c = (pi C(nu) S_y / (2 E*))^2 R [m] (the paper's Eq. 15) of the
    pair the result's law ran with (E*, tip radius, the S_y and nu of the body that yields
    first; a rate row's flat rate-raised); NaN where the law's parameters are not known."""
    law = getattr(result, "_law", None)
    params = law[1] if law is not None else getattr(result, "_law_params", None)
    if params is None:
        return math.nan
    p = np.asarray(params, dtype=np.float64)
    c = first_yield_factor(float(p[P_NU]))
    return float((math.pi * c * p[P_SY] / (2.0 * p[P_ESTAR])) ** 2 * p[P_R])


def _rigid_mu(result: Any, gravity: float | bool) -> float:
    """Eq. 28 of a rigid impact: |dv_x| / (dv_y + g T); NaN where the impulse does not lift."""
    (vx0, vy0), (vx1, vy1) = result.velocity_in, result.velocity_out
    try:
        mu = friction_from_velocities(
            vx1 - vx0, vy1 - vy0, duration=result.duration, g=gravity_value(gravity)
        )
    except ValueError:
        return math.nan
    return float(mu)
