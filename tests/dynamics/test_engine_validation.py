"""Bad input raises a clear ValueError naming the parameter; the batch flags bad cases."""

from __future__ import annotations

import math

import numpy as np
import pint
import pytest

from impactlab import ImplausibleInputWarning
from impactlab.bodies import NB, PAPER_ROD, Rod, Sphere
from impactlab.contact.kernels import NPARAM
from impactlab.dynamics import (
    FRICTION_IDS,
    OUTPUT_FIELDS,
    STATUS_MESSAGES,
    contact_model,
    run_arrays,
    simulate,
    simulate_batch,
)
from impactlab.flags import ResultFlag
from impactlab.friction import get_friction
from impactlab.materials import AISI_1010, AL_6061_T6

OK = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"length": -0.3, "tip_radius": 0.01, "mass": 1.0}, "length must be > 0"),
        ({"length": 0.3, "tip_radius": 0.0, "mass": 1.0}, "tip_radius must be > 0"),
        ({"length": 0.3, "tip_radius": 0.01, "mass": math.nan}, "mass must be finite"),
        ({"length": 0.3, "tip_radius": 0.01, "mass": 1.0, "inertia": -1.0}, "inertia must be > 0"),
        ({"length": math.inf, "tip_radius": 0.01, "mass": 1.0}, "length must be finite"),
        (
            {"length": 0.3, "tip_radius": 0.01, "mass": 1.0, "material": "steel"},
            "unknown material 'steel'",
        ),
    ],
)
def test_rod_validation(kwargs: dict, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        Rod(**kwargs)


def test_sphere_validation() -> None:
    with pytest.raises(ValueError, match="radius must be > 0"):
        Sphere(-0.01)
    with pytest.raises(ValueError, match="density must be > 0"):
        Sphere(0.01, density=-1.0)
    with pytest.raises(ValueError, match="either mass or density"):
        Sphere(0.01, mass=1.0, density=7800.0)
    s = Sphere(0.01)
    assert s.mass == pytest.approx(4 / 3 * math.pi * 1e-6 * s.material.density)
    assert s.inertia == pytest.approx(0.4 * s.mass * 1e-4)


def test_rod_defaults_and_paper_preset() -> None:
    r = Rod.paper()
    assert (r.tip_radius, r.L, r.mass) == (0.0088, 0.3048, 0.4607)
    assert r.inertia == pytest.approx(0.4607 * 0.3048**2 / 12)
    assert Rod.paper(inertia=0.01).inertia == 0.01
    p = r.to_params()
    assert p.shape == (NB,) and np.all(np.isfinite(p))


@pytest.mark.parametrize(
    ("override", "match"),
    [
        ({"mu": -0.1}, "mu must be >= 0"),
        ({"mu": math.nan}, "mu must be finite"),
        ({"angle": 20.0}, r"got 20.0 rad \(1145.92 deg\); if 20.0 is meant in degrees"),
        ({"angle": 90.0}, "if 90.0 is meant in degrees"),
        ({"angle": 1.6}, r"got 1.6 rad \(91.6732 deg\): the rod leans past the flat's normal"),
        ({"mu": 2e3}, r"mu must lie in \[0, 1000\]"),
        ({"velocity": {"vx": 0.0, "vy": -1.41}}, "velocity must be a pair .* got a dict"),
        ({"velocity": {0.0, -1.41}}, "velocity must be a pair .* got a set"),
        ({"angle": -0.2}, r"angle must be in radians in \(0, pi/2\]"),
        ({"angle": 120.0}, r"angle must be in radians"),
        ({"angle": None}, "angle is required"),
        ({"angle": math.nan}, "angle must be finite"),
        ({"velocity": (0.0, 1.0)}, "velocity: the contact point does not approach"),
        ({"velocity": (0.0, math.nan)}, r"velocity\[1\] \(vy\) must be finite"),
        ({"velocity": 3.0}, "velocity must be a pair"),
        ({"spin": math.inf}, "spin must be finite"),
        (
            {"friction": "viscous"},
            "unknown friction model 'viscous'; known models: impulse_ratio, coulomb, mindlin",
        ),
        ({"law": "nope"}, "unknown contact law 'nope'"),
        ({"rtol": 0.5}, "rtol must lie in"),
        ({"gravity": -9.8}, "gravity must be >= 0"),
        ({"law_params": {"bogus": 1.0}}, "unknown parameter"),
    ],
)
def test_simulate_bad_input(override: dict, match: str) -> None:
    kw = {**OK, "law": "ghaednia", "friction": "coulomb", **override}
    with pytest.raises(ValueError, match=match):
        simulate(PAPER_ROD, **kw)


@pytest.mark.parametrize(
    ("angle", "match"),
    [
        (20.0, r"got 20.0 rad \(1145.92 deg\); if 20.0 is meant in degrees"),
        (None, "angle is required"),
        (math.nan, "angle must be finite"),
    ],
)
def test_one_bad_angle_for_a_whole_batch_is_refused_as_by_simulate(angle, match) -> None:
    """One angle for every case is checked as ``simulate`` checks it (an array of angles
    keeps its per-case status)."""
    with pytest.raises(ValueError, match=match):
        simulate_batch(PAPER_ROD, angle=angle, vy=-1.41, mu=0.2)


def test_spin_can_make_the_rod_recede() -> None:
    # v_n = vy - spin * (L/2) cos(angle) >= 0: the tip moves away although vy < 0
    with pytest.raises(ValueError, match="does not approach"):
        simulate(PAPER_ROD, angle=0.3, velocity=(0.0, -0.5), spin=-10.0)


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")  # 400 m/s on purpose
def test_law_validity_exceeded_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="validity limit of the 'kogut-komvopoulos' law"):
        simulate(Sphere(0.002), law="kogut-komvopoulos", velocity=(0.0, -400.0))


