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


def test_every_model_runs_in_a_sweep_today() -> None:
    EngineEvaluator().validate({"friction": list(friction_names())})
