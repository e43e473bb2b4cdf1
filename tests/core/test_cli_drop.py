"""``impactlab drop``: the flexible (or rigid) drop from the command line, its output and its
one-line errors."""

from __future__ import annotations

import json
import math
import sys

import pytest

from impactlab._display import format_number
from impactlab._json import shape_problems
from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod
from impactlab.cli import main
from impactlab.dynamics.drop import simulate_drop

PAPER_20 = ("--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2")


def _cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    monkeypatch.setattr(sys, "argv", ["impactlab", "drop", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out = capsys.readouterr()
    return code, out.out, out.err


def test_flexible_json_equals_the_library(monkeypatch, capsys):
    code, out, err = _cli(monkeypatch, capsys, *PAPER_20, "--json")
    assert code == 0, err
    data = json.loads(out)
    assert shape_problems(data) == []  # docs/json-schema.md
    ref = simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))
    assert data["e"] == {"value": ref.e, "unit": "1"}
    assert data["dent_depth"] == {"value": ref.dent_depth, "unit": "m"}
    assert "delta_p" not in data and "duration" not in data  # a drop's totals: names of their own
    assert data["n_contacts"] == ref.n_contacts > 1
    assert len(data["contacts"]) == ref.n_contacts
    assert data["contacts"][0]["duration"]["unit"] == "s"
    assert data["rate"] is None


def test_table_lists_every_contact_and_the_totals(monkeypatch, capsys):
    code, out, _err = _cli(monkeypatch, capsys, *PAPER_20)
    assert code == 0
    lines = out.splitlines()
    i = lines.index("contacts")
    assert lines[i + 1].split()[:3] == ["#", "end", "start"]
    ref = simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))
    for k in range(1, ref.n_contacts + 1):
        assert lines[i + 1 + k].split()[0] == str(k)
    for name in ("scar_length", "dent_depth", "sequence_duration", "vibration_energy", "e"):
        assert name in out
    assert f"{format_number(ref.dent_depth * 1e6)} │ um" in out


def test_rigid_and_options(monkeypatch, capsys):
    code, out, err = _cli(monkeypatch, capsys, *PAPER_20, "--rigid", "--json")
    assert code == 0, err
    data = json.loads(out)
    ref = simulate_drop(PAPER_ROD, mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))
    assert data["n_contacts"] == 1 and data["n_modes"] == 0
    assert data["e"]["value"] == ref.e
    code, out, err = _cli(
        monkeypatch,
        capsys,
        *PAPER_20,
        "--modes-axial",
        "4",
        "--modes-bending",
        "6",
        "--damping",
        "0.01",
        "--rate",
        "johnson-cook",
        "--vx",
        "0.1 m/s",
        "--json",
    )
    assert code == 0, err
    data = json.loads(out)
    assert data["n_modes"] == 4 + 2 + 6
    assert "zeta = 0.01" in data["body"]
    assert data["rate"] == "johnson-cook" and data["rate_factor"]["value"] > 1.0
    assert data["velocity_in"] == {"value": [0.1, -1.41], "unit": "m/s"}


def test_rigid_rod_takes_its_inertia(monkeypatch, capsys, tmp_path):
    """``drop --rigid --inertia``: the rigid rod of ``simulate rod --inertia``; its JSON drops
    it again with ``--from``."""
    args = (*PAPER_20, "--rigid", "--inertia", "0.004 kg*m^2", "--json")
    code, out, err = _cli(monkeypatch, capsys, *args)
    assert code == 0, err
    body = Rod(length=PAPER_ROD.length, tip_radius=PAPER_ROD.tip_radius, mass=PAPER_ROD.mass,
               material=PAPER_ROD.material, inertia=0.004)  # fmt: skip
    ref = simulate_drop(body, mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))
    assert json.loads(out)["e"]["value"] == ref.e
    assert ref.e != simulate_drop(PAPER_ROD, mu=0.2, angle=math.radians(20),
                                  velocity=(0.0, -1.41)).e  # fmt: skip
    record = tmp_path / "drop.json"
    record.write_text(out)
    code, again, err = _cli(monkeypatch, capsys, "--from", str(record), "--json")
    assert code == 0, err
    assert json.loads(again)["e"] == json.loads(out)["e"]


