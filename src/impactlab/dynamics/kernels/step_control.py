"""The step-size factors of the engines' error control: after a step with scaled error norm
``err`` the next step is ``factor`` times as long, 0.9 err^-1/5 for the 5th-order pair
(Hairer, Norsett & Wanner, Solving ODEs I, Sec. II.4, doi:10.1007/978-3-540-78862-1), bounded
by the callers (at most 0.2 after a rejected step, at most 5 or 10 after an accepted one).

``growth`` is the rigid engine's fast form of the factor (within 2e-4 of it, no ``pow``);
``power_growth`` the exact power, which the partial-slip and flexible engines use (their
results were verified with it; the 2e-4 difference moves their steps and so their results at
the level of the tolerance, not of round-off).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab._floatbits import significand_exponent
from impactlab.dynamics.kernels._jit import njit_llvm_inline

#: m^-0.2 on [0.5, 1) as a cubic in t = 4 m - 3 (Chebyshev interpolant, relative error 1.5e-4).
_G0, _G1, _G2, _G3 = (
    1.0590986723409181,
    -0.0705797147103878,
    0.015114128135519066,
    -0.0037309280809643985,
)
#: 2^(-(e + 1)/5) for the binary exponents e = -65 ... 63 of err = s 2^e, s in [1, 2).
_POW2_FIFTH = np.array([2.0 ** (-0.2 * e) for e in range(-64, 65)])


@njit(cache=True, inline="always", error_model="numpy")
def growth(err):
    """The step-size factor 0.9 err^-0.2 of the controller (err > 0, finite), within 2e-4 and
    without ``pow`` or ``frexp``: err = s 2^e with s in [1, 2) read from the float's bits,
    (s/2)^-0.2 from a cubic, 2^(-(e+1)/5) from a table. The factor is needed before the next
    step can start: ``pow`` (~25 ns) sat in the dependency chain of every step. Beyond the table
    (err < 2^-65 or >= 2^64, subnormals included) it returns 1e30 or 0, which the callers'
    bounds clip."""
    s, e = significand_exponent(err)
    if e < -65:
        return 1e30
    if e > 63:
        return 0.0
    t = 2.0 * s - 3.0
    return 0.9 * (_G0 + t * (_G1 + t * (_G2 + t * _G3))) * _POW2_FIFTH[e + 65]


@njit(cache=True, inline="always", error_model="numpy")
def power_growth(err):
    """The step-size factor 0.9 err^-0.2 by ``pow`` (err > 0: inf at err = 0, which the
    callers' bounds clip)."""
    return 0.9 * err**-0.2


@njit_llvm_inline
def growth_llvm(err):
    """``growth`` compiled once and inlined by LLVM (``kernels._jit.njit_llvm_inline``), for the
    rigid engine's step loops (eight call sites that numba would translate and type again)."""
    return growth(err)
