"""The core's hot leaf functions are compiled without reference counting (``kernels._jit``)."""

from __future__ import annotations

import pytest

from impactlab.dynamics.core import accumulate, approach, integrator

pytestmark = pytest.mark.perf  # resource use of the compiled engine, not its speed


@pytest.mark.parametrize(
    "fn",
    [
        integrator.dp_step,
        integrator.first_event,
        integrator.locate,
        accumulate.track,
        approach._step,
    ],
)
def test_hot_leaf_functions_carry_no_reference_counts(fn: object) -> None:
    assert fn.targetoptions.get("_nrt") is False  # type: ignore[attr-defined]
