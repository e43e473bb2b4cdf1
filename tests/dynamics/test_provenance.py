"""Every result records what was simulated (bodies, materials, flat, law and its parameters,
friction, tolerances, the impactlab version) and can be run again from that record, in
Python (``impactlab.rerun``) and on the command line (``impactlab simulate --from``)."""

from __future__ import annotations

import json
import math
import sys
import warnings

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import impactlab as il
from impactlab._json import shape_problems
from impactlab.cli import main
from impactlab.dynamics.provenance import decode, encode, from_record
from impactlab.materials import AISI_1010, Material

ALU = Material("6061-T6 (test values)", 68.9e9, 0.33, 276e6, density=2700.0)


def _round_trip(result: il.ImpactResult) -> il.ImpactResult:
    """The result simulated again from its to_dict() after a trip through JSON text."""
    return il.rerun(json.loads(json.dumps(result.to_dict())))


def test_rod_record_names_everything_and_reruns_bit_for_bit() -> None:
    r = il.simulate(il.Rod.paper(), angle=math.radians(20), velocity=(0.1, -1.41), mu=0.2)
    rec = r.to_dict()["input"]
    assert rec["impactlab_version"] == il.__version__ == r.to_dict()["impactlab_version"]
    assert rec["body"]["type"] == "Rod" and rec["body"]["mass"] == {"value": 0.4607, "unit": "kg"}
    assert rec["body"]["material"]["yield_strength"] == {"value": 760e6, "unit": "Pa"}
    assert rec["flat"]["name"] == AISI_1010.name
    assert rec["rtol"]["value"] == il.dynamics.DEFAULT_RTOL and rec["gravity"]["value"] == 9.80665
    assert shape_problems(json.loads(json.dumps(rec))) == []  # floats only as quantities
    again = _round_trip(r)
    for name in ("e", "delta_p", "sliding_length", "duration", "velocity_out"):
        assert getattr(again, name) == getattr(r, name)


def test_sphere_on_a_custom_flat_with_law_parameters() -> None:
    s = il.Sphere(radius=0.003, material=il.AISI_201)
    r = il.simulate(
        s, ALU, law="thornton", law_params={"limit_pressure_ratio": 2.0}, gravity="9.81 m/s^2",
        velocity=(0.0, -1.0), mu=0.0, rtol=1e-9,
    )  # fmt: skip
    rec = r.input
    assert rec is not None and rec["angle"] is None
    assert rec["flat"]["E"] == {"value": 68.9e9, "unit": "Pa"}
    assert rec["flat"]["brinell_hardness"]["nonfinite"] == "nan"  # unset, not lost
    assert rec["law_params"] == {"limit_pressure_ratio": {"value": 2.0, "unit": "1"}}
    assert rec["gravity"]["value"] == pytest.approx(9.81) and rec["rtol"]["value"] == 1e-9
    again = _round_trip(r)
    assert (again.e, again.delta_p, again.duration) == (r.e, r.delta_p, r.duration)


def test_rerun_with_changes() -> None:
    r = il.simulate(il.Rod.paper(), angle=0.5, velocity=(0.0, -1.0), mu=0.1)
    other = il.rerun(r.to_dict(), mu=0.3)
    assert other.mu == 0.3 and other.input["mu"]["value"] == 0.3
    assert other.input["body"] == r.input["body"]


def test_a_record_that_is_not_one_is_named() -> None:
    with pytest.raises(ValueError, match=r"lacks \['body', 'flat', 'law', 'velocity'\]"):
        from_record({"e": 0.4})
    with pytest.raises(ValueError, match="unknown type 'Brick'"):
        decode({"type": "Brick", "size": 1})


_positive = st.floats(1e-3, 1e3, allow_nan=False)


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")  # drawn on purpose
@settings(deadline=None, max_examples=60, suppress_health_check=[HealthCheck.too_slow])
@given(
    E=st.floats(1e9, 1e12),
    nu=st.floats(-0.9, 0.49),
    ratio=st.floats(1e-5, 0.5),
    hb=st.one_of(st.just(math.nan), _positive),
    n=st.floats(2.01, 3.0),
    rho=st.floats(1e-2, 1e3, allow_nan=False),  # a density below 5e-3 kg/m^3 is refused
)
def test_material_encodes_and_decodes_exactly(E, nu, ratio, hb, n, rho) -> None:
    m = Material("m", E, nu, E * ratio, hb, n, rho)
    back = decode(json.loads(json.dumps(encode(m))))
    assert back.name == m.name and back.E == m.E and back.nu == m.nu
    assert back.yield_strength == m.yield_strength and back.density == m.density
    assert back.meyer_index == m.meyer_index
    assert (math.isnan(back.brinell_hardness) and math.isnan(hb)) or back.brinell_hardness == hb


def test_to_pint_gives_quantities_in_si() -> None:
    r = il.simulate(il.Rod.paper(), angle=0.5, velocity=(0.0, -1.0), mu=0.1)
    q = r.to_pint()
    assert q["delta_p"].to("um").magnitude == pytest.approx(r.delta_p * 1e6, rel=1e-12)
    assert q["duration"].to("ms").magnitude == pytest.approx(r.duration * 1e3, rel=1e-12)
    assert list(q["velocity_out"].to("m/s").magnitude) == list(r.velocity_out)
    assert q["e"].dimensionless


