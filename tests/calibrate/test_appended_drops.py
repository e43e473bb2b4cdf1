"""An analysed drop appended to a measurements file: the rod's inertia carried, a result that is
not ok refused unless asked for (then marked), the user's file left as written."""

from __future__ import annotations

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.calibrate import (
    CalibrationWarning,
    Measurements,
    parse_model,
    parse_parameter,
    predict,
    read_measurements,
)
from impactlab.calibrate.experiment_rows import append_experiment, experiment_record
from impactlab.experiment.uncertainty import Estimate

ROD = {"mass": PAPER_ROD.mass, "length": PAPER_ROD.length, "tip_radius": PAPER_ROD.tip_radius}


def _result(rod=None, doubts=(), errors=None, flat=None, e=0.4):
    """A stand-in analysed experiment (the attributes experiment_record reads)."""
    kin = SimpleNamespace(
        angle_in=Estimate(math.radians(45), 0.01, "rad"),
        v_c_in=(Estimate(0.0, 0.01, "m/s"), Estimate(-1.41, 0.01, "m/s")),
        spin_in=Estimate(0.0, 0.1, "rad/s"),
        mu=Estimate(0.2, 0.02, ""),
    )
    summary = {
        "e": Estimate(e, 0.01, ""),
        "spin_out": Estimate(-10.0, 0.05, "rad/s"),
        "delta_p": Estimate(22e-6, 1e-6, "m"),
    }
    return SimpleNamespace(kinematics=kin, summary=lambda: summary, rod=dict(rod or ROD),
                           errors=dict(errors or {}), doubts=tuple(doubts),
                           options={"flat": flat})  # fmt: skip


def test_the_rods_inertia_is_carried_and_changes_the_prediction():
    """An analysed Rod(inertia=1.3 I) was calibrated with m L^2/12: spin_out off by 1.2 rad/s."""
    inertia = 1.3 * PAPER_ROD.inertia
    rec = experiment_record(_result({**ROD, "inertia": inertia}), "I")
    assert rec["inertia"] == inertia
    uniform = experiment_record(_result({**ROD, "inertia": PAPER_ROD.inertia}), "U")
    assert "inertia" not in uniform  # the uniform rod's m L^2/12: left blank, the same
    ps = [parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)")]
    model = parse_model("ghaednia/coulomb")
    got = [
        predict(model, Measurements.from_records([r]), ps, np.array([[305e6]])).values
        for r in (rec, uniform)
    ]
    assert abs(got[0]["spin_out"][0, 0] - got[1]["spin_out"][0, 0]) > 0.5


def test_a_library_flat_of_the_analysis_is_the_drops_flat():
    assert experiment_record(_result(flat="al-6061-t6"), "a")["flat_material"] == "al-6061-t6"
    assert "flat_material" not in experiment_record(_result(flat="E=200 GPa"), "a")


def test_a_doubtful_result_is_refused_unless_asked_for_then_marked(tmp_path):
    path = tmp_path / "drops.csv"
    bad = _result(doubts=("the marker geometry is tilted",), errors={"scan": "unreadable"})
    with pytest.raises(ValueError, match=r"not ok \(scan failed: unreadable; the marker "
                       r"geometry is tilted\).*include_doubtful=True"):  # fmt: skip
        append_experiment(path, bad, "x")
    assert not path.exists()
    with pytest.warns(CalibrationWarning, match="appended though its analysis is not ok"):
        m = append_experiment(path, bad, "x", include_doubtful=True)
    assert m.labels == ("x",)
    text = path.read_text()
    assert "# doubtful drop 'x' (its analysis is not ok): scan failed: unreadable; the " in text
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        append_experiment(path, _result(e=0.45), "ok")  # an ok result: no warning


def test_the_users_file_is_left_as_written(tmp_path):
    """Comments were deleted and every row rewritten in SI with float noise."""
    path = tmp_path / "drops.csv"
    before = (
        "# my lab, 2 May\r\n"
        "label,angle [deg],vy [m/s],mu,e,e_sigma,delta_p [um],delta_p_sigma\r\n"
        "a,20,-1.41,0.2,0.42,0.02,60,3\r\n"
        "# b was dropped twice\r\n"
        "b,45,-2.18,0.2,0.41,0.02,114,3\r\n"
    )
    path.write_bytes(before.encode())
    m = append_experiment(path, _result({**ROD, "inertia": 0.005}), "c")
    lines = path.read_bytes().decode().split("\r\n")
    assert lines[0] == "# my lab, 2 May" and lines[3] == "# b was dropped twice"
    added = ",vx [m/s],spin [rad/s],mass [kg],length [m],tip_radius [m],inertia [kg*m^2],"
    assert lines[1].startswith(before.split("\r\n")[1] + ",vx [m/s]")
    assert lines[2] == "a,20,-1.41,0.2,0.42,0.02,60,3" + "," * (lines[1].count(",") - 7)
    new = dict(zip(lines[1].split(","), lines[5].split(","), strict=True))
    assert new["angle [deg]"] == "45" and new["delta_p [um]"] == "22"
    assert new["delta_p_sigma"] == "1" and new["vy [m/s]"] == "-1.41"
    assert lines[6] == ""  # one line ending after the last row
    assert m.labels == ("a", "b", "c")
    np.testing.assert_allclose(m.observed["delta_p"], [60e-6, 114e-6, 22e-6])
    np.testing.assert_allclose(m.inputs["inertia"][2], 0.005)
    assert added.split(",")[6] in lines[1]
    with pytest.raises(ValueError, match="a drop labelled 'c' is there already"):
        append_experiment(path, _result(), "c")


def test_the_same_drop_under_another_label_is_refused(tmp_path):
    """Analysing one drop folder twice appended it twice: counted twice by a calibration."""
    path = tmp_path / "drops.csv"
    append_experiment(path, _result(), "a")
    before = path.read_bytes()
    with pytest.raises(ValueError, match=r"drop 'b' holds the values of drop 'a' \(drop 1\): "
                       r"the same drop appended twice would count twice"):  # fmt: skip
        append_experiment(path, _result(), "b")
    assert path.read_bytes() == before
    m = append_experiment(path, _result(e=0.41), "c")  # another drop: another e
    assert m.labels == ("a", "c")


def test_percent_and_a_new_file(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("label,angle [deg],vy [m/s],mu [%],e [%],e_sigma\na,20,-1.41,20,42,2\n")
    append_experiment(path, _result(), "b")
    last = path.read_text().splitlines()[-1].split(",")
    assert last[:6] == ["b", "45", "-1.41", "20", "40", "1"]
    fresh = tmp_path / "new.csv"
    m = append_experiment(fresh, _result(), "n")
    assert fresh.read_text().splitlines()[0].startswith("label,angle [deg],vx [m/s],vy [m/s]")
    assert read_measurements(fresh).labels == m.labels == ("n",)
    with pytest.raises(ValueError, match=r"appended to a CSV file \(\.csv\)"):
        append_experiment(tmp_path / "d.toml", _result(), "n")
