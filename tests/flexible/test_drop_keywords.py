"""Keywords ``simulate`` and ``simulate_drop`` do not take: answered as ``simulate_batch``
answers them (the nearest name or a note, then the keywords taken), not Python's bare
TypeError; ``simulate``'s list names ``partial_slip_cells``."""

from __future__ import annotations

import inspect
from typing import Any

import pytest

import impactlab as il

ROD = il.Rod.paper()
KW: dict[str, Any] = {"angle": 0.3, "velocity": (0.0, -1.4)}


@pytest.mark.parametrize("body", [ROD, il.FlexibleRod.paper()])
def test_simulate_suggests_partial_slip_cells(body: object) -> None:
    with pytest.raises(TypeError) as err:
        il.simulate(body, friction="partial_slip", partial_slip_cell=32, **KW)  # type: ignore[call-overload]
    text = str(err.value)
    assert "partial_slip_cell (did you mean 'partial_slip_cells'?)" in text
    assert "partial_slip_cells" in text.split("it takes ")[1]


def test_simulate_drop_names_the_nearest_keyword() -> None:
    with pytest.raises(TypeError, match=r"^simulate_drop\(\) got unexpected keyword argument\(s\) "
                       r"mue \(did you mean 'mu'\?\); it takes angle, "):  # fmt: skip
        il.simulate_drop(ROD, mue=0.2, **KW)  # type: ignore[call-arg]


def test_simulate_drop_notes_what_a_drop_has_not() -> None:
    with pytest.raises(TypeError, match=r"partial_slip_cells \(a drop's partial slip has 16 "):
        il.simulate_drop(ROD, partial_slip_cells=32, **KW)  # type: ignore[call-arg]
    with pytest.raises(TypeError, match=r"constant_angle \(a drop follows the rod's rotation\)"):
        il.simulate_drop(ROD, constant_angle=False, **KW)  # type: ignore[call-arg]


def test_simulate_drop_keeps_its_signature_and_runs() -> None:
    assert "velocity" in inspect.signature(il.simulate_drop).parameters
    assert il.simulate_drop(ROD, history=False, **KW).e > 0.0
