"""Candidate models from tables (a calibration file's ``[[model]]``): known keys, fixed inputs
read in their unit, range- and magnitude-checked, and said when the model does not use them;
the calibration file's own checks; what a calibration refuses between the models, the
parameters and the drops; the settings it records."""

from __future__ import annotations

import json

import numpy as np
import pytest

from impactlab._json import shape_problems
from impactlab._version import __version__
from impactlab.calibrate import (
    CalibrationWarning,
    CandidateModel,
    Measurements,
    calibrate,
    parse_model,
)
from impactlab.calibrate import parse_parameter as prior
from impactlab.calibrate.config import load_config
from impactlab.calibrate.jsonout import calibration_json
from impactlab.calibrate.synthetic import synthetic_measurements

MU = prior("mu", "uniform(0, 0.6)")


@pytest.mark.parametrize(
    ("spec", "match"),
    [
        ({"law": "ghaednia", "frition": "mindlin"},
         r"model 'ghaednia': unknown key 'frition' \(did you mean 'friction'\?\); known: law"),
        ({"law": "ghaednia", "body": "flexible_rod", "fixed": {"dampin": 0.05}},
         r"model 'ghaednia/coulomb/flexible_rod': fixed 'dampin' is not an input a model can "
         r"fix \(did you mean 'damping'\?\)"),
        ({"law": "ghaednia", "fixed": {"damping": 5}},
         r"model 'ghaednia/coulomb', fixed damping: damping must lie in \[0, 1\), got 5"),
        ({"law": "ghaednia", "fixed": {"flat_yield_strength": "300 kg"}},
         r"fixed flat_yield_strength: flat_yield_strength: '300 kg' has the wrong dimension"),
        ({"law": "ghaednia", "fixed": {"angle": "20 deg"}}, "fixed 'angle' is not an input"),
        ({"law": "ghaednia", "fixed": 0.05}, "fixed must be a table of input = value"),
        ({"law": "ghaednia", "fixed": {"flat_yield_strength": 300}},
         r"model 'ghaednia/coulomb', fixed flat_yield_strength: flat_yield_strength = 300 Pa is "
         r"below 10000 Pa: an implausible magnitude .*give its unit, e.g. '300 MPa'"),
        ({"law": "ghaednia", "fixed": {"flat_E": 200}}, r"fixed flat_E: .*e.g. '200 GPa'"),
    ],
)  # fmt: skip
def test_bad_model_tables_name_the_key(spec, match):
    with pytest.raises(ValueError, match=match) as info:
        parse_model(spec)
    assert "\n" not in str(info.value)


def test_fixed_values_take_units():
    m = parse_model({"law": "ghaednia", "fixed": {"flat_yield_strength": "300 MPa",
                                                   "flat_brinell_hardness": 105}})  # fmt: skip
    assert m.fixed == {"flat_yield_strength": 3e8, "flat_brinell_hardness": 105.0}


def test_a_fixed_input_the_model_does_not_use_is_said(template):
    """A rigid body's damping, a Brinell hardness under Ghaednia's law (it reads S_y): each a
    warning naming the model and the input; a fixed input the model uses is not."""
    data = synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip
    model = CandidateModel(fixed={"damping": 0.05, "flat_brinell_hardness": "105 HB",
                                  "flat_yield_strength": "300 MPa"})  # fmt: skip
    with pytest.warns(CalibrationWarning) as caught:
        cal = calibrate(data, [MU], [model], walkers=4, steps=10, n_ppc=0)
    said = [w for w in cal.warnings if "does not use its fixed" in w]
    assert said == [
        "model 'ghaednia/coulomb' does not use its fixed damping (= 0.05): it changes none of "
        "the model's predictions of the measured values; remove it",
        "model 'ghaednia/coulomb' does not use its fixed flat_brinell_hardness (= 105 "
        "kgf/mm^2): it changes none of the model's predictions of the measured values; remove it",
    ]
    assert sum("does not use its fixed" in str(w.message) for w in caught) == 2


def _config(tmp_path, sampler: str, extra: str = "") -> object:
    path = tmp_path / "cal.toml"
    path.write_text(
        'measurements = "drops.csv"\n[parameters]\nmu = "uniform(0, 1)"\n'
        f"[sampler]\n{sampler}\n{extra}"
    )
    return path


@pytest.mark.parametrize(
    ("sampler", "match"),
    [
        ('steps = "ten"', r"cal.toml: \[sampler\] steps must be an integer, got 'ten'"),
        ("steps = 12.7", r"cal.toml: \[sampler\] steps must be an integer, got 12.7"),
        ("seed = true", r"\[sampler\] seed must be an integer, got True"),
    ],
)
def test_config_sampler_settings_are_integers(tmp_path, sampler, match):
    with pytest.raises(ValueError, match=match):
        load_config(_config(tmp_path, sampler))


def test_config_errors_name_the_file(tmp_path):
    path = _config(tmp_path, "steps = 20", '[[model]]\nlaw = "ghaednia"\nfrition = "mindlin"\n')
    with pytest.raises(ValueError, match=r"cal.toml: model 'ghaednia': unknown key 'frition'"):
        load_config(path)
    with pytest.raises(IsADirectoryError, match=r"calibration file .* is a directory"):
        load_config(tmp_path)


