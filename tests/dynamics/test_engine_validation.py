"""Bad input raises a clear ValueError naming the parameter; the batch flags bad cases."""

from __future__ import annotations

import math

import numpy as np
import pytest

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
from impactlab.friction import get_friction
from impactlab.materials import AISI_1010

OK = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"length": -0.3, "tip_radius": 0.01, "mass": 1.0}, "length must be > 0"),
        ({"length": 0.3, "tip_radius": 0.0, "mass": 1.0}, "tip_radius must be > 0"),
        ({"length": 0.3, "tip_radius": 0.01, "mass": math.nan}, "mass must be finite"),
        ({"length": 0.3, "tip_radius": 0.01, "mass": 1.0, "inertia": -1.0}, "inertia must be > 0"),
        ({"length": math.inf, "tip_radius": 0.01, "mass": 1.0}, "length must be finite"),
        ({"length": 0.3, "tip_radius": 0.01, "mass": 1.0, "material": "steel"}, "material must"),
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
        ({"angle": 20.0}, "looks like degrees"),
        ({"angle": 90.0}, "looks like degrees"),
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


def test_spin_can_make_the_rod_recede() -> None:
    # v_n = vy - spin * (L/2) cos(angle) >= 0: the tip moves away although vy < 0
    with pytest.raises(ValueError, match="does not approach"):
        simulate(PAPER_ROD, angle=0.3, velocity=(0.0, -0.5), spin=-10.0)


def test_law_validity_exceeded_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="validity limit of the 'kogut-komvopoulos' law"):
        simulate(Sphere(0.002), law="kogut-komvopoulos", velocity=(0.0, -400.0))


def test_contact_model_radius_mismatch() -> None:
    model = contact_model(Sphere(0.01), AISI_1010, "hertz")
    with pytest.raises(ValueError, match="differs from the body's tip radius"):
        simulate(PAPER_ROD, law=model, **OK)


def test_bad_body_and_flat() -> None:
    with pytest.raises(ValueError, match="body must be"):
        simulate("rod", **OK)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="flat must be"):
        simulate(PAPER_ROD, "steel", **OK)  # type: ignore[arg-type]


def test_batch_flags_bad_cases_and_never_crashes() -> None:
    angle = np.array([0.3, 0.3, 20.0, math.nan, 0.3, 0.3])
    vy = np.array([-1.0, 1.0, -1.0, -1.0, -1.0, -600.0])
    mu = np.array([0.2, 0.2, 0.2, 0.2, -1.0, 0.2])
    b = simulate_batch(
        Sphere(0.002), law="kogut-komvopoulos", friction="coulomb", mu=mu, angle=angle, vy=vy
    )
    # a sphere ignores the angle: only its NaN is flagged
    assert list(b.status) == [0, 2, 0, 4, 4, 1]
    assert np.isnan(b.e[1:]).sum() >= 4 and np.isfinite(b.e[0])
    assert b.messages[1] == STATUS_MESSAGES[2]
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