def test_friction_model_is_chosen(monkeypatch, capsys):
    code, out, err = _cli(
        monkeypatch, capsys, *PAPER_20, "--rigid", "--friction", "mindlin", "--json"
    )
    assert code == 0, err
    data = json.loads(out)
    ref = simulate_drop(
        PAPER_ROD, friction="mindlin", mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41)
    )
    assert data["friction"] == "mindlin"
    assert data["e"]["value"] == ref.e


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        ((*PAPER_20, "--friction", "glue"), "glue"),
        (("--vy", "-1.41 m/s"), "--angle is required"),
        (("--angle", "20 deg"), "--vy is required"),
        (("--angle", "20", "--vy", "-1.41"), "has no unit"),
        ((*PAPER_20, "--rate", "fast"), "--rate must be one of"),
        ((*PAPER_20, "--rigid", "--damping", "0.1"), "a rigid rod has no modes"),
        ((*PAPER_20, "--damping", "1.5"), "--damping must lie in [0.0, 1.0), got 1.5"),
        ((*PAPER_20, "--modes-bending", "-1"), "--modes-bending must be an integer >= 0"),
        ((*PAPER_20, "--law", "nope"), "nope"),
        (("--angle", "20 deg", "--vy", "1.41 m/s"), "does not approach"),
        (("--angle", "20 deg", "--vy", "-1.41 kg"), "--vy"),
        ((*PAPER_20, "--inertia", "0.004 kg*m^2"), "--inertia: the flexible rod's inertia"),
        ((*PAPER_20, "--rigid", "--inertia", "0"), "--inertia must be > 0"),
        ((*PAPER_20, "--rigid", "--inertia", "0.4 kg*m^2"), "--inertia = 0.4 kg m^2 exceeds m"),
    ],
)
def test_errors_are_one_line(monkeypatch, capsys, args, needle):
    code, _out, err = _cli(monkeypatch, capsys, *args)
    assert code == 2
    assert needle in err
    assert err.startswith("error: ") and len(err.strip().splitlines()) == 1


def test_help_has_examples(monkeypatch, capsys):
    code, out, _err = _cli(monkeypatch, capsys, "--help")
    assert code == 0
    assert 'impactlab drop --angle "20 deg"' in out and "--rigid" in out


def test_drop_takes_a_tolerance_and_says_whether_it_is_ok(cli_main, tmp_path) -> None:
    """``--rtol`` runs the drop at another tolerance (to check its convergence), also on top of
    ``--from``; the JSON says ``ok`` as the result does."""
    import json

    code, out, _ = cli_main("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2",
                            "--rtol", "1e-9", "--json")  # fmt: skip
    d = json.loads(out)
    assert code == 0 and d["input"]["rtol"] == {"value": 1e-9, "unit": "1"} and d["ok"] is True
    rec = tmp_path / "d.json"
    rec.write_text(out)
    code, out, _ = cli_main("drop", "--from", str(rec), "--rtol", "1e-8", "--json")
    assert code == 0 and json.loads(out)["input"]["rtol"]["value"] == 1e-8
    code, _, err = cli_main("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--rtol", "0.1")
    assert (
        code == 2
        and "rtol must lie in [1e-13, 1e-05] for a drop (the drop's default is 1e-07), got 0.1"
        in err
    )


def test_partial_slip_tolerance_is_capped(monkeypatch, capsys):
    """A loose rtol with partial slip (8 contacts and a 9 % energy error at 1e-3) is refused
    as the rigid engine refuses it, naming the option."""
    args = (*PAPER_20, "--friction", "partial_slip", "--rtol", "1e-3")
    code, _out, err = _cli(monkeypatch, capsys, *args)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith("error: --rtol 0.001 is too loose for friction 'partial_slip'")
    assert "up to 1e-05" in err


