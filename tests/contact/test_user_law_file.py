"""A user's law from the shell: a law file (TOML + CSV of measured data) read by
``impactlab --law-file FILE``, then ``--law NAME`` in ``simulate`` and ``impactlab laws NAME``;
a study file's ``[laws]`` table; one-line errors for bad files."""

from __future__ import annotations

import json
import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import impactlab as il
from impactlab.cli import app
from impactlab.contact import IndentationCurves, get_law, law_names, read_law_file, unregister_law
from impactlab.contact._common import jg_critical
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3
DC, FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)
NAME = "toy-measured"


def _write_law(folder: Path, name: str = NAME, **extra: str) -> Path:
    """Synthetic 'measured' data: Hertz to delta_c, then F ~ delta^1.2; delta_r growing."""
    d = DC * np.geomspace(1.0, 300.0, 40)
    f = FC * (d / DC) ** 1.2
    dm = DC * np.geomspace(1.0, 300.0, 20)
    dr = 0.6 * dm * (1.0 - np.sqrt(DC / dm))
    np.savetxt(folder / "loading.csv", np.c_[d, f], delimiter=",", header="delta,F")
    np.savetxt(folder / "unloading.csv", np.c_[dm, dr], delimiter=",", header="delta_max,delta_r")
    lines = {
        "name": name,
        "source": "synthetic data of the test",
        "body_material": "aisi-201",
        "flat_material": "aisi-1010",
        "radius": "8.8 mm",
        "loading": "loading.csv",
        "unloading": "unloading.csv",
        **extra,
    }
    path = folder / f"{name}.toml"
    path.write_text("".join(f"{k} = {json.dumps(v)}\n" for k, v in lines.items()))
    return path


