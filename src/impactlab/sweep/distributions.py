"""Seeded distributions for Monte Carlo studies, drawn by inverse transform from counter-based
uniforms.

Sample ``i`` of input ``x`` is a pure function of (seed, input name, i): the uniform is
``u = (splitmix64(key(seed, name) + (i + 1) * gamma) >> 11 + 1/2) 2^-53`` and the value is the
distribution's quantile function at ``u``. So a sample does not depend on the chunk size, on the
order in which chunks run, on which worker runs them, or on the other inputs of the study; a
resumed or distributed sweep draws exactly the same cases. SplitMix64 (Steele, Lea & Flood,
OOPSLA 2014, doi:10.1145/2660193.2660195) is the generator used to seed Java's and numpy's
streams; its output passes BigCrush.

All parameters are SI (the study-file parser converts units first).
"""

from __future__ import annotations

import dataclasses
import math
import zlib
from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from scipy import special

from impactlab._validation import check_finite, check_positive
from impactlab.sweep.inputs import INPUTS
from impactlab.units import has_unit

_GAMMA = np.uint64(0x9E3779B97F4A7C15)
_M1 = np.uint64(0xBF58476D1CE4E5B9)
_M2 = np.uint64(0x94D049BB133111EB)


def stream_key(seed: int, name: str) -> np.uint64:
    """The 64-bit key of input ``name``'s stream for ``seed`` (numpy SeedSequence mixing)."""
    ss = np.random.SeedSequence([int(seed), zlib.crc32(name.encode("utf-8"))])
    return np.uint64(ss.generate_state(1, dtype=np.uint64)[0])


def uniforms(seed: int, name: str, start: int, stop: int) -> np.ndarray:
    """Uniforms in (0, 1) for samples ``start <= i < stop`` of input ``name``."""
    if not (0 <= start <= stop):
        raise ValueError(f"need 0 <= start <= stop, got start={start}, stop={stop}")
    key = stream_key(seed, name)
    i = np.arange(start + 1, stop + 1, dtype=np.uint64)
    with np.errstate(over="ignore"):
        z = key + i * _GAMMA
        z = (z ^ (z >> np.uint64(30))) * _M1
        z = (z ^ (z >> np.uint64(27))) * _M2
        z = z ^ (z >> np.uint64(31))
    return ((z >> np.uint64(11)).astype(np.float64) + 0.5) * 2.0**-53


def _norm_cdf(x: float) -> float:
    return float(special.ndtr(x))


class Distribution(ABC):
    """A one-dimensional distribution with a quantile function (vectorised)."""

    kind: ClassVar[str]

    @abstractmethod
    def ppf(self, u: np.ndarray) -> np.ndarray:
        """Quantile function at ``u`` in (0, 1)."""

    @abstractmethod
    def to_dict(self) -> dict[str, Any]:
        """Canonical description (SI), part of the study hash."""

    def draw(self, seed: int, name: str, start: int, stop: int) -> np.ndarray:
        """Samples ``start..stop-1`` of input ``name`` (see the module docstring)."""
        return self.ppf(uniforms(seed, name, start, stop))


def _bounds(low: Any, high: Any) -> tuple[float, float]:
    lo = -math.inf if low is None else float(low)
    hi = math.inf if high is None else float(high)
    if math.isnan(lo) or math.isnan(hi):
        raise ValueError("truncation bounds low/high must not be NaN")
    if not lo < hi:
        raise ValueError(f"truncation bounds need low < high, got low={lo!r}, high={hi!r}")
    return lo, hi


def _bound_dict(lo: float, hi: float) -> dict[str, float]:
    d: dict[str, float] = {}
    if math.isfinite(lo):
        d["low"] = lo
    if math.isfinite(hi):
        d["high"] = hi
    return d


def _settle(dist: Distribution, **fields: Any) -> None:
    """Set the checked fields of a frozen distribution."""
    for name, value in fields.items():
        object.__setattr__(dist, name, value)


def _numbers(dist: Any) -> None:
    """ValueError for a parameter of ``dist`` given as text or a Quantity: a distribution
    built in Python does not know its input, so not the unit to read it in."""
    for f in dataclasses.fields(dist):
        value = getattr(dist, f.name)
        if isinstance(value, str) or has_unit(value):
            raise ValueError(
                f"{dist.kind} distribution: {f.name} = {value!r} is "
                f"{'text' if isinstance(value, str) else 'a Quantity'}; a distribution built in "
                "Python takes numbers in its input's SI unit (an angle in radians, "
                "np.radians(20); a speed in m/s); text with units is read in a study file's "
                "[sample] table and by Study.from_dict"
            )


