"""Study files that cannot be read, damaged stores and invalid grid values give one
clear error naming the file, the store or the dimension, its offending values and what is
allowed; valid inputs that fail physically are still stored with their status."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import VY_LIMIT, FakeEvaluator, run_cli

from impactlab.sweep import Study, load_study, open_sweep, run_sweep
from impactlab.sweep.store import CorruptStoreError

BASE = "[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['20 deg', '45 deg']\n"


def _one_line(err: str) -> str:
    assert err.startswith("error: ") and err.count("\n") == 1, err
    return err


# -- study files -------------------------------------------------------------------------------


def test_binary_study_file_names_the_file(tmp_path, monkeypatch, capsys) -> None:
    f = tmp_path / "junk.toml"
    f.write_bytes(b"\x8b\xff\x00\x10 binary")
    with pytest.raises(ValueError, match=r"study file '.*junk\.toml' is not a text file"):
        load_study(f)
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(f), "--out", str(tmp_path / "o"))
    assert code == 2 and str(f) in _one_line(err) and "codec" not in err


def test_invalid_toml_names_file_line_and_column(tmp_path, monkeypatch, capsys) -> None:
    f = tmp_path / "bad.toml"
    f.write_text('[fixed]\nvy = "-1 m/s\n')
    with pytest.raises(ValueError, match=r"bad\.toml' is not valid TOML: .*line 2, column 13"):
        load_study(f)
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "run", str(f))
    assert code == 2 and str(f) in _one_line(err)


# -- damaged stores ----------------------------------------------------------------------------


@pytest.fixture(scope="module")
def finished(tmp_path_factory) -> Path:
    """A finished store, run once for the module."""
    path = tmp_path_factory.mktemp("s") / "s.zarr"
    st = Study(name="s", grid={"angle": np.radians([20.0, 45.0])}, fixed={"vy": -1.0, "mu": 0.2})
    run_sweep(st, path, evaluator=FakeEvaluator(), quiet=True)
    return path


@pytest.fixture
def store(finished, tmp_path) -> Path:
    """A copy of the finished store, the test's own to damage."""
    return shutil.copytree(finished, tmp_path / "s.zarr")


@pytest.mark.parametrize(
    ("file", "content", "what"),
    [
        ("zarr.json", b"garbage{", "zarr.json is not valid JSON (Expecting value at line 1"),
        ("zarr.json", b"\x8b\xa7\xff\x00", "zarr.json is not text"),
        ("zarr.json", b"[1, 2]", "zarr.json is not a JSON object"),
        ("e/zarr.json", b'{"x":', "e/zarr.json is not valid JSON"),
        ("e/zarr.json", b'{"zarr_format": 2}', "e/zarr.json is not Zarr v3 metadata"),
        ("e/zarr.json", b'{"zarr_format": 3, "node_type": "array"}', "not valid Zarr metadata"),
        ("e/zarr.json", None, "e/zarr.json is missing"),
    ],
)
def test_damaged_metadata_names_store_and_file(
    store, monkeypatch, capsys, file: str, content: bytes | None, what: str
) -> None:
    target = store / file
    if content is None:
        target.unlink()
    else:
        target.write_bytes(content)
    with pytest.raises(CorruptStoreError, match=r"sweep store '.*s\.zarr' is damaged") as exc:
        open_sweep(store)
    assert what in str(exc.value) and "--restart" in str(exc.value)
    for args in (("info", str(store)), ("plot", str(store), "--out", str(store.parent / "p"))):
        code, out, err = run_cli(monkeypatch, capsys, "sweep", *args)
        assert code == 2 and out == "" and what in _one_line(err), args


