"""Bad calibration input: a clear error or warning, never a silent fit; a model that fails for
some parameter values is a likelihood of zero with a count, not a crash."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.calibrate import (
    CalibrationWarning,
    CandidateModel,
    Parameter,
    calibrate,
    parse_model,
    parse_parameter,
)
from impactlab.calibrate.synthetic import synthetic_measurements

MU = parse_parameter("mu", "uniform(0, 0.6)")


@pytest.mark.parametrize(
    ("name", "spec", "match"),
    [
        ("mu", "uniform(0.5, 0.2)", "excludes every value"),
        ("mu", "uniform(-1, 1)", "reaches outside the possible values"),
        ("mu", "normal(-5, 0.1)", "excludes every value"),
        ("flat_yield_strength", "loguniform(0, 1 GPa)", "loguniform needs low > 0"),
        ("flat_yield_strength", "uniform(1 m, 2 m)", "wrong dimension"),
        ("angle", "uniform(0, 1)", "unknown free parameter 'angle'"),
        ("colour", "uniform(0, 1)", "unknown free parameter 'colour'"),
        ("mu", "beta(1, 2)", "cannot read|unknown kind"),
        ("mu", "uniform(1)", "wrong number of values"),
    ],
)
def test_bad_priors(name, spec, match):
    with pytest.raises(ValueError, match=match):
        parse_parameter(name, spec)


@pytest.mark.parametrize(
    ("name", "spec", "message"),
    [
        (
            "mu",
            "uniform(-1,1)",
            "prior of mu: [-1, 1] reaches outside the possible values [0, inf]",
        ),
        (
            "flat_nu",
            "uniform(0.1, 0.7)",
            "prior of flat_nu: [0.1, 0.7] reaches outside the possible values [-1, 0.5]",
        ),
        (
            "flat_yield_strength",
            "uniform(-100 MPa, 1 GPa)",
            "prior of flat_yield_strength: [-1e+08, 1e+09] Pa reaches outside the possible "
            "values [0, inf] Pa",
        ),
    ],
)
def test_a_prior_outside_the_possible_values_gives_a_unit_only_where_there_is_one(
    name, spec, message
):
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        parse_parameter(name, spec)


@pytest.mark.parametrize(
    ("name", "spec", "message"),
    [
        (
            "flat_yield_strength",
            "uniform(100, 1000)",
            "prior of flat_yield_strength: uniform(100, 1000) in Pa lies wholly below 10000 "
            "Pa: an implausible magnitude (a number without its unit is in Pa); give the unit, "
            "e.g. 'uniform(100 MPa, 1000 MPa)'",
        ),
        (
            "body_E",
            {"prior": "normal", "mean": 200, "sd": 10},
            "prior of body_E: normal(200, 10) in Pa lies wholly below 10000 Pa: an "
            "implausible magnitude (a number without its unit is in Pa); give the unit, e.g. "
            "'normal(200 GPa, 10 GPa)'",
        ),
        (
            "tip_radius",
            "loguniform(4, 10)",
            "prior of tip_radius: loguniform(4, 10) in m lies wholly above 1 m: an implausible "
            "magnitude (a number without its unit is in m); give the unit, e.g. "
            "'loguniform(4 mm, 10 mm)'",
        ),
    ],
)
def test_a_prior_range_without_its_unit_is_refused(name, spec, message):
    """A prior whose whole range is an implausible magnitude (a unit left out: 100-1000 Pa for a
    yield strength) is refused naming the unit to give; one that only reaches past the
    plausible range is kept."""
    with pytest.raises(ValueError, match=f"^{re.escape(message)}$"):
        parse_parameter(name, spec)
    kept = parse_parameter("flat_yield_strength", "loguniform(1 kPa, 1 GPa)")
    assert (kept.low, kept.high) == (1e3, 1e9)


def test_prior_units_and_density():
    p = parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)")
    assert (p.low, p.high, p.unit) == (1e8, 1e9, "Pa")
    lp = p.logpdf(np.array([5e7, 5e8, 2e9]))
    assert lp[0] == -np.inf and lp[2] == -np.inf
    assert lp[1] == pytest.approx(-math.log(9e8))
    n = parse_parameter("mu", {"prior": "normal", "mean": 0.2, "sd": 0.1})
    assert n.low == 0.0  # truncated to mu >= 0


def test_bad_models():
    with pytest.raises(ValueError, match="unknown contact law"):
        parse_model("hooke/coulomb")
    with pytest.raises(ValueError, match="friction"):
        parse_model("hertz/glue")
    assert parse_model("hertz/mindlin").name == "hertz/mindlin"
    with pytest.raises(ValueError, match=r"a rate law \('johnson-cook'\) needs body="):
        parse_model(CandidateModel("hertz", rate="johnson-cook"))
    with pytest.raises(ValueError, match="unknown rate law 'nope'; known: cowper-symonds"):
        parse_model("hertz/coulomb/flexible_rod/nope")


def test_a_models_name_is_read_back_as_that_model():
    """Every name the ranking prints is a model specification (the rate law's included)."""
    for spec in ("ghaednia", "hertz/mindlin", "ghaednia/coulomb/flexible_rod",
                 "ghaednia/coulomb/flexible_rod/cowper-symonds"):  # fmt: skip
        model = parse_model(spec)
        assert parse_model(model.name) == model
    assert parse_model("ghaednia/coulomb/flexible_rod/cowper-symonds").rate == "cowper-symonds"


def test_parameter_no_model_uses(template):
    with pytest.raises(ValueError, match="'flat_brinell_hardness' changes no prediction"):
        calibrate(
            _data(template),
            [MU, parse_parameter("flat_brinell_hardness", "uniform(100, 200)")],
            ["ghaednia/coulomb"],
            steps=20,
        )


def test_parameter_some_models_do_not_use_warns(template):
    with pytest.warns(CalibrationWarning, match="'hertz/coulomb' does not use flat_yield"):
        calibrate(
            _data(template),
            [MU, parse_parameter("flat_yield_strength", "uniform(250 MPa, 350 MPa)")],
            ["ghaednia/coulomb", "hertz/coulomb"],
            walkers=8,
            steps=12,
            n_ppc=0,
        )


def _data(template, seed=0):
    return synthetic_measurements(
        template, CandidateModel(), [MU], [0.15], np.random.default_rng(seed)
    )


def test_quantity_a_model_does_not_predict(template):
    from dataclasses import replace

    data = _data(template)
    dis = {**data.observed, "energy_dissipated": np.full(data.n_drops, 1.0)}
    sig = {**data.sigma, "energy_dissipated": np.full(data.n_drops, 0.1)}
    with pytest.raises(ValueError, match="does not predict energy_dissipated"):
        calibrate(replace(data, observed=dis, sigma=sig), [MU], ["ghaednia/coulomb/flexible_rod"])


def test_mu_missing_and_not_free(template):
    from dataclasses import replace

    inputs = dict(template.inputs)
    inputs["mu"] = np.full(template.n_drops, np.nan)
    with pytest.raises(ValueError, match="give no mu"):
        calibrate(
            replace(template, inputs=inputs),
            [parse_parameter("flat_yield_strength", "uniform(250 MPa, 350 MPa)")],
            steps=20,
        )


def test_measurement_no_model_can_produce_warns(template):
    data = _data(template)
    e = data.observed["e"].copy()
    e[0] = 0.95  # the rod cannot rebound with e = 0.95 from this flat
    from dataclasses import replace

    with pytest.warns(CalibrationWarning, match=r"no model reproduces 20 deg e = 0.95"):
        cal = calibrate(replace(data, observed={**data.observed, "e": e}), [MU], walkers=8,
                        steps=20, n_ppc=0)  # fmt: skip
    assert any("no model reproduces" in w for w in cal.warnings)


def test_prior_where_every_case_fails(template):
    """Yield strengths above the flat's modulus: every material is refused, the prior holds
    no possible value: a clear error naming the reason."""
    sy = Parameter("flat_yield_strength", "uniform", 300e9, 400e9)
    with pytest.raises(ValueError, match=r"gives a likelihood above zero.*material rejected"):
        calibrate(_data(template), [MU, sy], walkers=8, steps=20)


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_failing_cases_count_as_zero_likelihood(template):
    """Part of the prior is impossible (S_y >= E*): those cases are counted, the fit goes on."""
    sy = Parameter("flat_yield_strength", "loguniform", 1e8, 1e12)
    cal = calibrate(_data(template), [MU, sy], walkers=8, steps=16, n_ppc=0)
    post = cal.best
    assert sum(post.failures.values()) > 0
    assert any("material rejected" in k for k in post.failures)
    assert np.isfinite(post.samples).all() and post.samples[:, 1].max() < 1e12


def test_bad_sampler_settings(template):
    for kw, match in (
        ({"steps": 5}, "steps must be >= 10"),
        ({"steps": 10**12}, r"steps must be at most [\d,]+ with \d+ walkers .* 1.6 GB\), got 1,0"),
        ({"walkers": 1}, "walkers must be >= 4"),
        ({"burn": 50, "steps": 20}, r"burn must lie in \[0, steps\)"),
    ):
        with pytest.raises(ValueError, match=match):
            calibrate(_data(template), [MU], **kw)
    with pytest.raises(ValueError, match="at least one free parameter"):
        calibrate(_data(template), [])
    with pytest.raises(ValueError, match="given twice"):
        calibrate(_data(template), [MU, MU])


@settings(max_examples=40)
@given(
    low=st.floats(1e6, 1e9),
    width=st.floats(1.01, 100.0),
    kind=st.sampled_from(["uniform", "loguniform"]),
    u=st.floats(0.0, 1.0),
)
def test_prior_support_property(low, width, kind, u):
    """Inside its bounds a prior's density is finite and its draws and quantiles stay there;
    outside it is zero (log -inf)."""
    p = Parameter("flat_yield_strength", kind, low, low * width)
    inside = float(p.quantile(u))
    assert p.low <= inside <= p.high
    assert np.isfinite(p.logpdf(np.array([inside])))[0]
    assert p.logpdf(np.array([p.low * 0.5, p.high * 2.0])).tolist() == [-np.inf, -np.inf]
    draws = p.sample(16, np.random.default_rng(0))
    assert ((draws >= p.low) & (draws <= p.high)).all()


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_one_drop_says_that_loo_needs_two() -> None:
    """ArviZ's remark on a single observation becomes a sentence a user can act on."""
    from impactlab.calibrate import Measurements

    one = Measurements.from_records(
        [{"label": "20 deg", "angle": "20 deg", "vy": -1.4, "e": 0.5, "e_sigma": 0.01}]
    )
    data = synthetic_measurements(one, CandidateModel(), [MU], [0.15], np.random.default_rng(0))
    cal = calibrate(data, [MU], walkers=8, steps=12, n_ppc=0)
    notes = " ".join(cal.posteriors["ghaednia/coulomb"].warnings)
    assert "PSIS-LOO with one drop" in notes and "point-wise LOO" not in notes


def test_a_semicolon_separated_file_is_named(tmp_path) -> None:
    from impactlab.calibrate.measurements import read_measurements

    path = tmp_path / "drops.csv"
    path.write_text("label;angle;vy;e\na;20 deg;-1.41;0.4\n")
    with pytest.raises(ValueError, match=r"line 1: the header is one column .*separates its "
                       r"columns with ';'; a measurements CSV"):  # fmt: skip
        read_measurements(path)


def _rod_drop(tmp_path, extra_header="", extra_value=""):
    path = tmp_path / "m.csv"
    path.write_text(
        f"label,body_material,angle [deg],vy [m/s],vx [m/s],mu,e,e_sigma{extra_header}\n"
        f"d1,al-6061-t6,45,-1.4,0.0,0.2,0.6,0.05{extra_value}\n"
    )
    return path


def test_rod_of_another_material_needs_its_mass(tmp_path):
    params = {"flat_yield_strength": "loguniform(100 MPa, 1 GPa)"}
    with pytest.raises(ValueError, match=r"drop 'd1': give the rod's mass .*al-6061-t6.*0.4607"):
        calibrate(_rod_drop(tmp_path), params, steps=20, walkers=8, n_ppc=2)


@pytest.mark.parametrize("how", ["column", "fixed"])
def test_rod_mass_given_passes_the_check(tmp_path, how):
    from impactlab.calibrate.input_checks import check_calibration_inputs
    from impactlab.calibrate.measurements import read_measurements

    path = _rod_drop(tmp_path, ",mass [kg]", ",0.16") if how == "column" else _rod_drop(tmp_path)
    fixed = {} if how == "column" else {"mass": "0.16 kg"}
    model = CandidateModel("ghaednia", "coulomb", fixed=fixed)
    params = (parse_parameter("flat_yield_strength", "loguniform(100 MPa, 1 GPa)"),)
    check_calibration_inputs(read_measurements(path), params, [model], [])


def test_the_papers_rod_in_inches_needs_no_mass(tmp_path):
    from impactlab.calibrate.input_checks import check_calibration_inputs
    from impactlab.calibrate.measurements import read_measurements

    path = tmp_path / "m.csv"
    path.write_text(
        "label,length [in],angle [deg],vy [m/s],vx [m/s],mu,e,e_sigma\n"
        "d1,12,45,-1.4,0.0,0.2,0.6,0.05\n"
    )
    params = (parse_parameter("flat_yield_strength", "loguniform(100 MPa, 1 GPa)"),)
    check_calibration_inputs(read_measurements(path), params, [CandidateModel("ghaednia")], [])
