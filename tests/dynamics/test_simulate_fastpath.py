"""``simulate``'s fast path: plain inputs skip the full checks and the dataclass
``__init__``, and give exactly what the full path gives.

The full path is forced by switching the fast path off (``_fast`` returning None) or by passing
the same values as pint Quantities; the results are compared field by field through ``repr``
(bit-identical floats, NaN and -0.0 included), with the flags, the warnings (text, category and
the line they point at) and the errors.
"""

from __future__ import annotations

import math
import sys
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD, Sphere
from impactlab.contact import law_names
from impactlab.contact.ranges import critical_interference, extrapolation_flags
from impactlab.dynamics import ImpactResult, contact_model, simulate
from impactlab.flags import ResultFlag
from impactlab.materials import AISI_201, AISI_1010
from impactlab.units import registry

#: The module (``impactlab.dynamics.simulate`` is also the name of the function).
SIM = sys.modules["impactlab.dynamics.simulate"]
SPHERE = Sphere(0.006, material=AISI_1010)
TH = math.radians(20.0)
PAPER: dict[str, Any] = {
    "law": "ghaednia",
    "friction": "coulomb",
    "mu": 0.2,
    "angle": TH,
    "velocity": (0.0, -1.41),
}

#: Inputs the fast path takes: (body, simulate's keyword arguments).
CASES: list[tuple[Any, dict[str, Any]]] = [
    (PAPER_ROD, PAPER),
    (PAPER_ROD, {**PAPER, "history": False}),
    (PAPER_ROD, {**PAPER, "law": "hertz"}),  # extrapolated: beyond first yield
    (PAPER_ROD, {**PAPER, "friction": "impulse_ratio", "mu": 1, "velocity": [0, -2]}),
    (PAPER_ROD, {**PAPER, "friction": "mindlin", "spin": -3.0, "gravity": False, "rtol": 1e-9}),
    (PAPER_ROD, {**PAPER, "law": "thornton", "angle": 0.5 * math.pi, "constant_angle": True}),
    (PAPER_ROD, {**PAPER, "law": "brake", "mu": np.float64(0.3), "gravity": 9.81}),
    (PAPER_ROD, {**PAPER, "mu": 0.0, "velocity": (0.3, -0.05)}),  # gravity-dominated
    (SPHERE, {"law": "hertz", "friction": "coulomb", "mu": 0.1, "velocity": (0.2, -0.5)}),
    (SPHERE, {"law": "kogut-komvopoulos", "mu": 0.2, "velocity": (0.1, -3.0)}),
    (SPHERE, {"law": "jackson-green", "mu": 0.2, "velocity": (0.1, -1.0), "spin": 50.0}),
]

#: Inputs that fail or warn, the fast path's pre-screen passed or not.
BAD: list[tuple[Any, dict[str, Any]]] = [
    (PAPER_ROD, {**PAPER, "velocity": (0.0, 0.5)}),  # receding
    (PAPER_ROD, {**PAPER, "velocity": (0.0, -0.0)}),
    (PAPER_ROD, {**PAPER, "velocity": (0.0, -1.41), "spin": -1000.0}),
    (PAPER_ROD, {**PAPER, "velocity": (0.0, -60.0)}),  # the law's validity limit (engine)
    (PAPER_ROD, {**PAPER, "velocity": (0.5, -1000.0)}),  # warns, then the limit
    (PAPER_ROD, {**PAPER, "velocity": (0.0, -99.0), "spin": 1000.0}),  # warns (contact point)
    (PAPER_ROD, {**PAPER, "angle": 20}),
    (PAPER_ROD, {**PAPER, "angle": 0.5 * math.pi + 2e-12}),
    (PAPER_ROD, {**PAPER, "mu": -0.1}),
    (PAPER_ROD, {**PAPER, "mu": math.inf}),
    (PAPER_ROD, {**PAPER, "spin": 10**400}),
    (PAPER_ROD, {**PAPER, "rtol": 1e-2}),
    (PAPER_ROD, {**PAPER, "law": "nope"}),
    (PAPER_ROD, {**PAPER, "friction": "nope", "law": "nope"}),
    (PAPER_ROD, {**PAPER, "history": 1}),
    (PAPER_ROD, {**PAPER, "flat": "steel"}),
    (SPHERE, {"law": "hertz", "velocity": (0.0, -1.0), "angle": math.nan}),
    (SPHERE, {"law": "hertz", "velocity": (0.0, -1.0), "angle": 0.3}),  # a sphere has none
]


