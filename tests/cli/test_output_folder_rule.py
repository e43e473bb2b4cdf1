"""One rule for the files a command writes into a folder (``--out``): a file that an earlier run
of the same command wrote is replaced; a user's file of the same name (or another command's) is
left as it is, and the command stops before any work with one line naming it."""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab.cli.output_paths import check_replaceable, mark, save_figure, written_by

ROD = ("simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--plot", "--out")


def _figure(path: Path, command: str | None) -> Path:
    """A small figure at ``path``: marked as ``command``'s, or (None) a user's."""
    from impactlab._mpl import pyplot

    fig, ax = pyplot().subplots()
    ax.plot([0, 1], [0, 1])
    if command is None:
        fig.savefig(path)
    else:
        save_figure(fig, path, command, dpi=50)
    pyplot().close(fig)
    return path


# --- the mark ---------------------------------------------------------------------------------


@pytest.mark.parametrize("suffix", [".png", ".pdf"])
def test_a_figure_knows_the_command_that_wrote_it(tmp_path: Path, suffix: str) -> None:
    ours = _figure(tmp_path / f"a{suffix}", "fe indent")
    theirs = _figure(tmp_path / f"b{suffix}", None)
    assert written_by(ours, "fe indent") and not written_by(ours, "simulate")
    assert not written_by(ours, "fe")  # "impactlab fe indent" is not "impactlab fe"'s
    assert not written_by(theirs, "fe indent")


def test_json_by_its_keys_html_by_its_generator_empty_always(tmp_path: Path) -> None:
    js = tmp_path / "r.json"
    js.write_text(json.dumps({"a": 1, "b": 2}))
    assert written_by(js, "x", ("a", "b")) and not written_by(js, "x", ("a", "c"))
    js.write_text("[1, 2]")
    assert not written_by(js, "x", ("a",))
    page = tmp_path / "report.html"
    page.write_text(f"<html><head><meta name='generator' content='{mark('calibrate')}'>")
    assert written_by(page, "calibrate") and not written_by(page, "simulate")
    page.write_text("<html><head><title>mine</title>")
    assert not written_by(page, "calibrate")
    empty = tmp_path / "empty.png"
    empty.touch()
    assert written_by(empty, "simulate")  # nothing to lose: left by an interrupted write


def test_the_refusal_names_the_files_and_the_option(tmp_path: Path) -> None:
    from impactlab.cli._common import UserError

    _figure(tmp_path / "own.png", "simulate")
    (tmp_path / "mine.png").write_bytes(b"holiday photo")
    check_replaceable(tmp_path, ["own.png", "absent.png"], "simulate")
    with pytest.raises(UserError) as caught:
        check_replaceable(tmp_path, ["own.png", "mine.png"], "simulate", "--out")
    text = str(caught.value)
    assert (
        f"{str(tmp_path / 'mine.png')!r} is in the output folder but was not written by "
        "impactlab simulate: it is left as it is (move it, or choose another --out)" == text
    )
    (tmp_path / "dir.png").mkdir()
    with pytest.raises(UserError, match="a folder of that name is in the way"):
        check_replaceable(tmp_path, ["dir.png"], "simulate")


# --- simulate --plot ----------------------------------------------------------------------------


