"""The '# key: value' lines of a marker CSV: a spreadsheet's padding stripped from every value,
Hz and kHz in any case, and a rate that contradicts the time column refused."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import FileFormatError, read_csv_markers, write_csv_markers

ROWS = "frame,A_x,A_y,A_z\n1,0,0,0\n2,0,0,1\n"


def _padded(text: str, n: int = 9, sep: str = ",") -> str:
    """Every line padded with ``n`` empty fields, as a spreadsheet saves a one-cell line."""
    return "".join(f"{line}{sep * n}\n" for line in text.splitlines())


@pytest.mark.parametrize("sep", [",", ";", "\t"])
def test_a_spreadsheets_padding_is_stripped_from_every_value(tmp_path: Path, sep: str) -> None:
    """'# rate: 0.5 kHz,,,,,,,,,' was refused with a message about commas, while
    '# units: mm,,,,,,,,,' was stored as 'mm,,,,,,,,,'."""
    p = tmp_path / "f.csv"
    head = _padded("# impactlab marker tracks\n# units: mm\n# rate: 0.5 kHz", sep=sep)
    p.write_text(head + ROWS.replace(",", sep))
    t = read_csv_markers(p)
    np.testing.assert_allclose(t.time, [0.0, 0.002])
    assert t.meta["units"] == "mm"
    np.testing.assert_allclose(t.positions[1, 0], [0.0, 0.0, 1e-3])


def test_a_value_in_the_next_cell_is_read_too(tmp_path: Path) -> None:
    p = tmp_path / "f.csv"
    p.write_text("# units:,mm,,\n# rate:,500 Hz,,\n" + ROWS)
    t = read_csv_markers(p)
    assert t.meta["units"] == "mm"
    np.testing.assert_allclose(t.time, [0.0, 0.002])


@pytest.mark.parametrize("rate", ["500 hz", "500 HZ", "0.5 khz", "0.5 KHz", "0.5KHZ"])
def test_hz_and_khz_in_any_case(tmp_path: Path, rate: str) -> None:
    p = tmp_path / "f.csv"
    p.write_text(f"# units: mm\n# rate: {rate}\n{ROWS}")
    np.testing.assert_allclose(read_csv_markers(p).time, [0.0, 0.002])


def _drop_csv(tmp_path: Path, rate: float) -> Path:
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, _ = S.marker_tracks(PAPER_ROD, truth, rate=rate, seed=4)
    return write_csv_markers(tracks, tmp_path / "drop.csv")


def _with_rate_line(path: Path, line: str) -> Path:
    text = path.read_text().replace("# units: mm\n", f"# units: mm\n{line}\n")
    path.write_text(text)
    return path


def test_a_rate_contradicting_the_time_column_is_refused(tmp_path: Path) -> None:
    """'# rate: 1000 Hz' above a time column in steps of 2 ms was silently ignored."""
    p = _with_rate_line(_drop_csv(tmp_path, 500.0), "# rate: 1000 Hz")
    with pytest.raises(FileFormatError) as caught:
        read_csv_markers(p)
    message = str(caught.value)
    assert "'# rate: 1000 Hz' contradicts the time column" in message
    assert "0.002 s (500 frames per second)" in message
    with pytest.raises(FileFormatError, match=r"rate=1000 Hz contradicts the time column"):
        read_csv_markers(_drop_csv(tmp_path, 500.0), rate=1000.0)


@pytest.mark.parametrize("line", ["# rate: 500 Hz", "# rate: 0.5 kHz,,,", "# rate: 503 fps"])
def test_a_rate_that_agrees_with_the_time_column_is_accepted(tmp_path: Path, line: str) -> None:
    """Within 1 %; gaps in the record (occluded frames) do not count."""
    p = _with_rate_line(_drop_csv(tmp_path, 500.0), line)
    lines = p.read_text().splitlines()
    p.write_text("\n".join(ln for i, ln in enumerate(lines) if i < 10 or i % 4) + "\n")
    assert read_csv_markers(p).n_frames > 50
