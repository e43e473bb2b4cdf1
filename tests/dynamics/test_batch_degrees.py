"""A batch of a rod whose every angle lies in (pi/2 + 10 deg, 90] was given degrees: refused
with the hint ``simulate`` gives for one angle (before, every case failed with status 7,
silently); up to 10 deg past pi/2 an angle is a rod leaning past the normal, refused case by
case with what it means, as ``simulate`` refuses it."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab as il


def test_angles_in_degrees_are_refused_with_the_hint() -> None:
    with pytest.raises(
        ValueError, match=r"every value lies in \(pi/2 \+ 10 deg, 90\] \(10 to 20\): degrees"
    ):
        il.simulate_batch(il.Rod.paper(), angle=np.array([10.0, 20.0]), vy=-1.41)


def test_a_batch_with_some_angles_beyond_pi_half_reports_them_case_by_case() -> None:
    b = il.simulate_batch(il.Rod.paper(), angle=np.array([0.3, 95.0]), vy=-1.41)
    assert b.status.tolist()[0] == 0 and b.status.tolist()[1] != 0
    ok = il.simulate_batch(il.Rod.paper(), angle=np.radians([10.0, 20.0]), vy=-1.41)
    assert (ok.status == 0).all()


def test_angles_just_past_pi_half_are_a_rod_past_the_normal() -> None:
    """1.6 rad was called degrees and the whole batch refused."""
    b = il.simulate_batch(il.Rod.paper(), angle=np.array([1.6, 1.62]), vy=-1.41)
    assert (b.status == 7).all()
    assert all("leans past the flat's normal" in m for m in b.messages)


def test_some_angles_in_degrees_are_said_once_as_drops_say_it() -> None:
    with pytest.warns(
        il.ImplausibleInputWarning, match=r"every refused angle \(1 case\(s\), 20\) lies in"
    ):
        b = il.simulate_batch(il.Rod.paper(), angle=np.array([0.3, 20.0]), vy=-1.41)
    assert b.status.tolist() == [0, 7]
