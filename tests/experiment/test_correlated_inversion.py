"""``analyze`` passes the correlations of its kinematic inputs (one pair of marker fits gives
the angle, v_i, mu, e, dv_cy and vt_in) to the inversion: on the shipped example sigma_F is
1.02 N, not the 0.91 N of inputs taken as independent, and sigma_T 37.4 us, not 41.2 us."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from impactlab.experiment.analysis import KINEMATIC_INPUTS, kinematic_correlation


def test_example_sigmas_correlated(analysed_example: Any) -> None:
    inv = analysed_example.inversion
    assert inv is not None
    assert inv.sigma_T_linear == pytest.approx(37.4e-6, rel=0.01)  # 41.2 us independent
    assert inv.sigma_F_linear == pytest.approx(1.023, rel=0.01)  # 0.913 N independent
    assert inv.sigma_T_mc == pytest.approx(inv.sigma_T_linear, rel=0.03)
    assert inv.sigma_F_mc == pytest.approx(inv.sigma_F_linear, rel=0.03)
    corr = inv.correlation
    assert corr[("e", "dv_cy")] == pytest.approx(0.94, abs=0.01)
    assert corr[("angle", "vt_in")] == pytest.approx(0.77, abs=0.01)
    # v_i is the magnitude of the tip's downward velocity: its sign flipped with it
    assert corr[("v_i", "vt_in")] == pytest.approx(0.75, abs=0.01)
    assert not any(k in pair for pair in corr for k in ("delta_p", "sliding_length"))


def test_kinematic_correlation_from_the_covariance(analysed_example: Any) -> None:
    """Every pair of the kinematic inputs, its coefficient that of the derived quantities."""
    k = analysed_example.kinematics
    corr = kinematic_correlation(k)
    keys = list(KINEMATIC_INPUTS)
    assert set(corr) == {(a, b) for i, a in enumerate(keys) for b in keys[i + 1 :]}
    names = list(k.derived_names)
    cov = np.asarray(k.derived_cov)
    i, j = names.index("e"), names.index("dv_cy")
    assert corr[("e", "dv_cy")] == pytest.approx(cov[i, j] / np.sqrt(cov[i, i] * cov[j, j]))
