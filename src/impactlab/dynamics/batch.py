"""Low-level batch interface of the impact engine (arrays in, arrays out; all cores).

Every friction model of ``BATCH_FRICTION_IDS`` runs here: the rigid core's models in
``core.batch.impact_batch``, ``partial_slip`` in ``slip_batch.slip_batch`` (the same compiled
impact as ``simulate(friction="partial_slip")``, so its results equal ``simulate``'s bit for bit).

``run_arrays`` is what sweeps call: every case may carry its own law parameters and body
parameters. Invalid cases are flagged in ``status`` (see ``STATUS_MESSAGES``) with NaN outputs
(the incoming ``vn_in`` and ``vt_in`` excepted wherever the inputs define them); they never stop
the batch.
"""

from __future__ import annotations

import contextlib
import math
import operator
from typing import Any

import numba
import numpy as np

from impactlab._compile_notice import one_line
from impactlab._validation import check_array
from impactlab.bodies import NB
from impactlab.bodies.layout import BP_HALF_LENGTH, BP_KIND, BP_RADIUS, KIND_ROD
from impactlab.contact.brittle import brittle_flags
from impactlab.contact.kernels import N_LAWS, NPARAM, param_length
from impactlab.contact.ranges import extrapolation_flags
from impactlab.contact.tabulate import has_table, with_table
from impactlab.dynamics.core.batch import impact_batch
from impactlab.dynamics.input_checks import (
    check_friction_rtol,
    check_partial_slip_cells,
    check_rtol,
    gravity_value,
)
from impactlab.dynamics.kernels.layout import N_OUT, OUTPUT_FIELDS, PARTIAL_SLIP_RTOL
from impactlab.dynamics.kernels.status import REGIME_NAMES, STATUS_MESSAGES
from impactlab.dynamics.rod_reach import rod_reach_flags
from impactlab.dynamics.slip_batch import prepass_address, slip_batch
from impactlab.dynamics.slipcore import slip_addresses
from impactlab.friction import BATCH_FRICTION_IDS, FRICTION_IDS, PARTIAL_SLIP, PARTIAL_SLIP_CELLS

__all__ = [
    "BATCH_FRICTION_IDS",
    "FRICTION_IDS",
    "KEPT_WHEN_FAILED",
    "OUTPUT_FIELDS",
    "REGIME_NAMES",
    "STATUS_MESSAGES",
    "blank_failed",
    "run_arrays",
]


def _rows(name: str, a: Any, width: int, n: int) -> np.ndarray:
    arr = np.asarray(a, dtype=np.float64)
    if arr.ndim == 1:
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != width or arr.shape[0] not in (1, n):
        raise ValueError(
            f"{name} must have shape ({width},), (1, {width}) or ({n}, {width}); got {np.shape(a)}"
        )
    return np.require(arr, np.float64, ["C", "W"])


