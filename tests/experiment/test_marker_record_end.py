"""Too few frames after the impact: the error names the cause (the record, or a marker, ends too
soon after the impact, which may then lie later than found), and the warnings the marker stage
found before it failed are kept."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import (
    MarkerGeometry,
    MarkerTracks,
    TooFewFramesError,
    analyze,
    measure_impact,
    write_csv_markers,
)
from impactlab.materials import AISI_1010


@pytest.fixture(scope="module")
def truth() -> S.ImpactTruth:
    return S.engine_impact(PAPER_ROD, AISI_1010, math.radians(45), (0.0, -2.18), mu=0.13)


def _tracks(truth: S.ImpactTruth, after: float) -> tuple[MarkerTracks, int, MarkerGeometry]:
    """Tracks without occlusions ending ``after`` [s] past the impact, the first frame after
    the impact and the geometry."""
    tracks, info = S.marker_tracks(
        PAPER_ROD, truth, after=after, noise=0.1e-3, occlusion=0.0, occlusion_burst=0, seed=1
    )
    first = int(np.searchsorted(tracks.time, info["t_impact"]))
    return tracks, first, MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])


def _error(tracks: MarkerTracks, geometry: MarkerGeometry) -> TooFewFramesError:
    with pytest.raises(TooFewFramesError) as info:
        measure_impact(tracks, PAPER_ROD, geometry=geometry)
    return info.value


def test_a_record_that_ends_soon_after_the_impact(truth: S.ImpactTruth) -> None:
    """The error gave an impact time up to 3 frames early and no cause."""
    tracks, first, geo = _tracks(truth, 0.004)
    text = str(_error(tracks, geo))
    assert "after the impact" in text and "the record ends" in text
    assert "may lie up to" in text and "record longer after the impact" in text
    found = float(text.split("the impact at t = ")[1].split(" s")[0])
    end = float(text.split("to ")[-1].split(" s)")[0])
    assert found <= tracks.time[first] <= end + 1e-9  # the true impact within the range given


def test_a_marker_that_vanishes_soon_after_the_impact(truth: S.ImpactTruth) -> None:
    tracks, first, geo = _tracks(truth, 0.06)
    pos = tracks.positions.copy()
    pos[first + 2 :, 2] = np.nan  # M3 lost two frames after the impact
    text = str(_error(MarkerTracks(tracks.time, pos, tracks.labels), geo))
    assert f"marker M3 is missing from frame {first + 2} on" in text
    assert "the markers' poses end" in text and "seen longer after the impact" in text


def test_the_warnings_found_before_a_failure_are_kept(truth: S.ImpactTruth, tmp_path: Path) -> None:
    """A marker 30 mm off for 6 frames after the impact: its frames are left out (a warning),
    then too few remain; the warning was lost with the failure."""
    tracks, first, geo = _tracks(truth, 0.026)
    pos = tracks.positions.copy()
    pos[first + 5 : first + 11, 2, 2] += 0.03
    glitch = MarkerTracks(tracks.time, pos, tracks.labels)
    err = _error(glitch, geo)
    assert any("far off the rigid cluster" in w for w in err.warnings)
    assert "6 of the frames after it have no pose" in str(err)
    res: Any = analyze(write_csv_markers(glitch, tmp_path / "glitch.csv"), None, geometry=geo)
    assert "markers" in res.errors and res.kinematics is None
    assert any(w.startswith("markers: ") and "far off the rigid cluster" in w for w in res.warnings)
