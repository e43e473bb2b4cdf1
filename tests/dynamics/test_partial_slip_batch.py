"""``partial_slip`` in the batch engine (``run_arrays``, ``simulate_batch``): every output equal
to ``simulate(friction="partial_slip")`` bit for bit, over laws, bodies and angles (fixed cases
and hypothesis); invalid cases flagged per case without stopping the batch."""

from __future__ import annotations

import math
import struct
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import impactlab as il
from impactlab.dynamics import BATCH_FRICTION_IDS, OUTPUT_FIELDS, contact_model, run_arrays
from impactlab.dynamics.kernels.status import REGIME_NAMES, ST_BAD_INPUT, ST_NOT_APPROACHING
from impactlab.friction import PARTIAL_SLIP

ROD = il.Rod.paper()
SPHERE = il.Sphere(radius=5e-3, material=il.AISI_201)
LAWS = ("hertz", "ghaednia", "thornton", "brake")


def _same_bits(a: float, b: float) -> bool:
    """Equal to the last bit (NaN equals NaN)."""
    return (math.isnan(a) and math.isnan(b)) or struct.pack("<d", a) == struct.pack("<d", b)


def _single(body, law, mu, angle, vx, vy, spin):  # type: ignore[no-untyped-def]
    """The output row of one ``simulate`` (OUTPUT_FIELDS order); mu = 0, the batch's
    frictionless case, draws ``simulate``'s warning that the model is unused."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "friction = .* with mu = 0 is frictionless")
        r = il.simulate(
            body, law=law, friction="partial_slip", mu=mu, angle=angle, velocity=(vx, vy),
            spin=spin, history=False,
        )  # fmt: skip
    row = []
    for name in OUTPUT_FIELDS:
        if name in ("vx_out", "vy_out"):
            v = r.velocity_out[0 if name == "vx_out" else 1]
        elif name == "regime":
            v = next(k for k, n in REGIME_NAMES.items() if n == r.regime)
        else:
            v = getattr(r, name, math.nan)  # energy_rise, friction_excess: not in a result
        row.append(float(v))
    return np.array(row)


def _assert_batch_equals_simulate(body, law, mu, angle, vx, vy, spin) -> int:  # type: ignore[no-untyped-def]
    """Every output of the batch equals simulate's to the last bit; returns the cases that
    succeeded."""
    b = il.simulate_batch(
        body, law=law, friction="partial_slip", mu=mu, angle=angle, vx=vx, vy=vy, spin=spin
    )
    assert b.friction == "partial_slip"
    n = len(b)
    arr = [np.broadcast_to(np.asarray(v, dtype=float), (n,)) for v in (mu, vx, vy, spin)]
    ang = np.broadcast_to(np.asarray(angle if angle is not None else math.nan), (n,))
    for i in range(n):
        a = None if angle is None else float(ang[i])
        m, vx_i, vy_i, w_i = (float(c[i]) for c in arr)
        if b.status[i] != 0:  # an engine failure: simulate raises it
            with pytest.raises(ValueError, match="partial_slip impact"):
                _single(body, law, m, a, vx_i, vy_i, w_i)
            assert math.isnan(b.out[i, OUTPUT_FIELDS.index("e")])
            continue
        want = _single(body, law, m, a, vx_i, vy_i, w_i)
        for j, name in enumerate(OUTPUT_FIELDS):
            if name in ("energy_rise", "friction_excess"):
                continue
            got = float(b.out[i, j])
            assert _same_bits(got, float(want[j])), (law, i, name, got, want[j])
    return int(np.sum(b.status == 0))


@pytest.mark.parametrize("law", LAWS)
def test_rod_batch_equals_simulate(law: str) -> None:
    angles = np.radians([5.0, 20.0, 45.0, 70.0, 89.0])
    spin = np.array([0, 0, 3, 0, -2.0])
    assert _assert_batch_equals_simulate(ROD, law, 0.3, angles, 0.2, -1.41, spin) == 5


@pytest.mark.parametrize("law", LAWS)
def test_sphere_batch_equals_simulate(law: str) -> None:
    inc = np.radians([0.0, 10.0, 30.0, 50.0, 75.0])
    mu = np.array([0.1, 0.3, 0.5, 0.2, 0.0])  # mu = 0: the core's frictionless impact
    vx, vy = 2.0 * np.sin(inc), -2.0 * np.cos(inc)
    assert _assert_batch_equals_simulate(SPHERE, law, mu, None, vx, vy, 0.0) == 5


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    law=st.sampled_from(LAWS),
    rod=st.booleans(),
    angle=st.floats(math.radians(3.0), math.pi / 2),
    vx=st.floats(-2.0, 2.0),
    vy=st.floats(-3.0, -0.2),
    mu=st.floats(0.0, 0.8),
)
def test_batch_equals_simulate_property(law, rod, angle, vx, vy, mu) -> None:  # type: ignore[no-untyped-def]
    body = ROD if rod else SPHERE
    _assert_batch_equals_simulate(body, law, mu, angle if rod else None, vx, vy, 0.0)


def test_invalid_cases_are_flagged_per_case() -> None:
    m = contact_model(SPHERE, il.AISI_1010, "hertz")
    init = np.array([[math.pi / 2, 0.3, -1.0, 0.0]] * 4)
    init[2, 2] = 0.5  # receding
    mu = np.array([0.3, np.nan, 0.3, -0.1])
    out, status = run_arrays(
        m.law_id, BATCH_FRICTION_IDS["partial_slip"], m.params, SPHERE.to_params(il.AISI_1010),
        init, mu,
    )  # fmt: skip
    assert BATCH_FRICTION_IDS["partial_slip"] == PARTIAL_SLIP
    assert list(status) == [0, ST_BAD_INPUT, ST_NOT_APPROACHING, ST_BAD_INPUT]
    skip = ("angle_out", "energy_rise", "friction_excess")  # a sphere's; the diagnostics
    cols = [j for j, name in enumerate(OUTPUT_FIELDS) if name not in skip]
    assert np.all(np.isfinite(out[0, cols])) and np.all(np.isnan(out[[1, 3]]))


def test_batch_diagnostics_bound_energy_and_friction() -> None:
    m = contact_model(ROD, il.AISI_1010, "ghaednia")
    a = np.radians(np.linspace(5.0, 85.0, 8))
    init = np.stack([a, 0 * a, -1.41 + 0 * a, 0 * a], axis=1)
    out, status = run_arrays(
        m.law_id, PARTIAL_SLIP, m.params, ROD.to_params(il.AISI_1010), init, 0.3,
        diagnostics=True,
    )  # fmt: skip
    assert np.all(status == 0)
    assert np.all(out[:, OUTPUT_FIELDS.index("energy_rise")] < 1e-6)
    assert np.all(out[:, OUTPUT_FIELDS.index("friction_excess")] < 1e-6)
