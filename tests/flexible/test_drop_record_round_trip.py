"""Every drop, of a rigid or a flexible rod, records its full input (``simulate_drop``'s call)
and runs again from it to identical numbers, in Python and through ``impactlab simulate
--from`` on the JSON of ``impactlab drop --json``; the drop takes speed and incidence with
``simulate``'s rule and errors."""

from __future__ import annotations

import json
import math
import sys

import pytest

import impactlab as il
from impactlab._json import shape_problems
from impactlab.bodies import PAPER_ROD
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.cli import main
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.input_checks import velocity_from
from impactlab.dynamics.provenance import SIMULATE_DROP
from impactlab.materials import AL_6061_T6

FLEX = FlexibleRod.paper(n_axial=1, n_bending=2)
#: The totals compared bit for bit after a round trip.
TOTALS = ("e", "e_raw", "dent_depth", "delta_max", "sequence_duration", "n_contacts")
TOTALS += ("velocity_out",)


def _same(a: il.DropResult, b: il.DropResult) -> None:
    for name in TOTALS:
        assert getattr(a, name) == getattr(b, name), name


def _cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.parametrize("body", [PAPER_ROD, FLEX], ids=["rigid", "flexible"])
def test_a_drop_records_everything_and_reruns_identically(body) -> None:
    r = simulate_drop(body, AL_6061_T6, angle="45 deg", velocity=(0.1, -1.0), mu=0.1,
                      law_params=None, stop="flight", time_limit=0.4)  # fmt: skip
    d = json.loads(json.dumps(r.to_dict()))
    rec = d["input"]
    assert rec is not None and shape_problems(rec) == []
    assert rec["function"] == SIMULATE_DROP and rec["impactlab_version"] == il.__version__
    assert rec["body"]["type"] == type(body).__name__
    assert rec["body"]["material"]["yield_strength"]["unit"] == "Pa"
    assert rec["flat"]["E"] == {"value": AL_6061_T6.E, "unit": "Pa"}
    assert rec["angle"] == {"value": math.radians(45), "unit": "rad"}
    assert rec["velocity"] == {"value": [0.1, -1.0], "unit": "m/s"}
    assert rec["stop"] == "flight" and rec["time_limit"] == {"value": 0.4, "unit": "s"}
    assert rec["rate"] is None and rec["rtol"]["value"] > 0 and "constant_angle" not in rec
    _same(il.rerun(d), r)
    _same(il.rerun(rec), r)
    changed = il.rerun(d, mu=0.2)
    assert changed.mu == 0.2 and changed.input["mu"]["value"] == 0.2
    turned = il.rerun(d, speed="1.5 m/s", incidence="10 deg")  # replaces the recorded velocity
    assert turned.velocity_in == velocity_from(None, "1.5 m/s", "10 deg")


def test_simulate_of_a_flexible_rod_records_the_drop_in_full() -> None:
    r = il.simulate(FLEX, angle=0.5, velocity=(0.0, -1.0), mu=0.1, history=False)
    rec = r.input
    assert rec["function"] == SIMULATE_DROP
    assert rec["stop"] == "sequence"
    assert rec["time_limit"]["value"] == il.dynamics.drop.DEFAULT_TIME_LIMIT
    _same(il.rerun(r.to_dict()), r)


@pytest.mark.parametrize("rigid", [True, False], ids=["rigid", "flexible"])
def test_cli_drop_json_then_simulate_from(rigid, tmp_path, monkeypatch, capsys) -> None:
    args = ["drop", "--angle", "30 deg", "--vy", "-1.2 m/s", "--mu", "0.1", "--json"]
    args += ["--rigid"] if rigid else ["--modes-axial", "1", "--modes-bending", "2"]
    code, out, err = _cli(monkeypatch, capsys, *args)
    assert code == 0, err
    data = json.loads(out)
    assert data["input"]["body"]["type"] == ("Rod" if rigid else "FlexibleRod")
    saved = tmp_path / "drop.json"
    saved.write_text(out)
    code, again, err = _cli(monkeypatch, capsys, "simulate", "--from", str(saved), "--json")
    assert code == 0, err
    again_data = json.loads(again)
    for name in ("e", "dent_depth", "sequence_duration", "n_contacts", "contacts", "input"):
        assert again_data[name] == data[name], name
    # an option on top of the recorded input: the drop's rate, the speed and incidence
    code, out, err = _cli(monkeypatch, capsys, "simulate", "--from", str(saved), "--json",
                          "--speed", "1.5 m/s", "--incidence", "10 deg")  # fmt: skip
    assert code == 0, err
    vx, vy = json.loads(out)["input"]["velocity"]["value"]
    assert (vx, vy) == pytest.approx((1.5 * math.sin(0.1745329), -1.5 * math.cos(0.1745329)))
    code, _, err = _cli(monkeypatch, capsys, "simulate", "--from", str(saved), "--constant-angle")
    assert code != 0 and "--constant-angle" in err and "Traceback" not in err


