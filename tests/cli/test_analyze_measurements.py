"""``impactlab analyze ... --measurements FILE.csv --label NAME``: the analysed drop appended to
a measurements file for ``impactlab calibrate`` (there was no route from one to the other)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from impactlab.calibrate import read_measurements

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"
ARGS = (
    "analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"), "--pixel-size", "12 um",
    "--height-unit", "um", "--up", "+y", "--geometry", str(DATA / "markers.toml"),
)  # fmt: skip

CliMain = Callable[..., tuple[int, str, str]]


def test_the_drop_is_appended_and_calibrate_reads_it(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "drops.csv"
    path.write_text(
        "# lab drops\nlabel,angle [deg],vy [m/s],mu,e,e_sigma\nold,45,-2,0.2,0.4,0.02\n"
    )
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d20")
    assert code == 0, err
    assert f"appended drop 'd20' to {path} (2 drops)" in err
    m = read_measurements(path)
    assert m.labels == ("old", "d20")
    assert {"e", "spin_out", "delta_p", "scar_length"} <= set(m.quantities)
    assert path.read_text().startswith("# lab drops\nlabel,angle [deg],vy [m/s],mu,e,e_sigma,")
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d20")
    assert code == 2 and "has a drop labelled 'd20' already: give another --label" in err
    code, _, err = cli_main(*ARGS, "--measurements", str(tmp_path / "d.toml"))
    assert code == 2 and "a drop is appended to a CSV file (.csv)" in err
    code, _, err = cli_main(*ARGS, "--label", "x")
    assert code == 2 and "give --measurements FILE.csv" in err


def test_a_result_that_is_not_ok_is_refused_unless_asked_for(
    tmp_path: Path, cli_main: CliMain
) -> None:
    rod = tmp_path / "rod.toml"
    rod.write_text(  # an inertia 100 times too small: a doubt
        '[rod]\nmass = 0.4607\nlength = "304.8 mm"\ntip_radius = "8.8 mm"\n'
        'inertia = "0.000035667 kg*m^2"\n'
    )
    path = tmp_path / "drops.csv"
    code, _, err = cli_main(*ARGS, "--rod", str(rod), "--measurements", str(path))
    assert code == 2
    assert "--measurements: nothing appended" in err and "is not ok (" in err
    assert "--include-doubtful" in err and not path.exists()
    code, _, err = cli_main(*ARGS, "--rod", str(rod), "--measurements", str(path),
                            "--include-doubtful")  # fmt: skip
    assert code == 0 and "appended though its analysis is not ok" in err
    assert read_measurements(path).labels == ("drop",)  # the marker file's name
    assert "# doubtful drop 'drop'" in path.read_text()


def test_the_help_shows_the_route_to_calibrate(tmp_path: Path, cli_main: CliMain) -> None:
    for cmd in ("analyze", "calibrate"):
        code, out, _ = cli_main(cmd, "--help")
        assert code == 0 and "Examples:" in out
        assert "--measurements drops.csv --label d20" in out
    (tmp_path / "results.json").write_text("{}")
    code, _, err = cli_main("calibrate", str(tmp_path / "results.json"), "-p", "mu=uniform(0, 1)")
    assert code != 0 and "impactlab analyze MARKERS SCAN --measurements" in err
