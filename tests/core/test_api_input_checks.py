"""The Python API refuses or warns about what the command line refuses or warns about, in one
line naming the parameter and the value as given: a heavy rigid rod, constant_angle for a
sphere, a sampled law's radius and residual depth, a sphere where a rod is needed, a velocity
or body of the wrong kind; and a sphere's result has no angle keys, as its CLI JSON."""

from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest

import impactlab as il
from impactlab import ImplausibleInputWarning, experiment
from impactlab.analytic import critical_friction
from impactlab.bodies import FlexibleRod, Rod, Sphere
from impactlab.bodies._checks import HEAVY_ROD_FACTOR
from impactlab.bodies._checks import PLAUSIBLE_RADIUS as BODY_RADIUS
from impactlab.contact import register_law, unregister_law
from impactlab.contact.registered import PLAUSIBLE_RADIUS as LAW_RADIUS
from impactlab.materials import AISI_201, AISI_1010, ContactPair

# -- a heavy rigid rod ------------------------------------------------------------------------


def test_a_rigid_rod_too_heavy_for_a_uniform_section_warns_with_the_flexible_rods_text() -> None:
    """5 kg over 0.3 m implies d = 52.2 mm for a 5 mm tip: FlexibleRod refuses it, Rod (whose
    mass may be a heavy head's) warns with the same text."""
    with pytest.raises(ValueError, match="exceeds twice the tip radius") as refused:
        FlexibleRod(length=0.3, tip_radius=0.005, mass=5.0)
    with pytest.warns(ImplausibleInputWarning) as rec:
        rod = Rod(length=0.3, tip_radius=0.005, mass=5.0)
    assert rod.mass == 5.0
    text = str(rec[0].message)
    assert text.startswith(str(refused.value).split("; ")[0])
    assert "below 78.9 deg to the flat its rim would strike" in text
    assert "27.2 times that of a uniform rod of the material (rho = 7800 kg/m^3)" in text
    assert rec[0].filename == __file__  # the warning points at the user's line


def test_a_heavy_head_or_a_plausible_rod_draws_no_warning() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Rod(length=0.3, tip_radius=0.005, mass=5.0, inertia=0.05)  # its own mass distribution
        Rod.paper()
        Rod(length=0.05, tip_radius=0.005, mass=0.05)  # 1.6 times a uniform rod of the tip
        Rod(length=0.3048, tip_radius=0.005, mass=0.4607)  # the paper's mass, a 5 mm tip: 2.5
        # just under the bound: HEAVY_ROD_FACTOR times a uniform rod as wide as the tip
        below = 0.999 * HEAVY_ROD_FACTOR * AISI_201.density * math.pi * 0.005**2 * 0.3
        Rod(length=0.3, tip_radius=0.005, mass=below)
    with pytest.warns(ImplausibleInputWarning, match="exceeds twice the tip radius"):
        Rod(length=0.3, tip_radius=0.005, mass=below / 0.999 * 1.001)


# -- constant_angle for a sphere --------------------------------------------------------------


@pytest.mark.parametrize("run", ["simulate", "simulate_batch"])
def test_constant_angle_is_refused_for_a_sphere(run: str) -> None:
    ball = Sphere(radius=0.003)
    call = {
        "simulate": lambda: il.simulate(ball, velocity=(0.0, -1.0), constant_angle=True),
        "simulate_batch": lambda: il.simulate_batch(ball, vy=-1.0, constant_angle=True),
    }[run]
    with pytest.raises(ValueError, match=r"^constant_angle=True: a Sphere has no angle"):
        call()
    # False is what every sphere has: accepted as before
    r = il.simulate(ball, velocity=(0.0, -1.0), constant_angle=False, history=False)
    b = il.simulate_batch(ball, vy=-1.0, constant_angle=False)
    assert b.status.tolist() == [0] and float(b["e"][0]) == r.e


# -- a law of one's own -----------------------------------------------------------------------

PAIR = ContactPair(AISI_201, AISI_1010)
E_STAR = PAIR.E_star


def _hertz(radius: float):
    return lambda d: 4.0 / 3.0 * E_STAR * math.sqrt(radius) * d**1.5


def test_the_contact_layer_bounds_the_radius_as_the_bodies_do() -> None:
    assert LAW_RADIUS == BODY_RADIUS


def test_a_sampled_law_blames_a_radius_in_mm() -> None:
    with (
        pytest.warns(ImplausibleInputWarning, match=r"radius = 8.8 m lies outside .* 0.0088 m"),
        pytest.raises(ValueError, match=r"delta_max .* delta_c at radius = 8.8 m .* got 0.0003$"),
    ):
        register_law(
            "mm-radius",
            loading=_hertz(8.8),
            unloading=lambda dm: 0.5 * dm,
            pair=PAIR,
            radius=8.8,
            delta_max=300e-6,
        )


