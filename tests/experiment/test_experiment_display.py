"""The experiment's objects print as short summaries in display units (um, mm, ms, deg), never
as raw arrays: MarkerTracks, HeightMap, ImpactKinematics (``result.kinematics``) and
DentMetrics (``result.dent``), the last two with a table in ``str`` and ``_repr_html_``."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from impactlab.experiment import read_markers, read_scan
from impactlab.experiment.markers.tracks import MarkerTracks
from impactlab.experiment.profilometry.heightmap import HeightMap

from .conftest import EXAMPLE_DATA


def _short(text: str, bound: int) -> None:
    assert len(text) <= bound, text
    assert "\n" not in text and "array(" not in text


def test_marker_tracks_repr_summarises_the_file() -> None:
    tracks = read_markers(EXAMPLE_DATA / "drop.csv")
    text = repr(tracks)
    _short(text, 200)
    missing = int(tracks.valid.size - np.count_nonzero(tracks.valid))
    span_ms = (tracks.time[-1] - tracks.time[0]) * 1e3
    assert text == (
        f"MarkerTracks(drop.csv: {tracks.n_frames} frames at {tracks.rate:.4g} Hz over "
        f"{span_ms:.4g} ms, 3 markers M1, M2, M3, {missing} of {tracks.valid.size} positions "
        "occluded; positions in m)"
    )
    assert text.startswith("MarkerTracks(drop.csv: 71 frames at 500 Hz over 140 ms")


def test_marker_tracks_repr_without_a_source_or_occlusion() -> None:
    tracks = MarkerTracks(np.arange(4) * 0.01, np.zeros((4, 2, 3)), ("a", "<b>"))
    assert repr(tracks) == (
        "MarkerTracks(4 frames at 100 Hz over 30 ms, 2 markers a, <b>, all seen; positions in m)"
    )


def test_height_map_repr_gives_pixels_size_and_heights_in_um() -> None:
    scan = read_scan(EXAMPLE_DATA / "dent.npy", pixel_size="12 um", height_unit="um")
    text = repr(scan)
    _short(text, 200)
    ny, nx = scan.shape
    z = scan.z[scan.valid] * 1e6
    assert text.startswith(f"HeightMap(dent.npy: {nx} x {ny} pixels (x by y) of 12 um = ")
    assert f"z {z.min():.4g} .. {z.max():.4g} um" in text
    assert f"{nx * 0.012:.4g} x {ny * 0.012:.4g} mm" in text


def test_height_map_repr_with_rectangular_pixels() -> None:
    scan = HeightMap(np.full((8, 10), 2e-6), 1e-6, 2e-6)
    assert repr(scan) == (
        "HeightMap(10 x 8 pixels (x by y) of 1 x 2 um = 0.01 x 0.016 mm, z 2 .. 2 um, 100 % valid)"
    )


def test_kinematics_repr_is_one_line_in_display_units(analysed_example: Any) -> None:
    k = analysed_example.kinematics
    text = repr(k)
    _short(text, 300)
    assert text.startswith("ImpactKinematics(e=")
    assert f"angle_in={math.degrees(k.angle_in.value):.5g} ± " in text and " deg," in text
    assert f"t_impact={k.t_impact.value * 1e3:.5g} ± {k.t_impact.sigma * 1e3:.2g} ms" in text
    assert f"v_i={k.v_i.value:.5g} ± {k.v_i.sigma:.2g} m/s" in text
    assert f"e={k.e.value:.5g} ± {k.e.sigma:.2g}," in text
    assert f"mu={k.mu.value:.4g}" in text
    assert "ok=True" in text and "derived_names" not in text and " rad" not in text


def test_kinematics_table_in_str_and_html(analysed_example: Any) -> None:
    k = analysed_example.kinematics
    text = str(k)
    assert text.startswith("ImpactKinematics\n") and text != repr(k)
    assert f"{math.degrees(k.angle_out.value):.5g} ± " in text
    assert "spin_out" in text and "rad/s" in text and "frames before / after" in text
    page = k._repr_html_()
    assert page.startswith("<table>") and "<td>deg</td>" in page and "<td>ms</td>" in page
    odd = dataclasses.replace(k, warnings=("<b>x & y</b>",))
    assert "&lt;b&gt;x &amp; y&lt;/b&gt;" in odd._repr_html_()
    assert "<b>x" not in odd._repr_html_()
    assert repr(odd).endswith(", 1 warning)")


def test_dent_repr_is_one_line_in_um(analysed_example: Any) -> None:
    d = analysed_example.dent
    text = repr(d)
    _short(text, 300)
    assert text.startswith("DentMetrics(dent.npy: delta_p=")
    p = d.delta_p
    assert f"delta_p={p.value * 1e6:.5g} ± {p.sigma * 1e6:.2g} um" in text
    ls = d.sliding_length
    assert f"sliding_length={ls.value * 1e6:.5g} ± {ls.sigma * 1e6:.2g} um" in text
    assert f"width={d.width.value * 1e3:.5g} ± {d.width.sigma * 1e3:.2g} mm" in text
    assert f"sliding_angle={math.degrees(d.sliding_angle):.5g} deg" in text
    assert f"pileup={d.pileup * 1e6:.5g} um" in text


def test_dent_table_in_str_and_html(analysed_example: Any) -> None:
    d = analysed_example.dent
    text = str(d)
    assert text.startswith("DentMetrics\n") and "outline points" in text
    assert f"noise                {d.noise * 1e6:.5g} um" in text
    odd = dataclasses.replace(d, source="a<b>.npy", warnings=("w & <i>",))
    page = odd._repr_html_()
    assert "a&lt;b&gt;.npy" in page and "w &amp; &lt;i&gt;" in page and "<i>" not in page
    assert repr(odd).startswith("DentMetrics(a<b>.npy: ") and repr(odd).endswith(", 1 warning)")
