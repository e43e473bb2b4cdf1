"""The self-consistent rate factor of a rate-dependent flat (SI units): the contact's strain
rate, the fixed point k = law.factor(eps_dot(a_m(k))) of :mod:`impactlab.contact.rate`, the
largest factor a pair takes and the warning of a factor that did not converge.

The fixed point: a_m(k), the contact radius at the largest interference of the first contact,
shrinks as k raises the flat's yield strength, so the strain rate and with it the law's factor
grow with k. A plain step k <- law.factor(eps_dot(a_m(k))) converges where that map is flat (the
paper's drops: slope about 0.03, four drops); where it is steep (a law's exponent 1/q large)
it creeps, so a steep map takes secant steps on law.factor(...) - k instead, kept inside the
bracket of the root that the evaluations found.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from impactlab._validation import _caller_level, check_nonnegative, check_positive
from impactlab.materials import Material, first_yield_factor

__all__ = [
    "BODY_MARGIN",
    "PLAIN_STEP_SLOPE",
    "RateFactor",
    "RateFactorWarning",
    "RateLimit",
    "body_margin",
    "self_consistent_factor",
    "tabor_strain_rate",
    "warn_no_dent",
]


class FactorLaw(Protocol):
    """What the fixed point reads of a :class:`impactlab.contact.rate.RateLaw`."""

    @property
    def text(self) -> str:
        """The law as the user wrote it."""
        ...

    def factor(self, rate: float) -> float:
        """The yield-strength factor k (1) at the strain rate ``rate`` [1/s]."""
        ...


#: How far the body's yield strength is raised above the rate-raised flat's where it would not
#: exceed it (``contact.rate.rate_materials``: only the flat yields, as the measured dents say).
BODY_MARGIN = 1.5
#: The largest estimated slope |d k_new / d k| of the fixed-point map for which the iteration
#: takes a plain step (each one shrinks the error at least twofold); above it, a secant step.
PLAIN_STEP_SLOPE = 0.5


def body_margin(body: Material, flat: Material) -> float:
    """The body's raised yield strength over the rate-raised flat's [1] (``contact.rate.
    rate_materials``): ``BODY_MARGIN``, times C(nu_flat) / C(nu_body) where that exceeds 1
    (``materials.first_yield_factor``), so that the body's first-yield pressure C(nu) S_y, which
    decides the body that yields first (``materials.body_yields_first``), is at least
    ``BODY_MARGIN`` times the flat's too."""
    return BODY_MARGIN * max(1.0, first_yield_factor(flat.nu) / first_yield_factor(body.nu))


class RateFactorWarning(RuntimeWarning):
    """A rate-dependent flat's factor is doubtful: its fixed point did not converge, or it
    leaves the drop without a dent although the rate-independent flat yields."""


def tabor_strain_rate(v: float, a: float, factor: float = 0.2) -> float:
    """Characteristic contact strain rate ``factor`` |v| / a [1/s] for an approach speed v
    [m/s] and a contact radius a [m] (``factor`` = 0.2: Tabor; 1 gives the cruder v / a)."""
    check_positive("a", a, "m")
    return check_nonnegative("factor", factor) * abs(v) / a


def _stress(x: float) -> str:
    """A stress [Pa] in words: ``305 MPa``, ``241 GPa``."""
    return f"{x / 1e9:.4g} GPa" if abs(x) >= 1e9 else f"{x / 1e6:.4g} MPa"


@dataclass(frozen=True)
class RateLimit:
    """The largest rate factor a pair takes, ``k_max`` [1]: the contact laws need each yield
    strength below its body's E, and a rate factor raises the flat's to k S_y and the body's,
    where it would not exceed that, to ``body_margin`` k S_y. ``yield_strength``: the flat's
    quasi-static S_y [Pa]; ``bound``: which modulus sets ``k_max``, in words."""

    k_max: float
    yield_strength: float
    bound: str

    @classmethod
    def of(cls, body: Material, flat: Material) -> RateLimit:
        """The limit of the pair (``body`` on ``flat``)."""
        sy, margin = flat.yield_strength, body_margin(body, flat)
        flat_k, body_k = flat.E / sy, body.E / (margin * sy)
        if flat_k <= body_k:
            return cls(flat_k, sy, f"the flat's yield strength below its E = {_stress(flat.E)}")
        return cls(
            body_k,
            sy,
            f"the rod's yield strength, raised to {margin:.4g} times the flat's, below its "
            f"E = {_stress(body.E)}",
        )

    def refusal(self, law: FactorLaw, rate: float, k: float) -> ValueError:
        """The one-line error of a factor ``k`` >= ``k_max`` given by ``law`` at the strain rate
        ``rate`` [1/s]."""
        return ValueError(
            f"rate {law.text!r}: at the contact's strain rate {rate:.4g} 1/s (Tabor's 0.2 "
            f"|v_n0| / a_m) the law gives the factor k = {k:.4g}, which would raise the flat's "
            f"yield strength {_stress(self.yield_strength)} to {_stress(k * self.yield_strength)}"
            f"; k must stay below {self.k_max:.4g} ({self.bound}): check the law's constants"
        )


