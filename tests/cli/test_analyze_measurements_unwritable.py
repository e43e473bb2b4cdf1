"""``impactlab analyze --measurements FILE.csv`` with a file that cannot be written: the analysis
is printed first, then one error naming the measurements file (not its temporary file) and
saying nothing was appended."""

from __future__ import annotations

import errno
import json
from collections.abc import Callable
from pathlib import Path

import pytest

import impactlab.calibrate.measurement_append as append_module

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"
ARGS = (
    "analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"), "--pixel-size", "12 um",
    "--height-unit", "um", "--up", "+y", "--geometry", str(DATA / "markers.toml"),
)  # fmt: skip

CliMain = Callable[..., tuple[int, str, str]]


@pytest.fixture
def read_only(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every write fails as on a read-only file system, naming the temporary file."""

    def refuse(path: object, data: bytes) -> None:
        partial = Path(str(path)).with_name(f".{Path(str(path)).name}.123.partial")
        raise OSError(errno.EROFS, "Read-only file system", str(partial))

    monkeypatch.setattr(append_module, "write_bytes_atomic", refuse)


@pytest.mark.parametrize("as_json", [False, True])
def test_the_analysis_is_shown_and_the_file_named(
    tmp_path: Path, cli_main: CliMain, read_only: None, as_json: bool
) -> None:
    """It printed nothing (the analysis lost) and named '.drops.csv.17816.partial'."""
    path = tmp_path / "drops.csv"
    code, out, err = cli_main(*ARGS, "--measurements", str(path), *(["--json"] * as_json))
    assert code != 0
    if as_json:
        assert json.loads(out)["ok"] is True
    else:
        assert "mean_force" in out and "sliding_length" in out
    lines = [x for x in err.splitlines() if x.startswith("error:")]
    assert lines == [f"error: --measurements: nothing appended to {path}: read-only file system"], (
        err
    )
    assert ".partial" not in err and not path.exists()
