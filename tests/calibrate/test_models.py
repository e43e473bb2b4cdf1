"""Candidate models: predictions through the batch, the flexible rod, the rate-dependent flat
and partial slip; the ranking prefers the model that made the data."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.bodies import Sphere
from impactlab.calibrate import CandidateModel, Measurements, calibrate, parse_parameter, predict
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.dynamics import simulate
from impactlab.materials import AISI_201, AISI_1010

MU = parse_parameter("mu", "uniform(0, 0.6)")


def test_batch_prediction_equals_simulate(template):
    pred = predict(CandidateModel(), template, [MU], np.array([[0.1], [0.3]]))
    assert (pred.status == 0).all()
    from impactlab.bodies import PAPER_ROD

    r = simulate(PAPER_ROD, AISI_1010, mu=0.3, angle=np.radians(45), velocity=(0.0, -1.4),
                 history=False)  # fmt: skip
    # e without the gravity impulse of the contact, as a drop's e and marker tracks give it
    e_free = (r.vn_out + 9.80665 * r.duration) / abs(r.vn_in)
    assert pred.values["e"][1, 1] == pytest.approx(e_free, rel=1e-9)
    assert 0.001 < e_free - r.e < 0.01  # the m g T of a 0.14 ms contact
    assert pred.values["spin_out"][1, 1] == pytest.approx(r.spin_out, rel=1e-9)


def test_the_rigid_e_is_the_drops_e() -> None:
    """A rigid model and the rigid rod's drop predict the same e (gravity's impulse removed
    in both), to the integrators' tolerance."""
    from impactlab.bodies import PAPER_ROD
    from impactlab.dynamics import simulate_drop

    m = Measurements.from_records([{"angle": "20 deg", "vy": -1.41, "e": 0.5, "e_sigma": 0.03}])
    got = predict(CandidateModel(), m, [MU], np.array([[0.2]])).values["e"][0, 0]
    drop = simulate_drop(PAPER_ROD, AISI_1010, mu=0.2, angle=np.radians(20), velocity=(0, -1.41))
    assert got == pytest.approx(drop.e, abs=2e-4)


def test_flexible_and_rate_dependent_models(template):
    theta = np.array([[0.2]])
    rigid = predict(CandidateModel(), template, [MU], theta)
    flex = predict(CandidateModel(body="flexible_rod"), template, [MU], theta)
    rate = predict(CandidateModel(body="flexible_rod", rate="cowper-symonds"), template, [MU],
                   theta)  # fmt: skip
    assert (flex.status == 0).all() and (rate.status == 0).all()
    # the rate-dependent flat changes the prediction, and so does the flexibility
    assert (rate.values["e"] != flex.values["e"]).any()
    assert (flex.values["e"] != rigid.values["e"]).any()
    # a measured dent depth is the drop's final dent (dent_depth), its slip the sequence's
    assert CandidateModel(body="flexible_rod").unsupported(list(template.quantities)) == []
    assert "sliding_length" in template.quantities
    assert np.isfinite(flex.values["sliding_length"]).all()
    with pytest.raises(ValueError, match="needs body='flexible_rod'"):
        CandidateModel(rate="cowper-symonds")
    with pytest.raises(ValueError, match="unknown rate law"):
        CandidateModel(body="flexible_rod", rate="fast")


def test_a_scar_is_the_marks_extent_for_every_body():
    """scar_length: an impact's |contact_travel|, a drop's scar_length (rigid, flexible and on
    a rate-dependent flat), never the slip integral."""
    from impactlab.bodies import PAPER_ROD, FlexibleRod
    from impactlab.dynamics import simulate_drop

    m = Measurements.from_records(
        [{"angle": "45 deg", "vy": -1.4, "scar_length": "1 mm", "scar_length_sigma": "0.1 mm"}]
    )
    theta = np.array([[0.2]])
    x = {"mu": 0.2, "angle": np.radians(45), "velocity": (0.0, -1.4)}
    r = simulate(PAPER_ROD, AISI_1010, history=False, **x)
    got = predict(CandidateModel(), m, [MU], theta).values["scar_length"][0, 0]
    assert got == pytest.approx(abs(r.contact_travel), rel=1e-9)
    assert abs(abs(r.contact_travel) - abs(r.sliding_length)) > 1e-6  # the slip differs
    for model, rate in ((CandidateModel(body="flexible_rod"), None),
                        (CandidateModel(body="flexible_rod", rate="cowper-symonds"),
                         "cowper-symonds")):  # fmt: skip
        d = simulate_drop(FlexibleRod.paper(), AISI_1010, rate=rate, **x)
        got = predict(model, m, [MU], theta).values["scar_length"][0, 0]
        assert got == pytest.approx(d.scar_length, rel=1e-6)


