"""The inversion: the paper's durations, uncertainty propagation, the result object, the CLI."""

from __future__ import annotations

import dataclasses
import json
import math
import sys
import warnings

import numpy as np
import pint
import pytest

import impactlab as il
from impactlab import analytic as an
from impactlab.bodies import Rod
from impactlab.paper.data import EXPERIMENTS, PAPER_ROD, published_row


def paper_inversion(angle_deg, **kw):
    x = EXPERIMENTS[angle_deg]
    return an.invert(
        angle=x.angle,
        v_i=x.v_i,
        e=x.e,
        mu=x.mu,
        delta_p=abs(x.delta_p),
        sliding_length=abs(x.L_s),
        n_samples=200,
        **kw,
    )


@pytest.mark.parametrize("angle_deg", [20, 45])
def test_paper_durations_within_5_percent(angle_deg):
    row = published_row(angle_deg, "experiment")
    r = paper_inversion(angle_deg)
    assert r.duration == pytest.approx(row.T, rel=0.05)


def test_paper_durations_hand_values():
    # |T| = (|L_s| / |alpha| + |delta_p|) / |v_i| with alpha computed by hand in test_closed_forms
    assert paper_inversion(20).duration == pytest.approx(
        (1400e-6 / 0.242744 + 22e-6) / 1.41, rel=1e-5
    )
    assert paper_inversion(45).duration == pytest.approx(
        (1650e-6 / 0.552338 + 26e-6) / 2.18, rel=1e-5
    )
    assert paper_inversion(20).duration == pytest.approx(4.106e-3, rel=1e-3)
    assert paper_inversion(45).duration == pytest.approx(1.382e-3, rel=1e-3)


def test_rigid_identity_force():
    r = paper_inversion(20)
    assert r.mean_force * r.duration == pytest.approx(1.5 * 1.41 / r.K_y, rel=1e-12)
    assert r.force_method == "rigid-body identity" and r.F_momentum is None


def test_sign_of_v_i_does_not_matter_and_paper_signs_of_the_dent_are_refused():
    # delta_p is a depth in impactlab (the paper prints the final tip height, negative); the
    # sliding length is signed in the engine and v_i's sign is ignored: both by magnitude
    x = EXPERIMENTS[45]
    a = an.invert(
        angle=x.angle,
        v_i=x.v_i,
        e=x.e,
        mu=x.mu,
        delta_p=abs(x.delta_p),
        sliding_length=abs(x.L_s),
        n_samples=200,
    )
    b = an.invert(
        angle=x.angle,
        v_i=-x.v_i,
        e=x.e,
        mu=x.mu,
        delta_p=abs(x.delta_p),
        sliding_length=abs(x.L_s),
        n_samples=200,
    )
    assert a.duration == b.duration and a.mean_force == b.mean_force
    for kw in ({"delta_p": -abs(x.delta_p)},):
        args = dict(
            angle=x.angle,
            v_i=x.v_i,
            e=x.e,
            mu=x.mu,
            delta_p=abs(x.delta_p),
            sliding_length=abs(x.L_s),
            n_samples=200,
        )
        args.update(kw)
        with pytest.raises(ValueError, match="magnitude"):
            an.invert(**args)


def test_uncertainty_linear_case_exact():
    """T is linear in delta_p and L_s: first order is exact and Monte Carlo agrees to its noise."""
    x = EXPERIMENTS[20]
    s_dp, s_ls = 3e-6, 80e-6
    r = an.invert(
        angle=x.angle,
        v_i=x.v_i,
        e=x.e,
        mu=x.mu,
        delta_p=(abs(x.delta_p), s_dp),
        sliding_length=(abs(x.L_s), s_ls),
        n_samples=40_000,
        seed=1,
    )
    alpha = abs(an.alpha(x.angle, x.mu))
    hand = math.hypot(s_dp / 1.41, s_ls / (alpha * 1.41))
    assert r.sigma_T_linear == pytest.approx(hand, rel=1e-5)
    assert r.sensitivity_T["delta_p"] == pytest.approx(1 / 1.41, rel=1e-6)
    assert r.sigma_T_mc == pytest.approx(hand, rel=0.02)  # MC noise ~ 1/sqrt(2 n) = 0.35 %
    assert r.T_mc == pytest.approx(r.duration, rel=2e-3)


@pytest.mark.parametrize("angle_deg", [20, 45, 70])
def test_first_order_agrees_with_monte_carlo(angle_deg):
    x = EXPERIMENTS[angle_deg]
    rel = 0.01  # 1 % on every input: first order is valid (at 70 deg, 2 % on the angle is not)
    r = an.invert(
        angle=(x.angle, rel * x.angle),
        v_i=(x.v_i, rel * abs(x.v_i)),
        e=(x.e, rel * x.e),
        mu=(x.mu, rel * x.mu),
        delta_p=(abs(x.delta_p), rel * abs(x.delta_p)),
        sliding_length=(abs(x.L_s), rel * abs(x.L_s)),
        n_samples=40_000,
        seed=7,
    )
    assert r.mc_rejected == 0.0
    assert r.sigma_T_mc == pytest.approx(r.sigma_T_linear, rel=0.03)
    assert r.sigma_F_mc == pytest.approx(r.sigma_F_linear, rel=0.03)
    assert r.T_interval_mc[0] < r.duration < r.T_interval_mc[1]


