"""Input values that read as something else: a complex height map (a cast dropped its imaginary
part), a length unit in the wrong case ('MM' is megamolar in pint, 'Mm' megametres) and an empty
pixel size (whose hint must be a value the next check accepts)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import ezc3d
import numpy as np
import pytest

from impactlab.experiment import FileFormatError, analyze, read_scan
from impactlab.experiment.markers import MarkerTracks, length_factor, read_c3d
from impactlab.experiment.profilometry.heightmap import pixel_pair


@pytest.mark.parametrize("imag", [0.0, 1e-3])
def test_a_complex_npy_scan_is_not_a_real_height_map(tmp_path: Path, imag: float) -> None:
    z = np.zeros((40, 40)) + 1j * imag
    np.save(tmp_path / "c.npy", z)
    with pytest.raises(FileFormatError, match="not a real height map: dtype complex128"):
        read_scan(tmp_path / "c.npy", pixel_size="2 um", height_unit="um")
    np.save(tmp_path / "r.npy", z.real)
    assert read_scan(tmp_path / "r.npy", pixel_size="2 um", height_unit="um").shape == (40, 40)


@pytest.mark.parametrize(
    ("unit", "reads", "meant"),
    [
        ("MM", "is megamolar, not a length", "'mm' (millimeter)"),
        ("Mm", "is megameter (1e+06 m)", "'mm' (millimeter)"),
        ("CM", "is not a known unit", "'cm' (centimeter)"),
        ("UM", "is not a known unit", "'um' (micrometer)"),
        ("µM", "is micromolar, not a length", "'um' (micrometer)"),
        ("M", "is molar, not a length", "'m' (meter)"),
    ],
)
def test_a_length_unit_in_the_wrong_case_names_the_lower_case_one(
    unit: str, reads: str, meant: str
) -> None:
    with pytest.raises(ValueError, match="case-sensitive") as err:
        length_factor(unit, name="units")
    assert str(err.value) == (
        f"units: {unit!r} {reads}; unit names are case-sensitive and not read in another "
        f"case: write {meant}"
    )


def test_length_units_in_their_own_case_still_read() -> None:
    for unit, fac in (("mm", 1e-3), ("m", 1.0), ("µm", 1e-6), ("um", 1e-6), (" cm ", 1e-2)):
        assert length_factor(unit) == pytest.approx(fac)
    with pytest.raises(ValueError, match="'kg' is not a length unit"):
        length_factor("kg")


def test_a_c3d_stating_upper_case_mm_names_the_unit_and_the_override(tmp_path: Path) -> None:
    t = np.arange(20) / 500.0
    pos = np.zeros((20, 1, 3)) + np.array([1.0, 2.0, 3.0])
    from impactlab.testing import write_c3d

    p = write_c3d(MarkerTracks(t, pos, ("M1",)), tmp_path / "d.c3d", units="mm")
    c = ezc3d.c3d(str(p))
    c["parameters"]["POINT"]["UNITS"]["value"] = ["MM"]
    c.write(str(p))
    with pytest.raises(FileFormatError, match="POINT:UNITS: 'MM' is megamolar") as err:
        read_c3d(p)
    assert "write 'mm'" in str(err.value)
    assert read_c3d(p, units="mm").positions[0, 0] == pytest.approx([1.0, 2.0, 3.0])


def test_an_empty_pixel_size_suggests_a_size_that_is_accepted(tmp_path: Path) -> None:
    np.save(tmp_path / "r.npy", np.zeros((40, 40)))
    for given in ("", "  "):
        with pytest.raises(FileFormatError, match=r"pixel_size \(--pixel-size\) is empty") as err:
            read_scan(tmp_path / "r.npy", pixel_size=given, height_unit="um")
        assert "e.g. '12.5 um'" in str(err.value)
    assert pixel_pair("12.5 um") == pytest.approx((12.5e-6, 12.5e-6))  # the hint is allowed
    rows = "\n".join(",".join(["0"] * 20) for _ in range(20))
    (tmp_path / "h.csv").write_text("# pixel_size:\n# height_unit: um\n" + rows + "\n")
    with pytest.raises(FileFormatError, match=r"'# pixel_size:' is empty; .*e\.g\. '12\.5 um'"):
        read_scan(tmp_path / "h.csv")


def test_analyze_refuses_an_empty_pixel_size_with_an_accepted_example(tmp_path: Path) -> None:
    np.save(tmp_path / "dent.npy", np.zeros((40, 40)))
    out = tmp_path / "out"
    with pytest.raises(ValueError, match=r"pixel_size \(--pixel-size\) is empty") as err:
        analyze(None, tmp_path / "dent.npy", pixel_size="", height_unit="um", out_dir=out)
    assert "e.g. '12.5 um'" in str(err.value) and "'1.0 m'" not in str(err.value)
    assert not out.exists()


def test_the_command_lines_empty_pixel_size_suggests_an_accepted_size(
    cli_main: Any, tmp_path: Path
) -> None:
    np.save(tmp_path / "dent.npy", np.zeros((40, 40)))
    out = tmp_path / "out"
    code, _, err = cli_main(
        "analyze", str(tmp_path / "dent.npy"), str(tmp_path / "dent.npy"),
        "--pixel-size", "", "--height-unit", "um", "--out", str(out),
    )  # fmt: skip
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1, err
    assert "e.g. '12.5 um'" in lines[0] and "'1.0 m'" not in lines[0]
    assert not out.exists()
