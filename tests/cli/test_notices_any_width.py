"""``warning:``, ``error:`` and ``note:`` lines at any terminal width: on a terminal wrapped
between words (continuations indented 2 spaces, a number kept with its unit, a word wider
than the terminal whole on its own line); into a pipe or a file one line, as before. The
stage errors of ``impactlab analyze --measurements`` are printed before the refusal."""

from __future__ import annotations

import io
import re
import sys
import warnings
from collections.abc import Callable
from pathlib import Path

import pytest

from impactlab._validation import ImplausibleInputWarning
from impactlab.cli import _one_line_warnings
from impactlab.cli.printing import KEEP, print_wrapped
from impactlab.cli.sweep_summary import _print_report

CliMain = Callable[..., tuple[int, str, str]]

LAW = (
    "warning: law extrapolated: the largest interference passed the range where the law was "
    "verified against FE (max delta/delta_c = 178, verified up to 1): it may differ from FE "
    "there by more than 10 % in force or 0.05 in delta_r/delta_max (advisory; `impactlab laws "
    "--accuracy` measures each law); about 25 s, mass = 0.4607 kg, inertia = 3.1894e-9 kg m^2"
)
DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


class Terminal(io.StringIO):
    """A text stream that says it is a terminal."""

    def isatty(self) -> bool:
        return True


def _check_wrapped(lines: list[str], text: str, width: int) -> None:
    """``lines`` are ``text`` wrapped between words within ``width``, continuations indented 2
    more spaces than the first line."""
    lead = len(lines[0]) - len(lines[0].lstrip(" "))
    assert all(len(line) <= width for line in lines), lines
    assert all(line.startswith(" " * (lead + 2) + "") for line in lines[1:]), lines
    assert " ".join(line.strip() for line in lines) == " ".join(text.split())
    assert [w for line in lines for w in line.split()] == text.split()  # no word broken


@pytest.mark.parametrize("width", [40, 80, 100])
def test_a_notice_is_wrapped_between_words_on_a_terminal(monkeypatch, width: int) -> None:
    monkeypatch.setenv("COLUMNS", str(width))
    out = Terminal()
    print_wrapped(LAW, out)
    lines = out.getvalue().splitlines()
    assert len(lines) > 1
    _check_wrapped(lines, LAW, width)
    for quantity in ("10 %", "25 s", "0.4607 kg", "3.1894e-9 kg m^2", "178, verified"):
        assert any(quantity in line for line in lines), (quantity, lines)
    if width < 70:  # the material names and options whole, never at their hyphens
        assert any("--accuracy`" in line.split() for line in lines)


def test_a_word_wider_than_the_terminal_stays_whole(monkeypatch) -> None:
    monkeypatch.setenv("COLUMNS", "30")
    url = "https://example.org/a/very/long/address/of/a/source.html"
    out = Terminal()
    print_wrapped(f"warning: the source {url} is not read", out)
    assert out.getvalue().splitlines() == ["warning: the source", f"  {url}", "  is not read"]


def test_into_a_pipe_a_notice_is_one_line_as_given(monkeypatch) -> None:
    monkeypatch.setenv("COLUMNS", "40")
    out = io.StringIO()
    print_wrapped(LAW, out)
    assert out.getvalue() == LAW + "\n"
    out = io.StringIO()
    print_wrapped(f"  e: vy{KEEP}0.411, mu{KEEP}0.0205", out)
    assert out.getvalue() == "  e: vy 0.411, mu 0.0205\n"


def test_a_warning_and_an_error_of_a_command(monkeypatch, cli_main: CliMain) -> None:
    """The warnings hook and the one-line error of ``main``: wrapped on a terminal, one line
    into a pipe."""
    monkeypatch.setenv("COLUMNS", "80")
    args = ("simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--flat", "nosuch")
    code, _, err = cli_main(*args)
    assert code == 2 and len(err.splitlines()) == 1 and len(err) > 200
    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    assert cli_main(*args)[0] == 2
    lines = terminal.getvalue().splitlines()
    _check_wrapped(lines, err, 80)
    assert any("alumina-99.5," in line.split() for line in lines)

    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    with _one_line_warnings():
        warnings.warn(LAW.removeprefix("warning: "), ImplausibleInputWarning, stacklevel=1)
    _check_wrapped(terminal.getvalue().splitlines(), LAW, 80)


SENSITIVITIES = [("flat_yield_strength", 0.498), ("vy", 0.411), ("mu", 0.0205),
                 ("angle", 0.00431), ("vx", 0.00352), ("flat_E", 0.00314)]  # fmt: skip
REPORT = {
    "summary": [{"output": "delta_p", "unit": "m", "mean": 2e-5, "std": 1e-6, "p5": 1.9e-5}],
    "n_cases": 5000,
    "n_invalid": 0,
    "n_extrapolated": 5000,
    "sensitivity": [
        {"output": "delta_p", "input": name, "rank_corr2": value} for name, value in SENSITIVITIES
    ],
}
PAIRS = [f"{name} {value}" for name, value in SENSITIVITIES]


def test_the_sensitivities_keep_each_input_with_its_number(monkeypatch, capsys) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    _print_report(REPORT, "uncertainty: all")
    piped = capsys.readouterr().out.splitlines()
    assert f"  delta_p: {', '.join(PAIRS)}" in piped  # into a pipe: as before, one line
    assert any(line.startswith("law extrapolated (advisory): 5,000 of") for line in piped)
    terminal = Terminal()
    monkeypatch.setattr(sys, "stdout", terminal)
    _print_report(REPORT, "uncertainty: all")
    lines = re.sub(r"\x1b\[[0-9;]*m", "", terminal.getvalue()).splitlines()  # the table's bold
    assert all(len(line) <= 80 for line in lines)
    start = next(i for i, line in enumerate(lines) if line.startswith("  delta_p: "))
    ranking = lines[start:]
    assert len(ranking) == 2 and ranking[1].startswith("    ")
    for pair in PAIRS:
        assert sum(pair in line for line in ranking) == 1, (pair, ranking)


def _says_see_the_error(table: str) -> bool:
    return "stage failed (see the error)" in " ".join(table.replace("│", " ").split())


def test_analyze_prints_the_stage_error_before_the_measurements_refusal(
    tmp_path: Path, cli_main: CliMain
) -> None:
    """Without --geometry the markers stage fails; with --measurements its error was never
    printed, though the summary says "(see the error)"."""
    args = ("analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"), "--pixel-size",
            "12 um", "--height-unit", "um", "--up", "+y")  # fmt: skip
    code, out, alone = cli_main(*args, "--out", str(tmp_path / "an"))
    assert code == 2 and alone.startswith("error: markers: ") and _says_see_the_error(out)
    drops = tmp_path / "drops.csv"
    code, out, err = cli_main(*args, "--out", str(tmp_path / "an2"), "--measurements",
                              str(drops), "--label", "d20")  # fmt: skip
    assert code == 2 and _says_see_the_error(out)
    assert err.splitlines() == [
        alone.strip(),
        f"error: --measurements: nothing appended to {drops}: the analysis has no kinematics "
        "(a drop needs its angle and incoming velocity)",
    ]
    assert not drops.exists()
