"""A dent's outline joined by something else: a second mark touching or overlapping it, or a pit
(dust, a dropout) at its edge. The length was extrapolated across the join (8 mm in a 6.4 mm
scan; L_s 4.8 times the truth) or took the pit in (+9 %), as plain success."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab.experiment import measure_dent
from impactlab.experiment.profilometry import HeightMap
from impactlab.experiment.profilometry.extent import OUTLINE_DOUBT
from impactlab.experiment.profilometry.plausibility import dent_findings

R, DX = 8.8e-3, 8e-6
X, Y = np.meshgrid(np.arange(800) * DX, np.arange(300) * DX)
DENT_NPY = Path(__file__).resolve().parents[2] / "examples" / "data" / "dent.npy"


def _groove(cx: float, depth: float, ls: float) -> np.ndarray:
    """A sphere of radius R pressed ``depth`` [m] deep and dragged ``ls`` [m] along x."""
    u = X - cx
    r2 = (u - np.clip(u, -ls / 2, ls / 2)) ** 2 + (Y - Y.mean()) ** 2
    return np.minimum(-depth + R - np.sqrt(R * R - r2), 0.0)


def _noisy(z: np.ndarray) -> np.ndarray:
    return z + 0.1e-6 * np.random.default_rng(0).standard_normal(z.shape)


@pytest.mark.parametrize("second_at", [4.0e-3, 3.8e-3])
def test_a_second_mark_joined_to_the_dent_is_a_doubt(second_at: float) -> None:
    z = _noisy(np.minimum(_groove(1.8e-3, 22e-6, 1.4e-3), _groove(second_at, 15e-6, 0.8e-3)))
    dent = measure_dent(HeightMap(z, DX, DX))
    said = [w for w in dent.warnings if w.startswith(OUTLINE_DOUBT)]
    assert said, dent.warnings
    _, doubts = dent_findings(dent, (), tip_radius=R)
    assert said[0] in doubts  # not a result to take as measured


def test_a_lone_or_separate_dent_has_no_such_doubt() -> None:
    alone = measure_dent(HeightMap(_noisy(_groove(1.8e-3, 22e-6, 1.4e-3)), DX, DX))
    assert alone.sliding_length.value == pytest.approx(1.4e-3, rel=0.01)
    apart = _noisy(np.minimum(_groove(1.8e-3, 22e-6, 1.4e-3), _groove(4.4e-3, 15e-6, 0.8e-3)))
    dent = measure_dent(HeightMap(apart, DX, DX))
    assert any(w.startswith("2 depressions qualify") for w in dent.warnings)
    assert not [w for w in dent.warnings if w.startswith(OUTLINE_DOUBT)]
    assert dent.sliding_length.value == pytest.approx(1.4e-3, rel=0.01)


def test_a_pit_at_the_dents_end_stays_out_of_its_outline() -> None:
    """examples/data/dent.npy (L_s 1400 um) with one 3 x 3 pixel pit 10 um deep just past the
    dent's end: L_s 1532 um (+9 %, 5.6 sigma) before; the outline is drawn without pits now."""
    z = np.load(DENT_NPY).astype(float)
    clean = measure_dent(HeightMap(z * 1e-6, 12e-6, 12e-6))
    z[75:78, 24:27] -= 10.0
    pitted = measure_dent(HeightMap(z * 1e-6, 12e-6, 12e-6))
    ls, ls0 = pitted.sliding_length, clean.sliding_length
    assert abs(ls.value - ls0.value) <= 3 * ls0.sigma
    assert pitted.delta_p.value == pytest.approx(clean.delta_p.value, rel=1e-3)


def test_a_readers_binary_quote_is_escaped() -> None:
    """An X3P renamed .sur: SurfaceTopography's error quoted 'PK\\x03\\x04...' raw."""
    from impactlab.experiment.profilometry.instrument import _first_line

    said = _first_line(ValueError("magic 'PK\x03\x04\x14\x00' at 0\nnext line"))
    assert said == "magic 'PK\\x03\\x04\\x14\\x00' at 0" and said.isprintable()


def test_a_height_matrix_with_its_coordinates_is_named(tmp_path: Path) -> None:
    """Refused as 'sign-flipped' with a hint to pass --flip-heights, which then failed too."""
    from impactlab.experiment import read_scan
    from impactlab.experiment.errors import FileFormatError

    z = np.random.default_rng(0).normal(0.0, 0.1, (20, 30))
    lines = ["# pixel_size: 16 um", "# height_unit: um"]
    lines.append("," + ",".join(f"{16.0 * j:g}" for j in range(30)))
    lines += [f"{16.0 * i:g}," + ",".join(f"{v:.4f}" for v in z[i]) for i in range(20)]
    path = tmp_path / "axes.csv"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(FileFormatError, match=r"coordinates, not heights; export the heights"):
        read_scan(path)
    path.write_text("\n".join(lines[:2] + [",".join(f"{v:.4f}" for v in r) for r in z]) + "\n")
    assert read_scan(path).z.shape == (20, 30)  # the heights alone: read


