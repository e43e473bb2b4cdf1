"""A drop label that a CSV measurements file would not read back as written (empty, a leading
'#', a line break, spaces at an end) is refused by name, by ``append_record`` and by
``impactlab analyze --measurements`` before the analysis runs (a '#' label was written as a
comment line and lost; an empty one was written as 'drop 1')."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from impactlab.calibrate import read_measurements
from impactlab.calibrate.measurement_append import append_record, check_label
from impactlab.cli._common import UserError
from impactlab.cli.analyze_measurements import check_measurements

DROP = {"angle": "20 deg", "vy": -1.4, "mu": 0.2, "e": 0.45, "e_sigma": 0.02}
OLD = "label,angle [deg],vy [m/s],mu,e,e_sigma\nold,45,-2,0.2,0.4,0.02\n"
BAD = [
    ("#x", "starts with '#'"),
    ("", "is empty"),
    ("   ", "is empty"),
    ("a\nb", "holds a line break"),
    ("a\r", "holds a line break"),
    ("a\u2028b", "holds a line break"),
    (" a", "has spaces at an end"),
    ("a\t", "has spaces at an end"),
]


@pytest.mark.parametrize(("label", "why"), BAD)
def test_append_record_refuses_a_label_the_file_would_change(
    tmp_path: Path, label: str, why: str
) -> None:
    path = tmp_path / "drops.csv"
    path.write_text(OLD)
    with pytest.raises(ValueError, match=re.escape(f"label {label!r} {why}")):
        append_record(path, {**DROP, "label": label})
    assert path.read_text() == OLD  # nothing written


def test_a_record_without_a_label_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "drops.csv"
    with pytest.raises(ValueError, match="the drop has no label"):
        append_record(path, DROP)
    assert not path.exists()


def test_a_good_label_reads_back_as_written(tmp_path: Path) -> None:
    path = tmp_path / "drops.csv"
    path.write_text(OLD)
    for n, label in enumerate(("a #1", 'quote "b", comma', "ü-drop")):
        append_record(path, {**DROP, "label": label, "e": 0.3 + 0.01 * n})  # three drops
    assert read_measurements(path).labels == ("old", "a #1", 'quote "b", comma', "ü-drop")


@pytest.mark.parametrize(("label", "why"), BAD)
def test_analyze_refuses_the_label_before_the_analysis(
    tmp_path: Path, label: str, why: str
) -> None:
    path = tmp_path / "drops.csv"
    path.write_text("label,angle [deg],vy [m/s],mu,e,e_sigma\n,45,-2,0.2,0.4,0.02\n")
    with pytest.raises(UserError, match=f"--label .* {why}"):
        check_measurements(path, label)
    with pytest.raises(ValueError, match=why):
        check_label(label)
