"""``impactlab sweep``: one-line errors for bad study files; end to end with the real engine."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sweep_fakes import run_cli

import impactlab
from impactlab._json import shape_problems

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            "[grid]\nangel = [10, 20]\n[fixed]\nvy = -1\nmu = 0.1\n",
            "unknown input 'angel'; known inputs: angle, vx, vy",
        ),
        (
            "[fixed]\nvy = -1\nangle = '20 deg'\n[sample]\nsize = 10\nmu = { dist = 'beta' }\n",
            "unknown distribution 'beta'",
        ),
        (
            "[fixed]\nvy = -1\nangle = '20 deg'\n[sample]\nsize = 10\n"
            "mu = { dist = 'normal', mean = 0.2 }\n",
            "needs 'std'",
        ),
        ("[grid\n", "not valid TOML"),
        (
            "[fixed]\nvy = -1\nmu = 0.1\nlaw = 'hooke'\n[grid]\nangle = ['10 deg']\n",
            "unknown contact law 'hooke'",
        ),
        (
            "[fixed]\nvy = -1\nmu = 0.1\n[grid]\nangle = ['10 deg']\n"
            "[outputs]\nkeep = ['e', 'zz']\n",
            "unknown output(s) ['zz']",
        ),
    ],
)
def test_bad_study_files_give_one_line(tmp_path, monkeypatch, capsys, text, message) -> None:
    f = tmp_path / "bad.toml"
    f.write_text(text)
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(f), "--out", str(tmp_path / "o"))
    assert code == 2
    assert err.startswith("error: ") and err.count("\n") == 1, err
    assert message in err


def test_missing_study_file(tmp_path, monkeypatch, capsys) -> None:
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(tmp_path / "nope.toml"))
    assert code == 2 and "does not exist" in err


def test_uncertainty_of_a_missing_store_names_a_store(tmp_path, monkeypatch, capsys) -> None:
    gone = tmp_path / "gone.zarr"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", str(gone))
    assert code == 2 and err.strip() == (
        f"error: sweep store {str(gone)!r} does not exist: give a Monte Carlo study file (TOML) "
        "or the Zarr store it ran into"
    )


def test_run_resume_export_plot_info(tmp_path, monkeypatch, capsys) -> None:
    study = tmp_path / "small.toml"
    study.write_text(
        "[study]\nname = 'small'\nchunk_size = 30\n"
        "[fixed]\nvy = '-1.41 m/s'\n"
        "[grid]\nangle = { start = 10, stop = 80, num = 8, unit = 'deg' }\n"
        "mu = [0.0, 0.1, 0.2, 0.4, 0.6]\n"
        "[outputs]\nkeep = ['e', 'delta_p', 'sliding_length', 'duration', 'regime']\n"
    )
    store = tmp_path / "small.zarr"
    code, out, err = run_cli(
        monkeypatch,
        capsys,
        "sweep",
        str(study),
        "--out",
        str(store),
        "--json",
        "--netcdf",
        str(tmp_path / "small.nc"),
        "--plot",
        str(tmp_path / "plots"),
    )
    assert code == 0, err
    summary = json.loads(out)
    assert shape_problems(summary) == []  # docs/json-schema.md
    assert summary["wall_time"]["unit"] == "s" and isinstance(summary["status"], dict)
    assert summary["cases"] == 40 and summary["chunks_computed"] == summary["chunks"]
    assert (tmp_path / "small.nc").is_file()
    assert (tmp_path / "plots" / "regime_map.png").is_file()
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "run", str(study), "--out", str(store), "--json"
    )
    resumed = json.loads(out)
    assert code == 0 and resumed["chunks_computed"] == 0  # nothing recomputed
    assert resumed["first_task"] is None  # nothing loaded the engine: no first task to time
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert shape_problems(json.loads(out)) == []
    counts = json.loads(out)
    assert code == 0 and counts["chunks_done"] == counts["chunks_total"] == summary["chunks"]
    assert counts["store_version"] == impactlab.__version__  # who wrote the store
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store))
    assert code == 0 and "0: finished = 40" in out and "{'" not in out  # no raw Python reprs
    changed = tmp_path / "changed.toml"
    changed.write_text(study.read_text().replace("-1.41 m/s", "-2 m/s"))
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(changed), "--out", str(store))
    assert code == 2 and "--restart" in err


def test_uncertainty_command(tmp_path, monkeypatch, capsys) -> None:
    study = tmp_path / "mc.toml"
    study.write_text(
        "[study]\nname = 'mc'\nchunk_size = 100\n"
        "[fixed]\nangle = '45 deg'\n"
        "[sample]\nsize = 300\nseed = 4\n"
        "vy = { dist = 'normal', mean = '-2.18 m/s', std = '0.05 m/s' }\n"
        "mu = { dist = 'uniform', low = 0.05, high = 0.3 }\n"
        "[uncertainty]\noutputs = ['e', 'delta_p', 'L_s', 'T', 'F']\n"
    )
    code, out, err = run_cli(
        monkeypatch,
        capsys,
        "sweep",
        "uncertainty",
        str(study),
        "--out",
        str(tmp_path / "mc.zarr"),
        "--json",
    )
    assert code == 0, err
    assert shape_problems(json.loads(out)) == []  # docs/json-schema.md
    rep = next(iter(json.loads(out).values()))
    outs = {r["output"] for r in rep["summary"]}
    assert outs == {"e", "delta_p", "sliding_length", "duration", "mean_force"}
    assert {r["input"] for r in rep["sensitivity"]} == {"vy", "mu"}


def test_a_cluster_without_workers_is_one_line(tmp_path, monkeypatch, capsys) -> None:
    """The sweep stops when the cluster has had no worker for worker_timeout: the command says
    so in one line (exit 2), not with the traceback of the watch."""
    import impactlab.sweep as sweep_pkg
    from impactlab.sweep.backends import NoWorkersError

    def no_workers(*_args: object, **_kwargs: object) -> None:
        raise NoWorkersError("no Dask worker left on the cluster for 5 s (worker_timeout); ...")

    monkeypatch.setattr(sweep_pkg, "run_sweep", no_workers)
    study = tmp_path / "s.toml"
    study.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['20 deg', '45 deg']\n")
    code, out, err = run_cli(monkeypatch, capsys, "sweep", str(study), "--out",
                             str(tmp_path / "s.zarr"))  # fmt: skip
    assert code == 2 and out == ""
    assert err == "error: no Dask worker left on the cluster for 5 s (worker_timeout); ...\n"


def test_a_scheduler_that_does_not_answer_says_the_store_resumes(
    tmp_path, monkeypatch, capsys
) -> None:
    """A scheduler that times out: one line naming it and saying that the store keeps what it
    holds and resumes."""
    import impactlab.sweep as sweep_pkg

    def unreachable(*_args: object, **_kwargs: object) -> None:
        raise TimeoutError("Timed out trying to connect to tcp://127.0.0.1:9 after 30 s")

    monkeypatch.setattr(sweep_pkg, "run_sweep", unreachable)
    study = tmp_path / "s.toml"
    study.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['20 deg', '45 deg']\n")
    store = tmp_path / "s.zarr"
    code, out, err = run_cli(monkeypatch, capsys, "sweep", str(study), "--out", str(store),
                             "--scheduler", "tcp://127.0.0.1:9")  # fmt: skip
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert "cannot use the Dask scheduler 'tcp://127.0.0.1:9': Timed out" in err
    assert f"the store {store} keeps what it holds (run again to resume" in err


def test_uncertainty_outputs_the_study_does_not_keep_are_refused_before_the_sweep(
    tmp_path, monkeypatch, capsys
) -> None:
    study = tmp_path / "u.toml"
    study.write_text(
        "[study]\nname = 'u'\n[fixed]\nangle = '20 deg'\nvy = -1.41\n[sample]\nsize = 20\n"
        "seed = 1\nmu = { dist = 'uniform', low = 0.1, high = 0.3 }\n"
        "[uncertainty]\noutputs = ['e', 'zz']\n"
    )
    store = tmp_path / "u.zarr"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(study), "--out", str(store), "-q")
    assert code == 2 and "[uncertainty] would report ['zz'], which the study does not keep" in err
    assert not store.exists()  # nothing computed


def test_a_chunking_warning_is_given_once(tmp_path, monkeypatch, capsys) -> None:
    """The study warns when it is built; the store's record read back does not warn again."""
    study = tmp_path / "w.toml"
    study.write_text(
        "[study]\nname = 'w'\nchunk_size = 1\n[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\n"
        "angle = ['10 deg', '20 deg', '30 deg', '40 deg', '50 deg', '60 deg', '70 deg', '80 deg']\n"
    )
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(study), "--out",
                           str(tmp_path / "w.zarr"), "-q")  # fmt: skip
    assert code == 0 and err.count("chunk_size = 1 cuts 8 cases") == 1


