"""Messages that say where the problem is: a marker label used twice in a CSV header, a trailing
comma on every line, random bytes given as a .npy height map (once "contains pickled data")."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab.experiment import FileFormatError, MarkerTracks, read_csv_markers, read_scan

LABELS = ("M1", "M2", "M3")


def _csv(path: Path, labels: tuple[str, ...], tail: str = "", head_tail: str = "") -> Path:
    header = ",".join(["time"] + [f"{lab}_{a}" for lab in labels for a in "xyz"]) + head_tail
    rows = [
        ",".join([f"{k / 500:.4f}"] + [f"{k + j:.3f}" for j in range(3 * len(labels))]) + tail
        for k in range(6)
    ]
    path.write_text("# units: mm\n" + "\n".join([header, *rows]) + "\n", encoding="utf-8")
    return path


def test_a_label_used_twice_names_the_header_line_and_columns(tmp_path: Path) -> None:
    p = _csv(tmp_path / "dup.csv", (*LABELS, "M1"))
    with pytest.raises(FileFormatError) as err:
        read_csv_markers(p)
    message = str(err.value)
    assert message.startswith(f"{p}: line 2: the header names 'M1' 2 times (columns 2-4, ")
    assert "columns 11-13)" in message and "a label of its own" in message


def test_a_label_used_twice_in_python_says_which(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"unique, got 'M1' 2 times \(marker 1, marker 3\)"):
        MarkerTracks(np.arange(3) / 500.0, np.zeros((3, 3, 3)), ("M1", "M2", "M1"))


def test_a_trailing_comma_on_every_line_is_named(tmp_path: Path) -> None:
    p = _csv(tmp_path / "trailing.csv", LABELS, tail=",", head_tail=",")
    with pytest.raises(FileFormatError, match="got 10 columns") as err:
        read_csv_markers(p)
    assert "its last column has no name (a trailing comma at the end of the line)" in str(err.value)


def test_a_trailing_comma_on_the_rows_only_is_named(tmp_path: Path) -> None:
    p = _csv(tmp_path / "rows.csv", LABELS, tail=",")
    with pytest.raises(FileFormatError, match="line 3: expected 10 fields, found 11") as err:
        read_csv_markers(p)
    assert "its last field is empty: a trailing separator" in str(err.value)


def test_random_bytes_are_not_a_npy_file(tmp_path: Path) -> None:
    p = tmp_path / "noise.npy"
    p.write_bytes(bytes(np.random.default_rng(0).integers(0, 256, 3000, dtype=np.uint8)))
    with pytest.raises(FileFormatError, match=r"not a \.npy file") as err:
        read_scan(p, pixel_size="8 um", height_unit="um")
    assert "pickled" not in str(err.value) and "damaged" in str(err.value)


def test_an_object_npy_is_still_named_as_such(tmp_path: Path) -> None:
    p = tmp_path / "objects.npy"
    np.save(p, np.array([{"a": 1}] * 64, dtype=object).reshape(8, 8), allow_pickle=True)
    with pytest.raises(FileFormatError, match="not a readable NPY array"):
        read_scan(p, pixel_size="8 um", height_unit="um")
