"""Studies too big to run are refused before anything is created (with the case count and an
estimate of time and disk); tiny chunks warn; study files name what is wrong (law parameters,
engine options, the study name)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import DEFAULT_MAX_CASES, Sample, Study, SweepSizeWarning, Uniform, run_sweep


def _table(**extra) -> dict:
    base = {"fixed": {"vy": -1.41, "mu": 0.2}, "grid": {"angle": ["10 deg", "20 deg"]}}
    for key, value in extra.items():
        base[key] = {**base.get(key, {}), **value}
    return base


@pytest.mark.parametrize(
    ("grid", "cases"),
    [
        (
            {"angle": {"start": 10, "stop": 80, "num": 10**10, "unit": "deg"}},
            "10,000,000,000 cases",
        ),
        (
            {
                "angle": {"start": 10, "stop": 80, "num": 100_000, "unit": "deg"},
                "mu": {"start": 0, "stop": 1, "num": 10_000},
                "vx": {"start": 0, "stop": 1, "num": 10_000},
            },
            "10,000,000,000,000 cases",
        ),
    ],
)
def test_huge_grids_are_refused_with_an_estimate(tmp_path, grid, cases) -> None:
    with pytest.raises(ValueError, match="more than max_cases = 100,000,000") as err:
        Study.from_dict(
            {"fixed": {"vy": -1.41, "mu": 0.2} if "mu" not in grid else {"vy": -1}, "grid": grid}
        )
    msg = str(err.value)
    assert cases in msg and "impacts/s per core" in msg and "of disk" in msg
    assert "--max-cases" in msg


def test_huge_sample_is_refused_before_a_store_exists(tmp_path) -> None:
    study = {
        "fixed": {"vy": -1.41, "angle": "20 deg"},
        "sample": {"size": 10**12, "mu": {"dist": "uniform", "low": 0, "high": 1}},
    }
    with pytest.raises(
        ValueError, match=r"1,000,000,000,000 cases.*: about .* on this machine"
    ) as err:
        run_sweep(study, tmp_path / "big.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert "study 'study'" in str(err.value)
    assert list(tmp_path.iterdir()) == []  # nothing created
    # the limit is the user's to raise; it changes no result and is not part of the hash
    big = Study(
        name="big",
        fixed={"vy": -1.41, "angle": 0.3},
        sample=Sample(size=10**12, seed=0, inputs={"mu": Uniform(0, 1)}),
        max_cases=10**12,
    )
    assert big.n_cases == 10**12
    small = Study.from_dict(_table(study={"max_cases": 10}))
    assert small.max_cases == 10 and small.hash() == Study.from_dict(_table()).hash()
    assert Study.from_dict(small.to_dict()).max_cases == 10
    assert Study.from_dict(_table()).max_cases == DEFAULT_MAX_CASES
    with pytest.raises(ValueError, match="2 cases, more than max_cases = 1"):
        Study.from_dict(_table(), max_cases=1)


def test_cli_max_cases_and_chunk_warnings(tmp_path, monkeypatch, capsys) -> None:
    f = tmp_path / "s.toml"
    f.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['10 deg', '20 deg', '30 deg']\n")
    code, _, err = run_cli(
        monkeypatch, capsys, "sweep", str(f), "--max-cases", "2", "-o", str(tmp_path / "x.zarr")
    )
    assert code == 2 and err.count("\n") == 1 and "3 cases, more than max_cases = 2" in err
    assert not (tmp_path / "x.zarr").exists()
    f.write_text("[study]\nchunk_size = 1\n" + f.read_text())
    out = tmp_path / "s.zarr"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(f), "-o", str(out), "-q")
    assert code == 0
    assert err.startswith("warning: study 's': chunk_size = 1 cuts 3 cases into 3 chunks")


def test_tiny_chunks_warn() -> None:
    base = {"name": "w", "fixed": {"vy": -1.41, "mu": 0.2}}
    with pytest.warns(SweepSizeWarning, match="chunk_size = 1 cuts 5 cases into 5 chunks"):
        Study(grid={"angle": np.linspace(0.1, 0.5, 5)}, chunk_size=1, **base)
    with pytest.warns(SweepSizeWarning, match="2,000 chunks of about 10 case"):
        Study(grid={"angle": np.linspace(0.1, 1.5, 20_000)}, chunk_size=10, **base)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Study(grid={"angle": np.linspace(0.1, 1.5, 20)}, chunk_size=5, **base)  # few chunks
        Study(grid={"angle": [0.3]}, chunk_size=1, **base)  # one case


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (
            {"law_params": {"bogus": 1.0}},
            r"'bogus' is not a parameter of contact law 'ghaednia'; its parameters: "
            r"published_switch",
        ),
        (
            {"law_params": {"hardness": 2e9}, "grid": {"law": ["brake", "hertz"]}},
            r"'hardness' is not a parameter of contact law 'hertz'; its parameters: none",
        ),
        (
            {"engine": {"rtol": "tight"}},
            r"engine rtol must be a number in \[1e-13, 0.001\], got 'tight'",
        ),
        ({"engine": {"gravity": "yes"}}, r"cannot parse 'yes' .*; allowed: true/false, a numb"),
        (
            {"engine": {"gravity": "9.81 m/s"}},
            r"^engine gravity: '9.81 m/s' has the wrong dimension; expected a quantity "
            r"convertible to m/s\^2; allowed: true/false, a number in \[0, 1e\+07\] \(m/s\^2\) "
            r"or a quantity such as '9.81 m/s\^2'$",
        ),
        (
            {"engine": {"gravity": "9,81 m/s^2"}},
            r"^engine gravity: '9,81 m/s\^2' holds a comma; write one quantity with a decimal "
            r"point, .*; allowed: true/false, a number in \[0, 1e\+07\]",
        ),
        ({"engine": {"gravity": "-3 m/s^2"}}, r"^engine gravity must be true/false, .*, got -3.0$"),
        ({"engine": {"rtol": 0.01}}, r"engine rtol must be a number in \[1e-13, 0.001\], got 0.01"),
        (
            {"engine": {"gravity": 1e8}},
            r"number in \[0, 1e\+07\] \(m/s\^2\) or a .*, got 100000000.0",
        ),
        ({"fixed": {"mu": 2000.0}}, r"input 'mu': mu must lie in \[0, 1000\], got 2000"),
        ({"fixed": {"vx": 2e4}}, r"input 'vx': vx must lie in \[-10000, 10000\] m/s, got 20000"),
        ({"study": {"max_cases": 0}}, "max_cases must be an integer >= 1, got 0"),
        ({"study": {"name": "../x"}}, r"study name must be letters, .* got '\.\./x'"),
        ({"study": {"name": "/tmp/x"}}, "study name must be letters"),
        ({"study": {"name": ".."}}, "study name must be letters"),
        ({"study": {"name": "a\nb"}}, "study name must be letters"),
        ({"study": {"name": "a b"}}, "study name must be letters"),
        ({"study": {"name": ""}}, "study name must be letters"),
    ],
)
def test_study_file_mistakes_are_named(extra, message) -> None:
    with pytest.raises(ValueError, match=message):
        Study.from_dict(_table(**extra))


def test_valid_law_params_and_names_pass(tmp_path) -> None:
    s = Study.from_dict(_table(law_params={"published_switch": 1.0}, study={"name": "v1.2_a-b"}))
    assert s.law_params == {"published_switch": 1.0} and s.name == "v1.2_a-b"
    f = tmp_path / "my study (2).toml"
    f.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['10 deg']\n")
    assert Study.from_toml(f).name == "my_study__2_"  # the file name, made a valid name


def test_bad_name_in_a_study_file_writes_nothing(tmp_path, monkeypatch, capsys) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "work").mkdir()
    f = tmp_path / "work" / "s.toml"
    f.write_text(
        "[study]\nname = '../escaped'\n[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['10 deg']\n"
    )
    monkeypatch.chdir(tmp_path / "work")
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "s.toml")
    assert code == 2 and "study name must be letters" in err and err.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["work"]
