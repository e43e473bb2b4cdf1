"""Event location on a bracket: regula falsi with the Anderson-Bjorck scaling and a closing
step, for the partial-slip engine's event search (``stepper.locate``).

An event fires where its function g goes from <= 0 to > 0; the search holds a bracket
[a, b] in theta (a fraction of the step) with g(a) <= 0 < g(b), starts from the linear
estimate and ends when b - a <= the tolerance. Anderson & Bjorck, BIT 13 (1973) 253,
doi:10.1007/BF01951936: where the same end moves twice in a row, the other end's value is
scaled by 1 - f_new / f_old (by 1/2 where that is not positive), which brings the next
estimate across the root (the Illinois variant halves it always). The closing step: an
estimate within half the tolerance of the end that moved last is put half the tolerance
past that end instead, across the root when the estimate is good, which closes the bracket
with one evaluation instead of creeping up on the root from one side.
"""

from __future__ import annotations

from numba import njit


@njit(cache=True, inline="always", error_model="numpy")
def next_point(a, fa, b, fb, side, half):
    """The next theta to evaluate in the bracket [a, b] (g = fa <= 0 at a, fb > 0 at b):
    the secant root, or ``half`` (half the tolerance) past the end that moved last (``side``
    +1: b, -1: a, 0: neither) where the secant root lies closer to it, or the midpoint where
    the secant root is not inside the bracket."""
    th = (a * fb - b * fa) / (fb - fa)
    if side == 1 and b - th < half:
        return b - half
    if side == -1 and th - a < half:
        return a + half
    if not (a < th < b):
        return 0.5 * (a + b)
    return th


@njit(cache=True, inline="always", error_model="numpy")
def update(a, fa, b, fb, side, th, f):
    """The bracket (a, fa, b, fb, side) after the value ``f`` of g at ``th`` (a < th < b),
    with the Anderson-Bjorck scaling of the end that stays when the same end moves twice."""
    if f > 0.0:
        if side == 1:
            m = 1.0 - f / fb if fb != 0.0 else 0.5
            fa *= m if m > 0.0 else 0.5
        return a, fa, th, f, 1
    if side == -1:
        m = 1.0 - f / fa if fa != 0.0 else 0.5
        fb *= m if m > 0.0 else 0.5
    return th, f, b, fb, -1