@dataclass(frozen=True)
class RateFactor:
    """The self-consistent rate factor: ``k`` [1], the strain rate [1/s], the contact radius
    a_m [m] it was computed from, the number of drops run (``iterations``), the last relative
    change |k_new - k| / k [1] and whether that met the tolerance (``converged``)."""

    k: float
    strain_rate: float
    contact_radius: float
    iterations: int
    change: float = 0.0
    converged: bool = True


def _next(
    k: float, k_new: float, last: tuple[float, float] | None, bracket: tuple[float, float]
) -> float:
    """The next iterate after ``k`` -> ``k_new``: the plain step ``k_new`` where the map's slope
    (estimated from ``last``, the previous (k, k_new)) is at most ``PLAIN_STEP_SLOPE``, else
    the secant root of k_new(k) - k; bisection of ``bracket`` (lo, hi) where a step leaves it."""
    step = k_new
    if last is not None and k != last[0]:
        slope = (k_new - last[1]) / (k - last[0])
        if abs(slope) > PLAIN_STEP_SLOPE and slope != 1.0:
            step = k + (k_new - k) / (1.0 - slope)
    lo, hi = bracket
    if lo < step < hi and math.isfinite(step):
        return step
    if lo < k_new < hi:
        return k_new
    return 0.5 * (lo + hi)


def self_consistent_factor(
    run: Callable[[float], float],
    law: FactorLaw,
    vn0: float,
    strain_factor: float = 0.2,
    tol: float = 1e-4,
    max_iter: int = 40,
    limit: RateLimit | None = None,
) -> RateFactor:
    """Fixed point k = law.factor(strain_factor |vn0| / a_m(k)).

    ``run(k)`` simulates with the flat's yield strength multiplied by k and returns a_m [m],
    the contact radius at the largest interference of the first contact; ``vn0`` [m/s] is the
    normal approach speed. Stops when k_new = law.factor(...) differs from k by at most ``tol``
    k and returns k_new; plain steps where the map is flat, secant steps where it is steep
    (module docstring). After ``max_iter`` drops: the closest iterate, with a
    :class:`RateFactorWarning` naming the law, its constants and the last change. ``limit``:
    ValueError (:meth:`RateLimit.refusal`) as soon as the law gives a factor at or above its
    ``k_max`` (the map grows with k, so the fixed point would too); ``run`` only sees factors
    below it. ValueError for a factor that overflows."""
    if isinstance(max_iter, bool) or not isinstance(max_iter, int) or max_iter < 1:
        raise ValueError(f"max_iter must be an int >= 1 (drops run), got {max_iter!r}")
    k_max = math.inf if limit is None else limit.k_max
    k, lo, hi = 1.0, 1.0, k_max
    last: tuple[float, float] | None = None
    best: RateFactor | None = None
    for it in range(1, max_iter + 1):
        a_m = run(k)
        rate = tabor_strain_rate(vn0, a_m, strain_factor)
        k_new = law.factor(rate)
        if limit is not None and k_new >= k_max:
            raise limit.refusal(law, rate, k_new)
        if not math.isfinite(k_new):
            raise ValueError(
                f"rate {law.text!r}: the law's factor overflows at the contact's strain rate "
                f"{rate:.4g} 1/s (k = {k:.4g}): no self-consistent factor; check its constants"
            )
        change = abs(k_new - k) / k
        if change <= tol:
            return RateFactor(k_new, rate, a_m, it, change)
        if best is None or change < best.change:
            best = RateFactor(k_new, rate, a_m, it, change, converged=False)
        lo, hi = (max(lo, k), hi) if k_new > k else (lo, min(hi, k))
        k, last = _next(k, k_new, last, (lo, hi)), (k, k_new)
    assert best is not None  # max_iter >= 1 drops ran
    warnings.warn(
        f"rate {law.text!r}: the self-consistent rate factor did not converge in {max_iter} "
        f"drops (last relative change of k {change:.2g}, tolerance {tol:g}); using k = "
        f"{best.k:.6g} at {best.strain_rate:.4g} 1/s, the closest iterate (change "
        f"{best.change:.2g})",
        RateFactorWarning,
        stacklevel=_caller_level(),
    )
    return best


def warn_no_dent(
    law: FactorLaw,
    factor: RateFactor,
    yield_strength: float,
    onsets: tuple[float, float],
    dent: float,
    delta_max: float,
) -> None:
    """A :class:`RateFactorWarning` where the rate factor leaves a drop without a dent (``dent``
    [m] zero) although its largest interference ``delta_max`` [m] passes the rate-independent
    flat's yield onset: ``onsets`` (rate-independent, rate-raised) [m]; ``yield_strength``: the
    flat's quasi-static S_y [Pa]."""
    plain, raised = onsets
    if dent > 0.0 or not delta_max > plain:
        return
    warnings.warn(
        f"rate {law.text!r}: the self-consistent factor k = {factor.k:.4g} (strain rate "
        f"{factor.strain_rate:.4g} 1/s) raises the flat's yield strength to "
        f"{_stress(factor.k * yield_strength)}, so the drop leaves no dent: its largest "
        f"interference {delta_max * 1e6:.4g} um stays below the raised yield onset "
        f"{raised * 1e6:.4g} um, while the rate-independent flat yields from {plain * 1e6:.4g} "
        "um; check the law's constants",
        RateFactorWarning,
        stacklevel=_caller_level(),
    )