def test_an_implausible_speed_is_said_once(tmp_path, monkeypatch, capsys) -> None:
    """A grid speed past 100 m/s (a unit slip: cm/s as m/s) gets the warning a single impact
    gives, once: when the study is built, not again when the store's record is read back."""
    study = tmp_path / "v.toml"
    study.write_text("[fixed]\nmu = 0.1\nangle = '45 deg'\n[grid]\nvy = [-1.0, -141.0]\n")
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(study), "--out",
                           str(tmp_path / "v.zarr"), "-q")  # fmt: skip
    assert code == 0
    assert err.count("the largest grid or fixed speed of the study (141 m/s) exceeds 100") == 1


def test_a_plausible_study_does_not_warn() -> None:
    import warnings

    from impactlab.sweep import Study

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Study(grid={"vy": [-1.0, -99.0]}, fixed={"angle": 0.5, "mu": 0.1})


def test_uncertainty_of_a_grid_study_is_refused_before_it_runs(
    tmp_path, monkeypatch, capsys
) -> None:
    """A grid without a [sample] has nothing to summarise: said at once, no store written."""
    study = tmp_path / "g.toml"
    study.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['20 deg', '45 deg']\n")
    store = tmp_path / "g.zarr"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", str(study),
                           "--out", str(store))  # fmt: skip
    assert code == 2 and "needs a Monte Carlo sample ([sample])" in err
    assert not store.exists()
