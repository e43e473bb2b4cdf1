"""``invert(correlation=...)``: correlated measured inputs in the first-order propagation
(J C J^T) and in the Monte Carlo (correlated draws); the coefficients checked; without them
the inversion is the same as ever."""

from __future__ import annotations

import json
import math
import warnings
from typing import Any

import numpy as np
import pytest

from impactlab._json import shape_problems
from impactlab.analytic import invert
from impactlab.analytic.result_json import inversion_json

#: The paper's 20 deg impact with small sigmas (first order holds).
PAPER = {
    "angle": (math.radians(20), 0.002),
    "v_i": (-1.41, 0.01),
    "e": (0.5, 0.01),
    "mu": (0.2, 0.004),
    "delta_p": (22e-6, 1e-6),
    "sliding_length": (1400e-6, 40e-6),
}


def _invert(**kw: Any) -> Any:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return invert(**{**PAPER, **kw})


@pytest.mark.parametrize("rho", [0.8, -0.6, 1.0])
def test_dent_pair_closed_form(rho: float) -> None:
    """T = (|delta_p| + |L_s|/|alpha|) / |v_i| is linear in the dent's two inputs: with only
    they uncertain, sigma_T^2 = (s_d/v)^2 + (s_L/(|alpha| v))^2 + 2 rho s_d s_L/(|alpha| v^2),
    to first order exactly and in the Monte Carlo to its sampling error."""
    s_d, s_L, v = 2e-6, 60e-6, 1.41
    r = _invert(
        angle=math.radians(20),
        v_i=v,
        mu=0.2,
        e=0.5,
        delta_p=(22e-6, s_d),
        sliding_length=(1400e-6, s_L),
        correlation={("sliding_length", "delta_p"): rho},
    )
    a = abs(r.alpha)
    exact = math.sqrt((s_d / v) ** 2 + (s_L / (a * v)) ** 2 + 2 * rho * s_d * s_L / (a * v * v))
    assert r.sigma_T_linear == pytest.approx(exact, rel=1e-6)
    assert r.sigma_T_mc == pytest.approx(exact, rel=0.03)  # 20000 draws: about 0.5 %
    assert dict(r.correlation) == {("delta_p", "sliding_length"): rho}


def test_first_order_is_j_c_jt() -> None:
    """sigma_F^2 = sum_ij J_i J_j sigma_i sigma_j C_ij with the reported sensitivities."""
    corr = {("angle", "v_i"): 0.6, ("e", "v_i"): 0.4, ("mu", "angle"): -0.3}
    r = _invert(correlation=corr)
    names = list(r.inputs)
    sigma = np.array([r.inputs[k][1] for k in names])
    c = np.eye(len(names))
    for (a, b), rho in r.correlation.items():
        c[names.index(a), names.index(b)] = c[names.index(b), names.index(a)] = rho
    for sens, got in ((r.sensitivity_T, r.sigma_T_linear), (r.sensitivity_F, r.sigma_F_linear)):
        j = np.array([sens[k] for k in names]) * sigma
        assert got == pytest.approx(math.sqrt(j @ c @ j), rel=1e-9)
    # v_i is given negative: its magnitude's coefficients change sign
    flipped = {("angle", "v_i"): -0.6, ("v_i", "e"): -0.4, ("angle", "mu"): -0.3}
    assert dict(r.correlation) == flipped


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_monte_carlo_agrees_with_first_order(sign: float) -> None:
    """On a near-linear case (sigmas of about 1 %), the Monte Carlo's sigmas agree with first
    order within 3 %, for strong correlations of either sign; and the correlations move them."""
    corr = {("angle", "mu"): 0.7 * sign, ("v_i", "e"): 0.8 * sign, ("delta_p", "angle"): 0.5}
    r, r0 = _invert(correlation=corr, seed=7), _invert(seed=7)
    assert r.sigma_T_mc == pytest.approx(r.sigma_T_linear, rel=0.03)
    assert r.sigma_F_mc == pytest.approx(r.sigma_F_linear, rel=0.03)
    assert abs(r.sigma_F_linear / r0.sigma_F_linear - 1.0) > 0.05


def test_magnitude_sign() -> None:
    """v_i = -1.41 correlated +rho is |v_i| correlated -rho: the same inversion."""
    a = _invert(correlation={("v_i", "e"): 0.5})
    b = _invert(v_i=(1.41, 0.01), correlation={("v_i", "e"): -0.5})
    assert a.to_dict() == b.to_dict()


def test_default_is_unchanged() -> None:
    """No correlation, an empty one and zero coefficients draw the same samples: every number
    of the result is bit-identical; only ``correlation`` records what was given."""
    base = _invert(vt_in=(-0.02, 0.01), dv_cy=(2.0, 0.05)).to_dict()
    assert base["correlation"] == []
    for corr in ({}, {("e", "dv_cy"): 0.0, ("angle", "vt_in"): 0.0}):
        d = _invert(vt_in=(-0.02, 0.01), dv_cy=(2.0, 0.05), correlation=corr).to_dict()
        assert {k: v for k, v in d.items() if k != "correlation"} == {
            k: v for k, v in base.items() if k != "correlation"
        }


@pytest.mark.parametrize(
    ("corr", "words"),
    [
        ({("e", "mu"): 1.5}, r"of \('e', 'mu'\) must be a number in \[-1, 1\], got 1.5"),
        ({("e", "mu"): math.nan}, r"in \[-1, 1\], got nan"),
        ({("e", "mu"): True}, r"in \[-1, 1\], got True"),
        ({("e", "speed"): 0.1}, r"'speed' in \('e', 'speed'\) is not an input given to invert"),
        ({("e", "dv_cy"): 0.1}, r"'dv_cy' .* is not an input given"),
        ({("e", "e"): 0.5}, "pairs 'e' with itself"),
        ({("e",): 0.5}, "a key must be a pair of input names"),
        ({("e", "mu"): 0.2, ("mu", "e"): 0.2}, r"the pair \('mu', 'e'\) is given twice"),
        (
            {("e", "mu"): 0.9, ("e", "angle"): 0.9, ("mu", "angle"): -0.9},
            "not positive semi-definite: its smallest eigenvalue is -0.8",
        ),
        ([("e", "mu", 0.5)], "correlation must be None or a mapping"),
    ],
)
def test_bad_correlation_refused(corr: Any, words: str) -> None:
    with pytest.raises(ValueError, match=words):
        _invert(correlation=corr)


def test_exact_input_refused() -> None:
    with pytest.raises(ValueError, match=r"'mu' in \('e', 'mu'\) has no sigma"):
        _invert(mu=0.2, correlation={("e", "mu"): 0.3})


def test_recorded_in_text_and_json() -> None:
    """The result's text lists the correlations, and ``invert --json`` its
    ``correlation``: pairs with a quantity coefficient (docs/json-schema.md)."""
    r = _invert(correlation={("e", "mu"): 0.25})
    assert "correlation: (mu, e) 0.25" in str(r)
    doc = json.loads(json.dumps(inversion_json(r)))
    assert doc["correlation"] == [
        {"inputs": ["mu", "e"], "coefficient": {"value": 0.25, "unit": "1"}}
    ]
    assert shape_problems(doc) == []