@pytest.fixture(scope="module")
def law_file(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    path = _write_law(tmp_path_factory.mktemp("law"))
    yield path
    if NAME in law_names():
        unregister_law(NAME)


def test_law_file_on_the_command_line(law_file: Path) -> None:
    runner = CliRunner()
    res = runner.invoke(app, ["--law-file", str(law_file), "laws", NAME, "--json"])
    assert res.exit_code == 0, res.output
    info = json.loads(res.stdout)
    assert info["name"] == NAME and info["registered"] is True
    assert info["sampling_error"]["force"] < 0.05  # leave-one-out, smooth synthetic data
    for columns in ("200", "80"):  # the table and the blocks of a narrow terminal
        res = runner.invoke(app, ["--law-file", str(law_file), "laws"], env={"COLUMNS": columns})
        assert res.exit_code == 0, res.output
        assert NAME in res.stdout
    args = ["--angle", "40 deg", "--vy", "-1.4", "--mu", "0.2", "--law", NAME, "--json"]
    res = runner.invoke(app, ["--law-file", str(law_file), "simulate", *args])
    assert res.exit_code == 0, res.output
    e = json.loads(res.stdout)["e"]
    e = e["value"] if isinstance(e, dict) else e
    r = il.simulate(il.Rod.paper(), law=NAME, mu=0.2, angle=math.radians(40), velocity=(0, -1.4))
    assert e == pytest.approx(r.e, rel=1e-12)


def test_study_file_brings_its_law(law_file: Path) -> None:
    from impactlab.sweep import Study

    study_file = law_file.parent / "study.toml"
    study_file.write_text(
        f'[laws]\n{NAME} = "{law_file.name}"\n[fixed]\nlaw = "{NAME}"\nvy = -1.4\nmu = 0.2\n'
        '[grid]\nangle = ["30 deg", "60 deg"]\n'
    )
    study = Study.from_toml(study_file)
    assert set(study.laws) == {NAME}
    assert get_law(NAME).name == NAME


def test_bad_law_files_say_what_is_wrong(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "x"\n')
    with pytest.raises(ValueError, match="missing key"):
        read_law_file(bad)
    with pytest.raises(ValueError, match=r"unknown key\(s\) \['colour'\]"):
        read_law_file(_write_law(tmp_path, "toy-colour", colour="red"))
    with pytest.raises(ValueError, match=r"law file .*: .*built-in law's"):
        read_law_file(_write_law(tmp_path, "hertz"))
    res = CliRunner().invoke(app, ["--law-file", str(tmp_path / "nowhere.toml"), "laws"])
    assert res.exit_code != 0 and "nowhere.toml" in str(res.exception)


def test_a_json_result_of_a_law_file_reruns_where_the_law_is_unknown(
    law_file: Path, tmp_path: Path
) -> None:
    """``simulate --json`` writes the law's data (its numbers as quantity objects); ``--from``
    and ``rerun`` register the law from them where it is not registered (another process)."""
    runner = CliRunner()
    args = ["--angle", "40 deg", "--vy", "-1.4", "--mu", "0.2", "--law", NAME, "--json"]
    res = runner.invoke(app, ["--law-file", str(law_file), "simulate", *args])
    assert res.exit_code == 0, res.output
    saved = tmp_path / "r.json"
    saved.write_text(res.stdout)
    e = json.loads(res.stdout)["e"]["value"]
    unregister_law(NAME)
    res = runner.invoke(app, ["simulate", "--from", str(saved), "--json"])
    assert res.exit_code == 0, res.output
    assert NAME in law_names() and json.loads(res.stdout)["e"]["value"] == e
    unregister_law(NAME)
    assert il.rerun(json.loads(saved.read_text())).e == e


def test_a_material_file_of_a_law_file_lies_beside_it(tmp_path: Path, monkeypatch) -> None:
    """It was read from the current folder: a file of the same name there built the law."""
    from impactlab.materials import get_material

    folder = tmp_path / "laws"
    folder.mkdir()
    (folder / "flat.toml").write_text('E = "200 GPa"\nnu = 0.3\nSy = "305 MPa"\nrho = 7870\n')
    path = _write_law(folder, "beside-law", flat_material="flat.toml")
    elsewhere = tmp_path / "work"
    elsewhere.mkdir()
    (elsewhere / "flat.toml").write_text('E = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = 2700\n')
    monkeypatch.chdir(elsewhere)
    try:
        law = read_law_file(path)
        beside = ContactPair(AISI_201, get_material(folder / "flat.toml"))
        assert [c.e_star_over_sy for c in law.curves] == [
            pytest.approx(beside.E_star / beside.yield_strength, rel=1e-12)
        ]
    finally:
        unregister_law("beside-law")


def test_a_table_laws_loading_fit_is_made_once_per_curves(monkeypatch) -> None:
    """Each build fitted the loading curve twice: 0.8 s a model for a 20 000-row export."""
    from impactlab.contact import tabulated_fit

    calls = []
    fit = tabulated_fit.fit_loading

    def counted(*args):
        calls.append(1)
        return fit(*args)

    monkeypatch.setattr(tabulated_fit, "fit_loading", counted)
    d, dm = DC * np.geomspace(1.0, 300.0, 40), DC * np.geomspace(1.0, 300.0, 20)
    residual = 0.6 * dm * (1.0 - np.sqrt(DC / dm))  # the law file's synthetic data
    curves = IndentationCurves.from_arrays(PAIR, R, d, FC * (d / DC) ** 1.2, dm, residual)
    law = il.contact.register_law("fit-once", curves)
    try:
        first = law.build(PAIR, R)
        second = law.build(PAIR, R)
        assert np.array_equal(first.params, second.params, equal_nan=True)
        assert len(calls) == 1
    finally:
        unregister_law("fit-once")


def test_laws_name_of_a_law_of_another_pair_says_which_pair(tmp_path: Path, cli_main) -> None:
    """It said "make curves for this pair" (run CalculiX) of the example pair never asked for."""
    from impactlab.materials import get_material

    al = ContactPair(AISI_201, get_material("al-6061-t6"))
    dc, fc = jg_critical(al.E_star, R, al.yield_strength, al.nu)
    d, dm = dc * np.geomspace(1.0, 300.0, 40), dc * np.geomspace(1.0, 300.0, 20)
    path = _write_law(tmp_path, "al-toy", flat_material="al-6061-t6")  # its tables: below
    np.savetxt(tmp_path / "loading.csv", np.c_[d, fc * (d / dc) ** 1.2], delimiter=",")
    np.savetxt(tmp_path / "unloading.csv", np.c_[dm, 0.6 * dm * (1.0 - np.sqrt(dc / dm))],
               delimiter=",")  # fmt: skip
    try:
        code, _, err = cli_main("--law-file", str(path), "laws", "al-toy")
        text = " ".join(err.split())
        assert code == 2 and "has no numbers for aisi-201 on aisi-1010" in text, err
        assert "E*/S_y = 207.2" in text
        code, _, err = cli_main("--law-file", str(path), "laws", "al-toy", "--flat", "al-6061-t6")
        assert code == 0, err
    finally:
        if "al-toy" in law_names():
            unregister_law("al-toy")
