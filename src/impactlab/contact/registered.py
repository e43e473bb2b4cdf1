"""Contact laws brought by the user (``register_law``): the tabulated law under a name of its own.

The engine's laws are compiled and dispatched by a law id, so an arbitrary Python function
cannot run inside them. A user's law is therefore carried by the tabulated law (``law_id``
``TABULATED``, ``contact.tabulated``): its loading curve F(delta) and its residual depths
delta_r(delta_max), given

- as tables: ``IndentationCurves`` (measured data: ``IndentationCurves.from_arrays``,
  ``from_csv``; or FE curves), fitted and interpolated as the tabulated law does (loading: a
  constrained least-squares spline, ``contact.loading_fit``; residual depths: PCHIP, Fritsch &
  Carlson 1980; cross-validated error stated: leave-one-out, 10-fold past 100 points), or
- as Python callables ``loading(delta) -> F`` [m -> N] and ``unloading(delta_max) -> delta_r``
  [m -> m] of one pair and radius, sampled on ``points`` interferences spaced evenly in
  log(delta) from the elastic limit to ``delta_max``; the law built from the samples is
  compared with the callables at every sample and between samples (``CHECKS_PER_INTERVAL``
  points per interval) and refused where it departs by more than ``tolerance``.

Like the tabulated law, the curves are kept dimensionless (Jackson & Green 2005's delta_c and
F_c of their pair), so the law serves every pair with the same E*/S_y (within 5 %) and nu
(within 0.03) in which the same body yields first, any radius, and refuses other pairs. Its
data travel as a plain record (``RegisteredLaw.record``, ``law_from_record``): sweeps carry it
to their worker processes in the study.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable
from typing import Any

import numpy as np

from impactlab._validation import check_finite, check_positive, warn_implausible
from impactlab.contact._common import jg_critical
from impactlab.contact.indentation_data import IndentationCurves, curves_from_record
from impactlab.contact.loading_fit import held_out_method
from impactlab.contact.names import Law
from impactlab.contact.sample_checks import check_below_radius as _check_below_radius
from impactlab.contact.sample_checks import check_hertz_switch as _check_switch
from impactlab.contact.sample_checks import check_samples as _check_samples
from impactlab.contact.sample_checks import sample_values as _values
from impactlab.contact.sample_checks import warn_force_departs
from impactlab.contact.table_input import PLAUSIBLE_RADIUS
from impactlab.contact.tabulated import (
    Tabulated,
    interpolation_error,
    loading_points,
    residual_points,
)
from impactlab.contact.tabulated_fit import TABLE_FIT_TOLERANCE, check_table_fit
from impactlab.materials import ContactPair

#: Largest relative force error and largest delta_r/delta_max error allowed by default between
#: a sampled law and its callables.
DEFAULT_TOLERANCE = 0.01
#: Default number of samples of the callables.
DEFAULT_POINTS = 64
#: Points compared between two neighbouring samples (besides the samples themselves).
CHECKS_PER_INTERVAL = 7
#: The format of a registered law's record.
RECORD_FORMAT = "impactlab registered law"


def check_law_name(name: Any) -> str:
    """``name`` as a law name: lower-case ASCII letters, digits, '-' and '_', starting with a
    letter (so it reads the same in a study file, on the command line and in a store, and no
    name looks like another's: "h\u0435rtz" with a Cyrillic e)."""
    ok = isinstance(name, str) and name.isascii() and name[:1].isalpha()
    ok = ok and all(ch.isalnum() or ch in "-_" for ch in name) and name == name.lower()
    if not ok:
        raise ValueError(
            f"law name must be lower-case ASCII letters, digits, '-' or '_', starting with a "
            f"letter, got {name!r}"
        )
    builtin = next((str(law) for law in Law if law == name.replace("_", "-")), name)
    if builtin != name:  # the built-in name itself: refused by the registry
        raise ValueError(
            f"law name {name!r} reads as the built-in law {builtin!r} ('_' for '-') and cannot "
            f"be registered: choose another name"
        )
    return str(name)


class RegisteredLaw(Tabulated):
    """A user's contact law: the tabulated law of its ``curves`` under its own ``name``.

    ``sampling_error`` is (largest relative force error, largest delta_r/delta_max error):
    against the callables for a sampled law, the cross-validated error of the fit and the
    interpolation for tables (``tabulated.interpolation_error``).
    """

    def __init__(
        self,
        name: str,
        curves: IndentationCurves,
        *,
        title: str = "",
        sampling_error: tuple[float, float] | None = None,
        sampled: bool = False,
    ) -> None:
        if not isinstance(curves, IndentationCurves):
            raise ValueError(f"curves must be IndentationCurves, got {type(curves).__name__}")
        super().__init__(curves)
        self.name = check_law_name(name)  # type: ignore[misc]
        if not sampled:  # a sampled law is checked against its callables (``sample_law``)
            check_table_fit(name, curves)
        self.title = title or f"User law {name!r} ({curves.name})"  # type: ignore[misc]
        self.sampled = bool(sampled)
        if sampling_error is None:
            sampling_error = interpolation_error(curves)
        self.sampling_error = (float(sampling_error[0]), float(sampling_error[1]))
        how = "sampled from callables; error against them"
        if not sampled:
            load = held_out_method(loading_points(curves)[0].size)
            res = held_out_method(residual_points(curves)[0].size)
            how = f"{load} error" if load == res else f"error by {load} (residual depths: {res})"
        self.validity = (  # type: ignore[misc]
            f"{curves.source}: the pair of the curves (E*/S_y = {curves.e_star_over_sy:.4g} "
            f"within 5 %, nu = {curves.nu:g} within 0.03, a yielding {curves.yielding}); delta up "
            f"to the last tabulated point "
            f"({curves.max_delta:.4g} delta_c, hard limit); {how}: "
            f"{100 * self.sampling_error[0]:.2g} % in force, {self.sampling_error[1]:.2g} in "
            f"delta_r/delta_max; unloading Hertzian"
        )

    @property
    def own_curves(self) -> IndentationCurves:
        """The law's curves."""
        assert self.curves is not None
        return self.curves[0]

    def record(self) -> dict[str, Any]:
        """The law as plain JSON-ready data (``law_from_record`` reads it back)."""
        return {
            "format": RECORD_FORMAT,
            "name": self.name,
            "title": self.title,
            "sampled": self.sampled,
            "sampling_error": list(self.sampling_error),
            "curves": self.own_curves.record(),
        }

    def fingerprint(self) -> str:
        """SHA-256 (hex, 16 digits) of the record: equal for equal data."""
        text = json.dumps(self.record(), sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()[:16]

    def describe(self) -> dict[str, Any]:
        out = super().describe()
        out["registered"] = True
        out["sampling_error"] = {
            "force": self.sampling_error[0],
            "residual_ratio": self.sampling_error[1],
        }
        return out


def law_from_record(record: Any) -> RegisteredLaw:
    """The law of a ``RegisteredLaw.record``; ValueError for anything else."""
    if not isinstance(record, dict) or record.get("format") != RECORD_FORMAT:
        raise ValueError(f"not a registered contact law's record (format {RECORD_FORMAT!r})")
    try:
        err = record["sampling_error"]
        return RegisteredLaw(
            record["name"],
            curves_from_record(record["curves"]),
            title=str(record.get("title", "")),
            sampling_error=(float(err[0]), float(err[1])),
            sampled=bool(record.get("sampled", False)),
        )
    except (KeyError, TypeError, IndexError) as exc:
        raise ValueError(f"registered contact law's record: missing or bad entry {exc}") from None


def sample_law(
    name: str,
    loading: Callable[[float], Any],
    unloading: Callable[[float], Any],
    pair: ContactPair,
    radius: Any,
    delta_max: Any,
    *,
    switch_interference: Any = None,
    points: int = DEFAULT_POINTS,
    tolerance: float = DEFAULT_TOLERANCE,
    title: str = "",
    source: str = "",
) -> RegisteredLaw:
    """The law of the callables ``loading`` (F [N] at delta [m]) and ``unloading`` (delta_r [m]
    after loading to delta_max [m]) of ``pair`` and a sphere of ``radius`` [m], sampled on
    ``points`` interferences from ``switch_interference`` [m] (default: the pair's Jackson-Green
    delta_c; Hertz below it, and ``loading`` must agree with Hertz there within 5 %) to
    ``delta_max`` [m] (the lengths in SI, or strings with units or pint Quantities, as every
    length of the Python API). ValueError where the law built from the samples departs from the
    callables by more than ``tolerance`` (relative in force, absolute in delta_r/delta_max)
    anywhere on the check grid (the samples and ``CHECKS_PER_INTERVAL`` points between each
    two)."""
    if not isinstance(pair, ContactPair):
        raise ValueError(f"pair must be a ContactPair, got {type(pair).__name__}")
    for what, fn in (("loading", loading), ("unloading", unloading)):
        if not callable(fn):
            raise ValueError(f"{what} must be a callable of one float [m], got {fn!r}")
    if isinstance(points, bool) or not isinstance(points, int) or not 8 <= points <= 4096:
        raise ValueError(f"points must be an integer in [8, 4096], got {points!r}")
    if not (isinstance(tolerance, float | int) and 0.0 < tolerance < 1.0):
        raise ValueError(f"tolerance must lie in (0, 1), got {tolerance!r}")
    radius = check_positive("radius", radius, "m")
    lo, hi = PLAUSIBLE_RADIUS
    if not lo <= radius <= hi:
        mm = f"; in mm it would be {radius / 1000:g} m" if radius > hi else ""
        warn_implausible(
            f"radius = {radius:g} m lies outside the plausible range [{lo:g}, {hi:g}] m; check "
            f"the units (impactlab takes SI: a bare number is in m{mm})"
        )
    dc, _fc = jg_critical(pair.E_star, radius, pair.yield_strength, pair.nu)
    default = switch_interference is None
    d0 = dc if default else check_positive("switch_interference", switch_interference, "m")
    top = check_finite("delta_max", delta_max, "m")
    _check_below_radius(delta_max, top, radius, d0)
    if not top > d0:
        limit = (
            f"the pair's delta_c at radius = {radius:g} m (Jackson & Green 2005)"
            if default
            else "switch_interference"
        )
        raise ValueError(
            f"delta_max must be a number of m above the elastic limit, {limit}: {d0:.4g} m; "
            f"got {top!r}"
        )
    grid = np.geomspace(d0, top, points)
    forces = _values("loading", loading, grid)
    residual = _values("unloading", unloading, grid)
    _check_samples(name, grid, forces, residual, default)
    _check_switch(name, pair, radius, d0, float(forces[0]), default)
    curves = IndentationCurves.from_arrays(
        pair,
        radius,
        grid,
        forces,
        grid,
        residual,
        name=name,
        source=source or f"sampled from Python callables ({points} points)",
    )
    law = RegisteredLaw(name, curves, title=title, sampling_error=(0.0, 0.0), sampled=True)
    model = law.build(pair, radius)
    t = np.linspace(0.0, 1.0, CHECKS_PER_INTERVAL + 2)[:-1]
    logs = np.log(grid)
    check = np.append(np.exp((logs[:-1, None] + t * np.diff(logs)[:, None]).ravel()), grid[-1])
    check = check[check <= model.max_interference]
    f_err = model.force(check) / _values("loading", loading, check) - 1.0
    r_model = np.array([model.unload(float(d)).delta_r for d in check])
    r_err = (r_model - _values("unloading", unloading, check)) / check
    worst = (float(np.max(np.abs(f_err))), float(np.max(np.abs(r_err))))
    for label, err, unit in (("force", f_err, " (relative)"), ("delta_r/delta_max", r_err, "")):
        i = int(np.argmax(np.abs(err)))
        if abs(err[i]) > tolerance:
            raise ValueError(
                f"law {name!r}: the law sampled on {points} points departs from the callable's "
                f"{label} by {float(err[i]):+.3g}{unit} at delta = {float(check[i]):.4g} m "
                f"(tolerance {tolerance:g}): give more points, or check that F/F_Hertz never "
                f"rises and delta_r/delta_max never falls (the tabulated law enforces both)"
            )
    warn_force_departs(name, check, f_err, TABLE_FIT_TOLERANCE)
    return RegisteredLaw(name, curves, title=title, sampling_error=worst, sampled=True)


__all__ = [
    "CHECKS_PER_INTERVAL",
    "DEFAULT_POINTS",
    "DEFAULT_TOLERANCE",
    "PLAUSIBLE_RADIUS",
    "RECORD_FORMAT",
    "TABLE_FIT_TOLERANCE",
    "RegisteredLaw",
    "check_law_name",
    "check_table_fit",
    "law_from_record",
    "sample_law",
]
