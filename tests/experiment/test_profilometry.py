"""Scans: instrument formats through SurfaceTopography, levelling, dent metrics, clear errors."""

from __future__ import annotations

import math
import sys
import zipfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.dynamics import simulate
from impactlab.experiment import (
    DentCutOffError,
    DentNotFoundError,
    FileFormatError,
    HeightMap,
    MarkerTracks,
    MissingDependencyError,
    ScanError,
    level_plane,
    measure_dent,
    read_scan,
)
from impactlab.experiment.plots import plot_dent

from .conftest import CASES

FORMATS = ["x3p", "gwy", "nc", "sdf", "sdf-binary", "npy", "csv"]


@pytest.fixture(scope="module")
def small() -> tuple[np.ndarray, float, float, S.ScanTruth]:
    return S.synthetic_scan(delta_p=22e-6, sliding_length=400e-6, pixel=10e-6, seed=1)


@pytest.mark.parametrize("fmt", FORMATS)
def test_formats_round_trip(tmp_path: Path, small: Any, fmt: str) -> None:
    """Every written format reads back exactly (heights, pixel size, dropouts)."""
    z, dx, dy, _ = small
    ext = "sdf" if fmt.startswith("sdf") else fmt
    p = S.write_scan(z, dx, dy, tmp_path / f"s.{ext}", fmt=fmt)
    kw = {"pixel_size": dx, "height_unit": "m"} if fmt == "npy" else {}
    hm = read_scan(p, **kw)
    assert hm.shape == z.shape
    assert hm.dx == pytest.approx(dx, rel=1e-6) and hm.dy == pytest.approx(dy, rel=1e-6)
    np.testing.assert_array_equal(np.isnan(hm.z), np.isnan(z))
    np.testing.assert_allclose(hm.z[~np.isnan(z)], z[~np.isnan(z)], rtol=0, atol=2e-11)


def test_x3p_is_a_real_x3p(tmp_path: Path, small: Any) -> None:
    """The X3P container is ISO 5436-2: a zip with main.xml and the binary data."""
    z, dx, dy, _ = small
    p = S.write_scan(z, dx, dy, tmp_path / "s.x3p")
    with zipfile.ZipFile(p) as zf:
        names = zf.namelist()
        assert "main.xml" in names
        assert "ISO5436_2" in zf.read("main.xml").decode("utf-8", "replace")


@pytest.mark.parametrize("case", sorted(CASES))
@pytest.mark.parametrize("fmt", ["x3p", "gwy", "sdf"])
def test_recovers_the_dent(scans: dict, case: int, fmt: str) -> None:
    """Acceptance: delta_p within 2 %, L_s within 5 % (0.1 um noise, tilt, dropouts), each also
    within 3 reported sigmas; the sliding direction within 5 deg."""
    sc = scans[case]
    d = measure_dent(read_scan(sc.files[fmt]))
    g = sc.truth.groove
    assert abs(d.delta_p.value - g.depth) < 0.02 * g.depth
    assert abs(d.delta_p.value - g.depth) < 3.0 * d.delta_p.sigma
    assert abs(d.sliding_length.value - g.sliding_length) < 0.05 * g.sliding_length
    assert abs(d.sliding_length.value - g.sliding_length) < 3.0 * d.sliding_length.sigma
    assert abs(d.width.value - g.width) < 0.02 * g.width
    ang = math.degrees(sc.truth.direction)
    diff = (math.degrees(d.sliding_angle) - ang + 180.0) % 360.0 - 180.0
    assert abs(diff) < 5.0 and not d.direction_ambiguous
    assert d.pileup == pytest.approx(g.pileup, rel=0.25)
    assert d.outline.shape[1] == 2 and np.allclose(d.outline[0], d.outline[-1])


def test_levelling_is_not_biased_by_the_dent(scans: dict) -> None:
    sc = scans[70]  # the deepest dent, the largest share of the scan
    hm = HeightMap(sc.z, sc.dx, sc.dx)
    lev = level_plane(hm)
    a, b, c = lev.plane
    ta, tb, tc = sc.truth.plane
    assert abs(b - tb) < 2e-6 and abs(c - tc) < 2e-6  # slope error < 2 um per metre
    assert abs(a - ta) < 0.05e-6
    assert lev.sigma == pytest.approx(sc.truth.noise, rel=0.1)


