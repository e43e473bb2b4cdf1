"""The checks of a flexible-rod drop: its inputs (body, friction, tolerance, stop, and each
case's kinematics as a status), its failure as a ``DropError`` with the status and a hint, the
energy balance against the tolerance, and the result flags (docs/flexible.md, "Flags")."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from impactlab._validation import check_finite, check_positive, did_you_mean
from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.contact.brittle import brittle_flags
from impactlab.contact.ranges import law_extrapolated
from impactlab.contact.rate import get_rate_law
from impactlab.dynamics.drop_gravity import e_lifted_by_gravity
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.batch import sequence_flags
from impactlab.dynamics.input_checks import (
    DROP_RTOL_MAX,
    PARTIAL_SLIP_RTOL_MAX,
    check_mu,
    contact_reach,
    degrees_hint,
    mu_problem,
    warn_degrees,
)
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.kernels.inputs import (
    IN_ANGLE,
    IN_GRAVITY,
    IN_MU,
    IN_OK,
    IN_RTOL,
    IN_SPIN,
    IN_VX,
    IN_VY,
    RTOL_MAX,
    RTOL_MIN,
    input_problem,
    problem_text,
)
from impactlab.flags import ENERGY_GAIN_RTOL_FACTOR, ENERGY_ROUNDOFF, ResultFlag
from impactlab.friction import FrictionKind, FrictionModel, get_friction

#: Smallest normal approach speed of the tip the drop integrates [m/s]: the Hertzian depth and
#: time scales of the integrator (delta* ~ v^0.8) underflow below about 1e-100 m/s; far above
#: that, every drop below about 1 cm/s is gravity-dominated (flagged).
MIN_APPROACH_SPEED = 1e-9

#: ``stop`` values: the tip's sequence (the other end's landing is a new impact), or the whole
#: flight through the other end's impacts until the rod flies off.
STOP_MODES = ("sequence", "flight")


def check_body(body: Any) -> FlexibleRod | Rod:
    if not isinstance(body, FlexibleRod | Rod):
        raise ValueError(f"body must be an impactlab FlexibleRod or Rod, got {type(body).__name__}")
    return body


#: The friction models of the drop integrator (``impactlab.dynamics.flexcore.friction``).
DROP_FRICTION: tuple[FrictionKind, ...] = (FrictionKind.IMPULSE_RATIO, FrictionKind.COULOMB)
DROP_FRICTION += (FrictionKind.MINDLIN, FrictionKind.PARTIAL_SLIP)


def check_friction(friction: str, mu: float) -> tuple[FrictionModel, float]:
    fric = get_friction(friction)
    if fric.kind not in DROP_FRICTION:
        names = ", ".join(repr(str(k)) for k in DROP_FRICTION)
        raise ValueError(f"friction: the drop integrator implements {names}, got {friction!r}")
    return fric, check_mu(mu)


def refuse_rate(rate: Any, caller: str) -> None:
    """ValueError for a ``rate`` law given to the batch ``caller`` (None and ``"none"``, no
    law, pass; a ``rate`` that is no law gets ``get_rate_law``'s error): the flat's
    self-consistent rate factor is iterated drop by drop, each case to its own, where a batch
    runs every case in one compiled call (studies take no rate law either)."""
    if get_rate_law(rate) is not None:
        raise ValueError(
            f"rate={rate!r}: {caller} takes no rate-dependent flat, since its self-consistent "
            "rate factor is iterated drop by drop (each case its own) and the batch runs every "
            f"case in one compiled call; run simulate_drop(body, flat, rate={rate!r}, ...) for "
            "each case"
        )


def drop_rtol(rtol: Any, friction: FrictionModel | None = None) -> float:
    """The relative tolerance of a drop: ``rtol``, checked, or ``DROP_DEFAULT_RTOL`` for None;
    in [``RTOL_MIN``, ``DROP_RTOL_MAX``] = [1e-13, 1e-5], the drop's own range (the rigid
    engine's reaches 1e-3; ``input_checks``: beyond 1e-5 the integrator creates energy and
    contacts; the 70 deg drop of the paper's rod at rtol 5e-4 had 6 contacts instead
    of 2 and 4.8 % of E0 created), with ``friction`` partial slip ``PARTIAL_SLIP_RTOL_MAX``,
    the rigid engine's cap: the paper's drops at rtol 1e-5 keep the contacts of rtol 1e-9
    and e, the dent and the slip within 0.04 %, at 1e-3 the 20 deg one has 8 contacts
    instead of 5 and an energy error of 9 %. Every refusal names the drop's range (outside the
    rigid engine's range too: "must lie in"; within it, above 1e-5: "too loose")."""
    r = check_finite("rtol", rtol if rtol is not None else F.DROP_DEFAULT_RTOL)
    allowed = f"[{RTOL_MIN:g}, {DROP_RTOL_MAX:g}]"
    default = f"the drop's default is {F.DROP_DEFAULT_RTOL:g}"
    if not RTOL_MIN <= r <= RTOL_MAX:  # outside every engine's range too
        raise ValueError(f"rtol must lie in {allowed} for a drop ({default}), got {float(r)!r}")
    partial_slip = friction is not None and friction.kind is FrictionKind.PARTIAL_SLIP
    if partial_slip and r > PARTIAL_SLIP_RTOL_MAX:
        raise ValueError(
            f"rtol {r:g} is too loose for friction 'partial_slip' (allowed: up to "
            f"{PARTIAL_SLIP_RTOL_MAX:g}, as in the rigid engine; {default}): beyond it the "
            "Mindlin-Deresiewicz cells' events outrun the steps and the contacts and the energy "
            "balance go wrong"
        )
    if r > DROP_RTOL_MAX:
        raise ValueError(
            f"rtol {r:g} is too loose for a drop (allowed: up to {DROP_RTOL_MAX:g}, a drop's "
            f"rtol in {allowed}; {default}): beyond it the integrator's error no longer "
            "shrinks with rtol, it creates energy and contacts that a tighter rtol does not have"
        )
    return r