def test_contact_model_radius_mismatch() -> None:
    model = contact_model(Sphere(0.01), AISI_1010, "hertz")
    with pytest.raises(ValueError, match="differs from the body's tip radius"):
        simulate(PAPER_ROD, law=model, **OK)


def test_contact_model_of_another_pair_is_refused() -> None:
    # built for the rod on aluminium, passed with the steel flat: the dent would be one pair's,
    # the Mindlin stiffness G* and the result's labels the other's
    model = contact_model(PAPER_ROD, AL_6061_T6, "ghaednia")
    for friction in ("coulomb", "mindlin"):
        with pytest.raises(ValueError, match="built for the flat 'aluminium 6061-T6', not for"):
            simulate(PAPER_ROD, AISI_1010, law=model, friction=friction, **OK)
    with pytest.raises(ValueError, match="built for the flat"):
        simulate_batch(PAPER_ROD, AISI_1010, law=model, angle=0.35, vy=-1.41)
    same = simulate(PAPER_ROD, AL_6061_T6, law=model, **OK)
    assert same.e == simulate(PAPER_ROD, AL_6061_T6, law="ghaednia", **OK).e


def test_bad_body_and_flat() -> None:
    with pytest.raises(ValueError, match="body must be"):
        simulate("rod", **OK)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="flat: unknown material 'steel'; known: aisi-201"):
        simulate(PAPER_ROD, "steel", **OK)  # type: ignore[arg-type]


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")  # 600 m/s on purpose
def test_batch_flags_bad_cases_and_never_crashes() -> None:
    vy = np.array([-1.0, 1.0, -2.0, math.nan, -1.0, -600.0])
    mu = np.array([0.2, 0.2, 0.2, 0.2, -1.0, 0.2])
    b = simulate_batch(Sphere(0.002), law="kogut-komvopoulos", friction="coulomb", mu=mu, vy=vy)
    # a sphere takes no angle (refused when given: test_angle_rule_echo); a NaN is flagged
    assert list(b.status) == [0, 2, 0, 4, 4, 1]
    assert np.isnan(b.e[1:]).sum() >= 4 and np.isfinite(b.e[0])
    assert b.messages[1] == f"{STATUS_MESSAGES[2]}: vn = +1.0 m/s"
    # a refused case keeps its incoming velocities where the inputs define them, NaN elsewhere
    assert b.vn_in[1] == 1.0 and np.isnan(b.vn_in[3])
    failed = [f for f in OUTPUT_FIELDS if f not in ("vn_in", "vt_in")]
    assert all(np.isnan(b[f][1]) for f in failed)
    r = simulate_batch(PAPER_ROD, law="hertz", mu=0.2, angle=[0.3, 20.0, -0.1], vy=-1.0)
    assert list(r.status) == [0, 7, 7]


