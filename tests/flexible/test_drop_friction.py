"""The friction models of the flexible drop: the rigid limit of each equals the rigid engine,
the energy balance closes with each, and the models the drop lacks are refused clearly."""

from __future__ import annotations

import math

import pytest
from paper_drops import CASES

from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact.ranges import critical_interference, law_extrapolated
from impactlab.dynamics import simulate
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.kernels import layout as core_layout
from impactlab.dynamics.models import contact_model
from impactlab.flags import ResultFlag
from impactlab.friction import FrictionKind
from impactlab.materials import AISI_1010

MODELS = ["impulse_ratio", "coulomb", "mindlin"]
#: (angle [deg], vx [m/s], vy [m/s], mu): the paper's drops, a large mu (stick, or the
#: impulse ratio's reversal) and an initial slip against the rotation.
RIGID_CASES = [(th, 0.0, vy, mu) for th, vy, mu in CASES] + [
    (20, 0.0, -1.41, 0.9),
    (45, -0.3, -2.18, 0.5),
    (30, 0.4, -1.5, 0.3),
]


@pytest.mark.parametrize("friction", MODELS)
@pytest.mark.parametrize(("th", "vx", "vy", "mu"), RIGID_CASES)
def test_rigid_limit(friction: str, th: float, vx: float, vy: float, mu: float) -> None:
    """A rigid Rod through the drop integrator equals the rigid engine to 1e-6 in e,
    delta_p, sliding_length, duration, the stick time and the flags (each relative to its
    natural scale)."""
    kw = {"friction": friction, "mu": mu, "angle": math.radians(th), "velocity": (vx, vy)}
    r0 = simulate(Rod.paper(), rtol=1e-10, **kw)
    r = simulate_drop(Rod.paper(), rtol=1e-10, **kw)
    assert r.n_contacts == 1
    pairs = {
        "e": (r.e_raw, r0.e, 1.0),
        "delta_p": (r.dent_depth, r0.delta_p, r0.delta_max),
        "sliding_length": (r.sequence_sliding_length, r0.sliding_length, r0.delta_max),
        "duration": (r.sequence_duration, r0.duration, r0.duration),
        "stick": (r.stick_time, r0.stick_time, r0.duration),
        "Pt": (r.tangential_impulse, r0.tangential_impulse, r0.normal_impulse),
        "spin": (r.spin_out, r0.spin_out, abs(vy) / 0.15),
    }
    for name, (a, b, scale) in pairs.items():
        assert abs(a - b) <= 1e-6 * abs(scale), (name, a, b)
    assert r.flags == r0.flags


@pytest.mark.parametrize("friction", MODELS)
@pytest.mark.parametrize(("th", "vy", "mu"), CASES)
def test_energy_balance(friction: str, th: float, vy: float, mu: float) -> None:
    """The flexible rod, zero damping: T + V - E0 = W_n + W_t over the whole sequence to
    1e-6 of E0 with every friction model."""
    body = FlexibleRod.paper(n_axial=4, n_bending=8, axial_residual=False)
    kw = {"friction": friction, "mu": mu, "angle": math.radians(th), "velocity": (0.0, vy)}
    r = simulate_drop(body, rtol=1e-9, **kw)
    assert r.friction == friction and r.n_contacts >= 2
    assert r.energy_error < 1e-6
    assert abs(r.energy_balance["residual"]) < 1e-6 * r.initial_energy
    assert r.work_damping == 0.0


def test_models_differ_on_the_flexible_rod() -> None:
    """The friction model matters: the three models give three different slips (same drop)."""
    body = FlexibleRod.paper(n_axial=2, n_bending=4, axial_residual=False)
    kw = {"mu": 0.2, "angle": math.radians(20), "velocity": (0.0, -1.41)}
    slips = {f: simulate_drop(body, friction=f, **kw).sequence_sliding_length for f in MODELS}
    assert len({round(s, 12) for s in slips.values()}) == 3


def test_unsupported_model_is_refused() -> None:
    """A friction model the drop integrator lacks: a ValueError naming the supported ones."""
    rod = FlexibleRod.paper(n_axial=1, n_bending=1)
    others = [str(k) for k in FrictionKind if str(k) not in [*MODELS, "partial_slip"]]
    for name in [*others, "nonsense"]:
        with pytest.raises(ValueError, match="friction"):
            simulate_drop(rod, friction=name, angle=0.3, velocity=(0.0, -1.0))


def test_rigid_mode_layout() -> None:
    """``flexcore.friction.rigid_mode`` builds the rigid core's mode tuple in this order."""
    L = core_layout
    order = (L.M_PHASE, L.M_DM, L.M_DR, L.M_RR, L.M_FM, L.M_COMP, L.M_SIR, L.M_AF)
    assert order == tuple(range(8)) and L.NM == 8


#: impulse_ratio creating energy (tests/dynamics/test_engine_flags.py): an oblique
#: case with spin and the vertical rod (v_slip,0 = 0, mu beyond the stick limit).
GAIN_CASES = [
    {"law": "hertz", "mu": 0.9962, "angle": 1.19009, "velocity": (0.72986, -9.12126)}
    | {"spin": -5.9105, "gravity": False},
    {"law": "hertz", "mu": 0.2, "angle": math.radians(89.0), "velocity": (0.0, -1.41)},
]