#: The status messages of a drop (``kernels.status.STATUS_MESSAGES``), ST_BAD_INPUT's with the
#: drop's own rtol range, [1e-13, 1e-5] (the table gives every engine's, up to 1e-3): the
#: meanings of a drop batch's status codes.
DROP_STATUS_MESSAGES: dict[int, str] = S.STATUS_MESSAGES | {
    S.ST_BAD_INPUT: S.STATUS_MESSAGES[S.ST_BAD_INPUT].replace(
        "rtol in [1e-13, 1e-3]", "rtol in [1e-13, 1e-5] for a drop"
    )
}


def check_stop(stop: Any, time_limit: Any) -> tuple[float, int]:
    """(time_limit [s], the compiled stop mode)."""
    if stop not in STOP_MODES:
        hint = did_you_mean(stop, STOP_MODES)
        raise ValueError(f"stop must be one of {', '.join(STOP_MODES)}, got {stop!r}{hint}")
    return check_positive("time_limit", time_limit, "s"), STOP_MODES.index(stop)


#: The keywords a drop's error tells the user to change: ``{time_limit}`` in a message's
#: template.
DROP_KEYWORDS = ("time_limit", "rtol", "friction")


def _literal(text: str) -> str:
    """``text`` as a literal part of a ``DropError`` template (its braces doubled)."""
    return text.replace("{", "{{").replace("}", "}}")


#: The kinematic inputs of a case, in the order of ``case_problem``'s ``case``.
CASE_INPUTS = ("angle", "vx", "vy", "spin", "mu")


def case_problem(
    half_length: float,
    reach: float,
    case: tuple[float, float, float, float, float],
    gravity: float,
    rtol: float,
) -> tuple[int, str]:
    """(status, why) of one case's inputs (angle [rad], vx, vy [m/s], spin [rad/s], mu) as
    ``simulate_drop`` refuses them, ``(ST_OK, "")`` when it runs: the rules of every impact
    (``kernels.inputs.input_problem``, with ``gravity`` [m/s^2], ``rtol`` and the contact
    point's ``reach`` L/2 + R [m]) and, for a rod of half length ``half_length`` [m], a tip
    that approaches the flat at ``MIN_APPROACH_SPEED`` or faster. A non-finite input, a speed,
    spin, mu, gravity or rtol outside its bound or too slow an approach: ST_BAD_INPUT; an
    angle outside (0, pi/2]: ST_BAD_ANGLE; a tip that does not approach: ST_NOT_APPROACHING."""
    for name, value in zip(CASE_INPUTS, case, strict=True):
        if not math.isfinite(value):
            return S.ST_BAD_INPUT, f"{name} = {value!r} is not finite"
    th, vx, vy, w, mu = case
    problem = input_problem(True, th, vx, vy, w, reach, mu, gravity, rtol)
    if problem != IN_OK:
        values = {IN_ANGLE: th, IN_VX: vx, IN_VY: vy, IN_SPIN: w, IN_MU: mu}
        values |= {IN_GRAVITY: gravity, IN_RTOL: rtol}
        code = S.ST_BAD_ANGLE if problem == IN_ANGLE else S.ST_BAD_INPUT
        if problem == IN_MU:  # in the words of simulate_drop's ValueError
            return code, mu_problem(mu)
        hint = degrees_hint(th) if problem == IN_ANGLE else ""  # 20 meant as 20 deg
        return code, problem_text(problem, values[problem]) + hint
    vn = vy - w * half_length * math.cos(th)
    if not vn < 0.0:
        return S.ST_NOT_APPROACHING, (
            f"the tip's normal velocity vy - spin (L/2) cos(angle) = {vn!r} m/s must be < 0"
        )
    if -vn < MIN_APPROACH_SPEED:
        return S.ST_BAD_INPUT, (
            f"vy = {vy!r} m/s, spin = {w!r} rad/s: the tip's normal approach speed "
            f"|vy - spin (L/2) cos(angle)| = {-vn:.3g} m/s is below {MIN_APPROACH_SPEED:g} m/s, "
            "the smallest the drop integrates"
        )
    return S.ST_OK, ""


