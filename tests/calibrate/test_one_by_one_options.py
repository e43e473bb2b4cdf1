"""A case the calibration runs one by one through ``simulate`` (the flexible rod on a
rate-dependent flat) gets the engine options the batch engines get: the same calibration
settings give the same numbers on either path."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pytest

from impactlab.calibrate import CandidateModel, Measurements, parse_parameter, predict
from impactlab.calibrate import models as M
from impactlab.sweep.models import Statics

MU = parse_parameter("mu", "uniform(0, 0.6)")
THETA = np.array([[0.3]])


class OneByOne:
    """An evaluator that runs every case as the calibration's one-by-one path does."""

    def __call__(
        self, cases: Mapping[str, np.ndarray], statics: Statics, outputs: Sequence[str]
    ) -> tuple[dict[str, np.ndarray], np.ndarray]:
        return M._one_by_one(cases, statics, outputs, None)


def _alone(*args: Any, **kw: Any) -> Any:
    """predict through :class:`OneByOne`."""
    return predict(*args, evaluator=OneByOne(), **kw)  # type: ignore[arg-type]


def _rod() -> Measurements:
    return Measurements.from_records([{"angle": "45 deg", "vy": -1.4, "e": 0.5, "e_sigma": 0.03}])


def _sphere() -> Measurements:  # near-normal incidence: e_t depends on the cells
    return Measurements.from_records(
        [{"body": "sphere", "radius": "5 mm", "vx": 0.05, "vy": -1.0, "e_t": 0.6,
          "e_t_sigma": 0.05}]
    )  # fmt: skip


@pytest.mark.parametrize(
    ("model", "meas", "q", "engine"),
    [
        (CandidateModel(body="flexible_rod"), _rod, "e", {"rtol": 1e-5}),
        (CandidateModel("hertz", "partial_slip"), _sphere, "e_t",
         {"gravity": False, "partial_slip_cells": 32}),
        (CandidateModel("hertz", "partial_slip"), _sphere, "e_t", {"gravity": False, "rtol": 1e-6}),
    ],
)  # fmt: skip
def test_one_by_one_equals_the_batch_with_the_same_options(
    model: CandidateModel, meas: Any, q: str, engine: dict[str, Any]
) -> None:
    m = meas()
    batch = predict(model, m, [MU], THETA, engine=engine).values[q][0, 0]
    alone = _alone(model, m, [MU], THETA, engine=engine).values[q][0, 0]
    plain = {"gravity": engine["gravity"]} if "gravity" in engine else None
    default = _alone(model, m, [MU], THETA, engine=plain).values[q][0, 0]
    assert math.isfinite(batch) and alone == batch
    assert alone != default  # the option changes the number: it reached simulate


def test_the_rate_dependent_flat_gets_the_rtol() -> None:
    """The one-by-one branch of predict (a rate law) runs the drop at the calibration's rtol."""
    from impactlab.bodies import FlexibleRod
    from impactlab.dynamics import simulate_drop
    from impactlab.materials import AISI_1010

    model = CandidateModel(body="flexible_rod", rate="cowper-symonds")
    assert not model.batched
    got = predict(model, _rod(), [MU], THETA, engine={"rtol": 1e-5}).values["e"][0, 0]
    x: dict[str, Any] = {"mu": 0.3, "angle": math.radians(45), "velocity": (0.0, -1.4)}
    x["rate"] = "cowper-symonds"
    loose = simulate_drop(FlexibleRod.paper(), AISI_1010, rtol=1e-5, **x)
    assert got == pytest.approx(loose.e, rel=1e-12)
    assert got != simulate_drop(FlexibleRod.paper(), AISI_1010, **x).e


def test_simulate_options_follow_the_batch_engines() -> None:
    def options(body: str, friction: str, **engine: Any) -> dict[str, Any]:
        cat = {"body": body, "friction": friction, "law": "hertz"}
        return M.simulate_options(Statics(cat, {}, engine))

    assert options("rod", "coulomb") == {"gravity": True}
    got = options("sphere", "partial_slip", gravity=9.81, rtol=1e-6, partial_slip_cells=32)
    assert got == {"gravity": 9.81, "rtol": 1e-6, "partial_slip_cells": 32}
    # the cells are partial_slip's only; a drop takes gravity and rtol (sweep.flexible)
    assert options("rod", "coulomb", partial_slip_cells=32) == {"gravity": True}
    flex = options("flexible_rod", "partial_slip", rtol=1e-7, partial_slip_cells=32,
                   constant_angle=True)  # fmt: skip
    assert flex == {"gravity": True, "rtol": 1e-7}
