"""The command line's JSON as an archive: every result names the impactlab version that wrote
it (invert, analyze with its options, calibrate, fe indent), ``--from`` refuses an incomplete
record and warns once for one of another version, ``invert --json``'s rod feeds back through
``--file``, a force that does not exist is a quantity of value null, and ``laws --json`` writes
dimensionless units as ``"1"``."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import impactlab as il

CliMain = Callable[..., tuple[int, str, str]]

INVERT = ("invert", "--angle", "20 deg", "--vi", "-1.41 m/s", "--e", "0.5", "--mu", "0.2",
          "--delta-p", "22 um", "--ls", "1400 um", "--samples", "200")  # fmt: skip
INPUTS = 'angle = "20 deg"\nv_i = "1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\n'
INPUTS += 'sliding_length = "1400 um"\nn_samples = 200\n'
DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


def _json(cli_main: CliMain, *args: str) -> dict[str, Any]:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    return json.loads(out)  # type: ignore[no-any-return]


def _impact_file(cli_main: CliMain, tmp_path: Path) -> tuple[Path, dict[str, Any]]:
    data = _json(cli_main, "simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s",
                 "--mu", "0.2")  # fmt: skip
    return tmp_path / "rod.json", data


def test_from_refuses_a_record_without_mu(cli_main: CliMain, tmp_path: Path) -> None:
    path, data = _impact_file(cli_main, tmp_path)
    del data["input"]["mu"]
    path.write_text(json.dumps(data))
    code, out, err = cli_main("simulate", "--from", str(path), "--json")
    assert code == 2 and out == ""
    assert "lacks 'mu'" in err and err.count("\n") == 1


def test_from_warns_once_for_another_version(cli_main: CliMain, tmp_path: Path) -> None:
    path, data = _impact_file(cli_main, tmp_path)
    data["impactlab_version"] = data["input"]["impactlab_version"] = "0.9.0"
    path.write_text(json.dumps(data))
    code, out, err = cli_main("simulate", "--from", str(path), "--json")
    assert code == 0, err
    said = [line for line in err.splitlines() if "0.9.0" in line]
    assert len(said) == 1 and said[0].startswith("warning: ") and il.__version__ in said[0]
    assert json.loads(out)["e"] == data["e"]


def test_invert_json_names_its_version_seed_and_missing_force(cli_main: CliMain) -> None:
    data = _json(cli_main, *INVERT)
    assert data["impactlab_version"] == il.__version__
    assert isinstance(data["seed"], int)
    assert data["F_momentum"] == {"value": None, "unit": "N"}  # no --dv-cy: no such force
    assert data["F_rigid"]["unit"] == "N"


def test_invert_json_rod_feeds_back_through_file(cli_main: CliMain, tmp_path: Path) -> None:
    given = _json(cli_main, *INVERT, "--mass", "0.5 kg")
    rod = "\n".join(
        f'{k} = {{ value = {q["value"]!r}, unit = "{q["unit"]}" }}' for k, q in given["rod"].items()
    )
    toml = tmp_path / "m.toml"
    toml.write_text(f"{INPUTS}seed = {given['seed']}\n[rod]\n{rod}\n")
    again = _json(cli_main, "invert", "--file", str(toml))
    assert again["rod"] == given["rod"]
    assert again["duration"] == given["duration"]


def test_a_rod_table_with_a_sigma_is_refused_naming_it(cli_main: CliMain, tmp_path: Path) -> None:
    toml = tmp_path / "m.toml"
    toml.write_text(f'{INPUTS}[rod]\nmass = {{ value = 0.5, unit = "kg", sigma = 0.1 }}\n')
    code, _out, err = cli_main("invert", "--file", str(toml))
    assert code == 2 and "rod.mass is a table of ['sigma', 'unit', 'value']" in err


def test_laws_json_writes_dimensionless_units_as_1(cli_main: CliMain) -> None:
    data = _json(cli_main, "laws")
    laws = [law for name, law in data.items() if name != "impactlab_version"]
    units = {p["unit"] for law in laws for p in law["parameters"]}
    assert "-" not in units and "1" in units


def test_fe_indent_json_names_its_version(
    cli_main: CliMain, monkeypatch: pytest.MonkeyPatch
) -> None:
    from impactlab import fe

    monkeypatch.setattr(fe, "indent", lambda flat, body, **kwargs: [])
    monkeypatch.setattr(fe, "find_ccx", lambda: "ccx")
    data = _json(cli_main, "fe", "indent", "--max", "1 um")
    assert data["impactlab_version"] == il.__version__ and data["runs"] == []


def test_calibrate_json_is_the_calibration_document_with_its_files(
    cli_main: CliMain, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import impactlab.calibrate
    import impactlab.calibrate.jsonout
    import impactlab.calibrate.report  # imported before the patch: imported under it, its
    # calibration_json kept the stand-in for the later tests of the same process

    monkeypatch.setattr(impactlab.calibrate, "calibrate", lambda **kwargs: object())
    doc = {"impactlab_version": il.__version__}  # calibration_json's own (tests/calibrate)
    monkeypatch.setattr(impactlab.calibrate.jsonout, "calibration_json", lambda cal: doc)
    drops = tmp_path / "drops.csv"
    drops.write_text("e\n0.5\n")
    data = _json(cli_main, "calibrate", str(drops), "-p", "mu=uniform(0, 0.6)", "--quiet")
    assert data == {"impactlab_version": il.__version__, "files": {}}


def test_analyze_json_records_its_options_and_version(cli_main: CliMain) -> None:
    data = _json(cli_main, "analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"),
                 "--geometry", str(DATA / "markers.toml"), "--pixel-size", "12 um",
                 "--height-unit", "um", "--up", "+y")  # fmt: skip
    assert data["impactlab_version"] == il.__version__
    options = data["options"]
    assert options["pixel_size"] == "12 um" and options["height_unit"] == "um"
    assert options["up"] == "+y" and options["geometry"] == str(DATA / "markers.toml")
    assert options["rod"] == "paper" and options["flat"] is None
    assert options["gravity"] is False and options["flip_heights"] is False