def input_problems(
    rod: Rod, cols: Mapping[str, np.ndarray], gravity: float, rtol: float, *, warn: bool = True
) -> tuple[np.ndarray, dict[int, str]]:
    """The status of each case's inputs (``cols``: the columns of ``CASE_INPUTS``; 0: runs) and,
    by case index, why each refused one is refused (``case_problem``); ``warn``: an
    ImplausibleInputWarning when every angle refused (ST_BAD_ANGLE) reads as degrees
    (``input_checks.warn_degrees``)."""
    reach = contact_reach(rod)
    columns = (np.asarray(cols[k], dtype=np.float64).tolist() for k in CASE_INPUTS)
    status = []
    why: dict[int, str] = {}
    for i, case in enumerate(zip(*columns, strict=True)):
        code, text = case_problem(rod.half_length, reach, case, gravity, rtol)
        status.append(code)
        if code != S.ST_OK:
            why[i] = text
    codes = np.array(status, dtype=np.int32)
    if warn:
        warn_degrees(np.asarray(cols["angle"], dtype=np.float64)[codes == S.ST_BAD_ANGLE])
    return codes, why


def input_status(
    rod: Rod, cols: Mapping[str, np.ndarray], gravity: float, rtol: float
) -> np.ndarray:
    """The status of each case's inputs as ``simulate_drop`` refuses them (0: runs;
    ``case_problem``; no warning: the caller words its refusals)."""
    return input_problems(rod, cols, gravity, rtol, warn=False)[0]


class DropError(ValueError):
    """A drop whose integration failed; ``status`` is its code (``flexcore.layout.ST_*``).
    ``template``: the message with the keywords it asks to change as ``{time_limit}``,
    ``{rtol}``, ``{friction}`` (``DROP_KEYWORDS``); ``str(error)`` names the Python keywords,
    ``worded(label)`` the caller's spelling (``impactlab drop``: ``--time-limit``)."""

    def __init__(self, message: str, status: int, *, template: str | None = None) -> None:
        self.template = _literal(message) if template is None else template
        super().__init__(self.worded(str))
        self.status = status

    def worded(self, label: Callable[[str], str]) -> str:
        """The message with each keyword it names spelled ``label(keyword)``."""
        return self.template.format(**{k: label(k) for k in DROP_KEYWORDS})


def status_error(status: int, model: ContactModel, out: np.ndarray | None = None) -> DropError:
    """The ValueError of a failed drop (``layout.ST_*``; ``out``: its output row, when known)."""
    text = _literal(F.STATUS_MESSAGES.get(status, f"status {status}"))
    where = ""
    if out is not None:
        steps, t = int(out[F.O_N_STEPS]), float(out[F.O_T_FINAL])
        where = f" after {steps} steps, {t * 1e3:.4g} ms after the first touch"
    past_limit = " (its last step ended past {time_limit})" if where else ""
    hints = {  # templates: {time_limit}, {rtol}, {friction} name the keyword (DropError.worded)
        F.ST_LAW_LIMIT: f" ({model.max_interference:.6g} m for the {_literal(repr(model.name))} "
        f"law){where}: the contact force could not stop the rod within the law's range (too "
        "fast an impact, a jammed friction contact or too strong gravity); lower the impact "
        "velocity, mu or gravity, or choose another law",
        F.ST_TMAX: f"{where}{past_limit}: raise {{time_limit}}",
        F.ST_MAX_STEPS: f"{where} (the limit: {F.DROP_MAX_STEPS}; with partial slip "
        f"{F.PARTIAL_STEP_FACTOR} times the steps of its Mindlin pre-pass, at least "
        f"{F.PARTIAL_MIN_STEPS}): a long, creeping contact (resting, rocking or rolling), or "
        "modes too stiff for the step (a very stiff body: fewer modes); try {friction}='mindlin'",
        F.ST_MISSED_CONTACT: f"{where}: lower {{rtol}}",
        F.ST_STEP_UNDERFLOW: f"{where}: the integrator could not meet {{rtol}}",
    }
    return DropError("", status, template=f"drop: {text}{hints.get(status, '')}")