def test_large_uncertainty_is_reported_as_rejected_samples():
    x = EXPERIMENTS[70]  # mu = 0.10 with mu_c = 0.257: a wide mu straddles the sticking regime
    with pytest.warns(il.ImplausibleInputWarning, match="Monte Carlo samples .* discarded"):
        r = an.invert(
            angle=x.angle,
            v_i=x.v_i,
            e=x.e,
            mu=(x.mu, 0.1),
            delta_p=abs(x.delta_p),
            sliding_length=abs(x.L_s),
            n_samples=5000,
        )
    assert r.mc_rejected > 0.05
    assert "discarded" in str(r)
    assert r.duration > 0 and r.T_mc > 0


def test_monte_carlo_is_seeded():
    x = EXPERIMENTS[45]
    kw = dict(
        angle=x.angle,
        v_i=x.v_i,
        e=(x.e, 0.05),
        mu=(x.mu, 0.02),
        delta_p=abs(x.delta_p),
        sliding_length=abs(x.L_s),
        n_samples=1000,
    )
    assert an.invert(**kw, seed=3).sigma_F_mc == an.invert(**kw, seed=3).sigma_F_mc
    assert an.invert(**kw, seed=3).sigma_F_mc != an.invert(**kw, seed=4).sigma_F_mc


def test_result_object():
    r = paper_inversion(20)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.duration = 1.0  # type: ignore[misc]
    with pytest.raises(TypeError):
        r.inputs["mu"] = (0.0, 0.0)  # type: ignore[index]
    d = r.to_dict()
    json.dumps(d)
    assert d["duration"] == r.duration and d["inputs"]["sliding_length"] == [1400e-6, 0.0]
    assert d["rod"]["inertia"] == pytest.approx(PAPER_ROD.mass * PAPER_ROD.length**2 / 12)
    text = str(r)
    assert "T = 4.106 ms" in text and "alpha = -0.2427" in text


def test_momentum_force_and_inertia_argument():
    with pytest.warns(il.ImplausibleInputWarning, match="implies e = 0.69"):  # e = 0.5 given
        r = paper_inversion(20, dv_cy=0.7)
    assert r.force_method == "momentum"
    assert r.mean_force == pytest.approx(0.4607 * 0.7 / r.duration)
    assert r.F_rigid == pytest.approx(1.5 * 1.41 / (r.K_y * r.duration))
    heavy = Rod(length=0.3048, tip_radius=0.0088, mass=0.4607, inertia=0.4607 * 0.3048**2 / 10)
    r2 = paper_inversion(20, rod=heavy)
    assert r2.rod["inertia"] == heavy.inertia and r2.duration != r.duration


# --- command line --------------------------------------------------------------------------


def run_cli(monkeypatch, capsys, *args):
    from impactlab.cli import main

    monkeypatch.setattr(sys, "argv", ["impactlab", "invert", *args])
    code = 0
    try:
        main()
    except SystemExit as exc:
        code = exc.code or 0
    out = capsys.readouterr()
    return code, out.out, out.err


def test_cli_paper_case_json(monkeypatch, capsys):
    code, out, _ = run_cli(monkeypatch, capsys, "--case", "paper-20", "--json", "--samples", "200")
    assert code == 0
    assert json.loads(out)["duration"]["value"] == pytest.approx(paper_inversion(20).duration)


def test_cli_units_and_sigmas(monkeypatch, capsys):
    code, out, _ = run_cli(
        monkeypatch,
        capsys,
        "--angle",
        "20 deg",
        "--vi",
        "-1.41 m/s",
        "--e",
        "0.5",
        "--mu",
        "0.2",
        "--delta-p",
        "22 um",
        "--ls",
        "1.4 mm",
        "--sigma-ls",
        "50 um",
        "--json",
        "--samples",
        "500",
    )
    assert code == 0
    d = json.loads(out)
    assert d["duration"]["value"] == pytest.approx(paper_inversion(20).duration)
    assert d["duration"]["sigma"] == pytest.approx(50e-6 / (0.242744 * 1.41), rel=1e-4)