def _truncate(dist: Any, floor: float = -math.inf) -> tuple[float, float]:
    """Check and set the truncation bounds ``low``, ``high`` of ``dist`` (``low`` at least
    ``floor``); returns them."""
    lo, hi = _bounds(dist.low, dist.high)
    _settle(dist, low=max(lo, floor), high=hi)
    return max(lo, floor), hi


def _truncated_dict(dist: Any, floor: float = -math.inf, **params: float) -> dict[str, Any]:
    """Canonical description of a truncated distribution: ``dist``, ``params``, then the bounds
    that truncate (a ``low`` at ``floor`` does not)."""
    lo = dist.low if dist.low > floor else -math.inf
    return {"dist": dist.kind, **params, **_bound_dict(lo, dist.high)}


@dataclass(frozen=True)
class Uniform(Distribution):
    """Uniform on [low, high]."""

    low: float
    high: float
    kind: ClassVar[str] = "uniform"

    def __post_init__(self) -> None:
        _numbers(self)
        lo = check_finite("low", self.low)
        hi = check_finite("high", self.high)
        if not lo < hi:
            raise ValueError(f"uniform distribution needs low < high, got low={lo!r}, high={hi!r}")
        _settle(self, low=lo, high=hi)

    def ppf(self, u: np.ndarray) -> np.ndarray:
        return self.low + np.asarray(u) * (self.high - self.low)

    def to_dict(self) -> dict[str, Any]:
        return {"dist": self.kind, "low": self.low, "high": self.high}


def _truncated_std_normal_ppf(u: np.ndarray, a: float, b: float) -> np.ndarray:
    """Quantiles of the standard normal truncated to [a, b] (a, b may be infinite).

    Works in the tail that keeps precision: for a > 0 the mirror image is used.
    """
    if a > 0.0:
        return -_truncated_std_normal_ppf(1.0 - u, -b, -a)
    pa = special.ndtr(a)
    pb = special.ndtr(b)
    return special.ndtri(pa + u * (pb - pa))


@dataclass(frozen=True)
class Normal(Distribution):
    """Normal(mean, std), truncated to [low, high] when either bound is given."""

    mean: float
    std: float
    low: float | None = None
    high: float | None = None
    kind: ClassVar[str] = "normal"

    def __post_init__(self) -> None:
        _numbers(self)
        _settle(self, mean=check_finite("mean", self.mean), std=check_positive("std", self.std))
        lo, hi = _truncate(self)
        a, b = self._std_bounds()
        mass = _norm_cdf(b) - _norm_cdf(a) if a <= 0 else _norm_cdf(-a) - _norm_cdf(-b)
        if not mass > 1e-12:
            raise ValueError(
                f"normal distribution (mean={self.mean!r}, std={self.std!r}) has no probability "
                f"in [low, high] = [{lo!r}, {hi!r}]"
            )

    def _std_bounds(self) -> tuple[float, float]:
        assert self.low is not None and self.high is not None
        return (self.low - self.mean) / self.std, (self.high - self.mean) / self.std

    def ppf(self, u: np.ndarray) -> np.ndarray:
        a, b = self._std_bounds()
        z = _truncated_std_normal_ppf(np.asarray(u, dtype=np.float64), a, b)
        x = self.mean + self.std * z
        assert self.low is not None and self.high is not None
        return np.clip(x, self.low, self.high)

    def to_dict(self) -> dict[str, Any]:
        return _truncated_dict(self, mean=self.mean, std=self.std)


@dataclass(frozen=True)
class LogNormal(Distribution):
    """exp(Normal(log(median), sigma)), truncated to [low, high] (> 0) when bounds are given.

    ``LogNormal.from_mean_std(mean, std)`` takes the mean and standard deviation of the variable
    itself: sigma^2 = ln(1 + std^2/mean^2), median = mean / sqrt(1 + std^2/mean^2).
    """

    median: float
    sigma: float
    low: float | None = None
    high: float | None = None
    kind: ClassVar[str] = "lognormal"

    def __post_init__(self) -> None:
        _numbers(self)
        median, sigma = check_positive("median", self.median), check_positive("sigma", self.sigma)
        _settle(self, median=median, sigma=sigma)
        lo, hi = _truncate(self, floor=0.0)
        try:  # the truncation check lives in the underlying normal (log values): said here
            self._log_normal()
        except ValueError:
            raise ValueError(
                f"lognormal distribution (median={median:.6g}, sigma={sigma:.6g}) has no "
                f"probability in [low, high] = [{lo:.6g}, {hi:.6g}]"
            ) from None

    @classmethod
    def from_mean_std(
        cls, mean: float, std: float, low: float | None = None, high: float | None = None
    ) -> LogNormal:
        m = check_positive("mean", mean)
        s = check_positive("std", std)
        r = 1.0 + (s / m) ** 2
        return cls(median=m / math.sqrt(r), sigma=math.sqrt(math.log(r)), low=low, high=high)

    def _log_normal(self) -> Normal:
        assert self.low is not None and self.high is not None
        lo = math.log(self.low) if self.low > 0.0 else None
        hi = math.log(self.high) if math.isfinite(self.high) else None
        return Normal(math.log(self.median), self.sigma, lo, hi)

    def ppf(self, u: np.ndarray) -> np.ndarray:
        return np.exp(self._log_normal().ppf(u))

    def to_dict(self) -> dict[str, Any]:
        return _truncated_dict(self, 0.0, median=self.median, sigma=self.sigma)