def run_arrays(
    law_id: int,
    friction_id: int,
    law_params: Any,
    body_params: Any,
    initial: Any,
    mu: Any,
    *,
    gravity: bool | float = True,
    constant_angle: bool = False,
    rtol: float | None = None,
    diagnostics: bool = False,
    tabulate: bool = True,
    brittle_limit: Any = math.inf,
    partial_slip_cells: int = PARTIAL_SLIP_CELLS,
) -> tuple[np.ndarray, np.ndarray]:
    """Run N impacts in parallel.

    law_id : contact-law id (``contact.kernels``); friction_id : ``BATCH_FRICTION_IDS[name]``.
    law_params : (N, NPARAM) or (NPARAM,) (``ContactModel.params``), or one law's
    ``kernel_params(model)`` (with its loading-curve table; shared parameters get one anyway).
    body_params : (N, NB) or (NB,) (``Rod/Sphere.to_params(flat)``, which includes G*).
    initial : (N, 4) = [angle [rad], vx, vy [m/s], spin [rad/s]]; mu : (N,) or scalar.
    gravity : True (9.80665), False or a value [m/s^2]; constant_angle : freeze the lever arms;
    rtol : relative tolerance (None: the engine default, ``PARTIAL_SLIP_RTOL`` for
    ``partial_slip``, as in ``simulate``); diagnostics : also compute the
    diagnostic outputs (energy_rise, friction_excess; NaN otherwise); tabulate : evaluate the
    law's loading curve from its table (``contact.table``, within 1e-13 of the closed form)
    where one parameter vector is shared by every case; per-case parameters (N, NPARAM) always
    use the closed forms, as ``tabulate=False`` does for shared ones. brittle_limit : the mean
    contact pressure [Pa] a brittle member of the pair stands (``contact.brittle``), for all
    cases or per case; inf (default): none is brittle. partial_slip_cells : the cells of
    ``partial_slip`` over the largest contact radius, one for the call, in [4, 64] (default
    ``PARTIAL_SLIP_CELLS``; another value is refused for the other friction models).

    Returns ``(out, status)``: out (N, len(OUTPUT_FIELDS)) float64, status (N,) int32
    (0 = ok; ``STATUS_MESSAGES``; a failed case's outputs are NaN but ``vn_in``, ``vt_in``:
    ``blank_failed``). The ``regime`` column holds codes (``REGIME_NAMES``); the
    ``flags`` column the ``ResultFlag`` bits, LAW_EXTRAPOLATED added here from each case's
    delta_max / delta_ref (the law's own reference) and the law's range
    (``impactlab.contact.ranges``: verified against FE, else a stand-in), and BEYOND_TIP,
    OTHER_END and BRITTLE (above).
    """
    lid = _integer("law_id", law_id)
    if not 0 <= lid < N_LAWS:
        raise ValueError(f"law_id must lie in [0, {N_LAWS - 1}], got {law_id!r}")
    fid = _integer("friction_id", friction_id)
    limit = check_array("brittle_limit", brittle_limit)
    if not bool(np.all(limit > 0.0)):
        raise ValueError(
            f"brittle_limit must be > 0 [Pa] (inf: no brittle member), got {brittle_limit!r}"
        )
    if fid not in BATCH_FRICTION_IDS.values():
        raise ValueError(f"friction_id must be one of {BATCH_FRICTION_IDS}, got {friction_id!r}")
    init = check_array("initial", initial)
    if init.ndim == 1 and init.shape[0] == 4:
        init = init[None, :]
    if init.ndim != 2 or init.shape[1] != 4:
        raise ValueError(
            f"initial must have shape (N, 4) = [angle, vx, vy, spin], got {np.shape(initial)}"
        )
    init = np.require(init, np.float64, ["C", "W"])
    n = init.shape[0]
    mu_a = check_array("mu", mu)
    if mu_a.ndim == 0:
        mu_a = np.full(n, float(mu_a))
    if mu_a.shape != (n,):
        raise ValueError(f"mu must be a scalar or have shape ({n},), got {mu_a.shape}")
    mu_a = np.require(mu_a, np.float64, ["C", "W"])
    if has_table(law_params):  # kernel_params(model): the parameters with their table
        lp = np.require(law_params, np.float64, ["C", "W"])[None, :]
        if not tabulate:
            lp = np.ascontiguousarray(lp[:, :NPARAM])
    else:
        lp = _rows("law_params", law_params, param_length(lid), n)
        if lp.shape[0] == 1 and tabulate:  # one law for all: its loading curve as a table
            lp = shared_table(lid, lp[0])[None, :]
    bp = _rows("body_params", body_params, NB, n)
    g = gravity_value(gravity)
    r = PARTIAL_SLIP_RTOL if rtol is None and fid == PARTIAL_SLIP else check_rtol(rtol)
    name = next(k for k, v in BATCH_FRICTION_IDS.items() if v == fid)
    check_friction_rtol(r, name)
    cells = check_partial_slip_cells(partial_slip_cells, name)
    out = np.empty((n, N_OUT))
    status = np.empty(n, dtype=np.int32)
    if n and fid == PARTIAL_SLIP:
        with one_line():  # a first batch compiles the addresses' functions, then the batch
            slip_batch(
                numba.get_num_threads(), lid, lp, bp, init, mu_a, g, bool(constant_angle), r,
                bool(diagnostics), cells, out, status, slip_addresses(),
                prepass_address(),
            )  # fmt: skip
        _mark_law_flags(lid, lp, out, brittle_limit)
        _mark_reach(bp, init, out)
    elif n:
        impact_batch(
            numba.get_num_threads(),
            lid,
            lp,
            fid,
            bp,
            init,
            mu_a,
            g,
            bool(constant_angle),
            r,
            bool(diagnostics),
            out,
            status,
        )
        _mark_law_flags(lid, lp, out, brittle_limit)
        _mark_reach(bp, init, out)
    blank_failed(out, status)
    return out, status


