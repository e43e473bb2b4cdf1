"""The finite-element reference warns when ``t_stop`` ends before its sequence does, judged
from the state at ``t_stop`` by the drop's end-of-sequence rule (docs/flexible.md,
"Independent discretisation")."""

from __future__ import annotations

import math
import warnings
from typing import Any

import pytest

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.flex_reference import SequenceOpenWarning, drop_reference

KW: dict[str, Any] = {"mu": 0.2, "angle": math.radians(20), "velocity": (0.0, -1.41)}


def test_a_sequence_cut_short_warns() -> None:
    """At 0.5 ms the paper's 20 deg drop has had 2 of its 4 contacts (e 0.093, not 0.721)."""
    with pytest.warns(SequenceOpenWarning, match=r"t_stop = 0.0005 s ends before the sequence"):
        ref = drop_reference(FlexibleRod.paper(), **KW, t_stop=0.5e-3)
    assert len(ref.contacts) == 2


def test_a_finished_sequence_does_not_warn() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", SequenceOpenWarning)
        ref = drop_reference(FlexibleRod.paper(), **KW, t_stop=0.95e-3 + 1e-3)
    assert len(ref.contacts) == 4
    assert ref.e == pytest.approx(0.721, abs=0.002)
