"""Event location on the dense output: the Illinois update of a bracket and the round-off
probe past a root, shared by every engine's event search.

An event fires where its function g goes from <= 0 to > 0 inside a step; each engine brackets
the root in theta in (0, 1] and iterates the Illinois variant of regula falsi (Dowell &
Jarratt, BIT 11 (1971) 168, doi:10.1007/BF01934364) on its dense output, with its own
evaluation of g. An iterate where g is zero to round-off (``G_ROUNDOFF`` of the bracket's
initial scale) ends the search: on the g > 0 side it is the answer, on the g <= 0 side a
probe just past it (``past_root``) closes the bracket; the Illinois iterates would otherwise
creep on from that side (CHANGELOG.md, "Performance history").
"""

from __future__ import annotations

from numba import njit

#: |g| at or below this fraction of the bracket's initial |g| is zero to round-off (the event
#: functions are sums of terms of their own scale, evaluated to ~1e-15 of it).
G_ROUNDOFF = 1e-13
#: Closed bracket width in theta (a fraction of the step).
THETA_TOL = 1e-14


@njit(cache=True, inline="always", error_model="numpy")
def past_root(th, f, b, fb):
    """Where to probe just past a root at ``th`` (g(th) = f <= 0, zero to round-off; bracket
    end ``b`` with g = fb > 0): twice the distance to the secant root, at least THETA_TOL."""
    return th + max(THETA_TOL, 2.0 * (-f) * (b - th) / (fb - f))


@njit(cache=True, inline="always", error_model="numpy")
def illinois(a, fa, b, fb, side, th, f):
    """One Illinois update of the bracket [a, b] (fa <= 0 < fb) with the value f at th: the
    new (a, fa, b, fb, side), the stale end's value halved when the same side moves twice
    (side: +1 after the g > 0 end moved, -1 after the other, 0 at the start)."""
    if f > 0.0:
        return a, (0.5 * fa if side == 1 else fa), th, f, 1
    return th, f, b, (0.5 * fb if side == -1 else fb), -1