def test_cli_file(monkeypatch, capsys, tmp_path):
    f = tmp_path / "m.toml"
    f.write_text(
        'case = "paper-45"\nmu = 0.13\n[sigma]\ne = 0.02\n[rod]\ninertia = "3.567e-3 kg*m^2"\n'
    )
    code, out, err = run_cli(monkeypatch, capsys, "--file", str(f), "--json", "--samples", "200")
    assert code == 0, err
    d = json.loads(out)
    assert d["inputs"]["e"] == {"value": 0.49, "unit": "1", "sigma": 0.02}
    assert d["duration"]["value"] == pytest.approx(paper_inversion(45).duration, rel=1e-3)


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--case", "paper-70", "--mu", "0.3"], "sticking regime"),
        (["--case", "paper-20", "--angle", "20 m"], "--angle"),
        (["--angle", "20", "--vi", "1", "--e", "0.5", "--mu", "0.2", "--delta-p", "1 um"], "--ls"),
        (["--case", "paper-99"], "unknown case"),
        (["--case", "paper-20", "--e", "abc"], "--e"),
    ],
)
def test_cli_errors_are_one_line(monkeypatch, capsys, args, needle):
    code, _out, err = run_cli(monkeypatch, capsys, *args)
    assert code == 2
    assert needle in err and err.count("\n") == 1 and "Traceback" not in err


# -- plausible units, one input rule --------------------------------------------------------------

BASE = dict(angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1.4e-3)


@pytest.mark.parametrize(
    ("override", "match"),
    [
        ({"seed": "abc"}, "seed must be None or an integer >= 0, got 'abc'"),
        ({"seed": True}, "seed must be None or an integer >= 0, got True"),
        ({"seed": -1}, "seed must be None or an integer >= 0"),
        ({"gravity": "yes"}, "gravity must be True or False, got 'yes'"),
        ({"mu": "0.2"}, "mu must be a real number, got the string '0.2': write mu=0.2"),
        ({"e": True}, "e must be a real number, got the bool True"),
        ({"v_i": "-1.41"}, "v_i: the string '-1.41' has no unit"),
        ({"delta_p": 22.0}, r"delta_p = 22.0 m is deeper than the rod's tip radius \(0.0088 m\)"),
        ({"sliding_length": 1.0}, r"sliding_length = 1.0 m is longer than the rod \(0.3048 m\)"),
    ],
)
def test_invert_refuses_bad_and_impossible_inputs(override, match):
    with pytest.raises(ValueError, match=match):
        an.invert(**{**BASE, **override}, n_samples=100)


def test_invert_warns_on_implausible_inputs():
    with pytest.warns(il.ImplausibleInputWarning, match="deeper than 0.1 of the tip radius"):
        an.invert(**{**BASE, "delta_p": 2e-3}, n_samples=100)
    with pytest.warns(il.ImplausibleInputWarning, match="v_i = 141.0 m/s exceeds 100 m/s"):
        an.invert(**{**BASE, "v_i": -141.0}, n_samples=100)
    with pytest.warns(il.ImplausibleInputWarning, match=r"duration T = .* s exceeds 0.1 s"):
        an.invert(**{**BASE, "v_i": -0.01}, n_samples=100)


def test_invert_takes_units_and_quantities_of_any_registry():
    other = pint.UnitRegistry()
    ref = an.invert(**BASE, n_samples=100)
    r = an.invert(
        angle="20 deg",
        v_i=-1.41 * other("m/s"),
        e=0.5,
        mu=0.2,
        delta_p="22 um",
        sliding_length=("1.4 mm", 0.0 * other.um),
        n_samples=100,
    )
    assert r.duration == pytest.approx(ref.duration, rel=1e-12)
    assert r.inputs["sliding_length"] == pytest.approx((1.4e-3, 0.0))
    assert r.seed == 0 and isinstance(an.invert(**BASE, seed=np.int64(3)).seed, int)


def test_a_velocity_change_that_contradicts_e_warns() -> None:
    base = {"angle": math.radians(20), "v_i": -1.41, "mu": 0.2, "delta_p": 22e-6,
            "sliding_length": 1400e-6}  # fmt: skip
    plain = an.invert(**base, e=0.5)
    consistent = 1.5 * 1.41 / (plain.K_y * PAPER_ROD.mass)  # F T = (1 + e)|v_i| / K_y = m dv_cy
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # consistent inputs: no warning
        agreed = an.invert(**base, e=0.5, dv_cy=consistent)
    assert agreed.F_momentum == pytest.approx(agreed.F_rigid, rel=1e-12)
    with pytest.warns(il.ImplausibleInputWarning, match=r"implies e = 23.* outside \[0, 1\]"):
        wild = an.invert(**base, e=0.5, dv_cy=10.0)
    assert "F from the rigid-body identity (with e): 69.31" in str(wild)
    with pytest.warns(il.ImplausibleInputWarning, match=r"but e = 0.5 \+- [0-9.e-]+ was measured"):
        an.invert(**base, e=0.5, dv_cy=1.3 * consistent)
    with pytest.warns(il.ImplausibleInputWarning, match="outside"):
        an.invert(**base, dv_cy=0.9)  # e > 1 without e given