def _cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    """``impactlab ARGS`` in this process: (exit status, stdout, stderr)."""
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out, err = capsys.readouterr()
    return code, out, err


def test_cli_json_then_from_reruns_the_same_impact(tmp_path, monkeypatch, capsys) -> None:
    args = ["simulate", "sphere", "--radius", "3 mm", "--vy", "-2.5 m/s", "--mu", "0.1"]
    code, out, err = _cli(monkeypatch, capsys, *args, "--json")
    assert code == 0, err
    saved = tmp_path / "s.json"
    saved.write_text(out)
    data = json.loads(out)
    assert data["input"]["body"]["type"] == "Sphere" and data["impactlab_version"]
    code, out, err = _cli(monkeypatch, capsys, "simulate", "--from", str(saved), "--json")
    assert code == 0, err
    assert json.loads(out)["e"] == data["e"]
    code, out, _ = _cli(monkeypatch, capsys, "simulate", "--from", str(saved))
    assert "Sphere: radius = 3 mm" in out and "AISI 1010" in out  # the body and the flat
    code, _, err = _cli(monkeypatch, capsys, "simulate", "--from", str(saved), "--radius", "1 mm")
    assert code != 0 and "--radius: --from simulates the recorded body" in err
    code, _, err = _cli(monkeypatch, capsys, "simulate", "--from", str(tmp_path / "no.json"))
    assert code != 0 and "cannot read" in err


def test_a_sphere_given_its_density_reruns_with_the_same_mass() -> None:
    s = il.Sphere(radius=0.004, density=2700.0)
    r = il.simulate(s, velocity=(0.0, -1.0))
    again = _round_trip(r)
    assert again.input["body"]["mass"] == r.input["body"]["mass"]
    assert (again.e, again.delta_p) == (r.e, r.delta_p)


def test_batch_to_pint() -> None:
    b = il.simulate_batch(il.Rod.paper(), angle=[0.3, 0.5], vy=-1.0, mu=0.1)
    q = b.to_pint()
    assert list(q["delta_p"].to("um").magnitude) == pytest.approx(list(b.delta_p * 1e6))
    assert str(q["duration"].units) == "second"


def test_a_built_contact_model_is_recorded_and_reruns() -> None:
    rod = il.Rod.paper()
    model = il.dynamics.contact_model(rod, AISI_1010, "hertz")  # params hold inf (no yield)
    r = il.simulate(rod, law=model, angle=0.4, velocity=(0.0, -1.0), mu=0.1)
    rec = json.loads(json.dumps(r.to_dict()))["input"]
    assert rec["law"]["type"] == "ContactModel" and rec["law"]["name"] == "hertz"
    again = il.rerun(rec)
    assert (again.e, again.delta_max) == (r.e, r.delta_max)


def test_a_contact_models_mixed_unit_params_are_written_as_si() -> None:
    """The compiled parameters hold pascals, metres and newtons: the record said unit "1"
    (dimensionless). It says "SI" now, and a record that says "1" reads back the same."""
    rod = il.PAPER_ROD
    model = il.dynamics.contact_model(rod, AISI_1010, "ghaednia")
    r = il.simulate(rod, law=model, angle=0.4, velocity=(0.0, -1.0), mu=0.1)
    rec = json.loads(json.dumps(r.to_dict()))["input"]
    assert rec["law"]["params"]["unit"] == "SI"
    assert {q["unit"] for q in rec["law"]["details"].values()} == {"SI"}
    older = json.loads(json.dumps(rec))
    older["law"]["params"]["unit"] = "1"
    assert il.rerun(older).e == il.rerun(rec).e == r.e


def test_a_record_edited_in_other_units_reruns_in_si() -> None:
    """A quantity object is read in the unit it names (a record edited by hand), converted to
    the unit written for its key; a unit of another dimension, or none pint knows, is refused
    with the key named."""
    s = il.Sphere(radius=0.005, material=il.AISI_201)
    r = il.simulate(s, ALU, law="thornton", law_params={"limit_pressure_ratio": 2.0},
                    velocity=(0.3, -1.0), mu=0.2, history=False)  # fmt: skip
    rec = json.loads(json.dumps(r.to_dict()))
    rec["input"]["body"]["radius"] = {"value": 5, "unit": "mm"}
    rec["input"]["velocity"] = {"value": [300, -1000], "unit": "mm/s"}
    rec["input"]["angle"] = None
    rec["input"]["flat"]["E"] = {"value": 68.9, "unit": "GPa"}
    again = il.rerun(rec)
    assert again.input["body"]["radius"]["value"] == pytest.approx(0.005, rel=1e-15)
    assert again.velocity_in == pytest.approx((0.3, -1.0), rel=1e-15)
    assert again.e == pytest.approx(r.e, rel=1e-12)
    for field, bad, needle in (
        ("radius", {"value": 5, "unit": "m/s"}, "'radius': the unit 'm/s' is not a unit of m"),
        ("radius", {"value": 5, "unit": "furlongz"}, "'radius': cannot read the unit"),
    ):
        wrong = json.loads(json.dumps(rec))
        wrong["input"]["body"][field] = bad
        with pytest.raises(ValueError, match=needle):
            il.rerun(wrong)
    rec["input"]["law_params"]["limit_pressure_ratio"] = {"value": 2.0, "unit": "m"}
    with pytest.raises(ValueError, match="'limit_pressure_ratio': the unit 'm' is not a unit of 1"):
        il.rerun(rec)


