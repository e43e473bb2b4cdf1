"""A drop's correlation coefficients: the column correlation_<a>_<b> of a measurements file
(CSV, TOML, records), the constructor's ``correlation``, what is refused, and the coefficient of
e and spin_out that an analysed experiment brings."""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.calibrate import Measurements, read_measurements
from impactlab.calibrate.experiment_rows import append_experiment, experiment_record

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "data"


def _rec(**extra):
    return {
        "label": "a", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.42, "e_sigma": 0.02,
        "spin_out": -9.8, "spin_out_sigma": 0.3, **extra,
    }  # fmt: skip


def test_a_coefficient_is_read_in_either_order_and_by_alias():
    m = Measurements.from_records(
        [_rec(correlation_spin_out_e=-0.97), _rec(label="b", T="0.2 ms", T_sigma="0.01 ms",
                                                   correlation_e_T="0.3")]
    )  # fmt: skip
    np.testing.assert_array_equal(m.correlation[("e", "spin_out")], [-0.97, np.nan])
    np.testing.assert_array_equal(m.correlation[("e", "duration")], [np.nan, 0.3])
    assert m.records()[0]["correlation_e_spin_out"] == -0.97
    assert "correlation_e_spin_out" not in m.records()[1]
    assert Measurements.from_records([_rec()]).correlation == {}


@pytest.mark.parametrize(
    ("extra", "match"),
    [
        ({"correlation_e_spin_out": 1.2}, r"drop 1: correlation_e_spin_out = 1.2 lies outside "
                                          r"\[-1, 1\]"),
        ({"correlation_e_spin_out": "strong"}, "correlation_e_spin_out must be a plain number"),
        ({"correlation_e_delta_p": 0.1}, r"drop 1 \(a\): correlation_e_delta_p = 0.1 names "
                                         "delta_p, which the drop does not measure"),
        ({"correlation_e_spin_out": -0.9, "correlation_spin_out_e": -0.9},
         "drop 1: correlation_e_spin_out is given twice"),
        ({"correlation_e_e": 0.3}, "names e twice"),
        ({"correlation_e_spinout": 0.3}, "a correlation column is correlation_<a>_<b>"),
        ({"correlation_e_spin_out [%]": 30}, "takes no unit"),
        ({"correlation_e_spin_out": -1.0}, r"drop 1 \(a\): the coefficients "
                                           "correlation_e_spin_out = -1 form no positive-definite"),
        ({"delta_p": "60 um", "delta_p_sigma": "3 um", "correlation_e_spin_out": 0.9,
          "correlation_e_delta_p": 0.9, "correlation_spin_out_delta_p": -0.9},
         r"drop 1 \(a\): the coefficients .*correlation_spin_out_delta_p = -0.9 form no "
         "positive-definite correlation matrix"),
    ],
)  # fmt: skip
def test_a_bad_coefficient_is_refused_naming_the_drop_and_the_pair(extra, match):
    with pytest.raises(ValueError, match=match):
        Measurements.from_records([_rec(**extra)])


def test_the_constructor_takes_and_checks_pairs():
    base = Measurements.from_records([_rec(), _rec(label="b", spin_out=None, spin_out_sigma=None)])
    args = (base.labels, base.categories, base.inputs, base.observed, base.sigma)
    m = Measurements(*args, correlation={("spin_out", "e"): [-0.97, np.nan]})
    assert list(m.correlation) == [("e", "spin_out")]
    with pytest.raises(ValueError, match=r"drop 2 \(b\): correlation_e_spin_out = 0.5 names "
                       "spin_out, which the drop does not measure"):  # fmt: skip
        Measurements(*args, correlation={("e", "spin_out"): [-0.97, 0.5]})
    with pytest.raises(ValueError, match=r"the pair \(e, spin_out\) is given twice"):
        Measurements(*args, correlation={("e", "spin_out"): [0, 0], ("spin_out", "e"): [0, 0]})
    with pytest.raises(
        ValueError, match=r"correlation of \(e, spin_out\): 3 coefficients for 2 drops"
    ):
        Measurements(*args, correlation={("e", "spin_out"): [0, 0, 0]})
    with pytest.raises(ValueError, match="must be a pair of two different measured quantities"):
        Measurements(*args, correlation={("e", "mu"): [0, np.nan]})


