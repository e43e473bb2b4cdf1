"""The CSV files of a law file: an empty, header-only, truncated or non-numeric file, a folder
or a missing file each get one line naming the file and what is wrong (the line number for a
bad row), with no Python warning and no numpy text."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from impactlab.cli import app
from impactlab.contact.table_input import read_two_columns

GOOD_UNLOADING = "delta_max,delta_r\n1e-6,1e-7\n2e-6,3e-7\n"


def _law_file(folder: Path, loading: str) -> Path:
    (folder / "unloading.csv").write_text(GOOD_UNLOADING)
    keys = {
        "name": "csv-check",
        "body_material": "aisi-201",
        "flat_material": "aisi-1010",
        "radius": "8.8 mm",
        "loading": loading,
        "unloading": "unloading.csv",
    }
    path = folder / "law.toml"
    path.write_text("".join(f"{k} = {json.dumps(v)}\n" for k, v in keys.items()))
    return path


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        ("", "the file is empty"),
        ("delta,F\n", "no data rows after the header line"),
        ("delta,F\n1e-6,0.1\n2e-6,0.3\n3.1e", "line 4 has 1 column(s), must have 2 columns"),
        ("delta,F\n1e-6,0.1,7\n", "line 2 has 3 column(s), must have 2 columns"),
        ("delta,F\n1e-6,abc\n", "line 2 is not two numbers (delta [m], F [N]), got '1e-6,abc'"),
    ],
)
def test_bad_loading_csv_is_one_line(tmp_path: Path, content: str, needle: str) -> None:
    (tmp_path / "loading.csv").write_text(content)
    law = _law_file(tmp_path, "loading.csv")
    res = CliRunner().invoke(app, ["--law-file", str(law), "laws"])
    assert res.exit_code != 0
    text = str(res.exception) if res.exception else res.output
    assert needle in text and "loading CSV" in text
    for leak in ("loadtxt", "usecols", "UserWarning", "numpy"):
        assert leak not in text


def test_missing_file_and_folder(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="loading CSV 'x' does not exist"):
        read_two_columns(tmp_path / "nothere.csv", "loading CSV 'x'", "delta [m], F [N]")
    with pytest.raises(ValueError, match="is a folder, not a CSV file"):
        read_two_columns(tmp_path, "loading CSV 'x'", "delta [m], F [N]")


def test_comments_and_blank_lines_are_skipped(tmp_path: Path) -> None:
    path = tmp_path / "c.csv"
    path.write_text("# delta,F\n1e-6,0.1\n\n# a note\n2e-6, 0.3  # end\n")
    delta, force = read_two_columns(path, "loading CSV", "delta [m], F [N]")
    assert delta.tolist() == [1e-6, 2e-6] and force.tolist() == [0.1, 0.3]


def test_empty_csv_through_the_command(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """Through the installed command's ``main``: stderr holds the one error line only."""
    import sys

    from impactlab.cli import main

    (tmp_path / "empty.csv").write_text("")
    law = _law_file(tmp_path, "empty.csv")
    monkeypatch.setattr(sys, "argv", ["impactlab", "--law-file", str(law), "laws"])
    with pytest.raises(SystemExit) as exit_:
        main()
    err = capsys.readouterr().err
    assert exit_.value.code == 2
    assert err.strip().splitlines() == [
        f"error: law file {str(law)!r}: loading CSV {str(tmp_path / 'empty.csv')!r}: the file "
        "is empty (expected rows of delta [m], F [N], after an optional header line)"
    ]
