"""``simulate_batch``: many impacts of one body, law and friction model, in one compiled call
on every core (``impactlab.dynamics.batch``); the inputs checked as ``simulate`` checks them."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._validation import check_array, check_flag, refuse_unknown_keywords
from impactlab.bodies import Rod, Sphere
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.geometry import lever_arms
from impactlab.contact import ContactModel
from impactlab.contact.brittle import brittle_pressure
from impactlab.contact.range_note import range_note
from impactlab.contact.ranges import delta_ratio
from impactlab.dynamics.batch import run_arrays
from impactlab.dynamics.batch_result import BatchResult
from impactlab.dynamics.batch_status import case_refusals
from impactlab.dynamics.checks import checked_model
from impactlab.dynamics.dent import body_flattening, flattening_warning
from impactlab.dynamics.export import batch_setup
from impactlab.dynamics.flex_simulate import FLEXIBLE_BATCH_ERROR
from impactlab.dynamics.input_checks import (
    PAST_NORMAL,
    batch_velocity,
    check_angle,
    check_body,
    check_constant_angle,
    check_flat,
    check_partial_slip_cells,
    contact_reach,
    gravity_value,
    warn_degrees,
    warn_fast,
)
from impactlab.dynamics.kernels import layout as L
from impactlab.dynamics.kernels.inputs import MAX_ANGLE, MAX_MU, MAX_SPEED
from impactlab.dynamics.kernels.status import (
    ST_BAD_ANGLE,
    ST_BAD_INPUT,
    ST_NOT_APPROACHING,
    ST_OK,
)
from impactlab.dynamics.models import body_params, references_used
from impactlab.dynamics.outcome import slip_jam, status_error
from impactlab.friction import DEFAULT_MU, PARTIAL_SLIP_CELLS, FrictionModel, get_friction
from impactlab.materials import AISI_1010, Material, body_yields_first
from impactlab.units import is_quantity

#: simulate_batch's array inputs and their units ("1": a plain number).
_BATCH_UNITS = {"mu": "1", "angle": "rad", "vx": "m/s", "vy": "m/s", "spin": "rad/s"}

#: What simulate_batch says of a keyword of ``simulate`` it does not take.
BATCH_KEYWORD_NOTES = {
    "history": (
        "a batch keeps no history, each case's outputs only; one case's time history: "
        "impactlab.simulate(body, flat, angle=..., velocity=(vx, vy), mu=...), history=True "
        "by default"
    ),
    "theta": "the rod's angle to the flat is angle= [rad]",
}


def _batch_column(name: str, value: Any) -> np.ndarray:
    """One input of simulate_batch as a 1-D float array (NaN allowed: flagged per case): a
    number, an array, a pint Quantity (dimensionless ones: percent read as a fraction), a
    string with units, or a list of numbers that holds Quantities (each element read so,
    named ``name[i]``; numpy would drop their units)."""
    if value is None:
        raise ValueError(f"{name} is required: a number or a 1-D array [{_BATCH_UNITS[name]}]")
    unit = "" if _BATCH_UNITS[name] == "1" else _BATCH_UNITS[name]
    if isinstance(value, list | tuple) and any(is_quantity(v) for v in value):
        value = np.array([check_array(f"{name}[{i}]", v, unit) for i, v in enumerate(value)])
    a = np.atleast_1d(check_array(name, value, unit))
    if a.ndim > 1:
        raise ValueError(
            f"{name} must be a scalar or a 1-D array, got shape {a.shape}: a batch is one case "
            "per entry, its 1-D inputs of one length; for a grid, give each input's values "
            "per case (np.meshgrid(...) then .ravel()) or use a sweep's [grid]"
        )
    return a


def _batch_inputs(inputs: dict[str, Any], body: Rod | Sphere) -> dict[str, np.ndarray]:
    """The batch's inputs broadcast against each other (C-contiguous float64 arrays); an
    ImplausibleInputWarning, as ``simulate`` warns, when the largest speed of the centre of
    mass or of the contact point (``_fastest``) exceeds 100 m/s."""
    arrays = {n: _batch_column(n, v) for n, v in inputs.items()}
    try:
        b = np.broadcast_arrays(*arrays.values())
    except ValueError:
        shapes = ", ".join(f"{n}: {a.shape}" for n, a in arrays.items())
        raise ValueError(f"mu, angle, vx, vy and spin do not broadcast ({shapes})") from None
    cols = {n: np.ascontiguousarray(x, dtype=np.float64) for n, x in zip(arrays, b, strict=True)}
    warn_fast("the largest impact speed of the batch", _fastest(cols, body))
    return cols


def _fastest(cols: Mapping[str, np.ndarray], body: Rod | Sphere) -> float:
    """The largest speed [m/s] over the cases that run, those whose inputs keep every
    per-case rule (``kernels.inputs``: finite, velocity components and the spin's contact
    point speed up to ``MAX_SPEED``, mu in [0, ``MAX_MU``], a rod's angle in (0, pi/2], the
    contact point approaching the flat; a
    refused case is said in its status, not in this warning): of the centre of mass,
    hypot(vx, vy), or of the contact point, hypot(vx + spin b, vy - spin a) with the body's
    lever arms at each case's angle (``bodies.geometry.lever_arms``; a sphere's a = 0, b = R),
    as ``simulate`` takes it for one impact; 0 when no case runs."""
    vx, vy, w, th = (cols[k] for k in ("vx", "vy", "spin", "angle"))
    with np.errstate(invalid="ignore", over="ignore"):
        a, b = lever_arms(body.half_length, body.tip_radius, th)
        speed = np.maximum(np.hypot(vx, vy), np.hypot(vx + w * b, vy - w * a))
        # kernels.inputs.speed_allowed and spin_allowed, elementwise
        reach = contact_reach(body)
        runs = (np.abs(vx) <= MAX_SPEED) & (np.abs(vy) <= MAX_SPEED)
        runs &= np.abs(w) * reach <= MAX_SPEED
        if "mu" in cols:  # kernels.inputs.mu_allowed, elementwise
            runs &= (cols["mu"] >= 0.0) & (cols["mu"] <= MAX_MU)
        if isinstance(body, Rod):
            runs &= (th > 0.0) & (th <= MAX_ANGLE)  # kernels.inputs.angle_allowed, elementwise
        runs &= vy - w * a < 0.0  # the contact point approaches the flat (ST_NOT_APPROACHING)
    return float(np.max(speed[runs & np.isfinite(speed)], initial=0.0))


@refuse_unknown_keywords(BATCH_KEYWORD_NOTES)
def simulate_batch(
    body: Rod | Sphere,
    flat: Material = AISI_1010,
    *,
    vy: Any = None,
    vx: Any = None,
    angle: Any = None,
    mu: Any = DEFAULT_MU,
    spin: Any = 0.0,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    law_params: Mapping[str, Any] | None = None,
    gravity: Any = True,
    constant_angle: bool = False,
    rtol: float | None = None,
    speed: Any = None,
    incidence: Any = None,
    velocity: Any = None,
    partial_slip_cells: int = PARTIAL_SLIP_CELLS,
) -> BatchResult:
    """Many impacts of one body, law and friction model, in parallel on all cores.

    ``body``: a ``Rod`` or a ``Sphere`` (a ``FlexibleRod``'s drops: ``simulate_drops``).
    ``mu``, ``angle`` [rad; a Rod's, required; a Sphere takes none and an angle given for it
    (or ``constant_angle=True``) is refused, as by ``simulate``; one angle for every case is
    checked as ``simulate`` checks it], ``vx``, ``vy`` [m/s] and ``spin`` [rad/s] are scalars or
    1-D arrays, broadcast against each other; each may also be a pint Quantity (any registry,
    scalar, array or in a list: converted to SI, ``mu`` in percent read as a fraction, a wrong
    dimension refused naming the input), and a dimensional one a string with units, as in
    ``simulate``. ``vy`` (``vx`` default 0), or
    ``velocity`` = (vx, vy) as ``simulate`` takes it (each a scalar or an array), or instead
    ``speed`` [m/s] and ``incidence`` [rad] (arrays too; vx = speed sin(incidence),
    vy = -speed cos(incidence), ``checks.velocity_from``) are required, one of the three.
    Invalid cases (NaN input, an angle outside (0, pi/2], a receding contact point, the law's
    validity exceeded, ...) are flagged in ``BatchResult.status`` (``messages``: a case refused
    for its inputs names the input, its value and its rule) and never stop the batch; a
    computed case that gained energy or that gravity dominates is flagged in
    ``BatchResult.flags``. A speed above 100 m/s draws an ``ImplausibleInputWarning``.
    ``speed`` and ``incidence`` are checked before any case runs, with ``simulate``'s rules
    (speed finite and > 0, incidence within +-90 deg): a bad one refuses the call, naming each
    offending case by its index.

    ``flat``: the flat's ``Material`` (default AISI 1010). ``law``: a law's name or a
    ``ContactModel``; ``law_params``: the law's parameters (``impactlab laws``), as
    ``simulate`` takes them, the same for every case. ``friction``: ``"coulomb"``,
    ``"impulse_ratio"``, ``"mindlin"`` or ``"partial_slip"`` (``BATCH_FRICTION_IDS``).
    ``gravity``: True (9.80665 m/s^2), False or a value [m/s^2]; ``constant_angle``: freeze
    the lever arms at the initial angle. ``rtol``: the relative tolerance, in [1e-13, 1e-3]
    (None: ``DEFAULT_RTOL`` = 2e-7; 3e-8 for ``partial_slip``, which takes at most 1e-5;
    ``mindlin`` at most 1e-4), as
    in ``simulate``; a bad one is refused (ValueError) before any case runs.
    ``partial_slip_cells``: the cells of ``partial_slip`` over the largest contact radius, in
    [4, 64] (default ``PARTIAL_SLIP_CELLS`` = 16), one for every case of the call, as in
    ``simulate``; another value is refused for the other friction models. Another keyword
    (``history``: a batch keeps none) is refused with a TypeError naming the nearest one and
    what the batch takes.

    Returns a ``BatchResult``: one row per case (the inputs broadcast), with its ``status``
    (0: computed; ``messages`` says why not), ``flags``, ``ok`` (computed, and no flag but the
    advisory ones), the outputs by name (``b.e``, ``b["delta_p"]``, SI), ``to_dataframe``,
    ``to_xarray`` and ``to_pint``, and ``setup`` (what was simulated besides the cases).
    When the body's material yields before the flat's (``materials.body_yields_first``, one
    pair per call), ``body_yields_first`` is True and ``warnings`` says once that delta_p is
    the body's flattening, not a dent in the flat (advisory: no value changes).
    """
    if isinstance(body, FlexibleRod):
        raise ValueError(FLEXIBLE_BATCH_ERROR)
    body = check_body(body)
    flat = check_flat(flat)
    fric = get_friction(friction)
    cells = check_partial_slip_cells(partial_slip_cells, fric.name)
    model = checked_model(body, flat, law, law_params)
    if isinstance(body, Sphere):
        angle = check_angle(angle, body)  # pi/2; an angle given for a sphere is refused
        check_constant_angle(constant_angle, body)  # and constant_angle=True
    elif angle is None or _one_value(angle):
        angle = check_angle(angle, body)  # one angle for every case: refused as by simulate
    vx, vy = batch_velocity(vx, vy, speed, incidence, velocity)
    x = _batch_inputs({"mu": mu, "angle": angle, "vx": vx, "vy": vy, "spin": spin}, body)
    _refuse_degrees(x["angle"], isinstance(body, Sphere))
    out, status = run_arrays(
        model.law_id,
        fric.friction_id,
        model.params,
        body_params(body, flat),
        np.ascontiguousarray(np.stack([x["angle"], x["vx"], x["vy"], x["spin"]], axis=1)),
        x["mu"],
        gravity=gravity,
        constant_angle=check_flag("constant_angle", constant_angle),
        rtol=rtol,
        brittle_limit=brittle_pressure(body.material, flat),
        partial_slip_cells=cells,
    )
    if not isinstance(body, Sphere):  # some cases' angles in degrees: said once, as drops say it
        warn_degrees(x["angle"][status == ST_BAD_ANGLE])
    yields, said = flattening_words(
        body.material, flat, out[:, L.OUTPUT_FIELDS.index("delta_p")][status == 0], "delta_p"
    )
    return BatchResult(
        out=out,
        status=status,
        inputs=_as_given(x, body),
        law=model.name,
        friction=fric.name,
        references=references_used(model, fric, bool(np.any(x["mu"] > 0.0))),
        max_delta_ratio=np.asarray(
            delta_ratio(model.law_id, model.params, out[:, L.OUTPUT_FIELDS.index("delta_max")])
        ),
        law_range=range_note(model.law_id, model.params),
        refusals=case_refusals(body, x, np.flatnonzero(status == ST_BAD_INPUT))
        | engine_failures(body, x, status, model, fric, gravity),
        setup=batch_setup(
            body,
            flat,
            friction=fric.name,
            gravity=gravity,
            rtol=rtol,
            constant_angle=constant_angle,
            law=law,
            law_params=law_params,
            partial_slip_cells=cells,
        )
        | {"body_yields_first": int(yields)},
        body_yields_first=yields,
        warnings=said,
    )


def _as_given(x: dict[str, np.ndarray], body: Rod | Sphere) -> dict[str, np.ndarray]:
    """The batch's input columns as a result holds them: a sphere's ``angle`` NaN (it has no
    axis; ``ImpactResult.angle`` is NaN too), where the engine took pi/2."""
    if not isinstance(body, Sphere):
        return x
    return {**x, "angle": np.full_like(x["angle"], np.nan)}


def flattening_words(
    body: Material, flat: Material, depths: np.ndarray, what: str
) -> tuple[bool, tuple[str, ...]]:
    """A batch's ``body_yields_first`` (its one pair: ``materials.body_yields_first``) and its
    ``warnings``: once per call, the advisory ``dynamics.dent.flattening_warning`` for the
    largest permanent interference ``depths`` [m] of its computed cases (the output
    ``what``); ``()`` when the flat yields first or no case left one."""
    yields = body_yields_first(body, flat)
    finite = depths[np.isfinite(depths)]
    if not yields or finite.size == 0:
        return yields, ()
    clause = body_flattening(body, flat, float(finite.max()), f"the batch's largest {what}")
    return yields, (flattening_warning(clause),) if clause else ()


def engine_failures(
    body: Rod | Sphere,
    cases: Mapping[str, np.ndarray],
    status: np.ndarray,
    model: ContactModel,
    friction: FrictionModel,
    gravity: Any,
) -> dict[int, str]:
    """The whole message of each case the engine ran and stopped (a status other than ok and
    the input refusals ST_BAD_INPUT, ST_BAD_ANGLE, ST_NOT_APPROACHING), by case index, in the
    words of ``simulate``'s ValueError (``outcome.status_error``) for the case's own values:
    the law's limit, the contact point's approach speed vn = vy - spin a [m/s], the gravity
    [m/s^2], what to change."""
    refused = (ST_OK, ST_BAD_INPUT, ST_BAD_ANGLE, ST_NOT_APPROACHING)
    failed = np.flatnonzero(~np.isin(status, refused))
    if failed.size == 0:
        return {}
    g = gravity_value(gravity)
    why: dict[int, str] = {}
    for i in failed.tolist():
        th, vx, vy, w, mu = (float(cases[k][i]) for k in ("angle", "vx", "vy", "spin", "mu"))
        a = float(lever_arms(body.half_length, body.tip_radius, th)[0])
        jam = slip_jam(body, th, friction, mu, (vx, vy), w)
        why[i] = str(status_error(int(status[i]), model, vn=vy - w * a, gravity=g, jam=jam))
    return why


def _one_value(value: Any) -> bool:
    """Whether ``value`` is one number (a scalar, a 0-d array or Quantity, a string), not a
    list or an array of the cases' values."""
    if isinstance(value, list | tuple):
        return False
    return np.ndim(getattr(value, "magnitude", value)) == 0


def _refuse_degrees(angle: np.ndarray, sphere: bool) -> None:
    """ValueError when every angle of a rod's batch lies in (pi/2 + ``PAST_NORMAL``, 90]:
    numbers in degrees, which would fail case by case (status 7) without a word. Up to
    ``PAST_NORMAL`` past pi/2 an angle is a rod leaning past the normal (``simulate``'s rule),
    refused case by case with what it means."""
    a = angle[np.isfinite(angle)]
    low = 0.5 * np.pi + PAST_NORMAL
    if not sphere and a.size and bool(np.all((a > low) & (a <= 90.0))):
        raise ValueError(
            f"angle: every value lies in (pi/2 + {math.degrees(PAST_NORMAL):g} deg, 90] "
            f"({float(a.min()):g} to {float(a.max()):g}): degrees? a bare angle is radians, as "
            "every bare number of the Python API is SI; pass np.radians(...) or a Quantity"
        )


__all__ = ["engine_failures", "flattening_words", "simulate_batch"]