def _drops(template):
    return synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip


def test_sampler_settings_are_checked(template):
    data = _drops(template)
    for kw, match in (
        ({"seed": -1}, r"seed must be an integer in \[0, 4294967295\], got -1"),
        ({"steps": 12.7}, "steps must be an integer, got 12.7"),
        ({"engine": {"gravity": True, "foo": 1}}, r"unknown engine option\(s\) \['foo'\]"),
        ({"engine": {"rtol": 5.0}}, "engine rtol must be a number in"),
    ):
        with pytest.raises(ValueError, match=match):
            calibrate(data, [MU], steps=kw.pop("steps", 10), **kw)


def test_an_input_both_fixed_and_free_is_refused(template):
    model = CandidateModel(fixed={"mu": 0.2})
    with pytest.raises(ValueError, match=r"model 'ghaednia/coulomb' fixes mu, which is also a "
                       "free parameter"):  # fmt: skip
        calibrate(_drops(template), [MU], [model], steps=10)


def test_one_material_property_for_drops_on_two_materials():
    recs = [
        {"label": lab, "angle": "20 deg", "vy": -1.41, "mu": 0.15, "e": 0.43, "e_sigma": 0.02,
         "flat_material": mat}
        for lab, mat in (("steel", "aisi-1010"), ("alu", "al-6061-t6"))
    ]  # fmt: skip
    m = Measurements.from_records(recs)
    with pytest.raises(ValueError, match=r"flat_yield_strength is one free parameter for every "
                       r"drop, but the drops' flat_material differ \(aisi-1010: steel; "
                       r"al-6061-t6: alu\)"):  # fmt: skip
        calibrate(m, [prior("flat_yield_strength", "uniform(100 MPa, 1 GPa)")], steps=10)


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_the_settings_hold_the_engine_and_the_models(template):
    """results.json runs the calibration again: the engine's options and every model's
    definition (fixed inputs, rate law) are in its settings."""
    model = CandidateModel(fixed={"flat_yield_strength": "300 MPa"}, name="sy300")
    brake = CandidateModel("brake", law_params={"hardness": "105 HB", "meyer_index": 2.2})
    cal = calibrate(_drops(template), [MU], [model, brake], walkers=4, steps=10, n_ppc=0,
                    engine={"gravity": "9.81 m/s^2", "rtol": 1e-6})  # fmt: skip
    st = cal.settings
    assert st["engine"] == {"gravity": 9.81, "rtol": 1e-6}
    assert st["model_definitions"]["sy300"]["fixed"] == {"flat_yield_strength": 3e8}
    assert st["model_definitions"]["sy300"]["rate"] is None
    doc = json.loads(json.dumps(calibration_json(cal)))
    assert shape_problems(doc) == []
    fixed = doc["settings"]["model_definitions"]["sy300"]["fixed"]
    assert fixed == {"flat_yield_strength": {"value": 3e8, "unit": "Pa"}}
    assert doc["settings"]["engine"]["gravity"] == {"value": 9.81, "unit": "m/s^2"}
    again = parse_model(doc["settings"]["model_definitions"]["sy300"])  # as a [[model]] table
    assert again.fixed == model.fixed
    hb = {"flat_brinell_hardness": {"value": 105.0, "unit": "kgf/mm^2"}, "damping": {
        "value": 0.05, "unit": "1"}}  # fmt: skip
    assert parse_model({"fixed": hb}).fixed == {"flat_brinell_hardness": 105.0, "damping": 0.05}
    assert doc["models"]["sy300"]["parameters"]["mu"]["tau"]["unit"] == "1"
    assert doc["impactlab_version"] == __version__  # also in results.json
    saved = doc["settings"]["model_definitions"]["brake/coulomb"]
    assert saved["law_params"] == {"hardness": {"value": 105.0, "unit": "kgf/mm^2"},
                                   "meyer_index": {"value": 2.2, "unit": "1"}}  # fmt: skip
    assert parse_model(saved).law_params == brake.law_params == {"hardness": 105.0,
                                                                 "meyer_index": 2.2}  # fmt: skip


@pytest.mark.parametrize(
    ("law_params", "match"),
    [
        ({"hardnes": 105.0}, r"model 'brake/coulomb', law_params: unknown parameter\(s\) "
         r"\['hardnes'\] for contact law 'brake'; known: \['hardness', 'meyer_index'\]"),
        ({"hardness": "1 m"}, "hardness: '1 m' has the wrong dimension"),
        ([105.0], "law_params must be a table of parameter = value"),
        ({"hardness": 1.03e9}, r"law_params: hardness = 1.03e\+09 kgf/mm\^2 is above 10000"),
    ],
)  # fmt: skip
def test_a_models_law_params_are_read_when_it_is_made(law_params, match):
    """A misspelt law parameter or a value of the wrong dimension is refused naming the model
    when the model is made, not in every case of the calibration."""
    with pytest.raises(ValueError, match=match):
        CandidateModel("brake", law_params=law_params)