def test_run_arrays_shapes_and_ids() -> None:
    model = contact_model(PAPER_ROD, AISI_1010, "hertz")
    bp = PAPER_ROD.to_params()
    init = np.array([[0.3, 0.0, -1.0, 0.0], [0.5, 0.1, -2.0, 1.0]])
    out, status = run_arrays(
        model.law_id, FRICTION_IDS["coulomb"], model.params, bp, init, np.array([0.1, 0.5])
    )
    assert out.shape == (2, len(OUTPUT_FIELDS)) and status.dtype == np.int32
    assert np.all(status == 0)
    # per-case law and body parameters
    out2, _status2 = run_arrays(
        model.law_id,
        1,
        np.tile(model.params, (2, 1)),
        np.tile(bp, (2, 1)),
        init,
        np.array([0.1, 0.5]),
        gravity=True,
        constant_angle=False,
        rtol=None,
    )
    np.testing.assert_array_equal(out, out2)
    with pytest.raises(ValueError, match="law_params must have shape"):
        run_arrays(0, 1, np.zeros(NPARAM - 1), bp, init, 0.1)
    with pytest.raises(ValueError, match="initial must have shape"):
        run_arrays(0, 1, model.params, bp, np.zeros((2, 3)), 0.1)
    with pytest.raises(ValueError, match="friction_id must be one of"):
        run_arrays(0, 7, model.params, bp, init, 0.1)
    with pytest.raises(ValueError, match="law_id must lie in"):
        run_arrays(99, 1, model.params, bp, init, 0.1)
    # a radius mismatch between law and body is flagged, not silently used
    p_bad = np.array(model.params)
    p_bad[1] *= 2.0
    _, st = run_arrays(0, 1, p_bad, bp, init, 0.1)
    assert list(st) == [8, 8]


def test_mindlin_needs_g_star() -> None:
    model = contact_model(PAPER_ROD, AISI_1010, "hertz")
    bp = PAPER_ROD.to_params()
    bp[5] = math.nan
    _, st = run_arrays(
        0, get_friction("mindlin").friction_id, model.params, bp, [0.3, 0.0, -1.0, 0.0], 0.2
    )
    assert list(st) == [10]


# -- one input rule, no leaked internal errors, no lenient coercions ------------------------------


