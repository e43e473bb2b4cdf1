"""What a calibration must not lose or overstate: a saved chain that does not fit is kept and
refused (never replaced unasked), files are written whole or not at all, one drop ranks no
model, and results.json's settings run the calibration again."""

from __future__ import annotations

import errno
import json
import math
import pickle
from dataclasses import replace

import numpy as np
import pytest
from typer.testing import CliRunner

from impactlab.calibrate import CandidateModel, Measurements, calibrate, parse_parameter
from impactlab.calibrate.config import load_config
from impactlab.calibrate.input_checks import engine_options
from impactlab.calibrate.jsonout import calibration_json
from impactlab.calibrate.report import save
from impactlab.calibrate.statelock import SavedChainError
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.cli import app

MU = parse_parameter("mu", "uniform(0, 0.6)")
runner = CliRunner()
pytestmark = pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")


def _data(template):
    return synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip


def _run(data, **kw):
    return calibrate(data, [MU], walkers=6, steps=10, n_ppc=0, **kw)


def _wider_e_sigma(data):
    return replace(data, sigma={**data.sigma, "e": data.sigma["e"] * 2})


def test_a_saved_chain_of_other_inputs_is_kept_and_refused(template, tmp_path):
    """One e_sigma changed: the chain was deleted and replaced without a word."""
    data = _data(template)
    first = _run(data, state_dir=tmp_path)
    chain = tmp_path / "ghaednia_coulomb.h5"
    saved = chain.read_bytes()
    with pytest.raises(SavedChainError) as info:
        _run(_wider_e_sigma(data), state_dir=tmp_path)
    assert str(info.value) == (
        f"the saved chain {chain} was made with other inputs (the measured values' "
        "uncertainties changed); it is kept: restart=True discards it and starts again (or "
        "give another state_dir)"
    )
    assert chain.read_bytes() == saved
    assert pickle.loads(pickle.dumps(info.value)).state == chain  # as a Dask worker raises it
    again = _run(data, state_dir=tmp_path)  # the same inputs resume it
    np.testing.assert_array_equal(again.best.samples, first.best.samples)
    fresh = _run(_wider_e_sigma(data), state_dir=tmp_path, restart=True)
    assert chain.read_bytes() != saved and fresh.best.steps == 10
    with pytest.raises(SavedChainError, match=r"other inputs \(the seed changed\)"):
        _run(_wider_e_sigma(data), state_dir=tmp_path, seed=1)