def outcome(body: Any, kwargs: dict[str, Any]) -> tuple[Any, ...]:
    """What a call shows: the result's fields (bit for bit), flags, warnings and ``vars``, or
    the error; and the warnings issued (text, category, the line they point at)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            r = simulate(body, **kwargs)
        except Exception as err:  # the error is what is compared
            shown: tuple[Any, ...] = ("error", type(err).__name__, str(err))
        else:
            shown = (
                "ok",
                repr(r.to_dict(include_history=True)),
                repr(r.flags),
                r.warnings,
                repr(vars(r)),
                [type(v) for v in vars(r).values()],
                r.dois(),
                str(r),
            )
    return shown, [(str(w.message), w.category, w.filename, w.lineno) for w in caught]


def full_path(monkeypatch: pytest.MonkeyPatch, call: Callable[[], Any]) -> Any:
    with monkeypatch.context() as m:
        m.setattr(SIM, "_fast", lambda *args: None)
        return call()


def as_quantities(body: Any, kwargs: dict[str, Any]) -> dict[str, Any]:
    """The same inputs as pint Quantities (identity conversions: the same floats in SI)."""
    Q = registry().Quantity
    q = dict(kwargs)
    q["velocity"] = tuple(Q(float(v), "m/s") for v in kwargs["velocity"])
    q["spin"] = Q(float(kwargs.get("spin", 0.0)), "rad/s")
    if kwargs.get("angle") is not None:
        q["angle"] = Q(float(kwargs["angle"]), "rad")
    g = kwargs.get("gravity", True)
    if not isinstance(g, bool):
        q["gravity"] = Q(float(g), "m/s^2")
    return q


@pytest.mark.parametrize(("body", "kwargs"), CASES)
def test_fast_path_equals_full_path(
    body: Any, kwargs: dict[str, Any], monkeypatch: pytest.MonkeyPatch
) -> None:
    fast = outcome(body, kwargs)
    assert fast[0][0] == "ok" and fast[1] == []
    assert full_path(monkeypatch, lambda: outcome(body, kwargs)) == fast
    assert outcome(body, as_quantities(body, kwargs)) == fast


def test_fast_path_is_taken(monkeypatch: pytest.MonkeyPatch) -> None:
    """Plain inputs never reach the full checks; an extrapolated result keeps its flag."""

    def refuse(*args: Any, **kwargs: Any) -> None:
        raise AssertionError("the full checks ran")

    monkeypatch.setattr(SIM, "check_impact", refuse)
    for body, kwargs in CASES:
        simulate(body, **kwargs)
    r = simulate(PAPER_ROD, **{**PAPER, "law": "hertz"})
    assert r.extrapolated and ResultFlag.LAW_EXTRAPOLATED in r.flags and r.ok
    with pytest.raises(AssertionError, match="full checks"):
        simulate(PAPER_ROD, **{**PAPER, "angle": "20 deg"})


@pytest.mark.parametrize(("body", "kwargs"), BAD)
def test_errors_and_warnings_unchanged(
    body: Any, kwargs: dict[str, Any], monkeypatch: pytest.MonkeyPatch
) -> None:
    kwargs = dict(kwargs)
    flat = kwargs.pop("flat", AISI_1010)
    fast = outcome(body, {**kwargs, "flat": flat})
    assert fast[0][0] == "error" or fast[1]
    assert full_path(monkeypatch, lambda: outcome(body, {**kwargs, "flat": flat})) == fast


def test_setups_follow_the_objects() -> None:
    """The cached setups are per (body, flat, law, friction) object: another flat, another
    rod or another law never reuses one; partial slip runs its own engine."""
    base = simulate(PAPER_ROD, **PAPER)
    other_flat = simulate(PAPER_ROD, AISI_201, **PAPER)
    assert other_flat.e != base.e
    assert simulate(PAPER_ROD, **PAPER).to_dict() == base.to_dict()
    slip = simulate(PAPER_ROD, **{**PAPER, "friction": "partial_slip"})
    assert slip.friction == "partial_slip"


@pytest.mark.parametrize(("body", "kwargs"), CASES[:4] + CASES[8:9])
def test_result_equals_dataclass_init(body: Any, kwargs: dict[str, Any]) -> None:
    """The assembled result equals ``ImpactResult(**fields)``, whose ``__post_init__`` adds
    LAW_EXTRAPOLATED to the engine's flags."""
    r = simulate(body, **kwargs)
    fields = dict(vars(r))
    fields["flags"] = float(int(r.flags) & ~ResultFlag.LAW_EXTRAPOLATED)  # as the engine wrote
    if r.history is not None:
        fields["history"] = r.history  # History copies its rows
    again = ImpactResult(**fields)
    assert repr(vars(again)) == repr(vars(r))
    assert again.flags == r.flags and type(again.flags) is type(r.flags)


@pytest.mark.parametrize("law", law_names())
def test_extrapolation_flag_equals_ranges(law: str) -> None:
    """The per-model cached check equals ``contact.ranges.extrapolation_flags``."""
    from impactlab.dynamics.outcome import _law_flag

    model = contact_model(PAPER_ROD, AISI_1010, law)
    ref = critical_interference(model.law_id, model.params)
    deltas = [0.0, -0.0, math.nan, math.inf, 1e-300, ref, 110.0 * ref, 1.0 + 1e-16, 5e-3]
    deltas += [*(ref * np.geomspace(1e-3, 1e3, 61)), np.nextafter(110.0 * ref, 1.0)]
    for d in map(float, deltas):
        assert _law_flag(model, d) == extrapolation_flags(model.law_id, model.params, d), d
