"""One rule for a measured e above 1 (or below 0): the markers stage accepted e within 3 sigma of
[0, 1] as noise, and the inversion then refused it (`e must lie in [0, 1], got 1.0013...`)."""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import pytest

from impactlab import testing as S
from impactlab._validation import ImplausibleInputWarning
from impactlab.analytic import invert
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, analyze

DROP = dict(angle=math.radians(20), v_i=-1.41, mu=0.2, delta_p=22e-6, sliding_length=1.4e-3)


def test_an_e_above_1_within_its_noise_is_taken_at_1() -> None:
    with pytest.warns(ImplausibleInputWarning, match="read as measurement noise") as caught:
        r = invert(**DROP, e=(1.0013, 0.0053), dv_cy=0.82, n_samples=200)
    (note,) = [str(w.message) for w in caught if "read as" in str(w.message)]
    assert note.startswith("e = 1.0013 +- 0.0053 lies above 1 (0.25 sigma")
    assert "taken as e = 1 +- 0.0053" in note
    assert r.inputs["e"] == (1.0, 0.0053) and r.duration > 0


def test_an_e_below_0_within_its_noise_is_taken_at_0() -> None:
    with pytest.warns(ImplausibleInputWarning, match="lies below 0 .2 sigma"):
        r = invert(**DROP, e=(-0.01, 0.005), dv_cy=0.42, n_samples=200)
    assert r.inputs["e"] == (0.0, 0.005)


@pytest.mark.parametrize(
    ("e", "needles"),
    [
        ((1.02, 0.0053), ("within 3 sigma of it as measurement noise", "[-0.0159, 1.016]",
                          "got e = 1.02 +- 0.0053, 3.77 sigma above 1")),
        (1.0013, ("e must lie in [0, 1], got 1.0013", "when given with its sigma")),
        ((-0.2, 0.01), ("got e = -0.2 +- 0.01, 20 sigma below 0",)),
    ],
)  # fmt: skip
def test_an_e_beyond_its_noise_is_refused_with_the_rule(e: Any, needles: tuple[str, ...]) -> None:
    with pytest.raises(ValueError, match="e must lie in") as err:
        invert(**DROP, e=e, dv_cy=0.62, n_samples=200)
    for needle in needles:
        assert needle in str(err.value)


def test_analyze_inverts_a_nearly_elastic_drop(tmp_path: Path, scans: dict) -> None:
    """A drop of e = 1 whose markers measure e = 1.004 +- 0.0022 (1.8 sigma above 1: the markers
    stage passes it on without a word)."""
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45), (-0.5, -2.0), e=1.0, mu=0.15)
    tracks, info = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=2)
    path = S.write_c3d(tracks, tmp_path / "elastic.c3d")
    geometry = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)  # all in res.warnings
        res = analyze(path, scans[45].files["x3p"], PAPER_ROD, geometry=geometry, n_samples=500)
    assert res.kinematics is not None and res.kinematics.e.value > 1.0
    assert not res.errors and res.inversion is not None
    (note,) = [w for w in res.warnings if "read as measurement noise" in w]
    assert note.startswith("inversion: e = 1.00") and "taken as e = 1 +- 0.002" in note