def drop_flags(
    out: np.ndarray,
    e0: float,
    m: float,
    g: float,
    rtol: float,
    model: ContactModel,
    contacts: np.ndarray,
    radius: float,
    brittle_limit: float = math.inf,
) -> tuple[ResultFlag, bool]:
    """The result flags of a finished sequence (docs/flexible.md, "Flags") from its output
    vector ``out`` (``layout.DROP_FIELDS``) and its contact table: the rigid engine's criteria
    (``impactlab.dynamics.kernels.quality``) on the state after the last contact, the
    vibration energy counted with the kinetic energy, and on the duration and the normal
    impulse of the tip's sequence (its contacts before the other end's first touch and, with
    ``stop="flight"``, before the tip's return after a clear flight); the law's (verified)
    range (``contact.ranges.law_extrapolated``) on the largest interference of the sequence;
    OTHER_END whenever the other end touched the flat, and, unless gravity dominates (the rod
    rests or rocks: that flag says it), when the tip still approaches the flat after the last
    contact (e < 0); BEYOND_TIP when the flat reached the rim of an end's
    hemisphere (``radius`` [m]) in a contact (``kernels.quality.beyond_rim``); BRITTLE when
    the largest mean contact pressure exceeds ``brittle_limit`` [Pa] (``contact.brittle``);
    GRAVITY_DOMINATED also where the gravity impulse removed from e alone lifts it above 1
    (``drop_gravity.e_lifted_by_gravity``). Returns the flags and whether that rule alone set
    GRAVITY_DOMINATED. The compiled part (``flexcore.batch.sequence_flags``) and that rule
    are those ``simulate_drops`` runs."""
    bits = sequence_flags(out, e0, m, g, rtol, contacts, contacts.shape[0], radius)
    flags = ResultFlag(int(bits))
    lifted = bool(e_lifted_by_gravity(out[F.O_E], out[F.O_E_RAW], int(bits), rtol))
    lifted_alone = lifted and ResultFlag.GRAVITY_DOMINATED not in flags
    if lifted:
        flags |= ResultFlag.GRAVITY_DOMINATED
    if law_extrapolated(model, float(out[F.O_DELTA_MAX])):
        flags |= ResultFlag.LAW_EXTRAPOLATED
    if brittle_limit < math.inf:
        dmax, fmax = float(out[F.O_DELTA_MAX]), float(out[F.O_MAX_FORCE])
        flags |= brittle_flags(model.law_id, model.params, dmax, fmax, brittle_limit)
    return flags, lifted_alone


def balance_residual(o: Mapping[str, Any], e0: Any) -> Any:
    """|T + V - E0 - W| [J] of the reported terms: the rigid kinetic, vibration and potential
    energy after the last contact, minus E0 and the works of the normal force, friction and
    damping (``DropResult.energy_balance["residual"]``)."""
    end = o["rigid_kinetic_energy"] + o["vibration_energy"] + o["potential_energy"]
    works = o["work_normal"] + o["work_friction"] + o["work_damping"]
    return abs(end - e0 - works)


def energy_balance_error(o: Mapping[str, Any], e0: Any) -> Any:
    """The energy balance's error relative to its energy scale (float, or an array over cases
    when ``o`` holds columns): the larger of the run's largest |T + V - E0 - W| and that of
    the reported terms (:func:`balance_residual`), over E0 + the final rigid kinetic,
    vibration and |potential| energy (the scale of the ENERGY_GAIN criterion)."""
    scale = e0 + o["rigid_kinetic_energy"] + o["vibration_energy"] + abs(o["potential_energy"])
    run, reported = o["energy_error"] * e0, balance_residual(o, e0)
    return np.where(reported > run, reported, run) / scale  # max(run, reported), elementwise


