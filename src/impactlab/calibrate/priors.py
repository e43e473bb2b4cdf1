"""Free parameters and their priors.

A free parameter is a numeric input of the sweep's catalogue (``flat_yield_strength``, ``mu``,
``flat_meyer_index``, ``damping``, ``body_E``, ...; not the per-drop kinematics), the same for
every drop. Its prior is one of

- ``uniform(low, high)``, ``loguniform(low, high)`` (``low > 0``),
- ``normal(mean, sd)`` or ``normal(mean, sd, low, high)`` (truncated to [low, high] and to the
  parameter's possible range; a bound may be ``inf`` or ``-inf``, an open end),

with values in the input's unit (SI; the Brinell hardness in kgf/mm^2, as the sweep stores it) or
as quantity strings (``"uniform(100 MPa, 1 GPa)"``; a Brinell hardness also ``"105 HB"``; a
fraction, mu or damping, also in percent: ``"uniform(0, 60 %)"`` is ``uniform(0, 0.6)``).
``Parameter.describe`` writes a prior in this form (``parse_parameter`` reads it back to the same
numbers). scipy.stats gives the densities and draws.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
from scipy import stats

from impactlab._display import display_unit
from impactlab.calibrate.input_magnitudes import PLAUSIBLE_INPUTS
from impactlab.calibrate.measurement_columns import fraction
from impactlab.calibrate.quantities import FRACTIONS, KINEMATICS, NUMERIC_INPUTS
from impactlab.calibrate.values import bare, did_you_mean, to_unit
from impactlab.sweep.inputs import INPUTS
from impactlab.units import bare_text

__all__ = ["PRIOR_KINDS", "Parameter", "parse_parameter"]

PRIOR_KINDS = ("uniform", "loguniform", "normal")

#: The possible range of each kind of input (open ends are excluded where marked below).
_POSITIVE = (0.0, math.inf)
_RANGES: dict[str, tuple[float, float]] = {
    "mu": (0.0, math.inf),
    "damping": (0.0, 1.0),
    "spin": (-math.inf, math.inf),
    "body_nu": (-1.0, 0.5),
    "flat_nu": (-1.0, 0.5),
}


def possible_range(name: str) -> tuple[float, float]:
    """[low, high] of the values ``name`` can take (mu >= 0, 0 <= zeta < 1, -1 < nu < 0.5, the
    rest > 0)."""
    return _RANGES.get(name, _POSITIVE)


@dataclass(frozen=True)
class Parameter:
    """One free parameter: its input ``name``, prior ``kind`` and the prior's numbers (in the
    input's ``unit``):
    ``low``/``high`` (uniform, loguniform; the truncation of normal) and ``mean``/``sd``
    (normal)."""

    name: str
    kind: str = "uniform"
    low: float = -math.inf
    high: float = math.inf
    mean: float = math.nan
    sd: float = math.nan

    def __post_init__(self) -> None:
        check_parameter_name(self.name)
        if self.kind not in PRIOR_KINDS:
            raise ValueError(
                f"prior of {self.name}: unknown kind {self.kind!r}; known: {', '.join(PRIOR_KINDS)}"
            )
        lo, hi = possible_range(self.name)
        if self.kind == "normal":
            if not (math.isfinite(self.mean) and math.isfinite(self.sd) and self.sd > 0):
                raise ValueError(
                    f"prior of {self.name}: normal needs a finite mean and sd > 0, "
                    f"got mean={self.mean!r}, sd={self.sd!r}"
                )
            object.__setattr__(self, "low", max(self.low, lo))
            object.__setattr__(self, "high", min(self.high, hi))
        elif not (math.isfinite(self.low) and math.isfinite(self.high)):
            raise ValueError(f"prior of {self.name}: {self.kind} needs finite low and high")
        if not self.low < self.high:
            raise ValueError(
                f"prior of {self.name} excludes every value: [{self.low:g}, {self.high:g}] is "
                "empty (low must be < high)"
            )
        u = "" if self.unit in ("", "1") else f" {self.unit}"
        if self.low < lo or self.high > hi or (self.high <= lo) or (self.low >= hi):
            raise ValueError(
                f"prior of {self.name}: [{self.low:g}, {self.high:g}]{u} reaches outside "
                f"the possible values [{lo:g}, {hi:g}]{u}"
            )
        if self.kind == "loguniform" and self.low <= 0:
            raise ValueError(f"prior of {self.name}: loguniform needs low > 0, got {self.low:g}{u}")
        if (
            self.kind == "normal"
            and stats.norm(self.mean, self.sd).cdf(self.high)
            - stats.norm(self.mean, self.sd).cdf(self.low)
            < 1e-12
        ):
            raise ValueError(
                f"prior of {self.name} excludes every value: normal({self.mean:g}, {self.sd:g}) "
                f"has no mass in [{self.low:g}, {self.high:g}]"
            )
        self._check_magnitude()

    def _check_magnitude(self) -> None:
        """ValueError when the whole prior (a normal's mean +- 5 sd within its bounds) lies
        outside what the input can plausibly be (``PLAUSIBLE_INPUTS``): a range given without
        its unit, ``uniform(100, 1000)`` for a yield strength, is 100-1000 Pa."""
        rule = PLAUSIBLE_INPUTS.get(self.name)
        if rule is None:
            return
        low, high = self.low, self.high
        if self.kind == "normal":
            low, high = max(low, self.mean - 5 * self.sd), min(high, self.mean + 5 * self.sd)
        plausible_low, plausible_high, hint = rule
        if plausible_low <= high and low <= plausible_high:
            return
        side = f"below {plausible_low:g}" if high < plausible_low else f"above {plausible_high:g}"
        numbers = (self.mean, self.sd) if self.kind == "normal" else (self.low, self.high)
        given = ", ".join(_number(x) for x in numbers)
        hinted = ", ".join(f"{_number(x)} {hint}" for x in numbers)
        try:  # the unit most likely left out, where the range then is plausible
            top = to_unit(f"{_number(max(numbers))} {hint}", self.unit, name=self.name)
        except ValueError:
            top = math.nan
        suggestion = f", e.g. '{self.kind}({hinted})'" if plausible_low <= top else ""
        raise ValueError(
            f"prior of {self.name}: {self.kind}({given}) in {self.unit} lies wholly {side} "
            f"{self.unit}: an implausible magnitude (a number without its unit is in "
            f"{self.unit}); give the unit{suggestion}"
        )

    @property
    def unit(self) -> str:
        """The parameter's unit: the input's (SI; a Brinell hardness in kgf/mm^2)."""
        return INPUTS[self.name].unit

    @cached_property
    def _frozen(self) -> Any:
        """The scipy.stats distribution (frozen once: freezing costs milliseconds)."""
        return self._dist()

    def _dist(self) -> Any:
        if self.kind == "uniform":
            return stats.uniform(self.low, self.high - self.low)
        if self.kind == "loguniform":
            return stats.loguniform(self.low, self.high)
        a, b = (self.low - self.mean) / self.sd, (self.high - self.mean) / self.sd
        if self.low == -math.inf and self.high == math.inf:
            return stats.norm(self.mean, self.sd)
        return stats.truncnorm(a, b, loc=self.mean, scale=self.sd)

    def logpdf(self, x: np.ndarray) -> np.ndarray:
        """The log prior density at ``x`` (-inf outside the support)."""
        x = np.asarray(x, dtype=np.float64)
        with np.errstate(divide="ignore"):
            out = np.asarray(self._frozen.logpdf(x), dtype=np.float64)
        return np.where((x >= self.low) & (x <= self.high), out, -np.inf)

    def sample(self, n: int, rng: np.random.Generator) -> np.ndarray:
        """``n`` draws from the prior."""
        x = np.asarray(self._frozen.rvs(size=n, random_state=rng), dtype=np.float64)
        return np.clip(x, self.low, self.high)

    def cdf(self, x: Any) -> np.ndarray:
        """The prior's cumulative distribution at ``x``: its share of mass below ``x``."""
        return np.asarray(self._frozen.cdf(np.asarray(x, dtype=np.float64)), dtype=np.float64)

    def quantile(self, q: Any) -> np.ndarray:
        """The prior's quantiles ``q`` in [0, 1]."""
        x = np.asarray(self._frozen.ppf(q), dtype=np.float64)
        return np.clip(x, self.low, self.high)  # scipy's ppf may round past a bound

    def describe(self) -> str:
        """The prior as ``-p`` and ``[parameters]`` read it (``parse_parameter`` gives this
        parameter back): ``"uniform(100 MPa, 1000 MPa)"``, ``"uniform(0, 0.6)"``,
        ``"normal(0.2, 0.05)"`` (bounds only where they cut more than the possible range),
        ``"uniform(50 kgf/mm^2, 200 kgf/mm^2)"``."""
        if self.kind != "normal":
            return f"{self.kind}({self._text(self.low)}, {self._text(self.high)})"
        head = f"normal({self._text(self.mean)}, {self._text(self.sd)}"
        if (self.low, self.high) == possible_range(self.name):
            return f"{head})"
        return f"{head}, {self._text(self.low)}, {self._text(self.high)})"

    def _text(self, x: float) -> str:
        """``x`` (in ``unit``) as a value ``parse_parameter`` reads back to the same float: in
        the display unit where that holds (``"100 MPa"``), else in ``unit``; ``inf``, ``-inf``
        bare (the open end of a truncated normal)."""
        if not math.isfinite(x):
            return "inf" if x > 0 else "-inf"
        if self.unit in ("", "1"):
            return _number(x)
        shown = display_unit(self.name, self.unit)
        for text in (f"{_number(x * shown.scale)} {shown.unit}", f"{_number(x)} {self.unit}"):
            try:
                if to_unit(text, self.unit, name=self.name) == x:
                    return text
            except ValueError:
                continue
        return f"{_number(x)} {self.unit}"


def _number(x: float) -> str:
    """The shortest text of ``x`` that reads back to it (``100``, ``0.6``, ``1e-05``)."""
    text = repr(float(x))
    return text.removesuffix(".0")


_NUMBERS = ("low", "high", "mean", "sd")
_SPEC = re.compile(r"^\s*([a-z]+)\s*\((.*)\)\s*$")


def _value(text: Any, unit: str, name: str, *, bound: bool, key: str = "") -> float:
    """A number of a prior (text or a number) in ``unit``; a bound of a truncated normal may be
    ``inf`` or ``-inf`` (an open end, as ``describe`` writes it); a fraction (mu, damping) may
    be in percent (``"60 %"``: 0.6). Errors name ``name`` or, given, ``name.key``."""
    if bound and isinstance(text, str) and text.lower().lstrip("+") in ("inf", "-inf"):
        return -math.inf if text.startswith("-") else math.inf
    share = fraction(name, text, None) if name in FRACTIONS else None
    if share is not None:
        return share
    return to_unit(text, unit, name=f"{name}.{key}" if key else name)


_LEADING_NUMBER = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*(?P<unit>\S.*)$")


def _mixed_units(name: str, unit: str, spec: Any, args: list[Any]) -> None:
    """ValueError when some numbers of a prior carry a unit and another one of a dimensional
    input does not: ``normal(300 MPa, 50)`` would read the sd as 50 Pa. A bare 0, ``inf`` or
    ``-inf`` is the same in every unit."""
    if unit in ("", "1"):
        _mixed_percent(name, spec, args)
        return
    given = [
        a
        for a in args
        if isinstance(a, str) and not bare(a) and a.strip().lower().lstrip("+-") != "inf"
    ]
    if not given:
        return
    for a in args:
        text = bare_text(str(a).strip())
        if bare(a) and float(text) != 0.0 and math.isfinite(float(text)):
            hint = f"{text} {_suggested(name, unit, text, given[0])}"
            raise ValueError(
                f"prior of {name}: {spec!r}: {text} has no unit while {str(given[0]).strip()!r}"
                f" has one: give its unit too (e.g. '{hint}'); a number without a unit would be "
                f"read in {unit}"
            )


def _mixed_percent(name: str, spec: Any, args: list[Any]) -> None:
    """ValueError when a prior of a fraction gives one number in percent and another bare:
    ``normal(30 %, 5)`` would read the sd as 5 (500 %), as the measurements file refuses a
    percent uncertainty beside a bare value. A bare 0, ``inf`` or ``-inf`` is the same in both."""
    percent = [a for a in args if (isinstance(a, str) and "%" in a) or "percent" in str(a)]
    if not percent:
        return
    for a in args:
        text = bare_text(str(a).strip())
        if bare(a) and float(text) != 0.0 and math.isfinite(float(text)):
            raise ValueError(
                f"prior of {name}: {spec!r}: {text} has no unit while "
                f"{str(percent[0]).strip()!r} is in percent: give both in percent (e.g. "
                f"'{text} %') or both as fractions (a bare number is a fraction: {text} is "
                f"{float(text) * 100:g} %)"
            )


def _suggested(name: str, unit: str, text: str, other: Any) -> str:
    """The unit to suggest for the bare number ``text`` of a prior whose number ``other`` has
    one: ``other``'s unit where ``text`` in it stays within a factor 1000 of ``other``
    (``normal(300 MPa, 50)``: MPa), else the input's own ``unit`` (``uniform(1e8, 1 GPa)``: Pa,
    not 1e8 GPa)."""
    m = _LEADING_NUMBER.match(str(other))
    shown = m.group("unit") if m else "HB"
    try:
        x, ref = to_unit(f"{text} {shown}", unit, name=name), to_unit(other, unit, name=name)
    except ValueError:
        return unit
    return shown if ref != 0 and 1e-3 <= abs(x / ref) <= 1e3 else unit


#: Numeric inputs that are a numerical resolution, not physics: never free parameters.
RESOLUTIONS = ("n_axial", "n_bending")


def check_parameter_name(name: str) -> None:
    """ValueError, with the nearest name, for what is not a free parameter (a numeric input
    that is not one of the measured drop's kinematics, nor a resolution: ``RESOLUTIONS``)."""
    if name in RESOLUTIONS:
        raise ValueError(
            f"{name} is a count of a flexible rod's modes, a numerical resolution, not a "
            "parameter to calibrate: give it as a fixed input of the model or a column of the "
            "measurements (explain checks a flexible result with twice its modes)"
        )
    allowed = tuple(n for n in NUMERIC_INPUTS if n not in KINEMATICS and n not in RESOLUTIONS)
    if name not in allowed:
        raise ValueError(
            f"unknown free parameter {name!r}{did_you_mean(name, allowed)}; a "
            f"parameter is one of {', '.join(allowed)}"
        )


def parse_parameter(name: str, spec: Any) -> Parameter:
    """A Parameter from a prior text, ``"uniform(100 MPa, 1 GPa)"`` (what
    ``Parameter.describe`` writes), or a mapping ``{"prior": "normal", "mean": ..., "sd": ...,
    "low": ..., "high": ...}``; bare numbers are in the input's unit (``Parameter.unit``),
    unless another number of the prior carries a unit: then a bare one (other than 0 or an
    infinite bound) is refused. The name is checked first (its unit reads the numbers)."""
    check_parameter_name(name)
    unit = INPUTS[name].unit
    if isinstance(spec, dict):
        _mixed_units(name, unit, spec, [v for k, v in spec.items() if k in _NUMBERS])
        kind = str(spec.get("prior", "uniform"))
        nums = {
            k: _value(v, unit, name, bound=k in ("low", "high"), key=k)
            for k, v in spec.items()
            if k in _NUMBERS
        }
        extra = set(spec) - {"prior", *_NUMBERS}
        if extra:
            raise ValueError(f"prior of {name}: unknown key(s) {sorted(extra)}")
        return Parameter(name, kind, **nums)
    m = _SPEC.match(str(spec))
    if not m:
        raise ValueError(
            f"prior of {name}: cannot read {spec!r}; expected e.g. 'uniform(low, high)', "
            "'loguniform(low, high)' or 'normal(mean, sd)'"
        )
    kind, args = m.group(1), [a.strip() for a in m.group(2).split(",") if a.strip()]
    if kind not in PRIOR_KINDS:
        raise ValueError(f"prior of {name}: unknown kind {kind!r}; known: {', '.join(PRIOR_KINDS)}")
    _mixed_units(name, unit, spec, args)
    values = [_value(a, unit, name, bound=i >= 2) for i, a in enumerate(args)]
    if kind in ("uniform", "loguniform") and len(values) == 2:
        return Parameter(name, kind, low=values[0], high=values[1])
    if kind == "normal" and len(values) in (2, 4):
        bounds = dict(zip(("low", "high"), values[2:], strict=False))
        return Parameter(name, kind, mean=values[0], sd=values[1], **bounds)
    raise ValueError(
        f"prior of {name}: {spec!r} has the wrong number of values; uniform/loguniform take "
        "(low, high), normal takes (mean, sd) or (mean, sd, low, high)"
    )