def test_run_into_damaged_store_rewrites_it_or_restarts(store) -> None:
    """A damaged root, and an array's damaged metadata, are rewritten by the same study
    (tests/sweep/test_sweep_store_repair.py, test_store_metadata_repair.py); the damaged
    metadata of a folder that is not the study's needs --restart, which starts the store
    fresh."""
    (store / "zarr.json").write_text("not json")
    st = Study(name="s", grid={"angle": np.radians([20.0, 45.0])}, fixed={"vy": -1.0, "mu": 0.2})
    again = run_sweep(st, store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    (store / "angle" / "zarr.json").write_text("not json")
    again = run_sweep(st, store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    (store / "notes").mkdir()
    (store / "notes" / "zarr.json").write_text("not json")
    with pytest.raises(CorruptStoreError, match="--restart"):
        run_sweep(st, store, evaluator=FakeEvaluator(), quiet=True)
    res = run_sweep(st, store, evaluator=FakeEvaluator(), quiet=True, restart=True)
    assert int((res.dataset["status"] == 0).sum()) == 2
    assert json.loads((store / "zarr.json").read_text())["node_type"] == "group"


# -- invalid grid values -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("table", "message"),
    [
        (
            "[fixed]\nvy = -1\nangle = '20 deg'\n[grid]\nmu = [0.1, -0.2, 0.3, -0.05]\n",
            "grid dimension 'mu': mu must lie in [0, 1000], got -0.2, -0.05 (2 of 4 values)",
        ),
        (
            "[fixed]\nvy = -1\nmu = 0.1\n[grid]\n"
            "angle = { start = 0, stop = 90, num = 4, unit = 'deg' }\n",
            "grid dimension 'angle': angle must lie in (0, 90] deg, got 0 deg (1 of 4 values)",
        ),
        (
            "[fixed]\nvy = -1\nmu = 0.1\n[grid]\nangle = ['30 deg', '95 deg', '120 deg']\n",
            "angle must lie in (0, 90] deg, got 95, 120 deg (2 of 3 values)",
        ),
        (
            "[fixed]\nangle = '20 deg'\nmu = 0.1\n[grid]\nvy = ['-1 m/s', '0.5 m/s', '2 m/s']\n",
            "grid dimension 'vy': the contact point must approach the flat (vy < 0 m/s with "
            "spin = 0), got 0.5, 2 m/s (2 of 3 values)",
        ),
        (
            BASE + "tip_radius = ['5 mm', '-1 mm']\n",
            "grid dimension 'tip_radius': tip_radius must be > 0 mm, got -1 mm (1 of 2 values)",
        ),
        (
            BASE + "body_nu = [0.3, 0.6]\n",
            "grid dimension 'body_nu': body_nu must lie in (-1, 0.5), got 0.6 (1 of 2 values)",
        ),
        (
            "[fixed]\nvy = -1\nangle = '20 deg'\nmu = -0.1\n[grid]\nvx = [0, 1]\n",
            "input 'mu': mu must lie in [0, 1000], got -0.1",
        ),
    ],
)
def test_invalid_grid_values_refused_when_loaded(
    tmp_path, monkeypatch, capsys, table: str, message: str
) -> None:
    f = tmp_path / "bad.toml"
    f.write_text(table)
    with pytest.raises(ValueError, match=r"^(grid dimension|input) '") as exc:
        load_study(f)
    assert message in str(exc.value)
    out = tmp_path / "o.zarr"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(f), "--out", str(out))
    assert code == 2 and message in _one_line(err) and not out.exists()  # nothing computed


def test_python_grid_axis_refuses_invalid_values() -> None:
    with pytest.raises(
        ValueError, match=r"'mu': mu must lie in \[0, 1000\], got -0.1 \(1 of 2 values\)"
    ):
        Study(name="s", grid={"mu": [-0.1, 0.2]}, fixed={"angle": 0.3, "vy": -1.0})


def test_what_only_a_case_can_tell_is_still_stored_with_its_status(tmp_path) -> None:
    """Valid inputs: a sphere beside a rod ignores the angle; a spin may turn vy > 0 into an
    approach; S_y >= E is a combination; the fake law's validity limit fails cases physically."""
    sphere = (  # a study of spheres and rods: the angle applies to the rods only
        "[fixed]\nradius = '5 mm'\nangle = '20 deg'\nvy = -1\nmu = 0.1\n"
        "[grid]\nbody = ['sphere', 'rod']\n"
    )
    spin = "[fixed]\nangle = '20 deg'\nmu = 0.1\nspin = '-40 rad/s'\n[grid]\nvy = [0.5, -1]\n"
    combo = (
        "[fixed]\nvy = -1.41\nmu = 0.2\nflat_E = '200 GPa'\nflat_nu = 0.3\n[grid]\n"
        "angle = ['20 deg', '45 deg']\nflat_yield_strength = ['300 MPa', '400 GPa']\n"
    )
    for i, text in enumerate((sphere, spin, combo)):
        f = tmp_path / f"ok{i}.toml"
        f.write_text(text)
        assert load_study(f).n_cases == (4 if i == 2 else 2)
    st = Study(name="v", grid={"vy": [-1.0, VY_LIMIT - 1.0]}, fixed={"angle": 0.3, "mu": 0.1})
    ds = run_sweep(st, tmp_path / "v.zarr", evaluator=FakeEvaluator(), quiet=True).dataset
    assert ds["status"].values.tolist() == [0, 1]  # stored, with the evaluator's status


@pytest.mark.parametrize(
    ("values", "said"),
    [
        (np.array([[0.1, 0.2]]), r"grid axis 'mu' must be a list of values \(one dimension\)"),
        ({0.1, 0.2}, r"grid axis 'mu' must be a list of values, in order, got a set"),
    ],
)
def test_a_grid_axis_that_is_no_list_is_named_as_such(values, said) -> None:
    """It said "input 'mu' must be a plain number, got [0.1, 0.2]"."""
    with pytest.raises(ValueError, match=said):
        Study(name="g", grid={"mu": values}, fixed={"vy": -1.41, "angle": "20 deg"})