#: The energy balance's error per Dormand-Prince step, in units of rtol times its energy scale:
#: the error control is local, so a long run's error grows with its steps (docs/flexible.md,
#: "Refused results"). Measured up to 0.0175 per step (a 4 mm rod's stop="flight" drops on
#: steel and carbide, rtol 1e-5 ... 1e-11; the paper's rod up to 0.0038); 0.1 leaves 5.7.
ENERGY_STEP_FACTOR = 0.1


#: The largest energy-balance error of an accepted drop, relative to its energy scale, whatever
#: rtol and the steps [1]: at rtol 1e-5 the step term alone would accept 3 % after 30,000 steps
#: (the rigid rod's stop="flight" drops there created up to 0.58 % of E0, 8.2e-4 of their
#: scale). At the default rtol the worst measured is 2.4e-5 (docs/flexible.md, "Refused
#: results"), and the step term reaches the ceiling only after 100,000 steps.
ENERGY_BALANCE_MAX = 1e-3


def energy_balance_bound(rtol: float, n_steps: Any = 0.0) -> Any:
    """The largest energy-balance error that ``rtol`` promises over ``n_steps`` steps (float,
    or an array over cases): min(max(ENERGY_GAIN_RTOL_FACTOR, ENERGY_STEP_FACTOR n_steps) rtol,
    ENERGY_BALANCE_MAX) + ENERGY_ROUNDOFF; the first term covers a run of up to 1000 steps."""
    steps = ENERGY_STEP_FACTOR * np.asarray(n_steps, dtype=np.float64)
    promised = np.maximum(ENERGY_GAIN_RTOL_FACTOR, steps) * rtol
    return np.minimum(promised, ENERGY_BALANCE_MAX) + ENERGY_ROUNDOFF


def inaccuracy_text(error: float, rtol: float, n_steps: float) -> str:
    """Why a drop whose energy balance closed to ``error`` (relative to its energy scale) over
    ``n_steps`` steps is refused at ``rtol``, with the advice that holds (``{rtol}``: the
    keyword, as in a ``DropError`` template)."""
    bound = float(energy_balance_bound(rtol, n_steps))
    return (
        f"the energy balance closed to {error:.3g} of its energy scale, beyond the "
        f"min(max({ENERGY_GAIN_RTOL_FACTOR:g}, {ENERGY_STEP_FACTOR:g} x {n_steps:.0f} steps) "
        f"rtol, {ENERGY_BALANCE_MAX:g}) + {ENERGY_ROUNDOFF:g} = {bound:.3g} that {{rtol}} = "
        f"{rtol:g} promises: an "
        f"integration error shrinks in proportion to rtol, so lower {{rtol}} (an error that "
        "does not shrink with it is not the integrator's)"
    )


def check_energy_balance(o: dict[str, Any], e0: float, rtol: float) -> None:
    """DropError when the energy balance closed worse than the tolerance promises: the
    largest |T + V - E0 - W| of the run (every accepted step, through every contact and every
    integrated flight of ``stop="flight"``; the closed-form flights conserve it exactly) or
    that of the reported terms after the last contact (:func:`balance_residual`), above
    :func:`energy_balance_bound` (over the run's ``n_steps``) times the energy scale of the
    ENERGY_GAIN criterion (E0 + the final rigid kinetic, vibration and |potential| energy):
    the results, energy gain or not, are not integrated to the tolerance."""
    steps = float(o.get("n_steps", 0.0))
    error = float(energy_balance_error(o, e0))
    if not error <= float(energy_balance_bound(rtol, steps)):
        text = _literal(F.STATUS_MESSAGES[F.ST_INACCURATE])
        why = inaccuracy_text(error, rtol, steps)
        raise DropError("", F.ST_INACCURATE, template=f"drop: {text}: {why}")


def inaccurate_cases(columns: Mapping[str, Any], e0: Any, rtol: float) -> dict[int, str]:
    """The cases (indices into the columns ``columns``, the outputs of finished drops, and
    ``e0`` [J]) whose energy balance closed worse than ``rtol`` promises
    (:func:`check_energy_balance`, on every case at once), each with why
    (:func:`inaccuracy_text`)."""
    error = np.atleast_1d(energy_balance_error(columns, e0))
    steps = np.broadcast_to(np.asarray(columns.get("n_steps", 0.0), dtype=np.float64), error.shape)
    bad = np.flatnonzero(~(error <= energy_balance_bound(rtol, steps)))
    return {
        int(i): inaccuracy_text(float(error[i]), rtol, float(steps[i])).format(rtol="rtol")
        for i in bad
    }
