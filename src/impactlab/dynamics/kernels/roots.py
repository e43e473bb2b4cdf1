"""Event location on the dense output: the bracket updates of regula falsi and the round-off
probe past a root, shared by the engines' event searches.

An event fires where its function g goes from <= 0 to > 0 inside a step; each engine brackets
the root in theta in (0, 1] and iterates a variant of regula falsi on its dense output, with its
own evaluation of g:

- the Illinois variant (Dowell & Jarratt, BIT 11 (1971) 168, doi:10.1007/BF01934364; the rigid
  and flexible engines, ``illinois``): an iterate where g is zero to round-off (``G_ROUNDOFF``
  of the bracket's initial scale) ends the search: on the g > 0 side it is the answer, on the
  g <= 0 side a probe just past it (``past_root``) closes the bracket; the Illinois iterates
  would otherwise creep on from that side (CHANGELOG.md, "Performance history");
- the Anderson-Bjorck variant with a closing step (Anderson & Bjorck, BIT 13 (1973) 253,
  doi:10.1007/BF01951936; the partial-slip engine, ``anderson_bjorck_point`` and
  ``anderson_bjorck``): where the same end moves twice in a row, the other end's value is scaled
  by 1 - f_new / f_old (by 1/2 where that is not positive), which brings the next estimate
  across the root (Illinois halves it always); an estimate within half the tolerance of the end
  that moved last is put half the tolerance past that end instead, across the root when the
  estimate is good, which closes the bracket with one evaluation instead of creeping up on the
  root from one side.
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


@njit(cache=True, inline="always", error_model="numpy")
def anderson_bjorck_point(a, fa, b, fb, side, half):
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
def anderson_bjorck(a, fa, b, fb, side, th, f):
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