def test_dropouts_at_the_deepest_point_are_filled(small: Any) -> None:
    z, dx, dy, truth = small
    d0 = measure_dent(HeightMap(z, dx, dy))
    z2 = z.copy()
    i, j = round(d0.deepest[1] / dy), round(d0.deepest[0] / dx)
    z2[i - 2 : i + 3, j - 2 : j + 3] = np.nan
    d = measure_dent(HeightMap(z2, dx, dy))
    assert d.filled_in_dent > 0
    assert d.delta_p.value == pytest.approx(truth.groove.depth, rel=0.02)


def test_no_dent(small: Any) -> None:
    z, dx, dy, _ = small
    rng = np.random.default_rng(0)
    flat = 0.1e-6 * rng.standard_normal(z.shape) + 1e-3 * np.arange(z.shape[1]) * dx
    with pytest.raises(DentNotFoundError, match=r"flat\.x3p: no dent found"):
        measure_dent(HeightMap(flat, dx, dy, "flat.x3p"))
    dust = flat.copy()
    dust[50:52, 60:62] -= 5e-6
    with pytest.raises(DentNotFoundError, match="dust or noise"):
        measure_dent(HeightMap(dust, dx, dy, "dust.x3p"))


@pytest.mark.parametrize(
    ("cut", "edge"),
    [((slice(None), slice(0, 180)), "right"), ((slice(170, None), slice(None)), "bottom")],
)
def test_dent_cut_off_by_the_edge(small: Any, cut: tuple, edge: str) -> None:
    z, dx, dy, _ = small
    with pytest.raises(DentCutOffError, match=rf"cut off by the scan's {edge}"):
        measure_dent(HeightMap(z[cut], dx, dy, "cut.x3p"))


