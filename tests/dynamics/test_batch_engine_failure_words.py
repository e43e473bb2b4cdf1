"""A case that the engine stops (status 1, 3, 5, 6, 9) reads in ``BatchResult.messages`` as
``simulate``'s ValueError words the same impact: the case's own values (the law's limit, the
approach speed, the gravity, Painleve's ratio) and what to change, not the bare status text;
a drop batch's own failures keep their words."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.kernels.status import STATUS_MESSAGES

ROD = il.Rod.paper()
SPHERE = il.Sphere(radius=0.01)


def _simulate_error(body: il.Rod | il.Sphere, **kw: object) -> str:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ValueError, match=r"\S") as err:
            il.simulate(body, **kw)  # type: ignore[call-overload]
    return str(err.value)


@pytest.mark.parametrize(
    ("body", "case", "status"),
    [
        (SPHERE, {"vy": -1e-9}, 3),  # comes to rest on the flat under gravity
        (ROD, {"angle": 1.5, "vy": -300.0}, 1),  # past the law's largest interference
        (ROD, {"angle": 0.3, "vy": -1.0, "mu": 5.0, "friction": "impulse_ratio"}, 1),  # jam
    ],
)
def test_an_engine_failure_reads_as_simulate_words_it(
    body: il.Rod | il.Sphere, case: dict[str, object], status: int
) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        batch = il.simulate_batch(body, **case)  # type: ignore[arg-type]
    assert batch.status.tolist() == [status]
    one = {k: v for k, v in case.items() if k not in ("vy",)} | {"velocity": (0.0, case["vy"])}
    said = _simulate_error(body, **one)
    assert batch.messages == [said]
    assert said != STATUS_MESSAGES[status]  # more than the bare status text


def test_the_words_follow_each_case_s_values_and_the_batch_s_gravity() -> None:
    batch = il.simulate_batch(SPHERE, vy=[-1e-9, -2e-9, -1.0], gravity="5 m/s^2")
    msgs = batch.messages
    assert msgs[2] == "ok"
    assert "approached the flat at 1e-09 m/s" in msgs[0]
    assert "approached the flat at 2e-09 m/s" in msgs[1]
    assert all("with gravity 5 m/s^2" in m and "pass gravity=False" in m for m in msgs[:2])
    assert set(batch.refusals) == {0, 1}


def test_a_drop_batch_keeps_its_own_words() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drops = il.simulate_drops(ROD, angle=1.5, vy=[-300.0, -1.0])
    law_limit = STATUS_MESSAGES[1]
    assert drops.messages[0].startswith(f"{law_limit} (")
    assert "lower the impact velocity" in drops.messages[0]
    assert drops.messages[1] == "ok"
    assert np.array_equal(drops.status, [1, 0])