def test_partial_slip_runs_in_the_batch_as_simulate():
    m = Measurements.from_records(
        [
            {
                "body": "sphere",
                "radius": "5 mm",
                "vx": 1.0,
                "vy": -1.0,
                "e_t": 0.6,
                "e_t_sigma": 0.05,
                "spin_out": -100,
                "spin_out_sigma": 10,
            }
        ]
    )
    pred = predict(CandidateModel("hertz", "partial_slip"), m, [MU], np.array([[0.3]]),
                   engine={"gravity": False})  # fmt: skip
    r = simulate(Sphere(radius=5e-3, material=AISI_201), AISI_1010, law="hertz",
                 friction="partial_slip", mu=0.3, velocity=(1.0, -1.0), gravity=False,
                 history=False)  # fmt: skip
    assert pred.status[0, 0] == 0
    assert pred.values["e_t"][0, 0] == pytest.approx(r.velocity_out[0] / 1.0, rel=1e-12)
    assert pred.values["spin_out"][0, 0] == pytest.approx(r.spin_out, rel=1e-12)
    assert CandidateModel("hertz", "partial_slip").batched
    assert CandidateModel("hertz", "partial_slip", body="flexible_rod").batched
    assert not CandidateModel(body="flexible_rod", rate="cowper-symonds").batched


def test_the_model_that_made_the_data_ranks_first(template):
    data = synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(7))  # fmt: skip
    cal = calibrate(data, [MU], ["ghaednia/coulomb", "ghaednia/mindlin"], walkers=8, steps=60,
                    n_ppc=20)  # fmt: skip
    best, second = cal.ranking
    assert best["model"] == "ghaednia/coulomb"
    assert second["elpd_diff"] > 2 * second["dse"]


def test_models_on_dask_equal_the_local_run(template):
    """Each model's chain as one Dask task (an in-process cluster here): the same chains."""
    from distributed import Client

    data = synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(3))  # fmt: skip
    models = ["ghaednia/coulomb", "ghaednia/mindlin"]
    local = calibrate(data, [MU], models, walkers=8, steps=20, n_ppc=0)
    with Client(processes=False, n_workers=1, threads_per_worker=2, dashboard_address=None) as c:
        remote = calibrate(data, [MU], models, walkers=8, steps=20, n_ppc=0, scheduler=c)
    for name in models:
        np.testing.assert_array_equal(local.posteriors[name].samples,
                                      remote.posteriors[name].samples)  # fmt: skip
    assert [r["model"] for r in local.ranking] == [r["model"] for r in remote.ranking]


def test_a_result_that_is_not_ok_is_no_prediction() -> None:
    """Every invalidating flag (not only ENERGY_GAIN) makes the case a failure with its reason:
    a brittle flat past first yield here; the advisory LAW_EXTRAPOLATED keeps its case."""
    from impactlab.calibrate.models import STATUS_FLAGGED, status_message
    from impactlab.flags import FLAG_BRITTLE

    m = Measurements.from_records([
        {"angle": "45 deg", "vy": -1.41, "flat_material": "soda-lime-glass", "e": 0.5,
         "e_sigma": 0.03},
        {"angle": "20 deg", "vy": -1.41, "e": 0.5, "e_sigma": 0.03},
    ])  # fmt: skip
    pred = predict(CandidateModel(), m, [MU], np.array([[0.2]]))
    assert pred.status[0].tolist() == [STATUS_FLAGGED[FLAG_BRITTLE], 0]
    assert np.isnan(pred.values["e"][0, 0]) and np.isfinite(pred.values["e"][0, 1])
    assert status_message(pred.status[0, 0]).startswith("result flagged BRITTLE")
    assert sorted(STATUS_FLAGGED) == [1, 2, 8, 16, 32]  # every flag but LAW_EXTRAPOLATED
