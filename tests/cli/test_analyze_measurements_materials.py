"""A drop appended without --flat to a file whose earlier drops name another flat material: a
warning names the default it takes and how to set it (it became aisi-1010 in silence)."""

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


def test_the_default_flat_is_named(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "drops.csv"
    path.write_text(
        "label,angle [deg],vy [m/s],mu,e,e_sigma,flat_material\nd1,45,-2,0.2,0.4,0.02,aisi-304\n"
    )
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d2")
    assert code == 0, err
    assert (
        "drop 'd2' names no material of the flat and takes the default aisi-1010, while earlier "
        "drops name aisi-304: give --flat NAME (flat= in Python), or edit its flat_material field"
    ) in " ".join(err.split())
    assert [c["flat_material"] for c in read_measurements(path).categories] == [
        "aisi-304",
        "aisi-1010",
    ]


def test_no_warning_where_the_materials_agree(tmp_path: Path, cli_main: CliMain) -> None:
    path = tmp_path / "drops.csv"
    path.write_text("label,angle [deg],vy [m/s],mu,e,e_sigma\nd1,45,-2,0.2,0.4,0.02\n")
    code, _, err = cli_main(*ARGS, "--measurements", str(path), "--label", "d2")
    assert code == 0 and "names no material" not in err
