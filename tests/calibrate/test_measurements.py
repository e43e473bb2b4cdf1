"""The measurements file: CSV and TOML, units, and one-line errors for what it cannot use."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.calibrate import Measurements, read_measurements

CSV = """# two drops of the paper's rod
label,angle [deg],vy [m/s],mu,e,e_sigma,delta_p [um],delta_p_sigma [um]
a,20,-1.41,0.2,0.31,0.02,12,1.5
b,45,-1.41,0.2,0.12,0.02,,
"""

TOML = """
[units]
delta_p = "um"
delta_p_sigma = "um"

[[drop]]
label = "a"
angle = "20 deg"
vy = "-1.41 m/s"
mu = 0.2
e = 0.31
e_sigma = 0.02
delta_p = 12
delta_p_sigma = 1.5

[[drop]]
label = "b"
angle = "45 deg"
vy = -1.41
mu = 0.2
e = 0.12
e_sigma = 0.02
"""


def _check(m: Measurements) -> None:
    assert m.labels == ("a", "b")
    assert m.quantities == ("e", "delta_p")
    np.testing.assert_allclose(m.inputs["angle"], np.radians([20, 45]))
    np.testing.assert_allclose(m.observed["delta_p"][0], 12e-6)
    np.testing.assert_allclose(m.sigma["delta_p"][0], 1.5e-6)
    assert math.isnan(m.observed["delta_p"][1])
    assert m.n_values == 3
    assert m.categories[0]["body"] == "rod"
    assert m.categories[0]["flat_material"] == "aisi-1010"


def test_csv_and_toml_read_the_same(tmp_path):
    (tmp_path / "m.csv").write_text(CSV)
    (tmp_path / "m.toml").write_text(TOML)
    _check(read_measurements(tmp_path / "m.csv"))
    _check(read_measurements(tmp_path / "m.toml"))


def test_csv_round_trip(tmp_path):
    (tmp_path / "m.csv").write_text(CSV)
    m = read_measurements(tmp_path / "m.csv")
    back = read_measurements(m.to_csv(tmp_path / "out.csv"))
    _check(back)
    more = {"label": "c", "angle": "70 deg", "vy": -2, "mu": 0.1, "e": 0.05, "e_sigma": 0.01}
    both = m.extended(Measurements.from_records([more]))
    assert both.labels == ("a", "b", "c") and both.n_values == 4


def _rec(**kw):
    base = {"label": "x", "angle": "20 deg", "vy": -1.4, "mu": 0.2, "e": 0.3, "e_sigma": 0.02}
    base.update(kw)
    return [{k: v for k, v in base.items() if v is not None}]


@pytest.mark.parametrize(
    ("change", "match"),
    [
        ({"e_sigma": None}, "e = 0.3 has no standard uncertainty"),
        ({"e_sigma": 0}, "e_sigma must be finite and > 0"),
        ({"e": 1.3}, r"e = 1.3 lies outside the possible range \[0, 1.014\d*\] by more than 3"),
        ({"vy": 1.4}, "vy = 1.4 m/s must be < 0"),
        ({"vy": None}, "the drop needs 'vy'"),
        ({"law": "hertz"}, "'law' is not a property of a drop"),
        ({"colour": "red"}, "unknown column 'colour'"),
        ({"flat_material": "unobtainium"}, "unknown flat_material 'unobtainium'"),
        ({"body": "cube"}, "unknown body 'cube'"),
        ({"delta_p": "12 kg", "delta_p_sigma": "1 um"}, "wrong dimension"),
        ({"delta_p": 12, "delta_p_sigma": 1}, "exceeds the tip radius"),
        ({"spin_out_sigma": 1.0}, "spin_out_sigma is given without spin_out"),
        ({"e_t": 0.5, "e_t_sigma": 0.1}, "e_t needs a drop with vx != 0"),
    ],
)
def test_bad_rows_are_refused_with_one_line(change, match):
    with pytest.raises(ValueError, match=match) as info:
        Measurements.from_records(_rec(**change))
    assert "\n" not in str(info.value)


def test_file_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        read_measurements(tmp_path / "none.csv")
    (tmp_path / "m.txt").write_text("x")
    with pytest.raises(ValueError, match=r"must end in \.csv or \.toml"):
        read_measurements(tmp_path / "m.txt")
    (tmp_path / "e.csv").write_text("label,angle,vy\n")
    with pytest.raises(ValueError, match="no drops"):
        read_measurements(tmp_path / "e.csv")
    with pytest.raises(ValueError, match="no measured quantity"):
        Measurements.from_records([{"angle": "20 deg", "vy": -1}])
    with pytest.raises(ValueError, match="the bare number 20 has no unit"):
        Measurements.from_records(_rec(angle=20))
    with pytest.raises(ValueError, match="duplicate drop labels"):
        Measurements.from_records(_rec() + _rec())


@pytest.mark.parametrize(
    ("change", "match"),
    [
        ({"angle": "200 deg"}, r"drop 1 \(x\), column 'angle': angle must lie in \(0, 90\] deg"),
        ({"angle": "0 deg"}, r"column 'angle': angle must lie in \(0, 90\] deg, got 0 deg"),
        ({"mu": -0.2}, r"drop 1 \(x\), column 'mu': mu must lie in \[0, 1000\], got -0.2"),
        ({"tip_radius": "-1 mm"}, r"column 'tip_radius': tip_radius must be > 0"),
        ({"flat_yield_strength": "0 MPa"}, r"column 'flat_yield_strength': .* must be > 0"),
    ],
)
def test_impossible_drop_inputs_are_refused_on_reading(change, match):
    """What a single impact refuses is refused when the file is read, naming drop and column
    (not after sampling, as a prior that gives no likelihood)."""
    with pytest.raises(ValueError, match=match) as info:
        Measurements.from_records(_rec(**change))
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("value", ["12", "0.000012"])
def test_column_unit_of_the_wrong_dimension_is_refused(tmp_path, value):
    """A header unit that does not fit the column is refused on the header's line, whatever the
    values under it."""
    path = tmp_path / "m.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,delta_p [kg],delta_p_sigma [kg]\n"
        f"a,20,-1.41,0.2,{value},0.000001\n"
    )
    with pytest.raises(
        ValueError,
        match=r"m\.csv: line 1: column 'delta_p \[kg\]': 'kg' has the wrong dimension; delta_p "
        r"takes a unit convertible to m",
    ):
        read_measurements(path)
    path.write_text(
        "label,angle [deg],vy [m/s],mu,delta_p [kg],delta_p_sigma [kg]\na,20,-1.41,0.2,12 um,1 um\n"
    )
    with pytest.raises(
        ValueError, match=r"line 1: column 'delta_p \[kg\]': 'kg' has the wrong dim"
    ):
        read_measurements(path)


def test_measurements_file_that_is_not_utf8_names_the_file(tmp_path):
    for name in ("binary.csv", "binary.toml"):
        (tmp_path / name).write_bytes(b"\x00\xff\xfe garbage")
        with pytest.raises(
            ValueError,
            match=rf"measurements file '.*{name}' is not a text file \((CSV|TOML) is UTF-8 "
            r"text; byte 1 is 0xff\)$",
        ) as info:
            read_measurements(tmp_path / name)
        assert "\n" not in str(info.value)


@pytest.mark.parametrize(("row", "fields"), [("a,20,-1.41,0.4", 4), ("a,20,-1.41,0.4,0.02,7", 6)])
def test_row_with_another_number_of_fields_names_the_line(tmp_path, row, fields):
    path = tmp_path / "ragged.csv"
    path.write_text(f"# drops\nlabel,angle [deg],vy [m/s],e,e_sigma\n\n{row}\n")
    with pytest.raises(ValueError, match=rf"ragged.csv: line 4: {fields} fields, the header has 5"):
        read_measurements(path)


def test_aliases_and_sphere_angle():
    m = Measurements.from_records(
        [
            {
                "body": "sphere",
                "radius": "2.5 mm",
                "vx": 1.0,
                "vy": -3.0,
                "mu": 0.1,
                "T": "0.1 ms",
                "T_sigma": "0.01 ms",
                "e_t": 0.7,
                "e_t_sigma": 0.05,
            }
        ]
    )
    assert m.quantities == ("duration", "e_t")
    assert m.inputs["angle"][0] == pytest.approx(math.pi / 2)


@pytest.mark.parametrize("column", ["L_s", "Ls", "L_s_sigma"])
def test_the_papers_L_s_is_refused_as_ambiguous(column):
    """A scan's L_s is the mark's extent, not the engine's signed slip: the file must say
    which (``scar_length`` or ``sliding_length``)."""
    rec = {"angle": "20 deg", "vy": -1.4, "mu": 0.2, column: "5 um"}
    with pytest.raises(ValueError, match=f"column '{column}': L_s names two quantities: give "
                       "scar_length"):  # fmt: skip
        Measurements.from_records([rec])


def test_an_analysed_experiment_is_appended(tmp_path):
    """``append_experiment`` turns analyze's result into a drop (a stand-in result with the
    attributes it reads: kinematics, summary(), rod, errors)."""
    from types import SimpleNamespace

    from impactlab.calibrate.experiment_rows import append_experiment
    from impactlab.experiment.uncertainty import Estimate

    kin = SimpleNamespace(
        angle_in=Estimate(math.radians(20), 0.01, "rad"),
        v_c_in=(Estimate(0.0, 0.01, "m/s"), Estimate(-1.41, 0.01, "m/s")),
        spin_in=Estimate(0.0, 0.1, "rad/s"),
        mu=Estimate(0.2, 0.02, ""),
    )
    summary = {
        "e": Estimate(0.5, 0.02, ""),
        "delta_p": Estimate(22e-6, 1e-6, "m"),
        "sliding_length": Estimate(1.4e-3, 0.1e-3, "m"),
        "pileup": Estimate(1e-6, 0.0, "m"),
    }
    res = SimpleNamespace(kinematics=kin, summary=lambda: summary, rod={"mass": 0.4607},
                          errors={})  # fmt: skip
    path = tmp_path / "drops.csv"
    append_experiment(path, res, "first")
    m = append_experiment(path, res, "second", body_material="aisi-1010")
    assert m.labels == ("first", "second")
    assert m.categories[1]["body_material"] == "aisi-1010"
    np.testing.assert_allclose(m.observed["scar_length"], [1.4e-3, 1.4e-3])
    np.testing.assert_allclose(m.inputs["mu"], [0.2, 0.2])
    assert set(m.quantities) == {"e", "delta_p", "scar_length"}
    assert read_measurements(path).n_values == 6
    with pytest.raises(ValueError, match="has no kinematics"):
        append_experiment(path, SimpleNamespace(kinematics=None, errors={"markers": "x"}), "bad")


def test_a_toml_unit_holds_for_the_quantitys_sigma_too(tmp_path):
    """[units] delta_p = "um" reads delta_p_sigma in um as well (it was read in metres)."""
    path = tmp_path / "drops.toml"
    path.write_text(
        '[units]\ndelta_p = "um"\nscar_length = "mm"\nscar_length_sigma = "um"\n'
        '[[drop]]\nangle = "20 deg"\nvy = -1.41\nmu = 0.2\ndelta_p = 22\ndelta_p_sigma = 2.2\n'
        "scar_length = 1.4\nscar_length_sigma = 140\n"
    )
    m = read_measurements(path)
    assert m.sigma["delta_p"][0] == pytest.approx(2.2e-6)
    assert m.observed["scar_length"][0] == pytest.approx(1.4e-3)
    assert m.sigma["scar_length"][0] == pytest.approx(140e-6)  # its own unit wins