def test_a_residual_depth_at_the_elastic_limit_is_refused_in_plain_numbers() -> None:
    with pytest.raises(ValueError, match="delta_r") as exc:
        register_law(
            "early-residual",
            loading=_hertz(8.8e-3),
            unloading=lambda dm: 0.1 * dm,
            pair=PAIR,
            radius=8.8e-3,
            delta_max=300e-6,
        )
    text = str(exc.value)
    assert re.search(r"delta_r .*elastic limit", text) and "4.362e-0" in text
    assert "np.float64" not in text and "(1.0)" not in text


def test_a_plausible_sampled_law_still_registers_without_warnings() -> None:
    R = 8.8e-3
    hz = _hertz(R)
    dc = 4.3624340008718965e-07

    def force(d: float) -> float:
        return hz(d) if d <= dc else hz(dc) * (d / dc) ** 1.2

    def residual(dm: float) -> float:
        return 0.0 if dm <= dc else dm * (1.0 - (dc / dm) ** 0.3) * 0.9

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            law = register_law(
                "plain-law", loading=force, unloading=residual, pair=PAIR, radius=R,
                delta_max=np.float64(300e-6),
            )  # fmt: skip
        assert law.sampling_error[0] < 1e-6
    finally:
        unregister_law("plain-law")


# -- a sphere where a rod is needed -----------------------------------------------------------


def test_a_sphere_given_as_the_rod_is_named() -> None:
    ball = Sphere(radius=0.003)
    with pytest.raises(ValueError, match=r"^rod: got a Sphere; invert and the closed forms need"):
        il.invert(angle=0.35, mu=0.2, v_i=1.4, delta_p=20e-6, sliding_length=1e-3, e=0.5, rod=ball)
    with pytest.raises(ValueError, match=r"^rod: got a Sphere; invert"):
        critical_friction(0.35, ball)
    with pytest.raises(ValueError, match=r"^rod: got a Sphere; analyze needs a Rod"):
        experiment.analyze(None, None, ball)


# -- messages that show what was given --------------------------------------------------------


def test_one_velocity_is_shown_as_given() -> None:
    rod = Rod.paper()
    with pytest.raises(ValueError, match=r"got one number, '-1.41 m/s' \(a vertical drop: "):
        il.simulate(rod, angle="20 deg", velocity="-1.41 m/s")
    with pytest.raises(ValueError, match=r"got one number, -1.41 \(a vertical drop: velocity="):
        il.simulate(rod, angle="20 deg", velocity=-1.41)


def test_a_body_class_or_none_is_named() -> None:
    with pytest.raises(ValueError, match=r"Rod, Sphere or FlexibleRod, got the class FlexibleRod"):
        il.simulate(FlexibleRod, angle="20 deg", velocity=(0.0, -1.41))
    with pytest.raises(ValueError, match=r"not an instance \(build one: Rod.paper\(\)"):
        il.simulate(Rod, angle="20 deg", velocity=(0.0, -1.41))
    with pytest.raises(ValueError, match=r"Rod, Sphere or FlexibleRod, got None$"):
        il.simulate(None, angle="20 deg", velocity=(0.0, -1.41))
    with pytest.raises(ValueError, match=r"Rod or Sphere, got the class Sphere, not an instance"):
        il.simulate_batch(Sphere, vy=-1.0)


# -- a sphere's result ------------------------------------------------------------------------


def test_a_spheres_result_and_its_cli_json_have_the_same_keys(monkeypatch, capsys) -> None:
    import json

    from impactlab.cli import main

    r = il.simulate(Sphere(radius=0.003), velocity=(0.0, -1.0), history=False)
    d = r.to_dict()
    args = ["impactlab", "simulate", "sphere", "--radius", "3 mm", "--vy", "-1 m/s", "--json"]
    monkeypatch.setattr("sys.argv", args)
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    assert code == 0
    cli = json.loads(capsys.readouterr().out)
    assert set(cli) - {"files"} == set(d)
    assert "angle" not in d and "angle_out" not in d
    assert il.rerun(d).e == r.e


def test_an_inertia_no_body_of_the_rod_can_have_is_refused() -> None:
    """All the mass at the tips gives I_C = m (L/2 + R)^2, the most a rod can have."""
    top = 0.4607 * (0.1524 + 0.0088) ** 2
    assert Rod.paper(inertia=top).inertia == top
    with pytest.raises(ValueError, match=r"inertia = 0.4 kg m\^2 exceeds m \(L/2 \+ R\)\^2"):
        Rod.paper(inertia=0.4)