@pytest.mark.parametrize("case", GAIN_CASES)
def test_energy_gain_flag(case: dict) -> None:
    """impulse_ratio creates energy: the drop flags it as the rigid engine does (the rigid
    limit), and the result is not ok."""
    r0 = simulate(Rod.paper(), friction="impulse_ratio", **case)
    r = simulate_drop(Rod.paper(), friction="impulse_ratio", **case)
    assert r0.flags == r.flags and ResultFlag.ENERGY_GAIN in r.flags
    assert not r.ok and r.warnings[0].startswith("energy gain")
    assert r.to_dict()["flags"] == int(r.flags)


def test_friction_that_gains_energy_in_one_contact_is_flagged() -> None:
    """The paper's drop with the flexible rod and impulse_ratio: friction does positive work in
    some contacts (the impulse keeps its direction where the slip reverses), hidden in the
    sequence's total by the others' losses; flagged ENERGY_GAIN, not ok. Coulomb: never."""
    case = {"mu": 0.2, "angle": math.radians(20), "velocity": (0.0, -1.41)}
    r = simulate_drop(FlexibleRod.paper(), friction="impulse_ratio", **case)
    works = [c.work_friction for c in r.contacts]
    assert max(works) > 1e-3 and sum(works) < 0.0  # created in a contact, lost in the sum
    assert ResultFlag.ENERGY_GAIN in r.flags and not r.ok
    c = simulate_drop(FlexibleRod.paper(), friction="coulomb", **case)
    assert max(x.work_friction for x in c.contacts) <= 0.0 and ResultFlag.ENERGY_GAIN not in c.flags


def _overlapping(contacts: list) -> int:
    """The pairs of contacts of the two ends that overlap in time."""
    return sum(
        1
        for i, a in enumerate(contacts)
        for b in contacts[i + 1 :]
        if a.end != b.end and a.start < b.start + b.duration and b.start < a.start + a.duration
    )


@pytest.mark.parametrize(
    ("friction", "angle_deg", "mu", "vy"),
    [
        ("partial_slip", 45.0, 0.8, -1.0),
        ("coulomb", 0.01, 0.3, -1.41),
        ("mindlin", 0.1, 0.3, -1.41),
    ],
)
def test_contact_works_are_each_ends_own(
    friction: str, angle_deg: float, mu: float, vy: float
) -> None:
    """While both ends touch, each contact's works are its end's own (each end integrates its
    own): the contacts' works add up to the drop's totals, overlapping contacts included, and
    the friction of a model that cannot create energy does negative work in every contact."""
    case = {"mu": mu, "angle": math.radians(angle_deg), "velocity": (0.0, vy), "stop": "flight"}
    r = simulate_drop(FlexibleRod.paper(), friction=friction, **case)
    assert _overlapping(r.contacts) > 0
    scale = abs(r.work_normal)
    assert sum(c.work_normal for c in r.contacts) == pytest.approx(r.work_normal, abs=1e-12 * scale)
    assert sum(c.work_friction for c in r.contacts) == pytest.approx(
        r.work_friction, abs=1e-12 * scale
    )
    assert max(c.work_friction for c in r.contacts) <= 1e-12 * scale
    assert ResultFlag.ENERGY_GAIN not in r.flags


def test_gravity_dominated_flag() -> None:
    """A slow drop (1 cm/s): gravity's impulse over the sequence exceeds a tenth of the normal
    impulse, flagged as the rigid engine flags its one impact (the law's range aside: the rod
    comes to rest on the flat over 95 contacts, deeper than its first impact; and lying on it,
    its ends' contacts pass the rims of their hemispheres, BEYOND_TIP; its other end touched,
    OTHER_END)."""
    case = {"mu": 0.2, "angle": math.radians(20), "velocity": (0.0, -0.01)}
    r0 = simulate(Rod.paper(), **case)
    r = simulate_drop(Rod.paper(), **case)
    law = ResultFlag.LAW_EXTRAPOLATED
    assert r0.flags & ~law == ResultFlag.GRAVITY_DOMINATED
    assert r.flags & ~law == (
        ResultFlag.GRAVITY_DOMINATED | ResultFlag.BEYOND_TIP | ResultFlag.OTHER_END
    )
    assert r.n_contacts > 1 and not r.ok and any("gravity" in w for w in r.warnings)


def test_paper_drop_flags() -> None:
    """The paper's drop with the flexible rod: no energy gain, gravity not dominating; the law's
    fitted range (``contact.ranges.law_extrapolated``) on the sequence's largest
    interference, advisory (``ok`` stays True), with its explanation."""
    r = simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0, -1.41))
    model = contact_model(Rod.paper(), AISI_1010, "ghaednia")
    assert r.ok and not r.flags & (ResultFlag.ENERGY_GAIN | ResultFlag.GRAVITY_DOMINATED)
    assert r.extrapolated == law_extrapolated(model, r.delta_max)
    assert r.extrapolated == (r.max_delta_ratio > r.fitted_delta_ratio_max)
    ref = critical_interference(model.law_id, model.params)
    assert r.max_delta_ratio == pytest.approx(r.delta_max / ref, rel=1e-12)
    assert len(r.warnings) == int(r.extrapolated)
    fast = simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0, -3.0))
    assert fast.max_delta_ratio > r.max_delta_ratio and fast.extrapolated
    assert fast.ok and "extrapolated" in fast.warnings[-1]
