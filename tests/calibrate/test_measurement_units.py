"""The measurements file's units and the drops it refuses: each input in its own unit (a Brinell
hardness in kgf/mm^2, or HB), an uncertainty in its quantity's unit, implausible magnitudes, the
velocity given once, a rod's and a sphere's own inputs, columns given twice and NaN."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from impactlab.calibrate import CandidateModel, Measurements, parse_parameter, predict
from impactlab.calibrate import read_measurements as read

HEAD = "label,angle [deg],vy [m/s],mu,e,e_sigma"
ROW = "a,20,-1.41,0.2,0.45,0.02"


def _csv(tmp_path, header: str, row: str, name: str = "m.csv"):
    path = tmp_path / name
    path.write_text(f"{HEAD},{header}\n{ROW},{row}\n" if header else f"{HEAD}\n{ROW}\n")
    return path


def _one(**kw):
    rec = {"label": "a", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.45, "e_sigma": 0.02}
    rec.update(kw)
    return Measurements.from_records([{k: v for k, v in rec.items() if v is not None}])


def test_a_brinell_hardness_is_read_in_its_own_unit(tmp_path):
    """HB 105 is 105 kgf/mm^2 (the sweep's unit), as in a study file: not 1.03e9."""
    plain = read(_csv(tmp_path, "flat_brinell_hardness", "105", "a.csv"))
    unit = read(_csv(tmp_path, "flat_brinell_hardness [kgf/mm^2]", "105", "b.csv"))
    text = _one(flat_brinell_hardness="1029.7 MPa")
    assert plain.inputs["flat_brinell_hardness"][0] == 105.0
    assert unit.inputs["flat_brinell_hardness"][0] == 105.0
    assert text.inputs["flat_brinell_hardness"][0] == pytest.approx(105.0, rel=1e-4)
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    e = [predict(CandidateModel("brake"), m, [mu], np.array([[0.2]])).values["e"][0, 0]
         for m in (plain, _one())]  # fmt: skip
    assert e[0] == pytest.approx(e[1], rel=1e-3)  # AISI 1010's own HB is 105
    back = read(plain.to_csv(tmp_path / "back.csv"))
    assert back.inputs["flat_brinell_hardness"][0] == 105.0


def test_hb_is_the_unit_of_a_brinell_hardness(tmp_path):
    """HB and HBW (a Brinell number: kgf/mm^2) in a header, a value, the [units] table."""
    header = read(_csv(tmp_path, "flat_brinell_hardness [HB]", "105", "a.csv"))
    value = read(_csv(tmp_path, "flat_brinell_hardness", "105 HB", "b.csv"))
    toml = tmp_path / "c.toml"
    toml.write_text('[units]\nflat_brinell_hardness = "HBW"\n[[drop]]\nangle = "20 deg"\n'
                    'vy = -1.41\nmu = 0.2\nflat_brinell_hardness = 105\ne = 0.45\n'
                    'e_sigma = 0.02\n')  # fmt: skip
    for m in (header, value, read(toml), _one(flat_brinell_hardness="HBW 105")):
        assert m.inputs["flat_brinell_hardness"][0] == 105.0
    with pytest.raises(ValueError, match=r"flat_yield_strength: '300 HB' is a Brinell hardness "
                       r"\(HB\), not a quantity of Pa"):  # fmt: skip
        _one(flat_yield_strength="300 HB")


def test_implausible_input_magnitudes_are_refused(tmp_path):
    """A unit left out of a drop's input: a yield strength of 300 Pa, a tip radius of 4 m."""
    for header, row, match in (
        ("flat_yield_strength", "300",
         r"drop 1 \(a\), column 'flat_yield_strength': flat_yield_strength = 300 Pa is below "
         r"10000 Pa: an implausible magnitude .*give its unit, e.g. '300 MPa'"),
        ("tip_radius", "4", r"tip_radius = 4 m is above 1 m: .* e.g. '4 mm'"),
        ("flat_brinell_hardness", "1.03e9",
         r"flat_brinell_hardness = 1.03e\+09 kgf/mm\^2 is above"),
    ):  # fmt: skip
        with pytest.raises(ValueError, match=match):
            read(_csv(tmp_path, header, row))
    assert read(_csv(tmp_path, "flat_yield_strength [MPa]", "300")).inputs[
        "flat_yield_strength"][0] == 3e8  # fmt: skip


def test_a_brinell_prior_is_in_kgf_per_mm2():
    p = parse_parameter("flat_brinell_hardness", "uniform(50, 200)")
    assert (p.low, p.high) == (50.0, 200.0)
    assert p.describe() == "uniform(50 kgf/mm^2, 200 kgf/mm^2)"
    q = parse_parameter("flat_brinell_hardness", "uniform(50 kgf/mm^2, 1 GPa)")
    assert q.high == pytest.approx(1e9 / 9.80665e6)


def test_an_uncertainty_without_a_unit_takes_its_quantitys(tmp_path):
    m = read(_csv(tmp_path, "delta_p [um],delta_p_sigma", "64,2"))
    assert m.sigma["delta_p"][0] == pytest.approx(2e-6)
    own = read(_csv(tmp_path, "delta_p [um],delta_p_sigma [nm]", "64,200", "own.csv"))
    assert own.sigma["delta_p"][0] == pytest.approx(2e-7)
    with pytest.raises(ValueError, match=r"delta_p_sigma = 2 has no unit while delta_p = '64 um' "
                       r"has one: give the uncertainty's unit too \(e.g. '2 um'\)"):  # fmt: skip
        _one(delta_p="64 um", delta_p_sigma=2)


def test_a_value_in_another_unit_than_its_column_needs_its_uncertaintys(tmp_path):
    """``0.11 mm`` in a ``delta_p [um]`` column with a bare 0.003: read as 0.003 um, 1000
    times too small (the drop then weighed a million times its due)."""
    with pytest.raises(ValueError, match=r"delta_p_sigma = '0.003' has no unit while delta_p = "
                       r"'0.11 mm' has one \(a bare number is read in um\)"):  # fmt: skip
        read(_csv(tmp_path, "delta_p [um],delta_p_sigma", "0.11 mm,0.003"))
    same = read(_csv(tmp_path, "delta_p [um],delta_p_sigma", "110 um,3", "same.csv"))
    assert same.sigma["delta_p"][0] == pytest.approx(3e-6)
    given = read(_csv(tmp_path, "delta_p [um],delta_p_sigma", "0.11 mm,0.003 mm", "given.csv"))
    assert given.sigma["delta_p"][0] == pytest.approx(3e-6)


@pytest.mark.parametrize(
    ("header", "row", "match"),
    [
        ("scar_length,scar_length_sigma", "1400,140",
         r"scar_length = 1400 m exceeds what an impact gives \(0.1 m\): an implausible "
         r"magnitude; give its unit"),
        ("duration,duration_sigma", "50,5", r"duration = 50 s exceeds .* implausible magnitude"),
        ("scar_length [um],scar_length_sigma [m]", "1400,0.5",
         r"scar_length_sigma = 0.5 m exceeds 0.1 m: an implausible magnitude"),
        ("delta_p [um],delta_p_sigma [m]", "60,0.05",
         r"delta_p_sigma = 0.05 m exceeds 0.0088 m: an implausible magnitude"),
        ("", "", None),
    ],
)  # fmt: skip
def test_implausible_magnitudes_are_refused(tmp_path, header, row, match):
    if match is None:  # e_sigma wider than e's whole range
        with pytest.raises(ValueError, match=r"e_sigma = 5 is wider than the whole range of e"):
            _one(e_sigma=5)
        return
    with pytest.raises(ValueError, match=match) as info:
        read(_csv(tmp_path, header, row))
    assert "\n" not in str(info.value)


def test_paper_scale_lengths_and_durations_are_accepted():
    m = _one(scar_length="1400 um", scar_length_sigma="140 um", duration="0.12 ms",
             duration_sigma="0.01 ms")  # fmt: skip
    assert m.observed["scar_length"][0] == pytest.approx(1.4e-3)


def test_speed_and_incidence_give_the_velocity_once():
    m = _one(vy=None, speed="2 m/s", incidence="30 deg")
    assert m.inputs["vx"][0] == pytest.approx(1.0)
    assert m.inputs["vy"][0] == pytest.approx(-2 * math.cos(math.radians(30)))
    for extra, match in (
        ({"speed": "5 m/s"}, "vy and speed both given: they say the same thing"),
        ({"incidence": "40 deg"}, "vy and incidence both given"),
        ({"vy": None, "speed": "5 m/s"}, "speed and incidence go together: incidence has no"),
    ):
        with pytest.raises(ValueError, match=match):
            _one(**extra)


def test_a_rod_and_a_sphere_take_their_own_inputs():
    rod = r"radius is the radius of a sphere, and this drop's body is a rod; a rod's tip radius"
    with pytest.raises(ValueError, match=rod + r" is the column 'tip_radius'"):
        _one(body="rod", radius="5 mm")
    sphere = {"body": "sphere", "angle": None, "vx": 1.0}
    with pytest.raises(ValueError, match=r"a sphere needs its radius \(column 'radius'\)"):
        _one(**sphere)
    with pytest.raises(ValueError, match=r"angle: a sphere has no angle, length, tip radius"):
        _one(**{**sphere, "angle": "20 deg", "radius": "5 mm"})
    ok = _one(**sphere, radius="5 mm")
    assert ok.inputs["angle"][0] == pytest.approx(math.pi / 2)


def test_a_sphere_is_written_and_read_back(tmp_path):
    m = _one(body="sphere", angle=None, radius="5 mm", vx=1.0)
    back = read(m.to_csv(tmp_path / "s.csv"))
    assert back.inputs["radius"][0] == pytest.approx(5e-3)


def test_a_column_given_twice_is_refused(tmp_path):
    path = tmp_path / "d.csv"
    path.write_text(f"{HEAD},e_sigma\n{ROW},0.5\n")
    with pytest.raises(ValueError, match=r"line 1: the header names the column\(s\) "
                       r"\['e_sigma'\] twice"):  # fmt: skip
        read(path)
    with pytest.raises(ValueError, match=r"duration is given twice \(columns 'T' and 'duration'"):
        _one(T="0.1 ms", T_sigma="0.01 ms", duration="0.1 ms")


def test_nan_is_named(tmp_path):
    path = tmp_path / "n.toml"
    path.write_text('[[drop]]\nangle = "20 deg"\nvy = -1.41\nmu = 0.2\ne = nan\ne_sigma = 0.02\n')
    with pytest.raises(ValueError, match=r"drop 1: e = nan is not a number; leave the key out"):
        read(path)
    with pytest.raises(ValueError, match=r"e is NaN \(not a number\) while e_sigma is given"):
        _one(e=math.nan)
    with pytest.raises(ValueError, match=r"e_sigma is NaN \(not a number\): give the standard "):
        _one(e_sigma=math.nan)


def test_a_directory_is_not_a_measurements_file(tmp_path):
    with pytest.raises(IsADirectoryError, match="is a directory; give the file"):
        read(tmp_path)


def test_a_drop_copied_under_another_label_warns(tmp_path):
    """Three copies of one drop were calibrated as three measurements, the intervals narrowed
    by sqrt(3), without a word; analyze --measurements refuses such an append."""
    from impactlab.calibrate import CalibrationWarning

    path = tmp_path / "copies.csv"
    path.write_text(f"{HEAD}\n{ROW}\n" + f"{ROW}\n".replace("a,", "b,", 1))
    with pytest.warns(CalibrationWarning, match=r"'b' holds the values of 'a'.*counts twice"):
        m = read(path)
    assert m.n_drops == 2
    other = tmp_path / "other.csv"
    other.write_text(f"{HEAD}\n{ROW}\n" + f"{ROW}\n".replace("a,", "b,", 1).replace("0.45", "0.46"))
    with warnings.catch_warnings():
        warnings.simplefilter("error", CalibrationWarning)
        read(other)


def test_an_uncertainty_column_with_its_own_unit_is_read_in_it(tmp_path):
    """``delta_p_sigma [um]`` beside ``0.022 mm`` was refused, with a hint 1000 times off."""
    m = read(_csv(tmp_path, "delta_p [um],delta_p_sigma [um]", "0.022 mm,2.2"))
    assert m.observed["delta_p"][0] == pytest.approx(22e-6)
    assert m.sigma["delta_p"][0] == pytest.approx(2.2e-6)