DISTRIBUTIONS: dict[str, str] = {
    "uniform": "low, high",
    "normal": "mean, std [, low, high: truncation]",
    "truncnormal": "mean, std, low and/or high",
    "lognormal": "median, sigma (of log) or mean, std (of the value) [, low, high]",
}


def distribution_from_dict(d: dict[str, Any], convert: Any, name: str) -> Distribution:
    """Build a distribution from a study-file table.

    ``convert(value, key)`` turns one parameter (a number or a quantity string) into SI; ``name``
    is the input's name for error messages. Keys: ``dist`` and the parameters listed in
    ``DISTRIBUTIONS`` (plus ``unit``, handled by ``convert``).
    """
    if "dist" not in d:
        raise ValueError(
            f"sample input {name!r}: missing 'dist'; known distributions: "
            f"{', '.join(DISTRIBUTIONS)}"
        )
    kind = d["dist"]
    if kind not in DISTRIBUTIONS:
        raise ValueError(
            f"sample input {name!r}: unknown distribution {kind!r}; known: "
            f"{', '.join(DISTRIBUTIONS)}"
        )
    allowed = {
        "uniform": {"low", "high"},
        "normal": {"mean", "std", "low", "high"},
        "truncnormal": {"mean", "std", "low", "high"},
        "lognormal": {"median", "sigma", "mean", "std", "low", "high"},
    }[kind]
    params = {k: v for k, v in d.items() if k not in ("dist", "unit")}
    unknown = sorted(set(params) - allowed)
    if unknown:
        raise ValueError(
            f"sample input {name!r}: unknown parameter(s) {unknown} for the {kind} distribution; "
            f"allowed: {sorted(allowed)}"
        )

    def need(key: str) -> float:
        if key not in params:
            raise ValueError(
                f"sample input {name!r}: the {kind} distribution needs {key!r} "
                f"({DISTRIBUTIONS[kind]})"
            )
        return float(convert(params[key], key))

    def opt(key: str) -> float | None:
        return None if key not in params else float(convert(params[key], key))

    try:
        if kind == "uniform":
            return Uniform(need("low"), need("high"))
        if kind in ("normal", "truncnormal"):
            if kind == "truncnormal" and "low" not in params and "high" not in params:
                raise ValueError("the truncnormal distribution needs low and/or high")
            return Normal(need("mean"), need("std"), opt("low"), opt("high"))
        # lognormal: sigma is dimensionless (log space), so it is not unit-converted
        if "median" in params or "sigma" in params:
            if "mean" in params or "std" in params:
                raise ValueError("give either median and sigma, or mean and std, not both")
            if "sigma" not in params:
                raise ValueError("the lognormal distribution needs 'sigma' with 'median'")
            return LogNormal(
                need("median"), check_finite("sigma", params["sigma"]), opt("low"), opt("high")
            )
        return LogNormal.from_mean_std(need("mean"), need("std"), opt("low"), opt("high"))
    except ValueError as exc:
        msg = str(exc)
        if msg.startswith("sample input"):
            raise
        raise ValueError(f"sample input {name!r}: {_in_si(msg, name)}") from None


def _in_si(msg: str, name: str) -> str:
    """``msg`` with the SI unit that the input's values were converted to, where it quotes a
    value (``got ...``, ``[low, high] = ...``) and the input has a unit; not for a lognormal's
    sigma, which is dimensionless (the spread of the log)."""
    spec = INPUTS.get(name)
    quotes = "got" in msg or "[low, high] =" in msg
    if spec is None or spec.unit in ("", "1") or not quotes or msg.startswith("sigma "):
        return msg
    return f"{msg} (in {spec.unit}, the input's SI unit)"


def distribution_from_canonical(d: dict[str, Any]) -> Distribution:
    """Inverse of ``Distribution.to_dict`` (SI values)."""
    kind = d["dist"]
    lo, hi = d.get("low"), d.get("high")
    if kind == "uniform":
        return Uniform(d["low"], d["high"])
    if kind == "normal":
        return Normal(d["mean"], d["std"], lo, hi)
    if kind == "lognormal":
        return LogNormal(d["median"], d["sigma"], lo, hi)
    raise ValueError(f"unknown distribution {kind!r}")
