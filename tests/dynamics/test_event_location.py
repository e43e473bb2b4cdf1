"""Event location on the dense output (``integrator.locate``): the bracket
end where g > 0, the root to round-off, and few evaluations. The search runs as plain Python
(``locate.py_func``, with the kernels it calls in their Python form) on a dense output made by
hand, with the event function replaced by a counting stand-in, so every evaluation is seen."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.dynamics.core import integrator
from impactlab.dynamics.kernels.layout import NS


def _locate(monkeypatch, g, coeffs) -> tuple[float, list[float]]:
    """theta located for the event g(x) on the dense output x(theta) = y0 + sum c_k theta^k
    (k = 1..4; component 0 of the state), and the thetas evaluated."""
    seen: list[float] = []
    coef = np.asarray(coeffs, dtype=float)

    def event_value(ev, law, p, fric, c, md, state):
        x = state[0]
        seen.append(x)
        return g(x)

    monkeypatch.setattr(integrator, "event_value", event_value)
    # the kernels compiled without a Python wrapper (inlined by LLVM) as their Python source:
    # called from Python, their compiled form would crash the interpreter
    for name, fn in list(vars(integrator).items()):
        if getattr(fn, "targetoptions", {}).get("no_cpython_wrapper"):
            monkeypatch.setattr(integrator, name, fn.py_func)
    y0 = np.zeros(NS)
    Q = np.zeros((NS, 4))
    Q[0, :] = coef
    yt = np.zeros(NS)
    K = np.zeros((7, NS))
    g0, g1 = g(0.0), g(float(coef.sum()))
    th = integrator.locate.py_func(0, g0, g1, 0, None, 0, None, None, y0, K, 1.0, Q, yt)
    return th, seen


def test_an_exact_zero_is_closed_at_once(monkeypatch) -> None:
    """A linear g: the first secant lands on the root, where g is exactly 0 (the g <= 0 side).
    One probe just past it closes the bracket (the search bisected towards the far end
    before: 40 evaluations)."""
    th, seen = _locate(monkeypatch, lambda x: x - 0.375, [1.0, 0.0, 0.0, 0.0])
    assert len(seen) == 2
    assert 0.375 < th <= 0.375 + 1e-13


def test_a_root_approached_from_the_far_side_stops_at_round_off(monkeypatch) -> None:
    th, seen = _locate(monkeypatch, lambda x: math.tanh(8.0 * (x - 0.3)), [1.0, 0.0, 0.0, 0.0])
    assert math.tanh(8.0 * (th - 0.3)) > 0.0
    assert th - 0.3 <= 1e-12
    assert len(seen) <= 8


@settings(max_examples=200, deadline=None)
@given(
    root=st.floats(0.01, 0.99),
    curvature=st.floats(-0.45, 0.45),
    scale=st.floats(1e-9, 1e3),
    cubic=st.booleans(),
)
def test_the_located_end_lies_past_the_root_within_round_off(root, curvature, scale, cubic) -> None:
    """Smooth monotonic event functions of any scale: theta has g > 0, lies within 1e-11 of the
    root, and takes at most 12 evaluations."""
    with pytest.MonkeyPatch.context() as m:
        if cubic:

            def g(x: float) -> float:
                return scale * ((x - root) + curvature * (x - root) ** 3)
        else:

            def g(x: float) -> float:
                return scale * ((x - root) * (1.0 + curvature * (x + root)))

        th, seen = _locate(m, g, [1.0, 0.0, 0.0, 0.0])
    assert g(th) > 0.0
    assert th - root == pytest.approx(0.0, abs=1e-11)
    assert len(seen) <= 12
