"""A saved chain resumes under the same engine settings however they are written, a chain saved
before the settings were normalised resumes too, and an empty chain file holds no work."""

from __future__ import annotations

import json

import numpy as np
import pytest

from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
from impactlab.calibrate import sampler as S
from impactlab.calibrate.statelock import SavedChainError
from impactlab.calibrate.synthetic import synthetic_measurements

MU = parse_parameter("mu", "uniform(0, 0.6)")
pytestmark = pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")
CHAIN = "ghaednia_coulomb.h5"


@pytest.fixture
def data(template):
    return synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip


def _run(data, **kw):
    return calibrate(data, [MU], walkers=6, steps=10, n_ppc=0, **kw)


@pytest.mark.parametrize(
    ("engine", "acting"),
    [
        (None, []),
        ({"gravity": True, "rtol": None}, []),
        ({"gravity": 9.80665}, []),
        ({"gravity": "9.80665 m/s^2"}, []),
        ({"gravity": False}, [("gravity", 0.0), ("rtol", None)]),
        ({"gravity": 0, "rtol": 1e-7}, [("gravity", 0.0), ("rtol", 1e-7)]),
        ({"gravity": 9.81}, [("gravity", 9.81), ("rtol", None)]),
    ],
)
def test_the_engine_options_are_hashed_as_they_act(engine, acting):
    assert S._engine(engine or {}) == acting


def _resumed(data, state_dir, engine):
    """Run again; True when the saved chain's 10 steps were taken up, not sampled anew."""
    seen: list[int] = []
    _run(data, state_dir=state_dir, engine=engine, progress=lambda m, done, n: seen.append(done))
    return seen[0] == 10


def test_equal_engine_settings_resume(data, tmp_path):
    first = _run(data, state_dir=tmp_path)
    for engine in (
        {"gravity": True},
        {"gravity": 9.80665},
        {"gravity": {"value": 9.80665, "unit": "m/s^2"}},  # results.json's settings
        {"rtol": None},
    ):
        assert _resumed(data, tmp_path, engine), engine
    again = _run(data, state_dir=tmp_path, engine={"gravity": True})
    np.testing.assert_array_equal(again.best.samples, first.best.samples)
    with pytest.raises(SavedChainError, match=r"other inputs \(the engine options changed\)"):
        _run(data, state_dir=tmp_path, engine={"gravity": False})
    off = tmp_path / "off"
    first = _run(data, state_dir=off, engine={"gravity": False})
    assert _resumed(data, off, {"gravity": 0.0})


def test_a_chain_saved_with_the_options_as_given_resumes(data, tmp_path, monkeypatch):
    """A chain saved before the normalisation (the options hashed as written) resumes with the
    same options, and is then stored under the new fingerprint."""
    monkeypatch.setattr(
        S, "_engine", lambda engine: sorted((k, repr(v)) for k, v in engine.items())
    )
    first = _run(data, state_dir=tmp_path, engine={"gravity": False})
    monkeypatch.undo()
    with pytest.raises(SavedChainError, match=r"the engine options changed"):
        _run(data, state_dir=tmp_path, engine={"gravity": 0})  # written otherwise: unknown
    assert _resumed(data, tmp_path, {"gravity": False})
    assert _resumed(data, tmp_path, {"gravity": 0})  # now stored as it acts
    again = _run(data, state_dir=tmp_path, engine={"gravity": 0.0})
    np.testing.assert_array_equal(again.best.samples, first.best.samples)


def test_an_empty_chain_file_holds_no_work(data, tmp_path):
    (tmp_path / CHAIN).write_bytes(b"")
    res = _run(data, state_dir=tmp_path)
    assert res.best.steps == 10 and (tmp_path / CHAIN).stat().st_size > 0
    np.testing.assert_array_equal(res.best.samples, _run(data).best.samples)


def test_the_stored_parts_name_the_engine(data, tmp_path):
    import h5py

    _run(data, state_dir=tmp_path, engine={"gravity": 9.81})
    with h5py.File(tmp_path / CHAIN, "r") as f:
        parts = json.loads(f["chain"].attrs["impactlab_parts"])
    assert parts["engine"] == S._hash([("gravity", 9.81), ("rtol", None)])


def test_a_chain_saved_without_correlations_is_not_resumed_with_them(data, tmp_path):
    """The correlations change the likelihood: a chain saved without them is refused, naming
    them, and one saved with them resumes with the same ones."""
    import dataclasses

    _run(data, state_dir=tmp_path)
    rho = {("e", "spin_out"): np.full(data.n_drops, -0.9)}
    correlated = dataclasses.replace(data, correlation=rho)
    with pytest.raises(SavedChainError, match=r"the drops' correlation coefficients changed"):
        _run(correlated, state_dir=tmp_path)
    other = tmp_path / "correlated"
    _run(correlated, state_dir=other)
    assert _resumed(correlated, other, None)
