"""``python -m impactlab.paper.calibration_report`` (``python3 tasks.py calibrate-paper``):
``-h`` and ``--help`` print the usage with exit status 0, anywhere among the arguments (the
task runner puts ``--shipped`` first), and start no calibration; an unknown option is refused
with the usage, never taken for the output folder."""

from __future__ import annotations

import pytest

from impactlab.paper import calibration_report
from impactlab.paper.calibration_report import main


@pytest.fixture
def no_calibration(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(*_args: object, **_kwargs: object) -> None:
        raise AssertionError("the help started a calibration")

    monkeypatch.setattr(calibration_report, "write_calibration_report", refuse)
    monkeypatch.setattr(calibration_report, "write_shipped_calibration", refuse)


@pytest.mark.usefixtures("no_calibration")
@pytest.mark.parametrize("args", [["--help"], ["-h"], ["--shipped", "--help"], ["out", "-h"]])
def test_help_prints_the_usage_with_status_0(
    args: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(args) == 0
    out = capsys.readouterr()
    assert out.out.startswith("usage: python -m impactlab.paper.calibration_report OUT_DIR")
    assert "--shipped" in out.out and "STEPS" in out.out and not out.err


@pytest.mark.usefixtures("no_calibration")
@pytest.mark.parametrize("args", [["--bogus"], ["-x", "20"], [], ["a", "20", "b"]])
def test_an_unknown_option_or_a_wrong_count_is_refused(
    args: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(args) == 2
    out = capsys.readouterr()
    assert out.err.startswith("usage: ") and not out.out