@pytest.mark.parametrize("fmt", ["x3p", "gwy", "nc", "sdf", "sdf-binary"])
def test_truncated_files(tmp_path: Path, small: Any, fmt: str) -> None:
    z, dx, dy, _ = small
    ext = "sdf" if fmt.startswith("sdf") else fmt
    p = S.write_scan(z, dx, dy, tmp_path / f"s.{ext}", fmt=fmt)
    raw = p.read_bytes()
    bad = tmp_path / f"trunc.{ext}"
    bad.write_bytes(raw[: len(raw) // 2])
    with pytest.raises(FileFormatError, match=rf"trunc\.{ext}: "):
        read_scan(bad)


def test_wrong_format_and_garbage(tmp_path: Path, small: Any) -> None:
    _z, _dx, _dy, _ = small
    tr = MarkerTracks(np.arange(10) / 500.0, np.zeros((10, 3, 3)), ("a", "b", "c"))
    c3d = S.write_c3d(tr, tmp_path / "drop.c3d")
    wrong = tmp_path / "drop.sur"
    wrong.write_bytes(c3d.read_bytes())
    with pytest.raises(FileFormatError, match=r"drop\.sur: cannot be read as Digital Surf SUR"):
        read_scan(wrong)
    with pytest.raises(
        FileFormatError,
        match=r"drop\.c3d: (not a scan format|SurfaceTopography "
        r"reads it as)",
    ):
        read_scan(c3d)
    junk = tmp_path / "junk.sur"
    junk.write_bytes(bytes(range(256)) * 20)
    with pytest.raises(FileFormatError, match=r"junk\.sur"):
        read_scan(junk)
    empty = tmp_path / "empty.plu"
    empty.write_bytes(b"")
    with pytest.raises(FileFormatError, match="empty file"):
        read_scan(empty)
    with pytest.raises(FileFormatError, match="does not exist"):
        read_scan(tmp_path / "missing.x3p")


def test_plain_maps_need_pixel_size_and_unit(tmp_path: Path, small: Any) -> None:
    z, _dx, _dy, _ = small
    p = tmp_path / "m.npy"
    np.save(p, z * 1e6)
    with pytest.raises(FileFormatError, match="pixel size"):
        read_scan(p)
    with pytest.raises(FileFormatError, match="height unit"):
        read_scan(p, pixel_size="10 um")
    hm = read_scan(p, pixel_size="10 um", height_unit="um")
    np.testing.assert_allclose(hm.z[~np.isnan(z)], z[~np.isnan(z)], atol=1e-15)
    assert hm.dx == pytest.approx(10e-6)
    c = tmp_path / "ragged.csv"
    c.write_text("# pixel_size: 2 um\n# height_unit: um\n" + "1,2,3,4,5,6,7,8\n" * 8 + "1,2,3\n")
    with pytest.raises(FileFormatError, match=r"ragged\.csv: line 11"):
        read_scan(c)


def test_missing_surface_topography(
    tmp_path: Path, small: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    z, dx, dy, _ = small
    x3p = S.write_scan(z, dx, dy, tmp_path / "s.x3p")
    npy = tmp_path / "s.npy"
    np.save(npy, z)
    monkeypatch.setitem(sys.modules, "SurfaceTopography", None)
    with pytest.raises(MissingDependencyError, match=r"pip install 'impactlab\[profilometry\]'"):
        read_scan(x3p)
    assert read_scan(npy, pixel_size=dx, height_unit="m").shape == z.shape  # no dependency


def test_plot_dent(tmp_path: Path, scans: dict) -> None:
    d = measure_dent(read_scan(scans[45].files["x3p"]))
    out = tmp_path / "dent.png"
    plot_dent(d, out)
    assert out.stat().st_size > 10_000
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_engine_dent_map() -> None:
    """The impact engine's predicted dent (``ImpactResult.dent()``), measured as a noisy, tilted
    scan: the depth and the extents agree with the engine's own."""
    r = simulate(PAPER_ROD, mu=0.13, angle=math.radians(45), velocity=(0.0, -2.18))
    dm = r.dent(nx=241, ny=181, margin=0.6)
    x, y = np.asarray(dm.x), np.asarray(dm.y)
    dx, dy = float(x[1] - x[0]), float(y[1] - y[0])
    rng = np.random.default_rng(0)
    X, Y = np.meshgrid(x - x[0], y - y[0])
    z = np.asarray(dm.height) + 1e-3 * X - 5e-4 * Y + 0.02e-6 * rng.standard_normal(X.shape)
    d = measure_dent(HeightMap(z, dx, dy, "engine-dent"))
    assert d.delta_p.value == pytest.approx(dm.max_depth, rel=0.02)
    assert d.length.value == pytest.approx(dm.length, rel=0.05)
    assert d.width.value == pytest.approx(dm.width, rel=0.05)


def test_a_dent_near_the_noise_floor_is_warned() -> None:
    """A dent only a few times deeper than the scan's noise is measured with a warning."""
    z, dx, dy, _ = S.synthetic_scan(
        delta_p=0.6e-6, sliding_length=300e-6, noise=0.15e-6, pileup=0.0, seed=3
    )
    d = measure_dent(HeightMap(z, dx, dy, "shallow.x3p"))
    assert any("times the scan's noise" in w and "barely resolved" in w for w in d.warnings)
    deep = measure_dent(HeightMap(*S.synthetic_scan(seed=3)[:3], "deep.x3p"))
    assert not any("noise" in w for w in deep.warnings)


def test_a_bump_is_not_a_dent(small: Any) -> None:
    """A sign-flipped scan (depths stored as heights) is refused, naming the way out; turned
    over, it measures as before; a dust grain higher than the dent does not trigger it."""
    z, dx, dy, truth = small
    hm = HeightMap(-z, dx, dy, "flipped.x3p")
    with pytest.raises(ScanError, match=r"flipped\.x3p: .*bump .* not a dent.*sign-flipped"):
        measure_dent(hm)
    d = measure_dent(hm.flipped())
    assert d.delta_p.value == pytest.approx(truth.groove.depth, rel=0.02)
    dusty = z.copy()
    dusty[20:24, 20:24] += 60e-6  # a grain three times higher than the dent is deep
    assert measure_dent(HeightMap(dusty, dx, dy)).delta_p.value == pytest.approx(
        truth.groove.depth, rel=0.02
    )


def test_rectangular_pixels_as_the_command_line_writes_them() -> None:
    """--pixel-size '2 um, 3 um' is (dx, dy), as the pair in Python."""
    from impactlab.experiment.profilometry.heightmap import pixel_pair

    assert pixel_pair("2 um, 3 um") == pixel_pair(("2 um", "3 um")) == (2e-6, 3e-6)
    assert pixel_pair("(4 um, 4 um)") == pixel_pair("4 um")
    with pytest.raises(ValueError, match="pixel_size must be one size or"):
        pixel_pair("2 um, 3 um, 4 um")