def test_a_csv_file_round_trips_its_coefficients(tmp_path):
    path = tmp_path / "drops.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma,spin_out [rad/s],spin_out_sigma,"
        "correlation_e_spin_out\n"
        "a,20,-1.41,0.2,0.42,0.02,-9.8,0.3,-0.97\n"
        "b,45,-2.18,0.2,0.41,0.02,-15.1,0.3,\n"
    )
    m = read_measurements(path)
    np.testing.assert_array_equal(m.correlation[("e", "spin_out")], [-0.97, np.nan])
    back = read_measurements(m.to_csv(tmp_path / "back.csv"))
    assert "correlation_e_spin_out" in (tmp_path / "back.csv").read_text().splitlines()[0]
    np.testing.assert_array_equal(back.correlation[("e", "spin_out")], [-0.97, np.nan])
    bad = tmp_path / "bad.csv"
    bad.write_text(path.read_text().replace("-0.97", "-1.5"))
    with pytest.raises(ValueError, match=r"bad.csv: line 2: drop 1: correlation_e_spin_out = "
                       r"-1.5 lies outside \[-1, 1\]"):  # fmt: skip
        read_measurements(bad)


def test_a_toml_drop_takes_the_column_and_its_units_table_refuses_it(tmp_path):
    drop = (
        '[[drop]]\nangle = "20 deg"\nvy = -1.41\nmu = 0.2\ne = 0.42\ne_sigma = 0.02\n'
        "spin_out = -9.8\nspin_out_sigma = 0.3\ncorrelation_e_spin_out = -0.97\n"
    )
    path = tmp_path / "drops.toml"
    path.write_text(drop)
    assert read_measurements(path).correlation[("e", "spin_out")][0] == -0.97
    path.write_text(drop + '[units]\ncorrelation_e_spin_out = "1"\n')
    with pytest.raises(ValueError, match="correlation coefficient is a plain number in"):
        read_measurements(path)


def _experiment(rho: float | None, e: float = 0.5):
    """A stand-in analysed experiment (the attributes experiment_record reads) whose marker
    fit correlates e and spin_out at ``rho`` (None: a kinematics without a covariance)."""
    from impactlab.experiment.uncertainty import Estimate

    kin = SimpleNamespace(
        angle_in=Estimate(math.radians(20), 0.01, "rad"),
        v_c_in=(Estimate(0.0, 0.01, "m/s"), Estimate(-1.41, 0.01, "m/s")),
        spin_in=Estimate(0.0, 0.1, "rad/s"),
        mu=Estimate(0.2, 0.02, ""),
    )
    if rho is not None:
        kin.derived_names = ("t_impact", "spin_out", "e")
        kin.correlation = np.array([[1, 0.1, 0.2], [0.1, 1, rho], [0.2, rho, 1]])
    summary = {
        "e": Estimate(e, 0.02, ""),
        "spin_out": Estimate(-10.0, 0.05, "rad/s"),
        "delta_p": Estimate(22e-6, 1e-6, "m"),
        "sliding_length": Estimate(1.4e-3, 0.1e-3, "m"),
    }
    return SimpleNamespace(kinematics=kin, summary=lambda: summary, rod={}, errors={})


def test_an_analysed_experiment_brings_the_correlation_of_e_and_spin_out(tmp_path):
    rec = experiment_record(_experiment(-0.97), "a")
    assert rec["correlation_e_spin_out"] == -0.97
    assert not any(k.startswith("correlation_") and "delta_p" in k for k in rec)
    assert "correlation_e_spin_out" not in experiment_record(_experiment(None), "a")
    left_out = experiment_record(_experiment(-0.97), "a", correlation_e_spin_out=None)
    assert Measurements.from_records([left_out]).correlation == {}
    m = append_experiment(tmp_path / "drops.csv", _experiment(-0.97), "a")
    m = append_experiment(tmp_path / "drops.csv", _experiment(-0.5, e=0.45), "b")
    np.testing.assert_array_equal(m.correlation[("e", "spin_out")], [-0.97, -0.5])


def test_the_example_drop_brings_its_marker_fit_correlation():
    """examples/data/drop.csv: e and spin_out of one marker fit, correlated at -0.97."""
    import tomllib

    from impactlab.experiment import MarkerGeometry, analyze

    table = tomllib.loads((EXAMPLES / "markers.toml").read_text())["markers"]
    res = analyze(
        EXAMPLES / "drop.csv", None, geometry=MarkerGeometry.from_mapping(table), up="+y",
        figures=False, n_samples=500,
    )  # fmt: skip
    m = Measurements.from_records([experiment_record(res, "example")])
    assert m.correlation[("e", "spin_out")][0] == pytest.approx(-0.97, abs=0.01)
