"""The pixel size as text: a decimal comma ("12,5 um") once read as the pair 12 m x 5 um, and
the dent's profiles then asked for 15.8 GiB; a bare pixel of 12 m; a stage that runs out of
memory lost the results of the others."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import HeightMap, ScanError, analyze, measure_dent
from impactlab.experiment import analysis as analysis_module
from impactlab.experiment.profilometry.heightmap import pixel_pair


@pytest.mark.parametrize(
    ("text", "needles"),
    [
        ("12,5 um", ("'12' has no unit while '5 um' has one", "write '12.5 um'", "'12.5 um, 12.5")),
        ("8,0 um", ("'8' has no unit while '0 um' has one", "write '8.0 um' (a decimal point)")),
        ("12 um, 5", ("'5' has no unit while '12 um' has one", "'12.5 um, 12.5 um' (x then y)")),
        ("12", ("a pixel of 12 m, larger than 1 cm", "a bare number is read in metres")),
        ("0 um", ("must be > 0",)),
    ],
)
def test_a_pixel_size_that_cannot_be_meant_is_refused(text: str, needles: tuple[str, ...]) -> None:
    with pytest.raises(ValueError, match="pixel_size") as err:
        pixel_pair(text)
    for needle in needles:
        assert needle in str(err.value)


def test_pixel_sizes_written_right_still_read() -> None:
    assert pixel_pair("12.5 um") == pytest.approx((12.5e-6, 12.5e-6))
    assert pixel_pair("12.5 um, 10 um") == pytest.approx((12.5e-6, 10e-6))
    assert pixel_pair((2e-6, "3 um")) == pytest.approx((2e-6, 3e-6))  # a number is metres
    assert pixel_pair("8 mm") == pytest.approx((8e-3, 8e-3))  # left to check_dent


def test_the_command_lines_decimal_comma_is_one_line_naming_the_option(
    cli_main: Callable[..., tuple[int, str, str]], tmp_path: Path
) -> None:
    z, *_ = S.synthetic_scan(delta_p=22e-6, sliding_length=400e-6, pixel=10e-6, seed=1)
    np.save(tmp_path / "dent.npy", z * 1e6)
    out = tmp_path / "out"
    code, _, err = cli_main(
        "analyze", str(tmp_path / "dent.npy"), str(tmp_path / "dent.npy"),
        "--pixel-size", "12,5 um", "--height-unit", "um", "--out", str(out),
    )  # fmt: skip
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and "Traceback" not in err
    assert "--pixel-size" in lines[0] and "write '12.5 um'" in lines[0]
    assert not out.exists()  # refused before any work


def test_pixels_far_longer_one_way_are_the_scans_error_not_a_memory_error() -> None:
    """12 m x 5 um pixels: the profiles would take 3e9 samples."""
    z, *_ = S.synthetic_scan(delta_p=22e-6, sliding_length=400e-6, pixel=10e-6, seed=1)
    with pytest.raises(ScanError, match="check the pixel size") as err:
        measure_dent(HeightMap(z, 12.0, 5e-6))
    assert "samples (at most 1e+06)" in str(err.value)


def test_a_stage_out_of_memory_keeps_the_other_stages_results(
    drops: dict, scans: dict, rod: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    def exhausted(*_a: Any, **_k: Any) -> Any:
        raise MemoryError("Unable to allocate 15.8 GiB for an array")

    monkeypatch.setattr(analysis_module, "measure_dent", exhausted)
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], rod, geometry=d.geometry, out_dir=tmp_path)
    assert res.kinematics is not None and set(res.errors) == {"scan"}
    assert res.errors["scan"].startswith("out of memory (Unable to allocate 15.8 GiB")
    assert "the pixel size" in res.errors["scan"]
    assert (tmp_path / "results.json").is_file() and (tmp_path / "kinematics.png").is_file()