def test_an_unreadable_saved_chain_is_kept_and_refused(template, tmp_path):
    data = _data(template)
    _run(data, state_dir=tmp_path)
    chain = tmp_path / "ghaednia_coulomb.h5"
    cut = chain.read_bytes()[: chain.stat().st_size // 2]  # a run stopped while writing
    chain.write_bytes(cut)
    with pytest.raises(SavedChainError, match=rf"the saved chain {chain} cannot be read \(.*\): "
                       r"a run stopped while writing it, or another file; it is kept: "
                       r"restart=True discards it") as info:  # fmt: skip
        _run(data, state_dir=tmp_path)
    assert "\n" not in str(info.value) and chain.read_bytes() == cut
    assert _run(data, state_dir=tmp_path, restart=True).best.steps == 10


def test_cli_names_the_chain_and_restart(template, tmp_path):
    data = _data(template)
    out = tmp_path / "o"
    args = ["-p", "mu=uniform(0, 0.6)", "--walkers", "6", "--steps", "10", "--out", str(out),
            "--quiet"]  # fmt: skip
    first = runner.invoke(app, ["calibrate", str(data.to_csv(tmp_path / "a.csv")), *args])
    assert first.exit_code == 0, first.output
    other = str(_wider_e_sigma(data).to_csv(tmp_path / "b.csv"))
    r = runner.invoke(app, ["calibrate", other, *args])
    assert isinstance(r.exception, ValueError)
    assert str(r.exception) == (
        f"the saved chain {out / 'state' / 'ghaednia_coulomb.h5'} was made with other inputs "
        "(the measured values' uncertainties changed); it is kept: --restart discards it and "
        "starts again (or choose another --out)"
    )
    assert runner.invoke(app, ["calibrate", other, *args, "--restart"]).exit_code == 0


def _no_space(monkeypatch):
    import impactlab._files

    def full(fd):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(impactlab._files.os, "fsync", full)


def test_a_full_disk_leaves_the_measurements_file_whole(template, tmp_path, monkeypatch):
    """append_experiment rewrote the user's file in place: a full disk left it cut short."""
    from types import SimpleNamespace

    from impactlab.calibrate.experiment_rows import append_experiment
    from impactlab.experiment.uncertainty import Estimate

    path = _data(template).to_csv(tmp_path / "drops.csv")
    before = path.read_bytes()
    kin = SimpleNamespace(
        angle_in=Estimate(math.radians(30), 0.01, "rad"),
        v_c_in=(Estimate(0.0, 0.01, "m/s"), Estimate(-1.4, 0.01, "m/s")),
        spin_in=Estimate(0.0, 0.1, "rad/s"),
        mu=Estimate(0.2, 0.02, ""),
    )
    summary = {"e": Estimate(0.5, 0.02, "")}
    res = SimpleNamespace(kinematics=kin, summary=lambda: summary, rod={}, errors={})
    _no_space(monkeypatch)
    with pytest.raises(OSError, match="No space left"):
        append_experiment(path, res, "new")
    assert path.read_bytes() == before
    assert [p.name for p in tmp_path.iterdir()] == ["drops.csv"]  # no partial file left
    monkeypatch.undo()
    assert append_experiment(path, res, "new").labels[-1] == "new"


@pytest.fixture(scope="module")
def one_drop_fit():
    """Two models on one drop (a tiny chain)."""
    one = Measurements.from_records(
        [{"label": "d20", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.45, "e_sigma": 0.02,
          "delta_p": "50 um", "delta_p_sigma": "3 um"}]
    )  # fmt: skip
    return calibrate(one, [MU], ["ghaednia/coulomb", "ghaednia/mindlin"], walkers=6, steps=12,
                     n_ppc=0)  # fmt: skip


def test_one_drop_ranks_no_model(one_drop_fit):
    """dse 0 and weights 1 / 1e-16 declared a winner ('distinguishable: true')."""
    note = "not distinguishable (one drop: PSIS-LOO does not rank)"
    assert [r["distinguishable"] for r in one_drop_fit.ranking] == [False, False]
    assert all(r["note"].startswith(note) for r in one_drop_fit.ranking)
    assert note in one_drop_fit.best_caveats
    text = "PSIS-LOO with one drop: leaving it out leaves no data, so elpd_loo does not rank"
    assert any(w.startswith(text) for w in one_drop_fit.warnings)
    doc = calibration_json(one_drop_fit)
    assert [r["distinguishable"] for r in doc["ranking"]] == [False, False]
    assert any(w.startswith(text) for w in doc["warnings"])


def test_results_are_written_whole_with_readable_settings(one_drop_fit, tmp_path, monkeypatch):
    files = save(one_drop_fit, tmp_path)
    html = files["report"].read_text()
    assert "<td>engine: gravity</td><td>9.80665 m/s^2</td>" in html
    assert "<td>engine: rtol</td><td>default</td>" in html
    assert "<td>parameters: mu</td><td>uniform(0, 0.6)</td>" in html
    assert "<td>model_definitions: ghaednia/mindlin</td><td>law = ghaednia; friction = mindlin" in (
        html
    )
    assert "{&#x27;" not in html and "[&#x27;" not in html  # no Python reprs
    before = {k: v.read_bytes() for k, v in files.items()}
    _no_space(monkeypatch)
    with pytest.raises(OSError, match="No space left"):
        save(one_drop_fit, tmp_path)
    assert {k: v.read_bytes() for k, v in files.items()} == before


def test_results_json_engine_settings_run_again(one_drop_fit, tmp_path):
    """Copied into a --config file's [engine] table, results.json's gravity was refused
    ("gravity must be a real number, got {'value': 9.80665, 'unit': 'm/s^2'}")."""
    engine = calibration_json(one_drop_fit)["settings"]["engine"]
    assert engine["gravity"] == {"value": 9.80665, "unit": "m/s^2"}
    cfg = tmp_path / "cal.toml"
    cfg.write_text(
        '[engine]\ngravity = { value = 9.80665, unit = "m/s^2" }\n'
        'rtol = { value = 1e-7, unit = "1" }\n'
    )
    assert load_config(cfg)["engine"] == {"gravity": 9.80665, "rtol": 1e-7}
    assert engine_options({"gravity": {"value": 981, "unit": "cm/s^2"}})[1] == pytest.approx(9.81)
    assert engine_options(json.loads(json.dumps(engine)))[1] == 9.80665
    cfg.write_text('[engine]\ngravity = { value = 9.8, unit = "m" }\n')
    with pytest.raises(ValueError, match=rf"{cfg}: \[engine\] gravity"):
        load_config(cfg)