@pytest.mark.parametrize(
    ("override", "match"),
    [
        ({"law_params": "abc"}, "law_params must be a mapping of parameter names to values"),
        ({"mu": "0.2"}, r"mu must be a real number, got the string '0.2': write mu=0.2"),
        ({"mu": True}, "mu must be a real number, got the bool True"),
        ({"velocity": (0, "-1.41")}, r"velocity\[1\] \(vy\): the string '-1.41' has no unit"),
        ({"angle": "20"}, "angle: the string '20' has no unit"),
        ({"angle": "20 m"}, "angle: '20 m' has the wrong dimension"),
        ({"spin": "1 m/s"}, "spin: '1 m/s' has the wrong dimension"),
        ({"rtol": "1e-8"}, "rtol must be a real number, got the string"),
        ({"gravity": "9.81"}, "gravity: the string '9.81' has no unit"),
        ({"history": "no"}, "history must be True or False, got 'no'"),
        ({"constant_angle": 1}, "constant_angle must be True or False, got 1"),
        ({"law_params": {"published_switch": "yes"}}, "published_switch must be a real number"),
    ],
)
def test_simulate_refuses_strings_bools_and_unitless_text(override: dict, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        simulate(PAPER_ROD, **{**OK, **override})


def test_quantities_with_units_and_of_any_registry_give_identical_results() -> None:
    other = pint.UnitRegistry()  # not impactlab's registry
    ref = simulate(PAPER_ROD, **OK)
    same = [
        simulate(PAPER_ROD, mu=0.2, angle="20 deg", velocity=(0.0, "-1.41 m/s")),
        simulate(PAPER_ROD, mu=0.2, angle=20 * other.deg, velocity=(0, -1.41 * other("m/s"))),
        simulate(PAPER_ROD, mu=0.2, angle=OK["angle"], velocity=(0.0, -1.41) * other("m/s")),
        simulate(PAPER_ROD, **OK, gravity="9.80665 m/s^2", spin="0 rad/s"),
    ]
    for r in same:
        assert (r.e, r.delta_p, r.duration) == pytest.approx((ref.e, ref.delta_p, ref.duration))
    exact = simulate(PAPER_ROD, mu=0.2, angle=OK["angle"], velocity=(0.0, "-1.41 m/s"))
    assert exact.e == ref.e and exact.delta_p == ref.delta_p


def test_simulate_batch_refuses_bad_arrays_with_the_parameter_named() -> None:
    with pytest.raises(ValueError, match="mu must be a real number, got the string 'abc'"):
        simulate_batch(PAPER_ROD, mu="abc", angle=0.3, vy=-1.0)
    with pytest.raises(ValueError, match="vy is required"):
        simulate_batch(PAPER_ROD, angle=0.3, vy=None)
    with pytest.raises(ValueError, match=r"vy\[1\]: the string '-2' has no unit; pass a number"):
        simulate_batch(PAPER_ROD, angle=0.3, vy=[-1.0, "-2"])
    with pytest.raises(ValueError, match="vy must hold real numbers, got an array of bytes"):
        simulate_batch(PAPER_ROD, angle=0.3, vy=np.array([b"-1", b"-2"]))
    with pytest.raises(ValueError, match="mu must hold real numbers, got an array of bools"):
        simulate_batch(PAPER_ROD, angle=0.3, vy=-1.0, mu=[True, False])
    with pytest.raises(ValueError, match="constant_angle must be True or False"):
        simulate_batch(PAPER_ROD, angle=0.3, vy=-1.0, constant_angle="yes")
    other = pint.UnitRegistry()
    a = simulate_batch(PAPER_ROD, angle=[0.3, 0.5], vy=-1.41, mu=0.2)
    b = simulate_batch(PAPER_ROD, angle=[0.3, 0.5] * other.rad, vy="-1.41 m/s", mu=0.2)
    np.testing.assert_array_equal(a.out, b.out)


# -- implausible units ----------------------------------------------------------------------------


def test_a_tip_wider_than_the_rod_is_refused_and_odd_sizes_warn() -> None:
    with pytest.raises(ValueError, match=r"tip_radius = 8.8 m exceeds half the rod's length"):
        Rod(length=0.3048, tip_radius=8.8, mass=0.4607)
    with pytest.warns(ImplausibleInputWarning) as rec:
        Rod(length=20.0, tip_radius=0.6, mass=0.4607)
    assert [str(w.message).split(" lies")[0] for w in rec] == [
        "length = 20.0 m",
        "tip_radius = 0.6 m",
    ]
    assert rec[0].filename == __file__  # the warning points at the user's line
    with pytest.warns(ImplausibleInputWarning) as rec:
        Rod(length=0.3048, tip_radius=0.0088, mass=4607.0)
    said = [str(w.message) for w in rec]
    assert said[0].startswith("mass = 4607.0 kg") and "exceeds twice the tip radius" in said[1]
    with pytest.warns(ImplausibleInputWarning, match="radius = 0.6 m"):
        Sphere(0.6, mass=500.0)
    assert Rod(length="30.48 cm", tip_radius="8.8 mm", mass="460.7 g") == PAPER_ROD


def test_a_fast_impact_warns() -> None:
    with pytest.warns(ImplausibleInputWarning, match=r"impact speed \(141 m/s\) exceeds 100 m/s"):
        simulate(Sphere(0.01), law="hertz", velocity=(0.0, -141.0))
    with pytest.warns(
        ImplausibleInputWarning, match=r"speed of the batch \(141 m/s\) exceeds 100 m/s"
    ):
        simulate_batch(Sphere(0.01), law="hertz", vy=[-1.0, -141.0])


# -- a gravity-dominated impact is flagged, not refused -------------------------------------------


def test_gravity_dominated_impact_is_flagged_not_refused() -> None:
    r = simulate(PAPER_ROD, mu=0.2, angle=math.radians(20), velocity=(0.0, -1e-9))
    assert ResultFlag.GRAVITY_DOMINATED in r.flags and not r.ok
    assert any("gravity-dominated" in w for w in r.warnings)
    assert simulate(PAPER_ROD, **OK).ok


@pytest.mark.parametrize("gravity", [True, False])
def test_an_impact_that_never_separates_names_the_approach_speed(gravity: bool) -> None:
    """A vanishing approach speed ends without separation; the error names the speed and, with
    gravity, why the body stays on the flat (never the bare engine status)."""
    with pytest.raises(ValueError, match=r"approached the flat at 1e-200 m/s") as info:
        simulate(Rod.paper(), AISI_1010, angle=0.35, velocity=(0.0, -1e-200), gravity=gravity)
    assert ("gravity=False" in str(info.value)) is gravity


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")
@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"velocity": (1e300, -1.0)}, r"velocity\[0\] \(vx\) = 1e\+300 m/s exceeds 10000 m/s"),
        ({"velocity": (0.0, -2e4)}, r"velocity\[1\] \(vy\) = -20000.0 m/s exceeds"),
        ({"spin": 1e10}, r"spin = 10000000000.0 rad/s moves the contact point .* beyond 10000 m/s"),
        ({"mu": 1e300}, r"mu must lie in \[0, 1000\]"),
        ({"gravity": 1e300}, r"gravity must lie in \[0, 1e\+07\] m/s\^2"),
    ],
)
def test_inputs_beyond_their_bounds_name_the_parameter(kwargs, match) -> None:
    # beyond these the energy bookkeeping overflows or cancels (a NaN or a 0.0 work)
    args = {**OK, "velocity": (0.0, -1.0), **kwargs}
    with pytest.raises(ValueError, match=match):
        simulate(PAPER_ROD, **args)


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")
def test_batch_cases_beyond_the_bounds_are_refused_per_case() -> None:
    b = simulate_batch(
        PAPER_ROD, angle=0.35, vx=[1e300, 0.0, 0.0, 0.0], vy=-1.0, mu=[0.2, 1e300, 0.2, 0.2],
        spin=[0.0, 0.0, 1e10, 0.0],
    )  # fmt: skip
    assert list(b.status) == [4, 4, 4, 0]
    assert b.messages[:3] == [  # each names its input, value and rule, as a batch of drops
        "invalid input: vx = 1e+300: a velocity component must be finite and at most 10000 m/s",
        "invalid input: mu must lie in [0, 1000] (dry friction stays below about 2; a larger "
        "mu only sticks), got 1e+300",
        "invalid input: spin = 10000000000.0: the spin times the reach of the contact point "
        "(L/2 + R) must be finite and at most 10000 m/s",
    ]
    assert np.isnan(b.energy_dissipated[:3]).all() and np.isfinite(b.energy_dissipated[3])
