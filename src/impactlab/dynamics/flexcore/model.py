"""The float64 inputs of ``driver.drop`` from the model's parameters (Python, pure): the
constants vector (``layout.FC_*``) and the model tuple (package docstring)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.contact.kernels import P_DLIM, P_DSW
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.indirect import addresses
from impactlab.dynamics.flexcore.setup import state_size
from impactlab.dynamics.kernels.cells import CP_DX


def constants(
    half_length: float,
    tip_radius: float,
    mass: float,
    inertia: float,
    gravity: float,
    angle: float,
    mu: float,
    p: np.ndarray,
    friction_id: int = 1,
    gstar: float = math.nan,
    cell_width: tuple[float, float] = (math.nan, math.nan),
    max_steps: int = F.DROP_MAX_STEPS,
) -> np.ndarray:
    """The constants vector (``layout.FC_*``; SI units) for the law parameters ``p``, the
    friction model's id (``impactlab.friction``; default coulomb), G* [Pa] (Mindlin, partial
    slip), the cell width of each end [m] (partial slip; the other cell parameters are set
    by the integrator) and the step limit of the run."""
    dsw = float(p[P_DSW])
    values = {
        F.FC_D: half_length,
        F.FC_R: tip_radius,
        F.FC_M: mass,
        F.FC_I: inertia,
        F.FC_G: gravity,
        F.FC_TH0: angle,
        F.FC_MU: mu,
        F.FC_DLIM: float(p[P_DLIM]),
        F.FC_DSW: dsw if (math.isfinite(dsw) and dsw > 0.0) else math.inf,
        F.FC_S0: math.sin(angle),
        F.FC_C0: math.cos(angle),
        F.FC_FRIC: float(friction_id),
        F.FC_GS: gstar,
        F.FC_MAX_STEPS: float(min(max_steps, F.DROP_MAX_STEPS)),
    }
    for k in range(F.NE):
        values[F.FC_CP + k * F.NFCP + CP_DX] = cell_width[k]
    c = np.zeros(F.NFC)
    for i, v in values.items():
        c[i] = v
    return c


def state_length(n_modes: int, friction_id: int) -> int:
    """Length of the integrator's state with ``n_modes`` modes (partial slip: plus the cells of
    both ends; last, the ends' own works): the compiled ``setup.state_size``, as Python."""
    return int(getattr(state_size, "py_func", state_size)(n_modes, friction_id))


def _array(a: Any, dtype: type = np.float64) -> np.ndarray:
    """A writable C-contiguous copy (one numba specialisation for every caller)."""
    return np.array(a, dtype=dtype, order="C", copy=True)


def model_tuple(
    law_id: int,
    p: np.ndarray,
    c: np.ndarray,
    omega: np.ndarray,
    zeta: np.ndarray,
    U: np.ndarray,
    W: np.ndarray,
    Psi: np.ndarray,  # noqa: N803 (the modal section rotation, as in ModalBasis)
    geometric: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
) -> tuple[Any, ...]:
    """``(law, p, c, om, om2, dmp, zeta, Ue, We, Pe, Tg, ia, ib, *addresses)`` for
    ``driver.drop``:
    omega (M,) [rad/s], zeta (M,) damping ratios, U, W, Psi (2, M) modal end values;
    ``geometric``: (T, ia, ib) of ``impactlab.bodies.geometric.geometric_tensor`` or None;
    the addresses (``address_call.AT_*``): of the right-hand side and of the Dormand-Prince
    step of the friction model in ``c`` (``indirect``: ``rates_cells`` and ``dp_step_cells``
    for partial slip, ``rates`` and ``dp_step_rates`` otherwise), of the event handler, the accepted
    step, the free flight, the outputs and the history row."""

    om = _array(omega)
    z = _array(zeta)
    if geometric is None:
        Tg = np.zeros((0, 0, 0))
        ia = np.zeros(0, dtype=np.int64)
        ib = np.zeros(0, dtype=np.int64)
    else:
        Tg = _array(geometric[0])
        ia = _array(geometric[1], np.int64)
        ib = _array(geometric[2], np.int64)
    return (
        int(law_id),
        _array(p),
        _array(c),
        om,
        om * om,
        2.0 * z * om,
        z,
        _array(U).reshape(2, om.size),
        _array(W).reshape(2, om.size),
        _array(Psi).reshape(2, om.size),
        Tg,
        ia,
        ib,
        *addresses(int(c[F.FC_FRIC]) == F.FR_PARTIAL),
    )
