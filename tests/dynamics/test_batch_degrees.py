"""A batch of a rod whose every angle lies in (pi/2, 90] was given degrees: refused with the
hint ``simulate`` gives for one angle (before, every case failed with status 7, silently)."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab as il


def test_angles_in_degrees_are_refused_with_the_hint() -> None:
    with pytest.raises(ValueError, match=r"every value lies in \(pi/2, 90\] \(10 to 20\): degrees"):
        il.simulate_batch(il.Rod.paper(), angle=np.array([10.0, 20.0]), vy=-1.41)


def test_a_batch_with_some_angles_beyond_pi_half_reports_them_case_by_case() -> None:
    b = il.simulate_batch(il.Rod.paper(), angle=np.array([0.3, 95.0]), vy=-1.41)
    assert b.status.tolist()[0] == 0 and b.status.tolist()[1] != 0
    ok = il.simulate_batch(il.Rod.paper(), angle=np.radians([10.0, 20.0]), vy=-1.41)
    assert (ok.status == 0).all()