def test_an_implausible_speed_warns(monkeypatch, capsys):
    code, _out, err = _cli(monkeypatch, capsys, "--angle", "20 deg", "--vy", "-120 m/s")
    assert "warning: the impact speed (120 m/s) exceeds 100 m/s" in err
    assert code in (0, 2)  # the warning, whatever the drop then does


#: Drops whose JSON is walked: flexible, rigid, the whole flight, a rate-dependent flat.
_DROPS = (
    PAPER_20,
    ("--angle", "70 deg", "--vy", "-3.45 m/s", "--mu", "0.1", "--rigid"),
    (*PAPER_20, "--stop", "flight"),
    ("--angle", "45 deg", "--vy", "-2.18 m/s", "--mu", "0.13", "--rate", "johnson-cook"),
)


def _not_quantities(data, units, path=""):
    """(path, value) of every value under a key with a unit that is no quantity object (an
    integer count or code aside), and of every null outside one."""
    found = []
    items = data.items() if isinstance(data, dict) else enumerate(data)
    for k, v in items:
        where = f"{path}.{k}"
        if isinstance(v, dict) and set(v) >= {"value", "unit"}:
            continue
        if isinstance(v, dict | list):
            found += _not_quantities(v, units, where)
        elif v is None or (k in units and not isinstance(v, int)):
            found.append((where, v))
    return found


@pytest.mark.parametrize("args", _DROPS)
def test_every_drop_quantity_is_an_object(monkeypatch, capsys, args):
    """docs/json-schema.md: every quantity is an object whose value is null when it does not
    exist (next_time of a rod that flies off, strain_rate without a rate law); bare nulls
    are names that are unset (rate, law_range) only. The recorded input is the record's."""
    from impactlab.cli._common import SI_UNITS
    from impactlab.dynamics.drop_result import UNITS

    code, out, err = _cli(monkeypatch, capsys, *args, "--json")
    assert code == 0, err
    data = json.loads(out)
    assert shape_problems(data) == []
    assert data["next_time"]["unit"] == "s" and data["strain_rate"]["unit"] == "1/s"
    rest = {k: v for k, v in data.items() if k != "input"}
    bare = _not_quantities(rest, {**SI_UNITS, **UNITS})
    assert {p for p, _v in bare} <= {".rate", ".law_range", ".fitted_range_status"}, bare
    if "--rate" not in args:
        assert data["strain_rate"] == {"value": None, "unit": "1/s"} and data["rate"] is None
    if "--rigid" in args or "flight" in args:  # nothing lands next
        assert data["next_time"] == {"value": None, "unit": "s"} and data["next_end"] == -1


def test_time_limit_is_an_option_and_its_error_names_it(monkeypatch, capsys, tmp_path):
    """``--time-limit`` with its unit (recorded in the JSON input; on top of ``--from``); the error
    of a drop that runs out of time says to raise ``--time-limit``."""
    code, _out, err = _cli(monkeypatch, capsys, *PAPER_20, "--time-limit", "0.01 ms")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "time_limit reached" in err and err.strip().endswith("raise --time-limit")
    code, out, err = _cli(monkeypatch, capsys, *PAPER_20, "--time-limit", "2 s", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert data["input"]["time_limit"] == {"value": 2.0, "unit": "s"}
    ref = simulate_drop(FlexibleRod.paper(), mu=0.2, angle=math.radians(20), velocity=(0.0, -1.41))
    assert data["e"]["value"] == ref.e  # the sequence ends long before either time_limit
    record = tmp_path / "drop.json"
    record.write_text(out)
    code, out, err = _cli(
        monkeypatch, capsys, "--from", str(record), "--time-limit", "1 s", "--json"
    )
    assert code == 0, err
    assert json.loads(out)["input"]["time_limit"] == {"value": 1.0, "unit": "s"}
    code, _out, err = _cli(monkeypatch, capsys, "--from", str(record), "--time-limit", "10 us")
    assert code == 2 and err.startswith(f"error: --from {str(record)!r}: drop: time_limit reached")
    assert err.strip().endswith("raise --time-limit")
    code, _out, err = _cli(monkeypatch, capsys, *PAPER_20, "--time-limit", "0 s")
    assert code == 2 and "--time-limit must be > 0" in err
