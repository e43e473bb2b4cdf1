"""A calibration's ``[engine] partial_slip_cells`` against its candidate models: refused, in a
sweep's words, when no model is a rigid body with friction ``partial_slip``; accepted (for
those models) when one is."""

from __future__ import annotations

import pytest

from impactlab.calibrate import Measurements, calibrate
from impactlab.calibrate.input_checks import check_engine_cells
from impactlab.calibrate.model_specs import parse_model

CELLS = {"partial_slip_cells": 32}
MEAS = Measurements.from_records([{"angle": "45 deg", "vy": -1.4, "e": 0.5, "e_sigma": 0.03}])


def _models(*names: str) -> list:
    return [parse_model(n) for n in names]


@pytest.mark.parametrize(
    ("models", "words"),
    [
        (["hertz/coulomb"], r"sets the cells of friction 'partial_slip' only, and the candidate "
         r"models' friction is coulomb: leave it out"),
        (["hertz/coulomb", "hertz/mindlin"], r"friction is coulomb, mindlin: leave it out"),
        (["hertz/partial_slip/flexible_rod"], r"a flexible rod's drop has its compiled 16 cells "
         r"per end, which cannot be changed; leave it out for body = 'flexible_rod'"),
    ],
)  # fmt: skip
def test_cells_no_model_uses_are_refused(models: list[str], words: str) -> None:
    with pytest.raises(ValueError, match=r"^\[engine\] partial_slip_cells = 32.*" + words):
        calibrate(MEAS, {"mu": "uniform(0, 0.6)"}, models, walkers=4, steps=10, engine=CELLS)


def test_cells_apply_where_a_rigid_partial_slip_model_is() -> None:
    check_engine_cells(CELLS, _models("hertz/partial_slip"))
    check_engine_cells(CELLS, _models("hertz/partial_slip", "hertz/partial_slip/flexible_rod"))
    check_engine_cells(CELLS, _models("hertz/coulomb", "hertz/partial_slip"))
    for default in ({}, {"partial_slip_cells": None}, {"partial_slip_cells": 16}):
        check_engine_cells(default, _models("hertz/coulomb", "hertz/partial_slip/flexible_rod"))
