"""Physical invariants over thousands of random valid impacts of every law and friction model.

Checked per case (compiled diagnostics along every accepted step, and the final results):
total energy (kinetic + potential + stored elastic, normal and tangential) never increases,
0 <= e* <= 1, 0 <= e <= 1 for impacts without initial slip or spin, |F_t| <= mu F_n (Coulomb,
Mindlin), energy dissipated >= 0, nothing NaN. With history: F_n >= 0 and the friction bound on
every recorded point.
"""

from __future__ import annotations

import math
import zlib

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.contact import law_names
from impactlab.dynamics import OUTPUT_FIELDS, contact_model, simulate
from impactlab.dynamics.batch import run_arrays
from impactlab.friction import FRICTION_IDS
from impactlab.materials import AISI_1010

O = {n: i for i, n in enumerate(OUTPUT_FIELDS)}
LAWS = law_names()
ENERGY_TOL = 5e-6  # relative to the initial kinetic energy (integration error, default rtol)
#: history rows are dense-output samples inside steps: they are held to the engine's accuracy
#: contract (1e-5 relative, tests/dynamics/test_accuracy.py), not to the step-end tolerance
HISTORY_ENERGY_TOL = 1e-5
FRICTION_TOL = 1e-4  # (|F_t| - mu F_n) / max F_n: integration error at events near separation
N_CASES = 250  # per (law, friction, body): 6 x 3 x 2 x 250 = 9000 impacts


def _random_cases(rng: np.random.Generator, n: int, rod: bool) -> tuple[np.ndarray, np.ndarray]:
    th = rng.uniform(0.05, 0.5 * math.pi, n) if rod else np.full(n, 0.5 * math.pi)
    vy = -rng.uniform(0.05, 2.5, n)
    vx = rng.uniform(-1.0, 1.0, n) * rng.integers(0, 2, n)
    w = rng.uniform(-15.0, 15.0, n) * rng.integers(0, 2, n)
    if rod:  # keep the contact point approaching
        a = PAPER_ROD.half_length * np.cos(th)
        w = np.where(vy - w * a < -0.02, w, 0.0)
    else:
        w *= 10.0
    mu = rng.uniform(0.0, 1.0, n)
    return np.stack([th, vx, vy, w], axis=1), mu


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("friction", list(FRICTION_IDS))
@pytest.mark.parametrize("rod", [True, False], ids=["rod", "sphere"])
def test_invariants_batch(law: str, friction: str, rod: bool) -> None:
    body: Rod | Sphere = PAPER_ROD if rod else Sphere(0.008)
    # a seed that is the same in every process (hash() of a str is salted per process)
    rng = np.random.default_rng(zlib.crc32(f"{law}/{friction}/{rod}".encode()))
    init, mu = _random_cases(rng, N_CASES, rod)
    model = contact_model(body, AISI_1010, law)
    out, status = run_arrays(
        model.law_id,
        FRICTION_IDS[friction],
        model.params,
        body.to_params(AISI_1010),
        init,
        mu,
        gravity=True,
        constant_angle=False,
        rtol=None,
        diagnostics=True,
    )
    assert np.all(status == 0), np.unique(status, return_counts=True)
    cols = [n for n in OUTPUT_FIELDS if not (n == "angle_out" and not rod)]
    assert np.all(np.isfinite(out[:, [O[c] for c in cols]]))
    e, ee = out[:, O["e"]], out[:, O["e_energy"]]
    assert np.all(ee >= 0.0) and np.all(ee <= 1.0 + 1e-6)
    assert np.all(e >= 0.0)
    # e <= 1 for dissipative laws without initial slip or spin (for an elastic contact the
    # rotation of the lever arms during contact and the tangential compliance can push the
    # kinematic e slightly above 1 with energy conserved; only e* is bounded by 1 there)
    plain = (init[:, 1] == 0.0) & (init[:, 3] == 0.0)
    if friction != "impulse_ratio" and law != "hertz":
        assert np.all(e[plain] <= 1.0 + 1e-6), e[plain].max()
    e0 = (
        0.5 * body.mass * (init[:, 1] ** 2 + init[:, 2] ** 2) + 0.5 * body.inertia * init[:, 3] ** 2
    )
    # the paper's Eq. 7 keeps F_t = mu F_n after the slip reverses: energy is created then
    # (a documented limitation); without a reversal it dissipates like Coulomb
    ok = out[:, O["regime"]] != 3 if friction == "impulse_ratio" else np.ones(len(e0), bool)
    assert ok.sum() > N_CASES // 10
    assert np.all(out[ok, O["energy_dissipated"]] >= -ENERGY_TOL * e0[ok])
    rise = out[ok, O["energy_rise"]]
    assert np.all(rise <= ENERGY_TOL), rise.max()
    if friction != "impulse_ratio":
        assert np.all(out[:, O["friction_excess"]] <= FRICTION_TOL)
    assert np.all(out[:, O["delta_p"]] >= 0.0)
    assert np.all(out[:, O["delta_p"]] < out[:, O["delta_max"]] + 1e-15)
    assert np.all(out[:, O["duration"]] > 0.0)


def test_impulse_ratio_creates_energy_after_reversal() -> None:
    """Documented limitation of the paper's model: beyond mu_c the constant F_t = mu F_n keeps
    pushing after the tip's slip has reversed, and does positive work."""
    r = simulate(
        PAPER_ROD,
        law="hertz",
        friction="impulse_ratio",
        mu=1.5,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
        gravity=False,
    )
    h = r.history
    assert r.regime == "reversal"
    assert h is not None and np.max(np.diff(h.energy)) > 0.0


@settings(max_examples=25, deadline=None)
# found by hypothesis: a stick that breaks just before separation; the sampled energy dips by
# 5.8e-6 E0 inside the last step at the default rtol (2e-8 at rtol 1e-9: integration error)
@example(law="hertz", friction="coulomb", th=1.140625, vx=-0.05859375, vy=-1.75, mu=0.5)
# found by hypothesis: a negligible friction (Mindlin, contact point at rest) chattered
@example(law="hertz", friction="mindlin", th=1.0, vx=0.0, vy=-1.0, mu=1e-14)
@given(
    law=st.sampled_from(LAWS),
    friction=st.sampled_from(list(FRICTION_IDS)),
    th=st.floats(0.05, 0.5 * math.pi),
    vx=st.floats(-0.8, 0.8),
    vy=st.floats(-2.5, -0.05),
    mu=st.floats(0.0, 1.2),
)
@pytest.mark.filterwarnings("ignore:friction = .* with mu = 0 is frictionless")  # mu drawn 0
def test_invariants_history(
    law: str, friction: str, th: float, vx: float, vy: float, mu: float
) -> None:
    r = simulate(PAPER_ROD, law=law, friction=friction, mu=mu, angle=th, velocity=(vx, vy))
    h = r.history
    assert h is not None
    assert np.all(np.isfinite(h.data))
    assert np.all(h.normal_force >= 0.0)
    assert np.all(h.penetration[1:-1] > -1e-15)
    assert np.all(np.diff(h.t) >= 0.0)
    e0 = h.energy[0]
    if friction != "impulse_ratio" or r.regime != "reversal":
        running_min = np.minimum.accumulate(h.energy)
        assert np.all(h.energy - running_min <= HISTORY_ENERGY_TOL * e0)
    if friction != "impulse_ratio":
        excess = np.abs(h.tangential_force) - mu * h.normal_force
        assert np.all(excess <= FRICTION_TOL * r.max_force)
    assert 0.0 <= r.e_energy <= 1.0 + 1e-6