def test_drop_takes_speed_and_incidence_like_simulate() -> None:
    by_speed = simulate_drop(PAPER_ROD, angle=0.5, speed="1.5 m/s", incidence="10 deg", mu=0.1)
    v = velocity_from(None, "1.5 m/s", "10 deg")
    by_velocity = simulate_drop(PAPER_ROD, angle=0.5, velocity=v, mu=0.1)
    _same(by_speed, by_velocity)
    assert by_speed.velocity_in == pytest.approx((1.5 * math.sin(math.radians(10)),
                                                  -1.5 * math.cos(math.radians(10))))  # fmt: skip
    for kwargs, says in (
        ({"speed": 1.0}, "incidence is missing"),
        ({"velocity": (0.0, -1.0), "speed": 1.0, "incidence": 0.1}, "not both"),
        ({}, "give the velocity"),
        ({"speed": 1.0, "incidence": 2.0}, "a bare incidence is radians"),
    ):
        with pytest.raises(ValueError, match=says) as drop_error:
            simulate_drop(PAPER_ROD, angle=0.5, **kwargs)
        with pytest.raises(ValueError, match=says) as simulate_error:
            il.simulate(PAPER_ROD, angle=0.5, **kwargs)
        assert str(drop_error.value) == str(simulate_error.value)


def test_cli_drop_from_with_options_on_top(tmp_path, monkeypatch, capsys) -> None:
    base = ["drop", "--angle", "30 deg", "--vy", "-1.2 m/s", "--rigid", "--json"]
    code, out, err = _cli(monkeypatch, capsys, *base, "--mu", "0.1")
    assert code == 0, err
    saved = tmp_path / "drop.json"
    saved.write_text(out)
    code, again, err = _cli(monkeypatch, capsys, "drop", "--from", str(saved), "--json")
    assert code == 0, err
    assert json.loads(again)["e"] == json.loads(out)["e"]
    code, changed, err = _cli(monkeypatch, capsys, "drop", "--from", str(saved), "--mu", "0.3",
                              "--json")  # fmt: skip
    code_direct, direct, _ = _cli(monkeypatch, capsys, *base, "--mu", "0.3")
    assert code == code_direct == 0, err
    assert json.loads(changed)["input"] == json.loads(direct)["input"]
    assert json.loads(changed)["e"] == json.loads(direct)["e"]
    code, _, err = _cli(monkeypatch, capsys, "drop", "--from", str(saved), "--rigid")
    assert code != 0 and "--rigid: --from simulates the recorded body" in err
    impact = tmp_path / "impact.json"
    code, out, err = _cli(monkeypatch, capsys, "simulate", "rod", "--angle", "30 deg", "--vy",
                          "-1.2 m/s", "--json")  # fmt: skip
    impact.write_text(out)
    code, _, err = _cli(monkeypatch, capsys, "drop", "--from", str(impact))
    assert code != 0 and "not a drop" in err and "impactlab simulate --from" in err


def test_cli_drop_stop(tmp_path, monkeypatch, capsys) -> None:
    """``--stop flight`` follows the other end's impacts as ``simulate_drop(stop="flight")``
    does, is recorded, and changes a recorded drop under ``--from``; a bad value is one line."""
    base = ["drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2", "--rigid", "--json"]
    code, seq, err = _cli(monkeypatch, capsys, *base)
    assert code == 0, err
    code, flight, err = _cli(monkeypatch, capsys, *base, "--stop", "flight")
    assert code == 0, err
    api = simulate_drop(PAPER_ROD, mu=0.2, angle=math.radians(20), velocity=(0, -1.41),
                        stop="flight", history=False)  # fmt: skip
    assert json.loads(flight)["n_contacts"] == api.n_contacts > json.loads(seq)["n_contacts"]
    saved = tmp_path / "drop.json"
    saved.write_text(seq)
    code, again, err = _cli(monkeypatch, capsys, "drop", "--from", str(saved), "--stop", "flight",
                            "--json")  # fmt: skip
    assert code == 0, err
    assert json.loads(again)["n_contacts"] == api.n_contacts
    code, _, err = _cli(monkeypatch, capsys, *base, "--stop", "landing")
    assert code != 0 and "stop must be one of" in err and len(err.strip().splitlines()) == 1


def test_a_rate_law_of_ones_own_constants_travels_with_the_record(monkeypatch, capsys) -> None:
    """A ``RateLaw.custom`` is recorded with its constants (the library law by its name), shown
    with them, and runs again to the same numbers (it ran with the library's constants)."""
    from impactlab.contact.rate import RateLaw

    own = RateLaw.custom("cowper-symonds", D=6500.0, q=4.0)
    kw = {"law": "ghaednia", "mu": 0.2, "angle": "20 deg", "velocity": (0.0, -1.41)}
    r = simulate_drop(FLEX, il.AISI_1010, rate=own, **kw)
    library = simulate_drop(FLEX, il.AISI_1010, rate="cowper-symonds", **kw)
    assert r.rate == "cowper-symonds (D = 6500 1/s, q = 4)" and library.rate == "cowper-symonds"
    assert r.rate_factor != library.rate_factor
    d = json.loads(json.dumps(r.to_dict()))
    rec = d["input"]
    assert shape_problems(rec) == [] and library.to_dict()["input"]["rate"] == "cowper-symonds"
    assert rec["rate"]["form"] == "cowper-symonds"
    assert rec["rate"]["parameters"] == {"D": {"value": 6500.0, "unit": "1/s"},
                                         "q": {"value": 4.0, "unit": "1"}}  # fmt: skip
    again = il.rerun(d)
    _same(again, r)
    assert again.rate_factor == r.rate_factor and again.rate == r.rate
    rec["rate"]["parameters"]["D"] = {"value": 6.5, "unit": "1/ms"}  # edited by hand
    assert il.rerun(d).rate_factor == r.rate_factor
    rec["rate"] = {"form": "cowper-symonds"}
    with pytest.raises(ValueError, match="is not a rate law: expected 'form' and 'parameters'"):
        il.rerun(d)
