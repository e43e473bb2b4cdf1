"""``calibrate.predict`` refuses ``partial_slip_cells`` for a model that never uses it, as
``calibrate`` does (formerly it was accepted and ignored)."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.calibrate import CandidateModel, predict
from impactlab.calibrate.models import _check_cells
from impactlab.friction import PARTIAL_SLIP_CELLS


@pytest.mark.parametrize(
    ("model", "why"),
    [
        (CandidateModel("ghaednia", "partial_slip", body="flexible_rod"), "flexible rod's drop"),
        (CandidateModel("ghaednia", "coulomb"), "friction 'coulomb'"),
    ],
)
def test_cells_for_a_model_that_never_uses_them_are_refused(model, why) -> None:
    with pytest.raises(ValueError, match=f"partial_slip_cells = 32 .*{why}.*leave it out"):
        predict(model, None, [], np.zeros((1, 0)), engine={"partial_slip_cells": 32})  # type: ignore[arg-type]


def test_the_default_count_and_a_rigid_partial_slip_model_pass() -> None:
    flexible = CandidateModel("ghaednia", "partial_slip", body="flexible_rod")
    _check_cells(flexible, {"partial_slip_cells": PARTIAL_SLIP_CELLS})
    _check_cells(flexible, None)
    _check_cells(CandidateModel("ghaednia", "partial_slip"), {"partial_slip_cells": 32})