def _with_axes(path: Path, z: np.ndarray, xs: list[str], ys: list[str], fmt: str) -> Path:
    """``z`` written as a CSV matrix beside the printed axes ``xs``, ``ys``, an empty corner."""
    lines = ["# pixel_size: 16 um", "# height_unit: um", "," + ",".join(xs)]
    lines += [f"{ys[i]}," + ",".join(f"{v:{fmt}}" for v in z[i]) for i in range(len(ys))]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize(
    ("xs", "ys", "step"),
    [
        ([f"{16 * j}" for j in range(30)], [f"{16 * i}" for i in range(19, -1, -1)], "16"),
        ([f"{j / 80:.3f}" for j in range(30)], [f"{i / 80:.3f}" for i in range(20)], "0.0125"),
    ],
    ids=["y_descending", "mm_to_3_decimals"],
)
def test_axes_written_top_down_or_rounded_are_named(
    tmp_path: Path, xs: list[str], ys: list[str], step: str
) -> None:
    """Read as heights (then called 'sign-flipped'): a y axis in image order (304, 288, ..., 0)
    and 12.5 um pixels in mm to 3 decimals (steps 0.012, 0.013: 8 % apart)."""
    from impactlab.experiment import read_scan
    from impactlab.experiment.errors import FileFormatError

    z = np.random.default_rng(0).normal(0.0, 0.1, (20, 30))
    path = _with_axes(tmp_path / "axes.csv", z, xs, ys, ".4f")
    with pytest.raises(FileFormatError) as err:
        read_scan(path)
    said = str(err.value)
    first = f"({float(ys[0]):g}, {float(ys[1]):g}, ...)"
    assert f"first column {first} run evenly from an empty corner: coordinates" in said
    assert said.endswith(f"give the pixel size (here {step} in the coordinates' unit)")


def test_a_height_map_with_an_empty_corner_is_read(tmp_path: Path) -> None:
    """A map's own first row and column, an empty corner pixel: a noisy dent, and a tilted
    plane printed to 0.1 um, whose edges rise evenly to that precision but are continued."""
    from impactlab.experiment import read_scan

    dent = _noisy(_groove(3.2e-3, 22e-6, 1.4e-3))[::4, ::8] * 1e6
    j, i = np.meshgrid(np.arange(60), np.arange(40))
    plane = 100.0 + 0.37 * j - 0.23 * i + 0.01 * np.random.default_rng(1).standard_normal(i.shape)
    spiked = plane.copy()
    spiked[1, 30] += 3.0  # a profilometer spike in the second row: no trend of the row
    for name, z in (("dent", dent), ("plane", plane), ("spiked", spiked)):
        rows = [",".join(f"{v:.1f}" for v in r) for r in z]
        rows[0] = "nan," + rows[0].split(",", 1)[1]  # the corner pixel: no data
        path = tmp_path / f"{name}.csv"
        path.write_text("# pixel_size: 16 um\n# height_unit: um\n" + "\n".join(rows) + "\n")
        scan = read_scan(path)
        assert scan.z.shape == z.shape and np.isnan(scan.z[0, 0])
        assert np.count_nonzero(np.isnan(scan.z)) == 1


def test_a_point_lists_xy_unit_is_named(tmp_path: Path) -> None:
    """x, y in mm and z in um: the error blamed a 'pixel size (16 nm)' nobody gave."""
    from impactlab.experiment import check_dent, read_scan

    dx = 16e-6
    xs, ys = np.meshgrid(np.arange(200) * dx, np.arange(150) * dx)
    u = xs - xs.mean()
    r2 = (u - np.clip(u, -7e-4, 7e-4)) ** 2 + (ys - ys.mean()) ** 2
    z = np.minimum(-22e-6 + R - np.sqrt(R * R - r2), 0.0)
    path = tmp_path / "mm_um.txt"
    np.savetxt(path, np.column_stack([xs.ravel() * 1e3, ys.ravel() * 1e3, z.ravel() * 1e6]))
    scan = read_scan(path, height_unit="um")
    with pytest.raises(ValueError, match=r"check the point list's x, y \(read in its height unit"):
        check_dent(measure_dent(scan), tip_radius=R, rod_length=0.3048, scan=scan)