def test_a_recorded_contact_model_is_not_rerun_on_another_flat() -> None:
    """The record's ContactModel (read back without its pair) ran on a new flat: the result
    named aluminium held the steel dent (e 0.42273 against 0.43593)."""
    from impactlab.materials import AISI_201, ContactPair

    model = il.get_law("ghaednia").build(ContactPair(AISI_201, il.AISI_1010), 8.8e-3)
    rec = il.simulate(il.PAPER_ROD, law=model, angle=0.4, velocity=(0, -1.2), mu=0.2).to_dict()
    al = il.get_material("al-6061-t6")
    with pytest.raises(
        ValueError, match=r"flat: the record's law is a ContactModel.*law='ghaednia'"
    ):
        il.rerun(rec, flat=al)
    fresh = il.simulate(il.PAPER_ROD, flat=al, angle=0.4, velocity=(0, -1.2), mu=0.2)
    assert il.rerun(rec, flat=al, law="ghaednia").e == fresh.e
    assert il.rerun(rec, flat=il.AISI_1010).e == il.rerun(rec).e  # the recorded flat: runs


def test_a_record_of_other_code_of_the_same_version_reruns_with_a_warning() -> None:
    """The version alone did not move with the physics: a record of other code reran silently."""
    from impactlab._code_identity import results_code_hash
    from impactlab.dynamics.provenance import RecordVersionWarning

    rec = json.loads(json.dumps(il.simulate(il.PAPER_ROD, angle=0.4, velocity=(0, -1.2)).to_dict()))
    assert rec["input"]["results_code_hash"] == results_code_hash()
    other = json.loads(json.dumps(rec))
    other["input"]["results_code_hash"] = "0123456789abcdef"
    with pytest.warns(RecordVersionWarning, match=r"other code of impactlab .*'0123456789abcdef'"):
        assert il.rerun(other).e == il.rerun(rec).e
    del other["input"]["results_code_hash"]  # a record from before the hash: its version's word
    with warnings.catch_warnings():
        warnings.simplefilter("error", RecordVersionWarning)
        il.rerun(other)


@pytest.mark.parametrize(
    ("key", "value", "said"),
    [
        ("velocity", {"value": [0, None], "unit": "m/s"}, "'velocity': every value of its list"),
        ("mu", {"value": None, "unit": "1", "nonfinite": "foo"}, "'mu': nonfinite must be"),
    ],
)
def test_a_tampered_quantity_names_its_key(key, value, said) -> None:
    """They raised float()'s TypeError and ValueError, naming no key."""
    rec = json.loads(json.dumps(il.simulate(il.PAPER_ROD, angle=0.4, velocity=(0, -1)).to_dict()))
    rec["input"][key] = value
    with pytest.raises(ValueError, match=f"the record's {said}"):
        il.rerun(rec)


def test_another_friction_takes_its_own_default_tolerance() -> None:
    """partial_slip rerun from a coulomb record ran at coulomb's default 2e-7, not its 3e-8."""
    kw = {"angle": 0.35, "velocity": (0.0, -1.41), "mu": 0.2}
    coulomb = il.simulate(il.PAPER_ROD, **kw)
    slip = il.simulate(il.PAPER_ROD, friction="partial_slip", **kw)
    assert il.rerun(coulomb, friction="partial_slip").e == slip.e
    assert il.rerun(slip, friction="coulomb").e == coulomb.e
    chosen = il.simulate(il.PAPER_ROD, rtol=1e-9, **kw)  # a tolerance of one's own stays
    assert il.rerun(chosen, friction="mindlin").to_dict()["input"]["rtol"]["value"] == 1e-9


def test_a_spheres_record_reads_back_as_written() -> None:
    """--from rewrote a sphere's density 7800 as 7799.999999999999 (from its mass)."""
    s = il.Sphere(radius=0.005, material=il.AISI_201)
    rec = json.loads(json.dumps(il.simulate(s, velocity=(0, -1.0)).to_dict()))
    again = il.rerun(rec).to_dict()
    assert again["input"]["body"] == rec["input"]["body"] and again["e"] == rec["e"]
    heavy = il.Sphere(radius=0.005, mass=0.01, material=il.AISI_201)  # a mass of its own
    rec = json.loads(json.dumps(il.simulate(heavy, velocity=(0, -1.0)).to_dict()))
    assert il.rerun(rec).to_dict()["input"]["body"]["mass"] == rec["input"]["body"]["mass"]