@pytest.fixture(scope="module")
def earlier_plots(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The folder of one ``simulate --plot --json`` run (``ROD``), shared: the tests below work
    on copies of it."""
    from impactlab.cli import main

    out = tmp_path_factory.mktemp("earlier") / "plots"
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv("IMPACTLAB_DEBUG", raising=False)
        mp.setattr(sys, "argv", ["impactlab", *ROD, str(out), "--json"])
        code: object = 0
        try:
            main()
        except SystemExit as exc:
            code = exc.code or 0
    assert code == 0 and (out / "impact_result.json").exists(), code
    return out


def test_simulate_replaces_its_own_files_and_marks_them(
    cli_main: Any, tmp_path: Path, earlier_plots: Path
) -> None:
    out = tmp_path / "plots"
    shutil.copytree(earlier_plots, out)
    code, _, err = cli_main(*ROD, str(out), "--json")  # replaces the earlier run's files
    assert code == 0, err
    assert written_by(out / "impact_force_time.png", "simulate")
    assert written_by(out / "impact_dent.pdf", "simulate")
    assert json.loads((out / "impact_result.json").read_text())["e"]["unit"] == "1"


def test_an_interrupted_plot_leaves_the_earlier_run_s_files(
    cli_main: Any, tmp_path: Path, earlier_plots: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Ctrl-C while the figures are drawn: none of the new run's files is written (the earlier
    run's force-time figure had been replaced beside its impact_result.json and dent)."""
    import os
    import signal

    from impactlab.dynamics import plotting

    out = tmp_path / "plots"
    shutil.copytree(earlier_plots, out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    real = plotting.plot_contact_path

    def interrupted(result: Any) -> Any:
        fig = real(result)
        os.kill(os.getpid(), signal.SIGINT)
        return fig

    monkeypatch.setattr(plotting, "plot_contact_path", interrupted)
    code, _, err = cli_main("simulate", "rod", "--angle", "45 deg", "--vy", "-1.41 m/s",
                            "--plot", "--out", str(out))  # fmt: skip
    assert code == 130, err
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before


@pytest.mark.parametrize("name", ["impact_result.json", "impact_dent.png", "impact_dent.pdf"])
def test_simulate_leaves_a_users_file_alone(cli_main: Any, tmp_path: Path, name: str) -> None:
    mine = tmp_path / name
    mine.write_text('{"my": "notes"}')
    code, out, err = cli_main(*ROD, str(tmp_path))
    assert code == 2 and out == ""
    assert err == (
        f"error: {str(mine)!r} is in the output folder but was not written by impactlab "
        "simulate: it is left as it is (move it, or choose another --out)\n"
    )
    assert mine.read_text() == '{"my": "notes"}'
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]  # nothing else written


# --- calibrate --out ----------------------------------------------------------------------------


#: Measured drops shipped with the examples.
DROPS = Path(__file__).resolve().parents[2] / "examples" / "data" / "drops.csv"
CALIBRATE = ("calibrate", str(DROPS), "-p", "mu=uniform(0, 0.6)", "--walkers", "4", "-q")


@pytest.mark.parametrize("name", ["results.json", "report.html"])
def test_calibrate_leaves_a_users_file_alone(cli_main: Any, tmp_path: Path, name: str) -> None:
    out = tmp_path / "cal"
    out.mkdir()
    (out / name).write_text("{}" if name.endswith(".json") else "<html>my page</html>")
    code, _, err = cli_main(*CALIBRATE, "--out", str(out))
    assert code == 2
    assert err.startswith(f"error: {str(out / name)!r} is in the output folder but was not "
                          "written by impactlab calibrate")  # fmt: skip
    assert not (out / "state").exists()  # stopped before the run


def test_calibrate_takes_a_folder_of_its_own_files(cli_main: Any, tmp_path: Path) -> None:
    """Its own results.json (its keys) and report.html (its generator): past the folder's
    check to the next one (--steps, checked before any sampling)."""
    from impactlab.calibrate.report import GENERATOR, RESULT_KEYS

    out = tmp_path / "cal"
    out.mkdir()
    (out / "results.json").write_text(json.dumps(dict.fromkeys(RESULT_KEYS, 0)))
    (out / "report.html").write_text(f"<html><head><meta name='generator' content='{GENERATOR}'>")
    code, _, err = cli_main(*CALIBRATE, "--out", str(out), "--steps", "5")
    assert (code, err) == (2, "error: --steps must be >= 10, got 5\n")


def test_calibrate_replaces_its_own_files_and_marks_them(cli_main: Any, tmp_path: Path) -> None:
    out = tmp_path / "cal"
    for _ in range(2):  # the second run replaces the first one's results.json and report.html
        code, _, err = cli_main(*CALIBRATE, "--steps", "10", "--out", str(out))
        assert code == 0, err
    assert written_by(out / "report.html", "calibrate")
    assert written_by(out / "results.json", "calibrate", ("settings", "ranking", "models"))


# --- fe indent --plot ---------------------------------------------------------------------------


@pytest.fixture
def fake_fe(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """``fe indent`` without CalculiX: one loading-only run; the list counts the runs."""
    from impactlab import fe

    runs: list[int] = []
    d, empty = np.array([0.0, 0.5e-6, 1e-6]), np.array([])

    def indent(flat: Any, body: Any, **kwargs: Any) -> list[Any]:
        runs.append(1)
        return [fe.IndentationResult(
            1e-6, d, 10.0 * d / 1e-6, np.array([0.0, 60e-6, 97.8e-6]), empty, empty, np.nan,
            empty, empty, 0.43624e-6, True, 1e-6, "", 10, 0, 30, 20.0, 2128, 1e-7, {},
        )]  # fmt: skip

    monkeypatch.setattr(fe, "indent", indent)
    monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")
    return runs


def test_fe_replaces_its_own_figure(cli_main: Any, tmp_path: Path, fake_fe: list[int]) -> None:
    _figure(tmp_path / "fe_indent.png", "fe indent")
    before = (tmp_path / "fe_indent.png").read_bytes()
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--plot", "--out", str(tmp_path))
    assert code == 0, err
    assert fake_fe == [1] and (tmp_path / "fe_indent.png").read_bytes() != before
    assert written_by(tmp_path / "fe_indent.png", "fe indent")


@pytest.mark.parametrize("command", [None, "simulate"])
def test_fe_leaves_another_figure_alone(
    cli_main: Any, tmp_path: Path, fake_fe: list[int], command: str | None
) -> None:
    theirs = _figure(tmp_path / "fe_indent.png", command)
    before = theirs.read_bytes()
    code, _, err = cli_main("fe", "indent", "--max", "1 um", "--plot", "--out", str(tmp_path))
    assert code == 2 and fake_fe == []  # refused before any run
    assert err == (
        f"error: {str(theirs)!r} is in the output folder but was not written by impactlab fe "
        "indent: it is left as it is (move it, or choose another --out)\n"
    )
    assert theirs.read_bytes() == before