#: The outputs a failed case keeps: its incoming velocities, wherever its inputs define them.
KEPT_WHEN_FAILED = ("vn_in", "vt_in")
_BLANKED = np.array([j for j, f in enumerate(OUTPUT_FIELDS) if f not in KEPT_WHEN_FAILED])


def blank_failed(out: np.ndarray, status: np.ndarray) -> np.ndarray:
    """Set every output of the cases with a non-zero ``status`` to NaN (in place; returns
    ``out``), ``KEPT_WHEN_FAILED`` excepted: a failed case stops part-way, and what the engine
    left in its row (the interference and force reached, the time run) is no result. ``regime``
    and ``flags`` included: a failed case has neither (its status says why)."""
    failed = np.flatnonzero(np.asarray(status) != 0)
    if failed.size:
        out[np.ix_(failed, _BLANKED)] = np.nan
    return out


_DMAX, _FLAGS = OUTPUT_FIELDS.index("delta_max"), OUTPUT_FIELDS.index("flags")
_FMAX = OUTPUT_FIELDS.index("max_force")
_ANGLE_OUT = OUTPUT_FIELDS.index("angle_out")
#: (law id, parameter bytes) -> the parameters with their table (the last few, for repeated
#: batches of one law: a sweep's chunks, a benchmark's repeats).
_TABLES: dict[tuple[int, bytes], np.ndarray] = {}


def shared_table(law_id: int, p: np.ndarray) -> np.ndarray:
    """``p`` with its loading-curve table (``contact.tabulate.with_table``), cached."""
    key = (law_id, np.ascontiguousarray(p, dtype=np.float64).tobytes())
    hit = _TABLES.get(key)
    if hit is None:
        if len(_TABLES) >= 32:
            _TABLES.clear()
        hit = _TABLES[key] = with_table(law_id, p)
    return hit


def _mark_reach(bp: np.ndarray, init: np.ndarray, out: np.ndarray) -> None:
    """Add ``BEYOND_TIP`` and ``OTHER_END`` to the ``flags`` column of the rods' cases whose
    tip or other end left the model's geometry (``rod_reach``; failed cases untouched)."""
    rod = np.broadcast_to(bp[:, BP_KIND] == KIND_ROD, out.shape[:1])
    done = np.isfinite(out[:, _FLAGS]) & rod
    if not done.any():
        return
    bits = rod_reach_flags(
        bp[:, BP_HALF_LENGTH], bp[:, BP_RADIUS], init[:, 0], out[:, _ANGLE_OUT], out[:, _DMAX]
    )
    out[done, _FLAGS] = out[done, _FLAGS].astype(np.int64) | np.broadcast_to(bits, done.shape)[done]


def _integer(name: str, value: Any) -> int:
    """``value`` as an integer id: an int or a whole float; ValueError naming ``name`` for a
    bool, a fraction or anything else (1.9 was read as 1)."""
    if not isinstance(value, bool | np.bool_):
        with contextlib.suppress(TypeError):
            return operator.index(value)
        if isinstance(value, float | np.floating) and float(value).is_integer():
            return int(value)
    raise ValueError(f"{name} must be an integer, got {value!r}")


def _mark_law_flags(
    law_id: int, law_params: np.ndarray, out: np.ndarray, brittle_limit: Any = math.inf
) -> None:
    """Add ``LAW_EXTRAPOLATED`` to the ``flags`` column where a case's delta_max / delta_ref
    exceeds the law's (verified) range (``contact.ranges``; vectorised), and ``BRITTLE`` where
    its mean contact pressure exceeds ``brittle_limit`` (``contact.brittle``); failed cases
    untouched."""
    done = np.isfinite(out[:, _FLAGS])
    dmax = np.where(done, out[:, _DMAX], np.nan)
    limit = np.broadcast_to(np.asarray(brittle_limit, dtype=np.float64), done.shape)
    extra = extrapolation_flags(law_id, law_params, dmax) | brittle_flags(
        law_id, law_params, dmax, out[:, _FMAX], limit
    )
    out[done, _FLAGS] = (
        out[done, _FLAGS].astype(np.int64) | np.broadcast_to(extra, done.shape)[done]
    )
