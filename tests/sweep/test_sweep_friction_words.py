"""A study's friction model: a model the batch engine does not run is named as such (not as
unknown), with the models a sweep runs and where the model does run; a name that is no model
is unknown, with the known models."""

from __future__ import annotations

import pytest

from impactlab.friction import friction_names
from impactlab.sweep.engine import EngineEvaluator, _validate_categories


def test_a_known_model_outside_the_batch_is_not_called_unknown() -> None:
    with pytest.raises(ValueError, match=r"^friction model 'mindlin' does not run") as info:
        _validate_categories({"friction": ["mindlin"]}, ("impulse_ratio", "coulomb"))
    message = str(info.value)
    assert "unknown" not in message
    assert message == (
        "friction model 'mindlin' does not run in the batch engine that sweeps use; "
        "sweep models: impulse_ratio, coulomb (impactlab.simulate runs 'mindlin')"
    )


def test_a_name_that_is_no_model_is_unknown_with_every_model() -> None:
    with pytest.raises(ValueError, match=r"^unknown friction model 'coulomn'") as info:
        _validate_categories({"friction": ["coulomn"]}, ("coulomb",))
    message = str(info.value)
    assert message.startswith("unknown friction model 'coulomn'")
    assert "coulomb" in message and message.endswith(f"known: {', '.join(friction_names())}")


def test_every_friction_model_runs_in_a_sweep(tmp_path) -> None:
    from impactlab.sweep import Study, run_sweep

    names = list(friction_names())
    EngineEvaluator().validate({"friction": names})
    study = Study(name="frictions", grid={"friction": names},
                  fixed={"angle": 0.35, "vy": -1.41, "mu": 0.2})  # fmt: skip
    ds = run_sweep(study, tmp_path / "f.zarr", quiet=True).dataset
    assert ds["status"].values.tolist() == [0] * len(names)
    e = dict(zip(ds["friction"].values.tolist(), ds["e"].values.tolist(), strict=True))
    assert set(e) == set(names) and all(0.0 < v < 1.0 for v in e.values())
